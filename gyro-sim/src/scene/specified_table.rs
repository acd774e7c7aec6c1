//! A SPECIFIED quantity given by a table in a scene: in comes `[specified] EA = { table =
//! "swing.csv" }` (a CSV file beside the scene, columns `t` and the quantity's name) or `EA = {
//! t = [...], values = [...] }`; out goes the model text `SPLINE(T, [...], [...])`, the
//! not-a-knot cubic spline through the rows, whose rates the equations read where the motion is
//! prescribed. A table that does not cover the run, is not increasing in time, or holds values
//! that are not finite numbers is an error that says which.

use std::path::{Path, PathBuf};

use thiserror::Error;

/// Why a table of a SPECIFIED quantity cannot be used.
#[derive(Debug, Error)]
pub enum TableError {
    /// `table` is not a file name.
    #[error("`table` is the name of a CSV file")]
    FileName,
    /// The keys are neither `table` nor `t` and `values`.
    #[error("keys are `table` (a CSV file) or `t` and `values`, not {}", .0.join(", "))]
    Keys(Vec<String>),
    /// `t` or `values` is not a list.
    #[error("`{key}` is a list of numbers")]
    NotAList {
        /// The key.
        key: String,
    },
    /// `t` or `values` holds something other than a number.
    #[error("`{key}` holds numbers only, not {value}")]
    NotANumber {
        /// The key.
        key: String,
        /// What it holds, as TOML.
        value: toml::Value,
    },
    /// The CSV file could not be read.
    #[error("{}: {source}", path.display())]
    Csv {
        /// The file.
        path: PathBuf,
        /// What the CSV reader said.
        #[source]
        source: csv::Error,
    },
    /// The CSV file lacks a column.
    #[error("{}: the header needs columns `t` and `{name}`; it has {}", path.display(), header.join(", "))]
    Columns {
        /// The file.
        path: PathBuf,
        /// The quantity.
        name: String,
        /// The columns it has.
        header: Vec<String>,
    },
    /// A cell of the CSV file is not a number.
    #[error("{}: row {row}: `{text}` is not a number", path.display())]
    Cell {
        /// The file.
        path: PathBuf,
        /// The row, counting the header as row 1.
        row: usize,
        /// The cell.
        text: String,
    },
    /// Too few rows, or times and values of different lengths.
    #[error("a table needs two rows or more and one value per time: {times} times, {values} values")]
    Shape {
        /// How many times.
        times: usize,
        /// How many values.
        values: usize,
    },
    /// A time or value is not finite.
    #[error("a table holds finite numbers only, not {0}")]
    NotFinite(f64),
    /// The times do not increase.
    #[error("times must increase: row {row} (t = {t}) follows t = {before}")]
    NotIncreasing {
        /// The row, from 1.
        row: usize,
        /// Its time.
        t: f64,
        /// The time before it.
        before: f64,
    },
    /// The table does not cover the run.
    #[error("the table covers t = {first} to {last} s but the run goes from 0 to {t_final} s (outside its rows a table has no values)")]
    Coverage {
        /// The first time.
        first: f64,
        /// The last time.
        last: f64,
        /// The run's final time.
        t_final: f64,
    },
}

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
    pub fn from_toml(name: &str, value: &toml::Table, folder: &Path) -> Result<Table, TableError> {
        let keys: Vec<&str> = value.keys().map(String::as_str).collect();
        let table = match keys.as_slice() {
            ["table"] => {
                let file = value["table"].as_str().ok_or(TableError::FileName)?;
                from_csv(name, &folder.join(file))?
            }
            ["t", "values"] | ["values", "t"] => {
                Table { times: numbers(&value["t"], "t")?, values: numbers(&value["values"], "values")? }
            }
            _ => return Err(TableError::Keys(keys.iter().map(|k| k.to_string()).collect())),
        };
        table.checked()
    }

    /// The model text of the spline through the points, in time `T`.
    pub fn spline_formula(&self) -> String {
        let list = |xs: &[f64]| xs.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>().join(", ");
        format!("SPLINE(T, [{}], [{}])", list(&self.times), list(&self.values))
    }

    /// An error unless the table covers `[0, t_final]`.
    pub fn covers(&self, t_final: f64) -> Result<(), TableError> {
        let (first, last) = (self.times[0], self.times[self.times.len() - 1]);
        if first > 0.0 || last < t_final {
            return Err(TableError::Coverage { first, last, t_final });
        }
        Ok(())
    }

    fn checked(self) -> Result<Table, TableError> {
        if self.times.len() != self.values.len() || self.times.len() < 2 {
            return Err(TableError::Shape { times: self.times.len(), values: self.values.len() });
        }
        if let Some(x) = self.times.iter().chain(&self.values).find(|x| !x.is_finite()) {
            return Err(TableError::NotFinite(*x));
        }
        if let Some(k) = self.times.windows(2).position(|w| w[1] <= w[0]) {
            return Err(TableError::NotIncreasing {
                row: k + 2,
                t: self.times[k + 1],
                before: self.times[k],
            });
        }
        Ok(self)
    }
}

