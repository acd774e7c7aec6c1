//! A Latin-hypercube sample made one member at a time: in come a seed, a range's place, the
//! member count and a member's index; out goes that member's fraction of the way along the range.
//! Each range is cut into `count` equal strata; a keyed permutation of the indices (a Feistel
//! network over the next even power of two, walked until it lands below `count`) gives each
//! member its own stratum, and a hash of the index a point inside it. Nothing is held, so a
//! sample of any size costs no memory, and the same seed gives the same sample.

/// Feistel rounds of the strata's permutation.
const ROUNDS: u64 = 6;

/// Tells the hash of a point inside a stratum from the rounds' hashes.
const JITTER: u64 = ROUNDS;

/// Member `index`'s fraction in `[0, 1)` along range `dim` of a `count`-member sample from
/// `seed` (`index` below `count`): inside stratum [`stratum`], each stratum taken once per range.
pub fn fraction(seed: u64, dim: usize, count: usize, index: usize) -> f64 {
    let s = stratum(seed, dim, count, index);
    // As many random bits as `s + jitter` holds exactly, so the sum never rounds up to `s + 1`.
    let used = (usize::BITS - count.leading_zeros()).min(52);
    let bits = 53 - used;
    let jitter = (hash(seed, dim, JITTER, index as u64) >> (64 - bits)) as f64 / (1u64 << bits) as f64;
    (s as f64 + jitter) / count as f64
}

/// Member `index`'s stratum along range `dim`: a permutation of `0..count` keyed by `seed` and
/// `dim` (`index` below `count`).
pub fn stratum(seed: u64, dim: usize, count: usize, index: usize) -> usize {
    let bits = usize::BITS - count.saturating_sub(1).leading_zeros();
    let half = bits.div_ceil(2);
    let mask = (1u64 << half) - 1;
    let mut x = index as u64;
    // The network permutes 0..4^half (at least `count`); walking the cycle from `index` until it
    // is below `count` again permutes 0..count.
    loop {
        let (mut left, mut right) = (x >> half, x & mask);
        for round in 0..ROUNDS {
            (left, right) = (right, left ^ (hash(seed, dim, round, right) & mask));
        }
        x = (left << half) | right;
        if x < count as u64 {
            return x as usize;
        }
    }
}

/// A well-mixed hash of a seed, a range's place, a purpose and a number.
fn hash(seed: u64, dim: usize, purpose: u64, x: u64) -> u64 {
    mix(mix(mix(seed ^ mix(purpose)) ^ dim as u64) ^ x)
}

/// splitmix64: a bijection of 64-bit words whose every output bit depends on every input bit.
fn mix(z: u64) -> u64 {
    let z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    let z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The strata and fractions of `count` members along `dims` ranges, checked to be a Latin
    /// hypercube: each stratum once per range, each fraction inside its member's stratum.
    fn checked(seed: u64, dims: usize, count: usize) -> Vec<Vec<usize>> {
        (0..dims)
            .map(|d| {
                let mut seen = vec![false; count];
                let strata: Vec<usize> = (0..count).map(|i| stratum(seed, d, count, i)).collect();
                for (i, s) in strata.iter().enumerate() {
                    assert!(*s < count && !seen[*s], "count {count}, range {d}: stratum {s} twice");
                    seen[*s] = true;
                    let f = fraction(seed, d, count, i);
                    assert!((0.0..1.0).contains(&f), "count {count}: fraction {f}");
                    assert_eq!((f * count as f64) as usize, *s, "count {count}, member {i}: {f}");
                }
                strata
            })
            .collect()
    }

    #[test]
    fn every_count_takes_each_stratum_once_per_range() {
        let counts = (1..=300).chain([511, 512, 513, 1000, 1023, 1024, 1025, 4097, 65_537, 100_000]);
        for count in counts {
            for seed in [0, 1, 42, u64::MAX] {
                checked(seed, 3, count);
            }
        }
        assert_eq!(checked(7, 1, 1), [[0]]);
    }

    #[test]
    fn the_sample_repeats_from_its_seed_and_differs_between_seeds_and_ranges() {
        let a = checked(7, 2, 1000);
        assert_eq!(a, checked(7, 2, 1000));
        assert_ne!(a, checked(8, 2, 1000));
        assert_ne!(a[0], a[1]);
        assert_eq!(fraction(7, 1, 1000, 17), fraction(7, 1, 1000, 17));
    }

    #[test]
    fn strata_are_shuffled_not_ordered() {
        // Rank correlation of two permutations of 0..n: about 1/sqrt(n) (0.03) when independent.
        let n = 1000;
        let rho = |a: &dyn Fn(usize) -> usize, b: &dyn Fn(usize) -> usize| {
            let mean = (n as f64 - 1.0) / 2.0;
            let cov: f64 = (0..n).map(|i| (a(i) as f64 - mean) * (b(i) as f64 - mean)).sum();
            cov / (0..n).map(|i| (i as f64 - mean).powi(2)).sum::<f64>()
        };
        let by_index = |i| i;
        for d in 0..3 {
            let s = move |i| stratum(3, d, n, i);
            assert!(rho(&s, &by_index).abs() < 0.15, "range {d} follows the index");
            let next = move |i| stratum(3, d + 1, n, i);
            assert!(rho(&s, &next).abs() < 0.15, "ranges {d} and {} move together", d + 1);
        }
        let moved = (0..n).filter(|i| stratum(3, 0, n, *i) != *i).count();
        assert!(moved > n * 9 / 10, "only {moved} of {n} members left their stratum");
    }
}
