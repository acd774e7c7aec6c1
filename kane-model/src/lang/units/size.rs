//! The size of a unit in SI base units and its dimension, and the unit system a file works in
//! (`UNITSYSTEM KG, METER, SEC`): INPUT values tagged with a unit are converted into it.
//!
//! In: a unit text as the parser writes it (`KG*M^2`, `M/S^2`, `RAD/(SEC*SEC)`). Out: a
//! [`UnitSize`], or an error naming what is not a unit.

/// Exponents of mass, length, time, angle, current and temperature.
pub type Dimension = [i32; 6];

const MASS: Dimension = [1, 0, 0, 0, 0, 0];
const LENGTH: Dimension = [0, 1, 0, 0, 0, 0];
const TIME: Dimension = [0, 0, 1, 0, 0, 0];
const ANGLE: Dimension = [0, 0, 0, 1, 0, 0];
const NONE: Dimension = [0; 6];

/// A unit: how many SI units (radians for angles) it is, and its dimension.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnitSize {
    /// The unit in SI base units (kg, m, s, rad, A, K).
    pub si: f64,
    /// Its dimension.
    pub dim: Dimension,
}

impl UnitSize {
    fn times(self, o: UnitSize, sign: i32) -> UnitSize {
        let mut dim = self.dim;
        for (d, e) in dim.iter_mut().zip(o.dim) {
            *d += sign * e;
        }
        UnitSize { si: if sign > 0 { self.si * o.si } else { self.si / o.si }, dim }
    }

    fn powi(self, k: i32) -> UnitSize {
        UnitSize { si: self.si.powi(k), dim: self.dim.map(|d| d * k) }
    }
}

/// The size of one unit word (upper-case), when it is known.
pub fn word_size(word: &str) -> Option<UnitSize> {
    let u = |si: f64, dim: Dimension| Some(UnitSize { si, dim });
    let force = [1, 1, -2, 0, 0, 0];
    let energy = [1, 2, -2, 0, 0, 0];
    let power = [1, 2, -3, 0, 0, 0];
    let pressure = [1, -1, -2, 0, 0, 0];
    let (deg, rev) = (std::f64::consts::PI / 180.0, 2.0 * std::f64::consts::PI);
    match word {
        "M" | "METER" | "METERS" | "METRE" | "METRES" => u(1.0, LENGTH),
        "CM" | "CENTIMETER" | "CENTIMETERS" => u(0.01, LENGTH),
        "MM" | "MILLIMETER" | "MILLIMETERS" => u(0.001, LENGTH),
        "KM" | "KILOMETER" | "KILOMETERS" => u(1000.0, LENGTH),
        "IN" | "INCH" | "INCHES" => u(0.0254, LENGTH),
        "FT" | "FOOT" | "FEET" => u(0.3048, LENGTH),
        "YD" | "YARD" | "YARDS" => u(0.9144, LENGTH),
        "MI" | "MILE" | "MILES" => u(1609.344, LENGTH),
        "KG" | "KILOGRAM" | "KILOGRAMS" => u(1.0, MASS),
        "G" | "GRAM" | "GRAMS" => u(0.001, MASS),
        "MG" => u(1e-6, MASS),
        "LBM" => u(0.453_592_37, MASS),
        "SLUG" | "SLUGS" => u(14.593_902_937_206_364, MASS),
        "S" | "SEC" | "SECOND" | "SECONDS" => u(1.0, TIME),
        "MS" => u(0.001, TIME),
        "MIN" | "MINUTE" | "MINUTES" => u(60.0, TIME),
        "HR" | "HOUR" | "HOURS" => u(3600.0, TIME),
        "DAY" | "DAYS" => u(86400.0, TIME),
        "N" | "NEWTON" | "NEWTONS" => u(1.0, force),
        "KN" => u(1000.0, force),
        "LBF" => u(4.448_221_615_260_5, force),
        "DYN" => u(1e-5, force),
        "J" | "JOULE" | "JOULES" => u(1.0, energy),
        "KJ" => u(1000.0, energy),
        "W" | "WATT" | "WATTS" => u(1.0, power),
        "KW" => u(1000.0, power),
        "HP" => u(745.699_871_582_270_2, power),
        "RAD" | "RADIAN" | "RADIANS" => u(1.0, ANGLE),
        "DEG" | "DEGREE" | "DEGREES" => u(deg, ANGLE),
        "REV" | "REVS" => u(rev, ANGLE),
        "HZ" => u(1.0, [0, 0, -1, 0, 0, 0]),
        "RPM" => u(rev / 60.0, [0, 0, -1, 1, 0, 0]),
        "PA" => u(1.0, pressure),
        "KPA" => u(1000.0, pressure),
        "PSI" => u(6_894.757_293_168_361, pressure),
        "A" | "AMP" | "AMPS" => u(1.0, [0, 0, 0, 0, 1, 0]),
        "V" | "VOLT" | "VOLTS" => u(1.0, [1, 2, -3, 0, -1, 0]),
        "OHM" | "OHMS" => u(1.0, [1, 2, -3, 0, -2, 0]),
        "K" | "KELVIN" => u(1.0, [0, 0, 0, 0, 0, 1]),
        "UNITLESS" => u(1.0, NONE),
        _ => None,
    }
}