/// Numbers from a TOML array.
fn numbers(value: &toml::Value, key: &str) -> Result<Vec<f64>, TableError> {
    let array = value.as_array().ok_or_else(|| TableError::NotAList { key: key.to_string() })?;
    array
        .iter()
        .map(|v| match v {
            toml::Value::Float(x) => Ok(*x),
            toml::Value::Integer(i) => Ok(*i as f64),
            other => Err(TableError::NotANumber { key: key.to_string(), value: other.clone() }),
        })
        .collect()
}

/// The columns `t` and `name` (case-insensitive) of a CSV file with a header.
fn from_csv(name: &str, path: &Path) -> Result<Table, TableError> {
    let fail = |source: csv::Error| TableError::Csv { path: path.to_path_buf(), source };
    let mut reader = csv::Reader::from_path(path).map_err(fail)?;
    let header = reader.headers().map_err(fail)?.clone();
    let column = |wanted: &str| header.iter().position(|h| h.trim().eq_ignore_ascii_case(wanted));
    let (Some(t), Some(v)) = (column("t"), column(name)) else {
        let header = header.iter().map(String::from).collect();
        return Err(TableError::Columns { path: path.to_path_buf(), name: name.to_string(), header });
    };
    let mut table = Table { times: Vec::new(), values: Vec::new() };
    for (row, record) in reader.records().enumerate() {
        let record = record.map_err(fail)?;
        let cell = |k: usize| -> Result<f64, TableError> {
            let text = record.get(k).unwrap_or("").trim();
            let bad = || TableError::Cell { path: path.to_path_buf(), row: row + 2, text: text.to_string() };
            text.parse().map_err(|_| bad())
        };
        table.times.push(cell(t)?);
        table.values.push(cell(v)?);
    }
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parsed(text: &str) -> Result<Table, TableError> {
        let value: toml::Table = toml::from_str(text).unwrap();
        Table::from_toml("EA", &value, Path::new("."))
    }

    /// The message `text` is refused with.
    fn refused(text: &str) -> String {
        parsed(text).unwrap_err().to_string()
    }

    #[test]
    fn inline_tables_are_checked_and_written_as_a_spline() {
        let t = parsed("t = [0, 0.5, 1.5]\nvalues = [0.0, 1, -2.5]").unwrap();
        assert_eq!(t.spline_formula(), "SPLINE(T, [0.0, 0.5, 1.5], [0.0, 1.0, -2.5])");
        assert!(t.covers(1.5).is_ok());
        assert!(t
            .covers(2.0)
            .unwrap_err()
            .to_string()
            .contains("covers t = 0 to 1.5 s but the run goes from 0 to 2 s"));
        assert!(refused("t = [0, 1, 1]\nvalues = [0, 1, 2]").contains("times must increase: row 3"));
        assert!(refused("t = [0, 1]\nvalues = [0]").contains("2 times, 1 values"));
        assert!(refused("t = [0, 1]\nvalues = [0, nan]").contains("finite"));
        assert!(refused("file = \"x.csv\"").contains("keys are `table`"));
    }
}
