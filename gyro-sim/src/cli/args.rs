//! The command line's own values: `--method`, `--rtol` / `--atol` and `--set NAME=VALUE`, read
//! as clap parses them.

use super::CliError;

/// A `--method` value: a method's name or `auto`.
pub fn parse_method(text: &str) -> Result<String, CliError> {
    let name = text.trim().to_ascii_lowercase();
    match name == crate::ode::AUTO || crate::ode::by_name(&name).is_some() {
        true => Ok(name),
        false => Err(CliError::UnknownMethod { name: text.to_string() }),
    }
}

/// A `--rtol` or `--atol` value: a positive, finite number.
pub fn parse_tolerance(text: &str) -> Result<f64, CliError> {
    match text.trim().parse::<f64>() {
        Ok(x) if x > 0.0 && x.is_finite() => Ok(x),
        _ => Err(CliError::NotPositive { text: text.to_string() }),
    }
}

/// Splits `NAME=VALUE`.
pub fn parse_set(text: &str) -> Result<(String, String), CliError> {
    match text.split_once('=') {
        Some((n, v)) if !n.trim().is_empty() && !v.trim().is_empty() => {
            Ok((n.trim().to_string(), v.trim().to_string()))
        }
        _ => Err(CliError::SetForm { text: text.to_string() }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn methods_tolerances_and_sets_are_read_or_refused() {
        assert_eq!(parse_method("VERN7").unwrap(), "vern7");
        let e = parse_method("euler").unwrap_err().to_string();
        assert!(e.starts_with("unknown integrator `euler` (methods: dop853"), "{e}");
        assert_eq!(parse_tolerance("1e-9").unwrap(), 1e-9);
        for bad in ["-1e-9", "0", "inf", "NaN", "tight"] {
            let e = parse_tolerance(bad).unwrap_err().to_string();
            assert_eq!(e, format!("`{bad}` is not a positive number (for example 1e-9)"));
        }
        assert!(parse_set("Y").is_err() && parse_set("Y=").is_err());
        assert_eq!(parse_set("Q2 = 30 deg").unwrap(), ("Q2".into(), "30 deg".into()));
    }
}
