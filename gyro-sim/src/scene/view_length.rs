//! A length of a 3-D view: in comes a number or a model parameter's name, scaled or not (`1.0`,
//! `"D"`, `"1.2*D"`); out goes the number once the run's parameter values are known, so a body
//! drawn at a distance `D` along its axle moves when `D` does.

use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// A view length: a number, or a factor times a model parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum Length {
    /// A number, in model units.
    Number(f64),
    /// `factor * name`, `name` a parameter of the model.
    Parameter {
        /// The factor (1 when only the name is given).
        factor: f64,
        /// The parameter's name as written.
        name: String,
    },
}

impl From<f64> for Length {
    fn from(x: f64) -> Length {
        Length::Number(x)
    }
}

impl Length {
    /// The number, when it is one.
    pub fn number(&self) -> Option<f64> {
        match self {
            Length::Number(x) => Some(*x),
            Length::Parameter { .. } => None,
        }
    }

    /// The number with parameters from `value_of`; the name when the model has no such parameter.
    pub fn with_parameters(&self, value_of: &dyn Fn(&str) -> Option<f64>) -> Result<f64, String> {
        match self {
            Length::Number(x) => Ok(*x),
            Length::Parameter { factor, name } => {
                value_of(name).map(|v| factor * v).ok_or_else(|| name.clone())
            }
        }
    }

    /// Reads `"NAME"` or `"FACTOR*NAME"`.
    fn parse(text: &str) -> Option<Length> {
        let (factor, name) = match text.split_once('*') {
            Some((f, n)) => (f.trim().parse::<f64>().ok().filter(|f| f.is_finite())?, n.trim()),
            None => (1.0, text.trim()),
        };
        super::text::is_simple_name(name).then(|| Length::Parameter { factor, name: name.to_string() })
    }
}

impl Serialize for Length {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Length::Number(x) => s.serialize_f64(*x),
            Length::Parameter { factor, name } if *factor == 1.0 => s.serialize_str(name),
            Length::Parameter { factor, name } => s.serialize_str(&format!("{factor}*{name}")),
        }
    }
}

impl<'de> Deserialize<'de> for Length {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Length, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Written {
            Number(f64),
            Text(String),
        }
        match Written::deserialize(d)? {
            Written::Number(x) => Ok(Length::Number(x)),
            Written::Text(t) => Length::parse(&t).ok_or_else(|| {
                serde::de::Error::custom(format!(
                    "`{t}` is not a length: give a number, a parameter's name (\"D\") or a factor times one (\"1.2*D\")"
                ))
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_names_and_scaled_names_are_read_and_resolved() {
        let read =
            |t: &str| toml::from_str::<std::collections::BTreeMap<String, Length>>(t).map(|m| m["x"].clone());
        assert_eq!(read("x = 2").unwrap(), Length::Number(2.0));
        assert_eq!(read("x = 0.5").unwrap(), Length::Number(0.5));
        assert_eq!(read("x = \"D\"").unwrap(), Length::Parameter { factor: 1.0, name: "D".into() });
        let scaled = read("x = \"1.2 * D\"").unwrap();
        assert_eq!(scaled, Length::Parameter { factor: 1.2, name: "D".into() });
        let d = |n: &str| (n == "D").then_some(2.0);
        assert_eq!(scaled.with_parameters(&d), Ok(2.4));
        assert_eq!(Length::from(3.0).with_parameters(&d), Ok(3.0));
        assert_eq!(read("x = \"RR\"").unwrap().with_parameters(&d), Err("RR".to_string()));
        for bad in ["x = \"1.2*\"", "x = \"*D\"", "x = \"two*D\"", "x = \"D+1\"", "x = \"\""] {
            let e = read(bad).unwrap_err().to_string();
            assert!(e.contains("is not a length"), "{bad}: {e}");
        }
        assert_eq!(serde_json::to_string(&scaled).unwrap(), "\"1.2*D\"");
        assert_eq!(serde_json::to_string(&Length::Number(1.5)).unwrap(), "1.5");
    }
}
