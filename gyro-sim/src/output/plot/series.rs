//! The time series like the paper's Figures 3-5: in comes a table; out goes a PNG with one panel
//! for the angles, one for each angle that grows through many turns (a rotor's spin, on its own
//! axis so the others stay readable), and one for the outputs (such as |a_P|), or for the rates
//! when there is none. Axis titles carry the quantity and its unit.

use std::path::Path;

use plotters::prelude::*;

use super::super::{Table, WriteError};
use super::panel::{self, Panel};
use super::{draw_atomically, pretty_unit, register_font, COLORS};

/// An angle whose range exceeds this many degrees gets a panel of its own.
const SPIN_RANGE_DEG: f64 = 1800.0;
/// Panels per row of the figure.
const PER_ROW: usize = 3;

/// Writes the time-series plot of `table` to `path` (atomically).
pub fn write_plot(table: &Table, path: &Path) -> Result<(), WriteError> {
    register_font();
    let panels = panels(table);
    draw_atomically(path, |tmp| {
        let n = panels.len().max(1);
        let (across, down) = (n.min(PER_ROW), n.div_ceil(PER_ROW));
        let size = (600 * across as u32, 450 * down as u32 + 30);
        let root = BitMapBackend::new(tmp, size).into_drawing_area();
        root.fill(&WHITE)?;
        let root = root.titled(&table.title, ("sans-serif", 22))?;
        let areas = root.split_evenly((down, across));
        for (area, p) in areas.iter().zip(&panels) {
            panel::draw(area, p)?;
        }
        Ok(root.present()?)
    })
}

/// The panels: angles, spins, then outputs grouped by unit (or rates when no output).
fn panels(table: &Table) -> Vec<Panel<'_>> {
    let cols = &table.columns;
    let range = |c: usize| {
        let (lo, hi) = table
            .rows
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| (lo.min(r[c + 1]), hi.max(r[c + 1])));
        let deg = if cols[c].degrees { 1.0 } else { 180.0 / std::f64::consts::PI };
        (hi - lo) * deg
    };
    let angles: Vec<usize> = (0..cols.len()).filter(|c| cols[*c].angle && !cols[*c].output).collect();
    let (spins, small): (Vec<usize>, Vec<usize>) =
        angles.into_iter().partition(|c| range(*c) > SPIN_RANGE_DEG);
    let mut groups: Vec<Vec<usize>> = Vec::new();
    if !small.is_empty() {
        groups.push(small);
    }
    groups.extend(spins.into_iter().map(|c| vec![c]));
    let mut rest: Vec<usize> = (0..cols.len()).filter(|c| cols[*c].output).collect();
    if rest.is_empty() {
        rest = (0..cols.len()).filter(|c| !cols[*c].angle).collect();
    }
    let mut units: Vec<&str> = Vec::new();
    for c in &rest {
        if !units.contains(&cols[*c].unit.as_str()) {
            units.push(cols[*c].unit.as_str());
        }
    }
    for unit in units {
        let same: Vec<usize> = rest.iter().copied().filter(|c| cols[*c].unit == unit).collect();
        groups.extend(by_vector(table, same));
    }
    // More series than colours would repeat colours on one panel: split into readable panels.
    let readable =
        groups.into_iter().flat_map(|g| g.chunks(COLORS.len()).map(<[usize]>::to_vec).collect::<Vec<_>>());
    readable.map(|g| panel_of(table, g)).collect()
}

/// Columns of one unit split into a group per vector (`L_N1`, `L_N2`, `L_N3`) and one for the
/// rest, in order of first appearance.
fn by_vector(table: &Table, columns: Vec<usize>) -> Vec<Vec<usize>> {
    let base = |c: usize| vector_component(&table.columns[c].label).map(|(b, _)| b.to_string());
    let mut groups: Vec<(Option<String>, Vec<usize>)> = Vec::new();
    for c in columns {
        let family = base(c)
            .filter(|b| (0..table.columns.len()).filter(|o| base(*o).as_ref() == Some(b)).count() == 3);
        match groups.iter_mut().find(|(f, _)| *f == family) {
            Some((_, g)) => g.push(c),
            None => groups.push((family, vec![c])),
        }
    }
    groups.into_iter().map(|(_, g)| g).collect()
}

/// `L_N1` -> (`L`, `N`): a vector output's name and frame, from its component's column.
fn vector_component(label: &str) -> Option<(&str, &str)> {
    let (base, suffix) = label.rsplit_once('_')?;
    let (frame, digit) = suffix.split_at(suffix.len().checked_sub(1)?);
    let is_frame = !frame.is_empty() && frame.chars().all(|c| c.is_ascii_alphabetic());
    (is_frame && matches!(digit, "1" | "2" | "3") && !base.is_empty()).then_some((base, frame))
}

/// A panel of columns `g`: the y title names the quantity (or "angle", "rate") and the unit.
fn panel_of(table: &Table, g: Vec<usize>) -> Panel<'_> {
    let cols = &table.columns;
    let unit = pretty_unit(&cols[g[0]].unit);
    let vector = vector_component(&cols[g[0]].label).filter(|(b, _)| {
        g.len() == 3 && g.iter().all(|c| vector_component(&cols[*c].label).is_some_and(|(o, _)| o == *b))
    });
    let quantity = match (g.as_slice(), vector) {
        ([c], _) => cols[*c].label.clone(),
        (_, Some((base, frame))) => format!("{base}, {frame} axes"),
        _ if cols[g[0]].angle => "angle".to_string(),
        _ if unit.contains("/s") => "rate".to_string(),
        _ => "value".to_string(),
    };
    let y_title = if unit.is_empty() { quantity } else { format!("{quantity} ({unit})") };
    Panel {
        rows: table.figure_rows(),
        series: g.iter().map(|c| (cols[*c].label.clone(), c + 1)).collect(),
        x_title: "t (s)".to_string(),
        y_title,
    }
}

#[cfg(test)]
mod tests {
    use super::{panels, vector_component};
    use crate::output::display::{Column, Table};

    #[test]
    fn eighteen_rates_are_split_over_panels_of_at_most_six() {
        let column = |k: usize| Column {
            name: format!("u{k}_rad_per_s"),
            label: format!("U{k}"),
            unit: "RAD/S".into(),
            degrees: false,
            angle: false,
            output: false,
        };
        let table = Table {
            title: "chain".into(),
            columns: (1..=18).map(column).collect(),
            rows: vec![vec![0.0; 19], vec![1.0; 19]],
            plot_rows: Vec::new(),
        };
        let sizes: Vec<usize> = panels(&table).iter().map(|p| p.series.len()).collect();
        assert_eq!(sizes, [6, 6, 6]);
    }

    #[test]
    fn vector_components_are_recognised_by_name() {
        assert_eq!(vector_component("L_N1"), Some(("L", "N")));
        assert_eq!(vector_component("OMEGA_N3"), Some(("OMEGA", "N")));
        assert_eq!(vector_component("A_D_23"), None);
        assert_eq!(vector_component("L3"), None);
        assert_eq!(vector_component("_N1"), None);
    }
}
