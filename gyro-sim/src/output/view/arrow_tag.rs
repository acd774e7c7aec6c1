//! The name drawn at an arrow's tip and beside its checkbox: in come the arrow's label, its
//! columns and their units, and the name of the space axes; out goes the label, or, where it
//! could be read as those axes (an arrow `N` beside axes N1, N2, N3), the vector its columns
//! name with their unit (`torque`, `torque (N·m)`).

/// The tag of the arrow labelled `label` drawing `columns` (of unit `unit`, empty for none)
/// among space axes `frame`1, 2, 3.
pub(super) fn arrow_tag(label: &str, columns: &[String; 3], unit: &str, frame: &str) -> String {
    if !reads_as_axes(label, frame) {
        return label.to_string();
    }
    let name = vector_name(columns, frame).filter(|n| !reads_as_axes(n, frame));
    let name = name.unwrap_or_else(|| format!("{label} arrow"));
    if unit.trim().is_empty() {
        name
    } else {
        format!("{name} ({})", unit_text(unit))
    }
}

/// Whether `text` is the axes' name or one axis's (`N`, `N1`, `n3`).
fn reads_as_axes(text: &str, frame: &str) -> bool {
    let text = text.trim();
    let axis = text.get(..frame.len()).is_some_and(|f| f.eq_ignore_ascii_case(frame))
        && matches!(&text[frame.len()..], "1" | "2" | "3");
    text.eq_ignore_ascii_case(frame) || axis
}

/// The vector the three columns are components of (`TORQUE_N1` ... -> `torque`), if they share
/// a name.
fn vector_name(columns: &[String; 3], frame: &str) -> Option<String> {
    let [a, b, c] = columns;
    let common = a.bytes().zip(b.bytes()).zip(c.bytes()).take_while(|((x, y), z)| x == y && y == z).count();
    let stem = a.get(..common)?;
    let upper = stem.to_ascii_uppercase();
    let frame_suffix = format!("_{}", frame.to_ascii_uppercase());
    let stem = match upper.strip_suffix(&frame_suffix) {
        Some(s) => &stem[..s.len()],
        None => stem,
    };
    let name = stem.trim_matches('_').replace('_', " ").to_lowercase();
    (!name.is_empty()).then_some(name)
}

/// A unit as a reader writes it: `N*M` -> `N·m`, `RAD/SEC` -> `rad/s`, `M/SEC^2` -> `m/s²`.
fn unit_text(unit: &str) -> String {
    let mut out = String::new();
    let mut word = String::new();
    for ch in unit.trim().chars().chain(std::iter::once(' ')) {
        if ch.is_ascii_alphabetic() {
            word.push(ch);
            continue;
        }
        out.push_str(&symbol(&word));
        word.clear();
        out.push(if ch == '*' { '·' } else { ch });
    }
    out.trim_end().replace("^2", "²").replace("^3", "³")
}

/// A unit's symbol: newtons, joules, watts and pascals capital, seconds `s`, others lower case.
fn symbol(word: &str) -> String {
    match word.to_ascii_uppercase().as_str() {
        "N" => "N".into(),
        "J" => "J".into(),
        "W" => "W".into(),
        "PA" => "Pa".into(),
        "SEC" => "s".into(),
        _ => word.to_ascii_lowercase(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn columns(stem: &str, frame: &str) -> [String; 3] {
        [1, 2, 3].map(|k| format!("{stem}_{frame}{k}"))
    }

    #[test]
    fn a_label_read_as_the_axes_names_its_vector() {
        assert_eq!(arrow_tag("N", &columns("TORQUE", "N"), "", "N"), "torque");
        assert_eq!(arrow_tag("N", &columns("TORQUE", "N"), "N*M", "N"), "torque (N·m)");
        assert_eq!(arrow_tag("a2", &columns("ANG_MOM", "A"), "KG*M^2/SEC", "A"), "ang mom (kg·m²/s)");
        // Columns with no shared name: the label, said to be an arrow's.
        let odd = ["X".to_string(), "Y".to_string(), "Z".to_string()];
        assert_eq!(arrow_tag("N", &odd, "", "N"), "N arrow");
    }

    #[test]
    fn other_labels_stay() {
        assert_eq!(arrow_tag("L", &columns("L", "N"), "", "N"), "L");
        assert_eq!(arrow_tag("omega", &columns("OMEGA", "N"), "RAD/SEC", "N"), "omega");
        assert_eq!(arrow_tag("N", &columns("TORQUE", "A"), "", "A"), "N", "the axes are A1, A2, A3");
        assert_eq!(arrow_tag("N4", &columns("F", "N"), "", "N"), "N4");
    }

    #[test]
    fn units_read_as_written_by_hand() {
        assert_eq!(unit_text("M/SEC^2"), "m/s²");
        assert_eq!(unit_text("RAD/SEC"), "rad/s");
        assert_eq!(unit_text("N*M"), "N·m");
    }
}
