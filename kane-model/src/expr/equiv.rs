//! Deciding whether two expressions are equal: by proof, else by sampling.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rustc_hash::FxHashMap;

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, SymbolId};

/// The verdict of [`Arena::equivalent`].
#[derive(Clone, Debug, PartialEq)]
pub enum Equivalence {
    /// The difference simplifies to exactly zero.
    Proven,
    /// Not proven, but equal at every sampled point within the stated tolerances.
    NumericallyEqual {
        /// Points at which both sides were finite and compared.
        samples: usize,
        /// Largest `|a - b| / max(1, |a|, |b|)` seen.
        max_relative_residual: f64,
        /// Tolerance used for that quantity.
        tolerance: f64,
    },
    /// Different at a point.
    Differs {
        /// The point: each free symbol with its value.
        point: Vec<(String, f64)>,
        /// Value of the first expression there.
        lhs: f64,
        /// Value of the second expression there.
        rhs: f64,
    },
    /// No point was found where both sides are finite.
    Inconclusive,
}

/// How one symbol is sampled: the first point takes `centre`, later ones a random value within
/// `spread` of it (a fraction of `centre` when `relative`, so the sign is kept).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleAround {
    /// The value at the first point (a file's INPUT value, say).
    pub centre: f64,
    /// Half-width of the interval sampled around the centre.
    pub spread: f64,
    /// Whether `spread` is relative to `centre`.
    pub relative: bool,
}

impl SampleAround {
    fn draw(&self, rng: &mut StdRng, first: bool) -> f64 {
        if first {
            return self.centre;
        }
        let r: f64 = rng.random_range(-1.0..1.0);
        if self.relative {
            self.centre * (1.0 + self.spread * r)
        } else {
            self.centre + self.spread * r
        }
    }
}

/// Settings of the numeric part of [`Arena::equivalent`].
#[derive(Clone, Debug)]
pub struct EquivalenceConfig {
    /// How many points to compare.
    pub samples: usize,
    /// Largest accepted `|a - b| / max(1, |a|, |b|)`.
    pub tolerance: f64,
    /// Symbols are sampled uniformly from this interval.
    pub range: (f64, f64),
    /// Seed of the sampler, so verdicts are reproducible.
    pub seed: u64,
    /// Symbols sampled around given values rather than uniformly from `range`.
    pub around: FxHashMap<SymbolId, SampleAround>,
}

impl Default for EquivalenceConfig {
    fn default() -> Self {
        EquivalenceConfig {
            samples: 64,
            tolerance: 1e-9,
            range: (-2.0, 2.0),
            seed: 0x6b616e65,
            around: FxHashMap::default(),
        }
    }
}

