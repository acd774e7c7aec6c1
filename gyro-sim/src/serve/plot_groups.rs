//! The second window's axes: in come the plotted columns (their unit and the values they take
//! over the run); out go groups of them, each drawn on a y axis of its own, so that a spin
//! angle of thousands of degrees never flattens swing angles of a few tens beside it.

use crate::problem::Trajectory;

/// How many times larger than another's a series' size may be on the axis they share.
pub(super) const MAX_RATIO: f64 = 10.0;

/// A plotted series: the unit its axis shows and the least and greatest value it takes.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Series {
    /// The unit shown (`deg` for any angle).
    pub unit: String,
    /// Least value.
    pub min: f64,
    /// Greatest value.
    pub max: f64,
}

impl Series {
    /// Its size: the largest magnitude it takes.
    fn size(&self) -> f64 {
        self.min.abs().max(self.max.abs())
    }
}

/// The plotted columns `plot` of `trajectory` in groups sharing an axis (names, in plot order).
pub(super) fn plot_groups(trajectory: &Trajectory, plot: &[String]) -> Vec<Vec<String>> {
    let series: Vec<Series> = plot
        .iter()
        .map(|name| {
            let Some(k) = trajectory.columns.iter().position(|c| &c.name == name) else {
                return Series { unit: String::new(), min: 0.0, max: 0.0 };
            };
            let column = &trajectory.columns[k];
            let values = trajectory.rows.iter().map(|r| r[k + 1]).filter(|v| v.is_finite());
            let (min, max) =
                values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
            let unit = if column.is_angle() { "deg".to_string() } else { column.unit.clone() };
            // Angles are plotted in degrees; the sizes' ratios are the same in radians.
            if min > max {
                return Series { unit, min: 0.0, max: 0.0 };
            }
            Series { unit, min, max }
        })
        .collect();
    group(&series).into_iter().map(|g| g.into_iter().map(|i| plot[i].clone()).collect()).collect()
}

/// A group being formed: its unit, its least and greatest size other than zero, its members.
type Group<'a> = (&'a str, Option<(f64, f64)>, Vec<usize>);

/// The series' indices in groups: each series joins the first group of its unit whose sizes,
/// with its own, are within [`MAX_RATIO`] of each other (a series that stays at zero joins any
/// group of its unit); else it starts a group.
pub(super) fn group(series: &[Series]) -> Vec<Vec<usize>> {
    let mut groups: Vec<Group> = Vec::new();
    for (i, s) in series.iter().enumerate() {
        let size = s.size();
        let fits = |unit: &str, sizes: Option<(f64, f64)>| {
            unit == s.unit
                && (size == 0.0 || sizes.is_none_or(|(lo, hi)| hi.max(size) <= MAX_RATIO * lo.min(size)))
        };
        match groups.iter_mut().find(|(unit, sizes, _)| fits(unit, *sizes)) {
            Some((_, sizes, members)) => {
                if size > 0.0 {
                    *sizes = Some(sizes.map_or((size, size), |(lo, hi)| (lo.min(size), hi.max(size))));
                }
                members.push(i);
            }
            None => groups.push((&s.unit, (size > 0.0).then_some((size, size)), vec![i])),
        }
    }
    groups.into_iter().map(|(_, _, members)| members).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn angle(min: f64, max: f64) -> Series {
        Series { unit: "deg".into(), min, max }
    }

    #[test]
    fn a_spin_angle_gets_an_axis_of_its_own() {
        // The gimbal's Q1, Q2 swing some tens of degrees; its rotor angle Q3 turns thousands.
        let series = [angle(-40.0, 5.0), angle(-12.0, 30.0), angle(0.0, 28_000.0)];
        assert_eq!(group(&series), [vec![0, 1], vec![2]]);
        // Sizes within ten times of each other share one.
        assert_eq!(group(&[angle(-1000.0, 0.0), angle(0.0, 2000.0), angle(-300.0, 50.0)]), [vec![0, 1, 2]]);
        // The top's elevations, of like size, stay together however little L's moves.
        assert_eq!(group(&[angle(22.5, 30.0), angle(29.7, 30.0)]), [vec![0, 1]]);
    }

    #[test]
    fn units_never_share_an_axis_and_zero_joins_any_group_of_its_unit() {
        let metres = Series { unit: "M".into(), min: 0.0, max: 2.0 };
        assert_eq!(group(&[angle(0.0, 2.0), metres.clone(), angle(1.0, 1.5)]), [vec![0, 2], vec![1]]);
        assert_eq!(group(&[angle(0.0, 2.0), angle(500.0, 500.0)]), [vec![0], vec![1]]);
        assert_eq!(group(&[angle(0.0, 0.0), angle(0.0, 28_000.0), angle(-3.0, 3.0)]), [vec![0, 1], vec![2]]);
        assert_eq!(group(&[metres]), [vec![0]]);
    }

    #[test]
    fn the_rule_is_ten_times() {
        assert_eq!(group(&[angle(0.0, 1.0), angle(-MAX_RATIO, 0.0)]), [vec![0, 1]]);
        assert_eq!(group(&[angle(0.0, 1.0), angle(0.0, MAX_RATIO * 1.01)]), [vec![0], vec![1]]);
        // Every member within ten times of every other: 1 and 8 share, 20 does not join them.
        assert_eq!(group(&[angle(0.0, 1.0), angle(0.0, 8.0), angle(0.0, 20.0)]), [vec![0, 1], vec![2]]);
    }
}
