//! Units in UNITS, INPUT and OUTPUT. In: a unit expression as parsed (`N*M`, `RAD/SEC^2`) or a
//! unit word; out: its text, upper-cased, or an error naming an unknown unit and listing the
//! known ones. [`normalised`] makes unit texts comparable regardless of case and spacing.

pub mod size;

use super::ast::{BinOp, Expr, ExprKind};
use super::diagnostic::Diagnostic;
use super::interp::names::edit_distance;
use super::token::Span;

/// A written column's header from a quantity's name and unit: `q1` + `DEG` -> `q1_deg`;
/// `AP` + `M/SEC^2` -> `ap_m_per_s2`.
pub fn column_name(name: &str, unit: &str) -> String {
    let slug = unit
        .to_ascii_lowercase()
        .replace("sec", "s")
        .replace('/', "_per_")
        .replace(['^', ' '], "")
        .replace('*', "_");
    if slug.is_empty() {
        name.to_ascii_lowercase()
    } else {
        format!("{}_{slug}", name.to_ascii_lowercase())
    }
}

/// The unit names a model may use (upper-case; combine them with `*`, `/` and `^`).
pub const KNOWN_UNITS: &[&str] = &[
    "M", "CM", "MM", "KM", "IN", "FT", "YD", "MI", // length
    "KG", "G", "MG", "LBM", "SLUG", // mass
    "S", "SEC", "MS", "MIN", "HR", "DAY", // time
    "N", "KN", "LBF", "DYN", // force
    "J", "KJ", "W", "KW", "HP", // energy, power
    "RAD", "DEG", "DEGREE", "DEGREES", "REV", // angle
    "HZ", "RPM", "PA", "KPA", "PSI", // frequency, pressure
    "A", "V", "OHM", "K", "UNITLESS", // others
];

/// The text of the unit expression `e` (`N*M`, `M/(SEC*SEC)`), or an error at the first name
/// that is not a known unit or part that is not a unit at all.
pub fn unit_expression(e: &Expr) -> Result<String, Diagnostic> {
    match &e.kind {
        ExprKind::Name { name, primes: 0, suffix: 0 } => unit_word(name, &e.span),
        ExprKind::Number { value, suffix: 0 } => Ok(format!("{value}")),
        ExprKind::Binary(op @ (BinOp::Mul | BinOp::Div | BinOp::Pow), a, b) => {
            let sym = match op {
                BinOp::Mul => "*",
                BinOp::Div => "/",
                _ => "^",
            };
            let (left, right) = (unit_expression(a)?, unit_expression(b)?);
            let compound = |x: &Expr| matches!(x.kind, ExprKind::Binary(..));
            let mul_div = |x: &Expr| matches!(x.kind, ExprKind::Binary(BinOp::Mul | BinOp::Div, ..));
            let (group_left, group_right) = match op {
                BinOp::Pow => (compound(a), compound(b)),
                BinOp::Div => (false, mul_div(b)),
                _ => (false, false),
            };
            let paren = |text: String, grouped: bool| if grouped { format!("({text})") } else { text };
            Ok(format!("{}{sym}{}", paren(left, group_left), paren(right, group_right)))
        }
        _ => Err(Diagnostic::error(e.span.clone(), "this is not a unit")
            .with_help("a unit is a unit name or names combined with *, / and ^, e.g. N*M or RAD/SEC^2")),
    }
}

/// `word` upper-cased if it is a known unit, else an error at `span` naming it.
pub fn unit_word(word: &str, span: &Span) -> Result<String, Diagnostic> {
    let upper = word.to_ascii_uppercase();
    if size::word_size(&upper).is_some() {
        return Ok(upper);
    }
    let nearest = KNOWN_UNITS
        .iter()
        .map(|k| (edit_distance(&upper, k), !same_letters(&upper, k), *k))
        .filter(|(d, _, k)| *d <= 2 && *d < k.len())
        .min();
    let hint = nearest.map_or(String::new(), |(_, _, k)| format!("did you mean `{k}`? "));
    Err(Diagnostic::error(span.clone(), format!("unknown unit `{word}`")).with_help(format!(
        "{hint}known units: {} (combined with *, / and ^, e.g. N*M or RAD/SEC^2)",
        KNOWN_UNITS.join(", ")
    )))
}

/// Whether `a` and `b` have the same letters in some order (a transposition: `DGE`, `DEG`).
fn same_letters(a: &str, b: &str) -> bool {
    let sorted = |s: &str| {
        let mut v: Vec<char> = s.chars().collect();
        v.sort_unstable();
        v
    };
    sorted(a) == sorted(b)
}

/// A unit text comparable with another: upper-case, `SEC` as `S`, `·` and a space between two
/// names as `*`, other spaces removed (`n * m`, `N m` and `N*M` compare equal).
pub fn normalised(unit: &str) -> String {
    let upper = unit.trim().to_ascii_uppercase().replace('·', "*");
    let words: Vec<&str> = upper.split_whitespace().collect();
    let mut out = String::new();
    for (i, w) in words.iter().enumerate() {
        let between_names = i > 0
            && w.starts_with(|c: char| c.is_ascii_alphabetic())
            && words[i - 1].ends_with(|c: char| c.is_ascii_alphanumeric() || c == ')');
        if between_names {
            out.push('*');
        }
        out.push_str(w);
    }
    replace_word(&out, "SEC", "S")
}

/// `text` with each whole word `from` (a run of letters) replaced by `to`.
fn replace_word(text: &str, from: &str, to: &str) -> String {
    let mut out = String::new();
    let mut word = String::new();
    let flush = |word: &mut String, out: &mut String| {
        out.push_str(if word == from { to } else { word });
        word.clear();
    };
    for c in text.chars() {
        if c.is_ascii_alphabetic() {
            word.push(c);
        } else {
            flush(&mut word, &mut out);
            out.push(c);
        }
    }
    flush(&mut word, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_texts_compare_regardless_of_case_and_spacing() {
        for same in ["N*M", "n*m", "N * m", "N m", "n·m", " N*M "] {
            assert_eq!(normalised(same), "N*M", "{same}");
        }
        assert_eq!(normalised("rad/sec"), "RAD/S");
        assert_eq!(normalised("M/SEC^2"), "M/S^2");
        assert_eq!(normalised("SECOND"), "SECOND");
        assert_ne!(normalised("NM"), normalised("N*M"));
    }

    #[test]
    fn unknown_words_are_named_with_the_nearest_known_one() {
        assert_eq!(unit_word("deg", &(0..3)).unwrap(), "DEG");
        let e = unit_word("DGE", &(0..3)).unwrap_err();
        assert_eq!(e.message, "unknown unit `DGE`");
        let help = e.help.unwrap();
        assert!(help.starts_with("did you mean `DEG`? known units: M, CM"), "{help}");
        assert!(unit_word("SCE", &(0..3)).unwrap_err().help.unwrap().starts_with("did you mean `SEC`?"));
    }
}