impl Arena {
    /// Whether `a` and `b` are equal: [`Equivalence::Proven`] if `a - b` simplifies to 0 (with
    /// sums and multiples of angles expanded and over a common denominator when needed),
    /// otherwise compared at random points (see [`EquivalenceConfig::around`]).
    ///
    /// # Example
    /// ```
    /// use kane_model::expr::{Arena, Equivalence, EquivalenceConfig};
    /// let mut ar = Arena::new();
    /// let x = ar.constant("x").unwrap();
    /// let s = ar.sin(x).unwrap();
    /// let c = ar.cos(x).unwrap();
    /// let s2 = ar.powi(s, 2).unwrap();
    /// let c2 = ar.powi(c, 2).unwrap();
    /// let lhs = ar.add(&[s2, c2]).unwrap();
    /// let one = ar.one();
    /// let cfg = EquivalenceConfig::default();
    /// assert_eq!(ar.equivalent(lhs, one, &cfg).unwrap(), Equivalence::Proven);
    /// ```
    pub fn equivalent(
        &mut self,
        a: ExprId,
        b: ExprId,
        cfg: &EquivalenceConfig,
    ) -> Result<Equivalence, ExprError> {
        let d = self.sub(a, b)?;
        if self.is_zero(d) || {
            let s = self.simplify(d)?;
            self.is_zero(s) || self.proves_zero_over_common_denominator(s)
        } {
            return Ok(Equivalence::Proven);
        }
        let syms: Vec<SymbolId> = self.free_symbols(&[a, b]);
        let mut rng = StdRng::seed_from_u64(cfg.seed);
        let (lo, hi) = cfg.range;
        let mut compared = 0;
        let mut worst: f64 = 0.0;
        for attempt in 0..cfg.samples.saturating_mul(10) {
            if compared == cfg.samples {
                break;
            }
            let values: FxHashMap<SymbolId, f64> = syms
                .iter()
                .map(|s| match cfg.around.get(s) {
                    Some(a) => (*s, a.draw(&mut rng, attempt == 0)),
                    None => (*s, rng.random_range(lo..hi)),
                })
                .collect();
            let Ok(v) = self.eval(&[a, b], |s| values.get(&s).copied()) else { continue };
            compared += 1;
            let rel = (v[0] - v[1]).abs() / v[0].abs().max(v[1].abs()).max(1.0);
            worst = worst.max(rel);
            if rel > cfg.tolerance {
                let point = syms.iter().map(|s| (self.symbol_info(*s).name.clone(), values[s])).collect();
                return Ok(Equivalence::Differs { point, lhs: v[0], rhs: v[1] });
            }
        }
        if compared == 0 {
            return Ok(Equivalence::Inconclusive);
        }
        Ok(Equivalence::NumericallyEqual {
            samples: compared,
            max_relative_residual: worst,
            tolerance: cfg.tolerance,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn differs_reports_a_point() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let s = ar.sin(x).unwrap();
        let r = ar.equivalent(s, x, &EquivalenceConfig::default()).unwrap();
        match r {
            Equivalence::Differs { point, lhs, rhs } => {
                assert_eq!(point.len(), 1);
                assert_eq!(point[0].0, "x");
                assert!((lhs - point[0].1.sin()).abs() < 1e-15 && (rhs - point[0].1).abs() < 1e-15);
            }
            other => panic!("expected Differs, got {other:?}"),
        }
    }

    #[test]
    fn numerically_equal_when_not_provable() {
        // 2 sin(x/2)^2 = 1 - cos(x) needs a half angle, beyond the canonical form: only sampling
        // confirms it. sin(2x) = 2 sin(x) cos(x) is proven.
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let (one, two) = (ar.one(), ar.integer(2));
        let half = ar.rational(1, 2).unwrap();
        let hx = ar.mul(&[half, x]).unwrap();
        let sh = ar.sin(hx).unwrap();
        let sh2 = ar.powi(sh, 2).unwrap();
        let lhs = ar.mul(&[two, sh2]).unwrap();
        let c = ar.cos(x).unwrap();
        let rhs = ar.sub(one, c).unwrap();
        let r = ar.equivalent(lhs, rhs, &EquivalenceConfig::default()).unwrap();
        assert!(matches!(r, Equivalence::NumericallyEqual { samples: 64, .. }), "{r:?}");
        let x2 = ar.mul(&[two, x]).unwrap();
        let lhs = ar.sin(x2).unwrap();
        let s = ar.sin(x).unwrap();
        let rhs = ar.mul(&[two, s, c]).unwrap();
        assert_eq!(ar.equivalent(lhs, rhs, &EquivalenceConfig::default()).unwrap(), Equivalence::Proven);
    }

    #[test]
    fn samples_around_given_values_first_at_the_centre() {
        let mut ar = Arena::new();
        let m = ar.constant("m").unwrap();
        let ms = ar.as_symbol(m).unwrap();
        let s = ar.sin(m).unwrap();
        let mut cfg = EquivalenceConfig::default();
        cfg.around.insert(ms, SampleAround { centre: 50.0, spread: 0.1, relative: true });
        let Equivalence::Differs { point, .. } = ar.equivalent(s, m, &cfg).unwrap() else { panic!() };
        assert_eq!(point[0].1, 50.0);
        // every later draw stays within 10 % of the centre, so sqrt(m) is always defined
        let r = ar.sqrt(m).unwrap();
        let r2 = ar.powi(r, 2).unwrap();
        let v = ar.equivalent(r2, m, &cfg).unwrap();
        assert!(
            matches!(v, Equivalence::Proven | Equivalence::NumericallyEqual { samples: 64, .. }),
            "{v:?}"
        );
    }
}