/// The size of a unit text such as `KG*M^2`, `M/S^2` or `RAD/(SEC*SEC)`; an error names the
/// first word that is not a unit.
pub fn unit_size(text: &str) -> Result<UnitSize, String> {
    let tokens = unit_tokens(text);
    let mut r = Reader { tokens: &tokens, pos: 0 };
    let size = r.product()?;
    match r.tokens.get(r.pos) {
        None => Ok(size),
        Some(t) => Err(format!("unexpected `{t}` in the unit `{text}`")),
    }
}

fn unit_tokens(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut word = String::new();
    for c in text.chars() {
        if c.is_ascii_alphanumeric()
            || c == '_'
            || (c == '.' && word.starts_with(|d: char| d.is_ascii_digit()))
        {
            word.push(c.to_ascii_uppercase());
        } else {
            if !word.is_empty() {
                out.push(std::mem::take(&mut word));
            }
            if !c.is_whitespace() {
                // `KG.M^2`: a dot between names multiplies.
                out.push(if c == '.' { "*".into() } else { c.to_string() });
            }
        }
    }
    if !word.is_empty() {
        out.push(word);
    }
    out
}

struct Reader<'a> {
    tokens: &'a [String],
    pos: usize,
}

impl Reader<'_> {
    fn next(&mut self) -> Option<&str> {
        let t = self.tokens.get(self.pos)?;
        self.pos += 1;
        Some(t)
    }

    fn peek(&self) -> Option<&str> {
        self.tokens.get(self.pos).map(String::as_str)
    }

    fn product(&mut self) -> Result<UnitSize, String> {
        let mut size = self.power()?;
        while let Some(op @ ("*" | "/")) = self.peek() {
            let sign = if op == "*" { 1 } else { -1 };
            self.pos += 1;
            size = size.times(self.power()?, sign);
        }
        Ok(size)
    }

    fn power(&mut self) -> Result<UnitSize, String> {
        let base = self.atom()?;
        if self.peek() != Some("^") {
            return Ok(base);
        }
        self.pos += 1;
        let negative = self.peek() == Some("-");
        if negative {
            self.pos += 1;
        }
        let k: i32 = self.next().and_then(|t| t.parse().ok()).ok_or("a unit's power is a whole number")?;
        Ok(base.powi(if negative { -k } else { k }))
    }

    fn atom(&mut self) -> Result<UnitSize, String> {
        match self.next() {
            Some("(") => {
                let inner = self.product()?;
                match self.next() {
                    Some(")") => Ok(inner),
                    _ => Err("a `(` in a unit is not closed".into()),
                }
            }
            Some(t) if t.starts_with(|c: char| c.is_ascii_digit()) => match t.parse::<f64>() {
                Ok(x) => Ok(UnitSize { si: x, dim: NONE }),
                Err(_) => Err(format!("`{t}` is not a number")),
            },
            Some(t) => word_size(t).ok_or_else(|| format!("unknown unit `{t}`")),
            None => Err("a unit is missing".into()),
        }
    }
}

/// The base units of mass, length and time a file's values are in (SI unless UNITSYSTEM says
/// otherwise); angles are always radians inside the model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnitSystem {
    /// Mass, length and time units, each in SI.
    pub base: [f64; 3],
}

impl Default for UnitSystem {
    fn default() -> UnitSystem {
        UnitSystem { base: [1.0; 3] }
    }
}

