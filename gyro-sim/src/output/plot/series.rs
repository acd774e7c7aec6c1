//! The time series like the paper's Figures 3-5: in comes a table; out goes a PNG with one panel
//! for the angles, one for each angle that grows through many turns (a rotor's spin, on its own
//! axis so the others stay readable), and one for the outputs (such as |a_P|), or for the rates
//! when there is none. Axis titles carry the quantity and its unit.

use std::path::Path;

use plotters::prelude::*;

use super::super::{write_atomically, Table};
use super::panel::{self, Panel};
use super::{pretty_unit, register_font};

/// An angle whose range exceeds this many degrees gets a panel of its own.
const SPIN_RANGE_DEG: f64 = 1800.0;

/// Writes the time-series plot of `table` to `path` (atomically).
pub fn write_plot(table: &Table, path: &Path) -> Result<(), String> {
    register_font();
    let panels = panels(table);
    write_atomically(path, |tmp| {
        let root = BitMapBackend::new(tmp, (600 * panels.len().max(1) as u32, 450)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root.titled(&table.title, ("sans-serif", 22)).map_err(|e| e.to_string())?;
        let areas = root.split_evenly((1, panels.len().max(1)));
        for (area, p) in areas.iter().zip(&panels) {
            panel::draw(area, p)?;
        }
        root.present().map_err(|e| e.to_string())
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
        groups.push(rest.iter().copied().filter(|c| cols[*c].unit == unit).collect());
    }
    groups.into_iter().map(|g| panel_of(table, g)).collect()
}

/// A panel of columns `g`: the y title names the quantity (or "angle", "rate") and the unit.
fn panel_of(table: &Table, g: Vec<usize>) -> Panel<'_> {
    let cols = &table.columns;
    let unit = pretty_unit(&cols[g[0]].unit);
    let quantity = match g.as_slice() {
        [c] => cols[*c].label.clone(),
        _ if cols[g[0]].angle => "angle".to_string(),
        _ if unit.contains("/s") => "rate".to_string(),
        _ => g.iter().map(|c| cols[*c].label.as_str()).collect::<Vec<_>>().join(", "),
    };
    let y_title = if unit.is_empty() { quantity } else { format!("{quantity} ({unit})") };
    Panel {
        rows: table.figure_rows(),
        series: g.iter().map(|c| (cols[*c].label.clone(), c + 1)).collect(),
        x_title: "t (s)".to_string(),
        y_title,
    }
}
