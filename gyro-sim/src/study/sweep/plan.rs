//! Which members a sweep has: in come the ranges to vary (`NAME=START:STOP[:N] [UNIT]`) and a
//! grid or a Latin-hypercube sample; out go the members, each an index and one value per range,
//! made from its index when asked, in a fixed order (so a member's index names it in every shard and every re-run).

use super::DesignError;
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

impl std::fmt::Display for Range {
    /// `NAME=START:STOP[:N] [UNIT]`, numbers in their shortest round-trip form.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}={}:{}", self.name, self.start, self.stop)?;
        if let Some(n) = self.points {
            write!(f, ":{n}")?;
        }
        match &self.unit {
            Some(u) => write!(f, " {u}"),
            None => Ok(()),
        }
    }
}

/// Reads `NAME=START:STOP[:N] [UNIT]` (`U3=10:100:10 rad/s`).
pub fn parse_range(text: &str) -> Result<Range, DesignError> {
    let bad = || DesignError::Range { text: text.to_string() };
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

/// The most members one sweep may have (each costs one bit of bookkeeping: which are done).
pub const MAX_MEMBERS: usize = 10_000_000;

/// How a sweep's members are chosen.
#[derive(Clone, Debug, PartialEq)]
pub enum Design {
    /// Every combination of the ranges' N points.
    Grid,
    /// A Latin-hypercube sample of `count` members drawn from `seed`.
    Samples {
        /// How many members.
        count: usize,
        /// The random generator's seed.
        seed: u64,
    },
}

/// A sweep's members, each made from its index when asked (none are held).
#[derive(Clone, Debug)]
pub struct Members {
    ranges: Vec<Range>,
    how: Points,
}

/// Where the members' values come from.
#[derive(Clone, Debug)]
enum Points {
    /// Points per range (a grid).
    Grid(Vec<usize>),
    /// A Latin-hypercube sample: each member's fractions made from its index.
    Sample {
        /// How many members the sweep has.
        count: usize,
        /// The seed the strata's order and the points inside them come from.
        seed: u64,
    },
}

impl Members {
    /// The members of `design` over `ranges`; an error naming the limit when there would be
    /// more than [`MAX_MEMBERS`] (or none).
    pub fn new(ranges: &[Range], design: &Design) -> Result<Members, DesignError> {
        for (k, r) in ranges.iter().enumerate() {
            if let Some(first) = ranges[..k].iter().find(|o| o.name.eq_ignore_ascii_case(&r.name)) {
                return Err(DesignError::Twice {
                    range: Box::new(r.clone()),
                    first: Box::new(first.clone()),
                });
            }
        }
        let how = match design {
            Design::Grid => Points::Grid(grid_points(ranges)?),
            Design::Samples { count, seed } => {
                if *count == 0 || *count > MAX_MEMBERS {
                    return Err(DesignError::Samples { count: *count });
                }
                Points::Sample { count: *count, seed: *seed }
            }
        };
        Ok(Members { ranges: ranges.to_vec(), how })
    }

    /// How many members there are.
    pub fn len(&self) -> usize {
        match &self.how {
            Points::Grid(points) => points.iter().product(),
            Points::Sample { count, .. } => *count,
        }
    }

    /// Member `index` (below [`Members::len`]).
    pub fn get(&self, index: usize) -> Member {
        let values = match &self.how {
            Points::Grid(points) => {
                let mut rest = index;
                let mut values = vec![Value { number: 0.0, unit: None }; points.len()];
                for (d, n) in points.iter().enumerate().rev() {
                    let k = rest % n;
                    rest /= n;
                    values[d] = at(&self.ranges[d], if *n == 1 { 0.0 } else { k as f64 / (n - 1) as f64 });
                }
                values
            }
            Points::Sample { count, seed } => (0..self.ranges.len())
                .map(|d| at(&self.ranges[d], super::latin::fraction(*seed, d, *count, index)))
                .collect(),
        };
        Member { index, values }
    }
}

/// The points of each range of a grid, checked: each range needs N and their product may not
/// pass [`MAX_MEMBERS`].
fn grid_points(ranges: &[Range]) -> Result<Vec<usize>, DesignError> {
    let mut points = Vec::with_capacity(ranges.len());
    for r in ranges {
        points.push(r.points.ok_or_else(|| DesignError::GridPoints { name: r.name.clone() })?);
    }
    let total = points.iter().try_fold(1u128, |acc, n| acc.checked_mul(*n as u128));
    if total.is_none_or(|t| t > MAX_MEMBERS as u128) {
        return Err(DesignError::GridTooLarge { counts: points, total });
    }
    Ok(points)
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
            assert!(parse_range(bad).unwrap_err().to_string().contains("NAME=START:STOP[:N]"), "{bad}");
        }
    }

    #[test]
    fn a_grid_varies_the_last_range_fastest() {
        let ranges = [parse_range("A=0:1:2").unwrap(), parse_range("B=10:30:3").unwrap()];
        let g = Members::new(&ranges, &Design::Grid).unwrap();
        let pairs: Vec<(f64, f64)> =
            (0..g.len()).map(|i| g.get(i)).map(|m| (m.values[0].number, m.values[1].number)).collect();
        assert_eq!(pairs, [(0.0, 10.0), (0.0, 20.0), (0.0, 30.0), (1.0, 10.0), (1.0, 20.0), (1.0, 30.0)]);
        assert!(Members::new(&[parse_range("A=0:1").unwrap()], &Design::Grid).is_err());
    }

    #[test]
    fn sizes_past_the_limit_are_refused_naming_it() {
        let huge: Vec<Range> = (0..6).map(|i| parse_range(&format!("A{i}=0:1:2048")).unwrap()).collect();
        let e = Members::new(&huge, &Design::Grid).unwrap_err().to_string();
        assert!(e.contains("= 73786976294838206464 members") && e.contains("10000000"), "{e}");
        let one = [parse_range("A=0:1").unwrap()];
        for count in [0, usize::MAX, MAX_MEMBERS + 1] {
            let e = Members::new(&one, &Design::Samples { count, seed: 1 }).unwrap_err().to_string();
            assert!(e.contains(&format!("--samples {count}: give 1 to 10000000")), "{e}");
        }
        assert_eq!(parse_range("U3=5:50:8 rad/s").unwrap().to_string(), "U3=5:50:8 rad/s");
    }

    #[test]
    fn a_quantity_varied_twice_is_an_error_naming_both_ranges() {
        let ranges = [parse_range("Y=0:1:2").unwrap(), parse_range("y=5:6:3").unwrap()];
        let e = Members::new(&ranges, &Design::Grid).err().unwrap().to_string();
        assert!(e.starts_with("--vary y=5:6:3 and --vary Y=0:1:2 vary the same quantity"), "{e}");
    }

    #[test]
    fn latin_hypercube_uses_every_stratum_once_and_repeats_from_its_seed() {
        let ranges = [parse_range("A=0:1").unwrap(), parse_range("B=-5:5").unwrap()];
        let lhs = |count, seed| {
            let m = Members::new(&ranges, &Design::Samples { count, seed }).unwrap();
            (0..m.len()).map(|i| m.get(i)).collect::<Vec<_>>()
        };
        let s = lhs(8, 7);
        for (d, r) in ranges.iter().enumerate() {
            let mut strata: Vec<usize> = s
                .iter()
                .map(|m| ((m.values[d].number - r.start) / (r.stop - r.start) * 8.0) as usize)
                .collect();
            strata.sort();
            assert_eq!(strata, (0..8).collect::<Vec<_>>());
        }
        assert_eq!(s, lhs(8, 7));
        assert_ne!(s, lhs(8, 8));
    }
}
