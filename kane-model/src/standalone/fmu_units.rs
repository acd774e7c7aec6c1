//! An FMU's units: in come the model's unit texts (`DEG`, `M/SEC^2`, `N*M`); out go the SI unit
//! each value is in (the FMU computes in internal units) with its base-unit exponents, and the
//! declared unit as its display unit with the factor between them.

use std::collections::BTreeMap;

use crate::lang::units::size::{unit_size, Dimension};

/// The SI units of base-unit exponents, and the display units of each.
#[derive(Default)]
pub(super) struct Units {
    units: BTreeMap<String, (Dimension, BTreeMap<String, f64>)>,
}

/// The base units in the order of [`Dimension`]'s exponents, as FMI names them.
const BASE: [&str; 6] = ["kg", "m", "s", "rad", "A", "K"];

impl Units {
    /// The `unit` and `displayUnit` attributes of a value declared in `declared` (none for a
    /// dimensionless value or an unknown unit), the unit recorded.
    pub(super) fn attributes(&mut self, declared: &str) -> String {
        let Ok(size) = unit_size(declared) else { return String::new() };
        if size.dim == [0; 6] {
            return String::new();
        }
        let name = si_name(size.dim);
        let entry = self.units.entry(name.clone()).or_insert_with(|| (size.dim, BTreeMap::new()));
        if declared == name {
            return format!(" unit=\"{}\"", escape(&name));
        }
        entry.1.insert(declared.to_string(), 1.0 / size.si);
        format!(" unit=\"{}\" displayUnit=\"{}\"", escape(&name), escape(declared))
    }

    /// The `<UnitDefinitions>` element (empty text when no value has a unit).
    pub(super) fn definitions(&self) -> String {
        if self.units.is_empty() {
            return String::new();
        }
        let mut x = String::from("  <UnitDefinitions>\n");
        for (name, (dim, displays)) in &self.units {
            let exponents: Vec<String> =
                BASE.iter().zip(dim).filter(|(_, e)| **e != 0).map(|(b, e)| format!("{b}=\"{e}\"")).collect();
            x.push_str(&format!(
                "    <Unit name=\"{}\">\n      <BaseUnit {}/>\n",
                escape(name),
                exponents.join(" ")
            ));
            for (display, factor) in displays {
                x.push_str(&format!(
                    "      <DisplayUnit name=\"{}\" factor=\"{factor:?}\"/>\n",
                    escape(display)
                ));
            }
            x.push_str("    </Unit>\n");
        }
        x.push_str("  </UnitDefinitions>\n");
        x
    }
}

/// The SI unit of `dim`: `m/s2`, `kg.m2/s2`, `rad/s`.
fn si_name(dim: Dimension) -> String {
    let part = |positive: bool| -> Vec<String> {
        BASE.iter()
            .zip(dim)
            .filter(|(_, e)| if positive { *e > 0 } else { *e < 0 })
            .map(|(b, e)| if e.abs() == 1 { b.to_string() } else { format!("{b}{}", e.abs()) })
            .collect()
    };
    let (up, down) = (part(true), part(false));
    match (up.is_empty(), down.is_empty()) {
        (_, true) => up.join("."),
        (true, false) => format!("1/{}", down.join(".")),
        (false, false) => format!("{}/{}", up.join("."), down.join(".")),
    }
}

/// XML text with `&`, `<`, `>` and `"` escaped.
pub(super) fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn declared_units_display_the_si_values() {
        let mut units = Units::default();
        assert_eq!(units.attributes("DEG"), " unit=\"rad\" displayUnit=\"DEG\"");
        assert_eq!(units.attributes("M/SEC^2"), " unit=\"m/s2\" displayUnit=\"M/SEC^2\"");
        assert_eq!(units.attributes("N*M"), " unit=\"kg.m2/s2\" displayUnit=\"N*M\"");
        assert_eq!(units.attributes(""), "");
        let x = units.definitions();
        assert!(x.contains("<Unit name=\"rad\">\n      <BaseUnit rad=\"1\"/>"), "{x}");
        assert!(x.contains("<DisplayUnit name=\"DEG\" factor=\"57.29577951308232\"/>"), "{x}");
    }
}
