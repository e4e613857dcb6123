//! Domains built from their definitions: regular grids and lattices for
//! the tests of tasks that evaluate a surface over a domain, so that they
//! never run the primitive generator (topic 10's task 2).

use std::collections::HashMap;

use freeform::{QuadDomain, TriangleDomain};
use glam::DVec2;

/// `0, 1/n, …, 1` (`n ≥ 1`).
#[must_use]
pub fn cuts(n: usize) -> Vec<f64> {
    (0..=n).map(|i| i as f64 / n as f64).collect()
}

/// The tensor grid of the parameters `us × vs` (each rising from 0 to 1):
/// points `(u, v)` row by row (`u` running fastest), two counter-clockwise
/// triangles per cell, cut along the diagonal from `(uᵢ, vⱼ)` to
/// `(uᵢ₊₁, vⱼ₊₁)`.
#[must_use]
pub fn grid(us: &[f64], vs: &[f64]) -> QuadDomain {
    let mut domain = QuadDomain::default();
    for &v in vs {
        for &u in us {
            domain.points.push(DVec2::new(u, v));
        }
    }
    let (n_u, n_v) = (us.len() as u32, vs.len() as u32);
    let at = |i: u32, j: u32| j * n_u + i;
    for j in 0..n_v.saturating_sub(1) {
        for i in 0..n_u.saturating_sub(1) {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            domain.triangles.push([a, b, c]);
            domain.triangles.push([a, c, d]);
        }
    }
    domain
}

/// The regular triangle domain of level `n ≥ 1`: the barycentric lattice
/// `(i, j, n − i − j)/n` with its up and down triangles, `n²` in all,
/// counter-clockwise in the embedding `u·(1, 0) + v·(½, √3/2)`.
#[must_use]
pub fn lattice(n: usize) -> TriangleDomain {
    let mut domain = TriangleDomain::default();
    let mut id = HashMap::new();
    for i in 0..=n {
        for j in 0..=n - i {
            id.insert((i, j), domain.points.len() as u32);
            let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
            domain.points.push([u, v, 1.0 - u - v]);
        }
    }
    for i in 0..n {
        for j in 0..n - i {
            domain
                .triangles
                .push([id[&(i, j)], id[&(i + 1, j)], id[&(i, j + 1)]]);
            if i + j + 2 <= n {
                domain
                    .triangles
                    .push([id[&(i + 1, j)], id[&(i + 1, j + 1)], id[&(i, j + 1)]]);
            }
        }
    }
    domain
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::topology::directed_edges;

    /// Twice the signed area of a triangle of plane points.
    fn area2([a, b, c]: [DVec2; 3]) -> f64 {
        (b - a).perp_dot(c - a)
    }

    #[test]
    fn a_grid_tiles_the_square_counter_clockwise() {
        let domain = grid(&[0.0, 0.25, 1.0], &cuts(3));
        assert_eq!((domain.points.len(), domain.triangles.len()), (12, 12));
        let areas: Vec<f64> = domain
            .triangles
            .iter()
            .map(|t| area2(t.map(|k| domain.points[k as usize])))
            .collect();
        assert!(areas.iter().all(|&a| a > 0.0), "{areas:?}");
        assert!((areas.iter().sum::<f64>() - 2.0).abs() < 1e-12);
        assert!(directed_edges(&domain.triangles).values().all(|&n| n == 1));
    }

    #[test]
    fn a_lattice_tiles_the_triangle_counter_clockwise() {
        let domain = lattice(4);
        assert_eq!((domain.points.len(), domain.triangles.len()), (15, 16));
        let areas: Vec<f64> = domain
            .triangles
            .iter()
            .map(|t| area2(t.map(|k| freeform::embed(domain.points[k as usize]))))
            .collect();
        assert!(areas.iter().all(|&a| a > 0.0), "{areas:?}");
        // The embedded triangle's area √3/4, twice.
        assert!((areas.iter().sum::<f64>() - 3.0_f64.sqrt() / 2.0).abs() < 1e-12);
        assert!(directed_edges(&domain.triangles).values().all(|&n| n == 1));
    }
}
