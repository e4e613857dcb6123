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

/// `d/dt B_{i,n}(t) = n · (B_{i−1,n−1}(t) − B_{i,n−1}(t))`, by the
/// definition's derivative; `0` for `n = 0` or `i > n`.
#[must_use]
pub fn bernstein_derivative(i: usize, n: usize, t: f64) -> f64 {
    if n == 0 || i > n {
        return 0.0;
    }
    let below = if i == 0 {
        0.0
    } else {
        bernstein(i - 1, n - 1, t)
    };
    n as f64 * (below - bernstein(i, n - 1, t))
}

/// A tensor-product Bézier surface of degree `p × q` by its definition,
/// the double Bernstein sum, with its partial derivatives:
///
/// ```text
///   S(u, v) = Σ_i Σ_j B_i,p(u) B_j,q(v) P_ij      S_u = Σ_i Σ_j B'_i,p(u) B_j,q(v) P_ij
/// ```
///
/// Returns `[S, S_u, S_v]`; `point(i, j)` is `P_ij` (`i ≤ p` along `u`,
/// `j ≤ q` along `v`), so that any storage order can be used.
#[must_use]
pub fn tensor_bezier(
    p: usize,
    q: usize,
    point: impl Fn(usize, usize) -> glam::DVec3,
    [u, v]: [f64; 2],
) -> [glam::DVec3; 3] {
    let mut out = [glam::DVec3::ZERO; 3];
    for i in 0..=p {
        for j in 0..=q {
            let pij = point(i, j);
            out[0] += pij * (bernstein(i, p, u) * bernstein(j, q, v));
            out[1] += pij * (bernstein_derivative(i, p, u) * bernstein(j, q, v));
            out[2] += pij * (bernstein(i, p, u) * bernstein_derivative(j, q, v));
        }
    }
    out
}

/// A triangular Bézier patch of degree `n` by its definition, with its
/// partial derivatives as a polynomial in `u`, `v` and `w`:
///
/// ```text
///   B(u, v, w) = Σ_{i+j+k=n} n!/(i! j! k!) · uⁱ vʲ wᵏ · P_ijk
/// ```
///
/// Returns `[B, ∂B/∂u, ∂B/∂v, ∂B/∂w]`; `point(i, j, k)` is `P_ijk`. On
/// the plane `u + v + w = 1` the surface's tangents are `∂B/∂v − ∂B/∂u`
/// and `∂B/∂w − ∂B/∂u`.
#[must_use]
pub fn triangle_bezier(
    n: usize,
    point: impl Fn(usize, usize, usize) -> glam::DVec3,
    [u, v, w]: [f64; 3],
) -> [glam::DVec3; 4] {
    // xᵉ, and its derivative e · xᵉ⁻¹ (0 for e = 0).
    let power = |x: f64, e: usize| x.powi(i32::try_from(e).expect("a small degree"));
    let slope = |x: f64, e: usize| {
        if e == 0 {
            0.0
        } else {
            e as f64 * power(x, e - 1)
        }
    };
    let mut out = [glam::DVec3::ZERO; 4];
    for i in 0..=n {
        for j in 0..=n - i {
            let k = n - i - j;
            let c = (binomial(n, i) * binomial(n - i, j)) as f64;
            let pijk = point(i, j, k) * c;
            out[0] += pijk * (power(u, i) * power(v, j) * power(w, k));
            out[1] += pijk * (slope(u, i) * power(v, j) * power(w, k));
            out[2] += pijk * (power(u, i) * slope(v, j) * power(w, k));
            out[3] += pijk * (power(u, i) * power(v, j) * slope(w, k));
        }
    }
    out
}

/// The B-spline basis function `N_{i,p}(u)` over `knots` by the Cox–de
/// Boor recursion (seed 001, (1.8)), with half-open steps
/// `[u_i, u_{i+1})`; at the domain's end `end` only the last non-empty
/// step ending there counts (the limit from the left), so that the basis
/// sums to 1 on the whole closed domain. `0/0` terms are 0.
///
/// # Panics
/// If `knots` has fewer than `i + p + 2` entries.
#[must_use]
pub fn bspline_basis(knots: &[f64], end: f64, i: usize, p: usize, u: f64) -> f64 {
    let k = knots;
    if p == 0 {
        let closing = k.iter().rposition(|&x| x < end).unwrap_or(0);
        let on = if u == end {
            i == closing
        } else {
            k[i] <= u && u < k[i + 1]
        };
        return if on { 1.0 } else { 0.0 };
    }
    let mut value = 0.0;
    if k[i + p] > k[i] {
        value += (u - k[i]) / (k[i + p] - k[i]) * bspline_basis(k, end, i, p - 1, u);
    }
    if k[i + p + 1] > k[i + 1] {
        value +=
            (k[i + p + 1] - u) / (k[i + p + 1] - k[i + 1]) * bspline_basis(k, end, i + 1, p - 1, u);
    }
    value
}

/// A NURBS curve of degree `p` by its definition (seed 001, (1.12)):
/// `C(u) = Σ N_{i,p}(u) Pᵢʷ` over all homogeneous control points
/// `Pᵢʷ = (wᵢ Pᵢ, wᵢ)`, projected. The domain is `[u_p, u_{m−p}]`.
///
/// # Panics
/// If `knots` has fewer than `points.len() + p + 1` entries.
#[must_use]
pub fn nurbs_curve(knots: &[f64], p: usize, points: &[glam::DVec4], u: f64) -> glam::DVec3 {
    let end = knots[knots.len() - 1 - p];
    let sum: glam::DVec4 = points
        .iter()
        .enumerate()
        .map(|(i, &pw)| pw * bspline_basis(knots, end, i, p, u))
        .sum();
    sum.truncate() / sum.w
}

