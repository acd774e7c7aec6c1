//! Which members a sweep has: in come the ranges to vary (`NAME=START:STOP[:N] [UNIT]`) and a
//! grid or a Latin-hypercube sample; out go the members, each an index and one value per range,
//! in a fixed order (so a member's index names it in every shard and every re-run).

use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};

use crate::scene::Value;

/// One quantity to vary.
#[derive(Clone, Debug, PartialEq)]
pub struct Range {
    /// A parameter or state of the scene's model.
    pub name: String,
    /// First value.
    pub start: f64,
    /// Last value.
    pub stop: f64,
    /// Grid points (grids only).
    pub points: Option<usize>,
    /// The unit both ends are in (as a scene would write it).
    pub unit: Option<String>,
}

/// One member: its index and one value per range.
#[derive(Clone, Debug, PartialEq)]
pub struct Member {
    /// Its place in the sweep.
    pub index: usize,
    /// One value per range, in the ranges' order.
    pub values: Vec<Value>,
}

/// Reads `NAME=START:STOP[:N] [UNIT]` (`U3=10:100:10 rad/s`).
pub fn parse_range(text: &str) -> Result<Range, String> {
    let bad =
        || format!("`{text}` is not NAME=START:STOP[:N] [UNIT] (for example --vary \"U3=10:100:10 rad/s\")");
    let (name, rest) = text.split_once('=').ok_or_else(bad)?;
    let (numbers, unit) = match rest.trim().split_once(char::is_whitespace) {
        Some((n, u)) => (n, Some(u.trim().to_string())),
        None => (rest.trim(), None),
    };
    let parts: Vec<&str> = numbers.split(':').collect();
    let number = |s: &str| s.trim().parse::<f64>().ok().filter(|x| x.is_finite());
    let (start, stop) = match parts.as_slice() {
        [a, b] | [a, b, _] => (number(a).ok_or_else(bad)?, number(b).ok_or_else(bad)?),
        _ => return Err(bad()),
    };
    let points = match parts.get(2) {
        Some(n) => Some(n.trim().parse::<usize>().ok().filter(|n| *n >= 1).ok_or_else(bad)?),
        None => None,
    };
    if name.trim().is_empty() {
        return Err(bad());
    }
    Ok(Range { name: name.trim().to_string(), start, stop, points, unit })
}

/// The grid over `ranges` (each needs N points), the first range varying slowest.
pub fn grid(ranges: &[Range]) -> Result<Vec<Member>, String> {
    let mut axes = Vec::with_capacity(ranges.len());
    for r in ranges {
        let n = r
            .points
            .ok_or_else(|| format!("--vary {}: a grid needs the number of points, START:STOP:N", r.name))?;
        axes.push(
            (0..n).map(|k| at(r, if n == 1 { 0.0 } else { k as f64 / (n - 1) as f64 })).collect::<Vec<_>>(),
        );
    }
    let total: usize = axes.iter().map(Vec::len).product();
    let mut members = Vec::with_capacity(total);
    for index in 0..total {
        let mut rest = index;
        let mut values = vec![Value { number: 0.0, unit: None }; axes.len()];
        for (d, axis) in axes.iter().enumerate().rev() {
            values[d] = axis[rest % axis.len()].clone();
            rest /= axis.len();
        }
        members.push(Member { index, values });
    }
    Ok(members)
}

/// `samples` members by Latin-hypercube sampling from `seed`: each range cut into `samples`
/// equal strata, each stratum used once, a uniform point inside it.
pub fn latin_hypercube(ranges: &[Range], samples: usize, seed: u64) -> Vec<Member> {
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let columns: Vec<Vec<Value>> = ranges
        .iter()
        .map(|r| {
            let mut strata: Vec<usize> = (0..samples).collect();
            strata.shuffle(&mut rng);
            strata.into_iter().map(|s| at(r, (s as f64 + rng.random::<f64>()) / samples as f64)).collect()
        })
        .collect();
    (0..samples)
        .map(|index| Member { index, values: columns.iter().map(|c| c[index].clone()).collect() })
        .collect()
}

/// The value a fraction `f` of the way from a range's start to its stop.
fn at(r: &Range, f: f64) -> Value {
    Value { number: r.start + (r.stop - r.start) * f, unit: r.unit.clone() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_parse_with_units_and_errors_say_the_form() {
        let r = parse_range("U3=10:100:10 rad/s").unwrap();
        assert_eq!((r.name.as_str(), r.start, r.stop, r.points), ("U3", 10.0, 100.0, Some(10)));
        assert_eq!(r.unit.as_deref(), Some("rad/s"));
        assert_eq!(parse_range("Y=0:5").unwrap().points, None);
        for bad in ["Y", "Y=1", "Y=a:2:3", "=1:2:3", "Y=1:2:0", "Y=1:2:3:4"] {
            assert!(parse_range(bad).unwrap_err().contains("NAME=START:STOP[:N]"), "{bad}");
        }
    }

    #[test]
    fn a_grid_varies_the_last_range_fastest() {
        let ranges = [parse_range("A=0:1:2").unwrap(), parse_range("B=10:30:3").unwrap()];
        let g = grid(&ranges).unwrap();
        let pairs: Vec<(f64, f64)> = g.iter().map(|m| (m.values[0].number, m.values[1].number)).collect();
        assert_eq!(pairs, [(0.0, 10.0), (0.0, 20.0), (0.0, 30.0), (1.0, 10.0), (1.0, 20.0), (1.0, 30.0)]);
        assert!(grid(&[parse_range("A=0:1").unwrap()]).is_err());
    }

    #[test]
    fn latin_hypercube_uses_every_stratum_once_and_repeats_from_its_seed() {
        let ranges = [parse_range("A=0:1").unwrap(), parse_range("B=-5:5").unwrap()];
        let s = latin_hypercube(&ranges, 8, 7);
        for (d, r) in ranges.iter().enumerate() {
            let mut strata: Vec<usize> = s
                .iter()
                .map(|m| ((m.values[d].number - r.start) / (r.stop - r.start) * 8.0) as usize)
                .collect();
            strata.sort();
            assert_eq!(strata, (0..8).collect::<Vec<_>>());
        }
        assert_eq!(s, latin_hypercube(&ranges, 8, 7));
        assert_ne!(s, latin_hypercube(&ranges, 8, 8));
    }
}
