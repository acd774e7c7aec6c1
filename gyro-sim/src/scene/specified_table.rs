//! A SPECIFIED quantity given by a table in a scene: in comes `[specified] EA = { table =
//! "swing.csv" }` (a CSV file beside the scene, columns `t` and the quantity's name) or `EA = {
//! t = [...], values = [...] }`; out goes the model text `SPLINE(T, [...], [...])`, the
//! not-a-knot cubic spline through the rows, whose rates the equations read where the motion is
//! prescribed. A table that does not cover the run, is not increasing in time, or holds values
//! that are not finite numbers is an error that says which.

use std::path::Path;

/// The points of a table: times and values.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// Strictly increasing times.
    pub times: Vec<f64>,
    /// One value per time.
    pub values: Vec<f64>,
}

impl Table {
    /// The table `value` (a TOML table) gives for `name`, files read from `folder`.
    pub fn from_toml(name: &str, value: &toml::Table, folder: &Path) -> Result<Table, String> {
        let keys: Vec<&str> = value.keys().map(String::as_str).collect();
        let table = match keys.as_slice() {
            ["table"] => {
                let file = value["table"].as_str().ok_or("`table` is the name of a CSV file")?;
                from_csv(name, &folder.join(file))?
            }
            ["t", "values"] | ["values", "t"] => {
                Table { times: numbers(&value["t"], "t")?, values: numbers(&value["values"], "values")? }
            }
            _ => {
                return Err(format!(
                    "keys are `table` (a CSV file) or `t` and `values`, not {}",
                    keys.join(", ")
                ))
            }
        };
        table.checked()
    }

    /// The model text of the spline through the points, in time `T`.
    pub fn spline_formula(&self) -> String {
        let list = |xs: &[f64]| xs.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>().join(", ");
        format!("SPLINE(T, [{}], [{}])", list(&self.times), list(&self.values))
    }

    /// An error unless the table covers `[0, t_final]`.
    pub fn covers(&self, t_final: f64) -> Result<(), String> {
        let (first, last) = (self.times[0], self.times[self.times.len() - 1]);
        if first > 0.0 || last < t_final {
            return Err(format!(
                "the table covers t = {first} to {last} s but the run goes from 0 to {t_final} s (outside its rows a table has no values)"
            ));
        }
        Ok(())
    }

    fn checked(self) -> Result<Table, String> {
        if self.times.len() != self.values.len() || self.times.len() < 2 {
            return Err(format!(
                "a table needs two rows or more and one value per time: {} times, {} values",
                self.times.len(),
                self.values.len()
            ));
        }
        if let Some(x) = self.times.iter().chain(&self.values).find(|x| !x.is_finite()) {
            return Err(format!("a table holds finite numbers only, not {x}"));
        }
        if let Some(k) = self.times.windows(2).position(|w| w[1] <= w[0]) {
            return Err(format!(
                "times must increase: row {} (t = {}) follows t = {}",
                k + 2,
                self.times[k + 1],
                self.times[k]
            ));
        }
        Ok(self)
    }
}

/// Numbers from a TOML array.
fn numbers(value: &toml::Value, key: &str) -> Result<Vec<f64>, String> {
    let array = value.as_array().ok_or_else(|| format!("`{key}` is a list of numbers"))?;
    array
        .iter()
        .map(|v| match v {
            toml::Value::Float(x) => Ok(*x),
            toml::Value::Integer(i) => Ok(*i as f64),
            other => Err(format!("`{key}` holds numbers only, not {other}")),
        })
        .collect()
}

/// The columns `t` and `name` (case-insensitive) of a CSV file with a header.
fn from_csv(name: &str, path: &Path) -> Result<Table, String> {
    let mut reader = csv::Reader::from_path(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let header = reader.headers().map_err(|e| format!("{}: {e}", path.display()))?.clone();
    let column = |wanted: &str| header.iter().position(|h| h.trim().eq_ignore_ascii_case(wanted));
    let (Some(t), Some(v)) = (column("t"), column(name)) else {
        return Err(format!(
            "{}: the header needs columns `t` and `{name}`; it has {}",
            path.display(),
            header.iter().collect::<Vec<_>>().join(", ")
        ));
    };
    let mut table = Table { times: Vec::new(), values: Vec::new() };
    for (row, record) in reader.records().enumerate() {
        let record = record.map_err(|e| format!("{}: {e}", path.display()))?;
        let cell = |k: usize| -> Result<f64, String> {
            let text = record.get(k).unwrap_or("").trim();
            text.parse().map_err(|_| format!("{}: row {}: `{text}` is not a number", path.display(), row + 2))
        };
        table.times.push(cell(t)?);
        table.values.push(cell(v)?);
    }
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parsed(text: &str) -> Result<Table, String> {
        let value: toml::Table = toml::from_str(text).unwrap();
        Table::from_toml("EA", &value, Path::new("."))
    }

    #[test]
    fn inline_tables_are_checked_and_written_as_a_spline() {
        let t = parsed("t = [0, 0.5, 1.5]\nvalues = [0.0, 1, -2.5]").unwrap();
        assert_eq!(t.spline_formula(), "SPLINE(T, [0.0, 0.5, 1.5], [0.0, 1.0, -2.5])");
        assert!(t.covers(1.5).is_ok());
        assert!(t.covers(2.0).unwrap_err().contains("covers t = 0 to 1.5 s but the run goes from 0 to 2 s"));
        assert!(parsed("t = [0, 1, 1]\nvalues = [0, 1, 2]")
            .unwrap_err()
            .contains("times must increase: row 3"));
        assert!(parsed("t = [0, 1]\nvalues = [0]").unwrap_err().contains("2 times, 1 values"));
        assert!(parsed("t = [0, 1]\nvalues = [0, nan]").unwrap_err().contains("finite"));
        assert!(parsed("file = \"x.csv\"").unwrap_err().contains("keys are `table`"));
    }
}