/// A NURBS surface given as data (one of the course's
/// [`freeform::NurbsSurfaceData`]) by its definition (seed 001, (1.15)):
/// `S(u, v) = Σᵢ Σⱼ N_{i,p}(u) N_{j,q}(v) Pᵢⱼʷ` over the whole net,
/// projected.
///
/// # Panics
/// If the data's knots do not fit its net.
#[must_use]
pub fn nurbs_surface(data: &freeform::NurbsSurfaceData, u: f64, v: f64) -> glam::DVec3 {
    let (p, q) = (data.degree_u, data.degree_v);
    let end_u = data.knots_u[data.knots_u.len() - 1 - p];
    let end_v = data.knots_v[data.knots_v.len() - 1 - q];
    let mut sum = glam::DVec4::ZERO;
    for i in 0..data.rows {
        let nu = bspline_basis(&data.knots_u, end_u, i, p, u);
        for j in 0..data.columns {
            let k = i * data.columns + j;
            let w = data.weights[k];
            let n = nu * bspline_basis(&data.knots_v, end_v, j, q, v);
            sum += (data.points[k] * w).extend(w) * n;
        }
    }
    sum.truncate() / sum.w
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nurbs_torus_lies_on_the_torus_and_the_vase_turns_its_profile() {
        let (major, minor) = (2.0, 0.5);
        let torus = freeform::NurbsSurfaceData::torus(major, minor);
        let vase = freeform::NurbsSurfaceData::vase();
        for k in 0..=12 {
            for l in 0..=12 {
                let (u, v) = (f64::from(k) / 12.0, f64::from(l) / 12.0);
                let p = nurbs_surface(&torus, u, v);
                let off = ((p.x.hypot(p.y) - major).hypot(p.z) - minor).abs();
                assert!(off < 1e-12, "S({u}, {v}) = {p} is {off} off the torus");
                // The vase at u and at u = 0 (on the x axis): the same
                // profile point, turned about z.
                let (p, q) = (nurbs_surface(&vase, u, v), nurbs_surface(&vase, 0.0, v));
                assert!((p.x.hypot(p.y) - q.x).abs() < 1e-12 && (p.z - q.z).abs() < 1e-12);
            }
        }
    }

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

    #[test]
    fn surfaces_by_definition_reproduce_linear_functions() {
        use glam::DVec3;
        // Control points on a plane (evenly spaced) give the plane itself.
        let linear = |x: f64, y: f64| DVec3::new(x, y, 2.0 * x - y);
        let [s, su, sv] = tensor_bezier(
            3,
            2,
            |i, j| linear(i as f64 / 3.0, j as f64 / 2.0),
            [0.3, 0.6],
        );
        assert!((s - linear(0.3, 0.6)).length() < 1e-14, "{s}");
        assert!((su - DVec3::new(1.0, 0.0, 2.0)).length() < 1e-13, "{su}");
        assert!((sv - DVec3::new(0.0, 1.0, -1.0)).length() < 1e-13, "{sv}");
        let [b, bu, bv, bw] = triangle_bezier(
            3,
            |i, j, _| linear(i as f64 / 3.0, j as f64 / 3.0),
            [0.2, 0.5, 0.3],
        );
        assert!((b - linear(0.2, 0.5)).length() < 1e-14, "{b}");
        // Tangents in the plane u + v + w = 1: moving weight from u to v
        // moves the point by (−1, 1) in (x, y).
        assert!((bv - bu - DVec3::new(-1.0, 1.0, -3.0)).length() < 1e-13);
        assert!((bw - bu - DVec3::new(-1.0, 0.0, -2.0)).length() < 1e-13);
        assert_eq!(bernstein_derivative(0, 0, 0.5), 0.0);
        assert!((bernstein_derivative(1, 2, 0.25) - 2.0 * (0.75 - 0.25)).abs() < 1e-15);
    }

    #[test]
    fn the_bspline_basis_is_bernstein_for_the_bezier_knots_and_sums_to_one() {
        // {0, 0, 0, 0, 1, 1, 1, 1}: the cubic Bernstein basis.
        let bezier = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        for t in [0.0, 0.2, 0.5, 0.9, 1.0] {
            for i in 0..4 {
                let n = bspline_basis(&bezier, 1.0, i, 3, t);
                assert!((n - bernstein(i, 3, t)).abs() < 1e-15, "N_{i},3({t}) = {n}");
            }
        }
        // A clamped quadratic with interior knots: partition of unity on
        // the closed domain, its end included.
        let knots = [0.0, 0.0, 0.0, 0.3, 0.6, 1.0, 1.0, 1.0];
        for u in [0.0, 0.1, 0.3, 0.45, 0.6, 0.99, 1.0] {
            let sum: f64 = (0..5).map(|i| bspline_basis(&knots, 1.0, i, 2, u)).sum();
            assert!((sum - 1.0).abs() < 1e-15, "Σ N_i,2({u}) = {sum}");
        }
        // With equal weights the rational curve is the polynomial one.
        let points = [
            glam::DVec4::new(0.0, 0.0, 0.0, 2.0),
            glam::DVec4::new(2.0, 4.0, 0.0, 2.0),
            glam::DVec4::new(4.0, 0.0, 0.0, 2.0),
        ];
        let mid = nurbs_curve(&[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 2, &points, 0.5);
        assert!(
            (mid - glam::DVec3::new(1.0, 1.0, 0.0)).length() < 1e-15,
            "{mid}"
        );
    }
}
