//! Values by their definitions, for tests to compare with: never by the
//! algorithms the tasks teach.

/// `n choose k`, exact as long as it fits in a `u64` (every `n ≤ 62`);
/// `0` for `k > n`.
#[must_use]
pub fn binomial(n: usize, k: usize) -> u64 {
    if k > n {
        return 0;
    }
    let k = k.min(n - k);
    // C(n, j + 1) = C(n, j) · (n − j) / (j + 1), exact at every step.
    let exact = (0..k).fold(1_u128, |c, j| c * (n - j) as u128 / (j as u128 + 1));
    u64::try_from(exact).expect("a binomial that fits in a u64")
}

/// The Bernstein polynomial `B_{i,n}(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ` by its
/// definition (seed 000 §2.1, seed 001 equation (1.2)), for any real `t`;
/// `0` for `i > n`.
#[must_use]
pub fn bernstein(i: usize, n: usize, t: f64) -> f64 {
    if i > n {
        return 0.0;
    }
    let (i, rest) = (
        i32::try_from(i).expect("a small degree"),
        i32::try_from(n - i).expect("a small degree"),
    );
    binomial(n, i as usize) as f64 * t.powi(i) * (1.0 - t).powi(rest)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomials_are_pascals_triangle() {
        assert_eq!(
            (0..=4).map(|k| binomial(4, k)).collect::<Vec<_>>(),
            [1, 4, 6, 4, 1]
        );
        assert_eq!(binomial(62, 31), 465_428_353_255_261_088);
        assert_eq!(binomial(3, 4), 0);
    }

    #[test]
    fn bernstein_has_its_known_values() {
        assert_eq!(bernstein(1, 2, 0.5), 0.5);
        assert_eq!(bernstein(0, 3, 0.0), 1.0);
        assert_eq!(bernstein(3, 3, 1.0), 1.0);
        assert_eq!(bernstein(4, 3, 0.3), 0.0);
        assert!((bernstein(1, 3, 0.25) - 3.0 * 0.25 * 0.75 * 0.75).abs() < 1e-15);
    }
}