impl UnitSystem {
    /// The unit system of `UNITSYSTEM` words: one each of mass, length and time, in any order
    /// (missing ones stay SI); an error names a word that is not one of those or repeats one.
    pub fn from_words(words: &[String]) -> Result<UnitSystem, (usize, String)> {
        let mut base = [None; 3];
        for (i, w) in words.iter().enumerate() {
            let size = word_size(&w.to_ascii_uppercase()).ok_or((i, format!("unknown unit `{w}`")))?;
            let slot = [MASS, LENGTH, TIME].iter().position(|d| *d == size.dim);
            let Some(slot) = slot else {
                return Err((i, format!("`{w}` is not a unit of mass, length or time")));
            };
            if base[slot].replace(size.si).is_some() {
                let what = ["mass", "length", "time"][slot];
                return Err((i, format!("UNITSYSTEM names two units of {what}")));
            }
        }
        Ok(UnitSystem { base: base.map(|b| b.unwrap_or(1.0)) })
    }

    /// How many of this system's units one `unit` is (angles in radians): the factor an INPUT
    /// value tagged with `unit` is multiplied by.
    pub fn factor(&self, unit: UnitSize) -> f64 {
        let system: f64 = self.base.iter().zip(&unit.dim[..3]).map(|(b, e)| b.powi(*e)).product();
        unit.si / system
    }
}

/// How many internal units one plain number of a quantity declared in `unit` is: where the unit
/// measures an angle or an angle's rate, the model computes in radians (DEG: pi/180, DEG/S: pi/180,
/// RPM: pi/30, in `system`'s mass, length and time); any other unit's values are kept as written (1).
pub fn internal_per_declared(unit: &str, system: &UnitSystem) -> f64 {
    match unit_size(&unit.to_ascii_uppercase()) {
        Ok(size) if size.dim[3] != 0 => system.factor(size),
        _ => 1.0,
    }
}

/// How many `unit` one internal value of a quantity declared in it is, in SI: the inverse of
/// [`internal_per_declared`] (DEG: 180/pi; M: 1).
pub fn shown_per_internal(unit: &str) -> f64 {
    1.0 / internal_per_declared(unit, &UnitSystem::default())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-14 * b.abs().max(1.0)
    }

    #[test]
    fn compound_units_have_their_si_size_and_dimension() {
        let a = unit_size("M/S^2").unwrap();
        assert_eq!((a.si, a.dim), (1.0, [0, 1, -2, 0, 0, 0]));
        let i = unit_size("KG.M^2").unwrap();
        assert_eq!(i, unit_size("kg*m^2").unwrap());
        assert_eq!(i.dim, [1, 2, 0, 0, 0, 0]);
        let w = unit_size("RAD/(SEC*SEC)").unwrap();
        assert_eq!(w.dim, [0, 0, -2, 1, 0, 0]);
        assert!(close(unit_size("DEG/S").unwrap().si, std::f64::consts::PI / 180.0));
        assert!(close(unit_size("G*CM^2").unwrap().si, 1e-7));
        assert_eq!(unit_size("N").unwrap().dim, unit_size("KG*M/S^2").unwrap().dim);
        assert_eq!(unit_size("M/FURLONG").unwrap_err(), "unknown unit `FURLONG`");
    }

    #[test]
    fn values_convert_into_the_unit_system() {
        let si = UnitSystem::default();
        assert!(close(si.factor(unit_size("CM").unwrap()), 0.01));
        assert!(close(si.factor(unit_size("RPM").unwrap()), std::f64::consts::PI / 30.0));
        let cgs = UnitSystem::from_words(&["G".into(), "CM".into(), "SEC".into()]).unwrap();
        assert!(close(cgs.factor(unit_size("KG*M^2").unwrap()), 1e7));
        assert!(close(cgs.factor(unit_size("N").unwrap()), 1e5), "a newton is 1e5 dyn");
        assert!(close(cgs.factor(unit_size("DEG").unwrap()), std::f64::consts::PI / 180.0));
        assert!(close(internal_per_declared("deg/s", &si), std::f64::consts::PI / 180.0));
        assert!(close(internal_per_declared("RPM", &si), std::f64::consts::PI / 30.0));
        assert_eq!(internal_per_declared("CM", &cgs), 1.0, "a length is kept as written");
        assert_eq!(internal_per_declared("DFG", &si), 1.0);
        let e = UnitSystem::from_words(&["KG".into(), "N".into()]).unwrap_err();
        assert_eq!(e, (1, "`N` is not a unit of mass, length or time".into()));
        assert!(UnitSystem::from_words(&["M".into(), "FT".into()])
            .unwrap_err()
            .1
            .contains("two units of length"));
    }
}
