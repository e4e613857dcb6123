//! The zipper: triangulating the strip between two polylines that run side
//! by side, as both the per-patch adaptive tessellation (the ring between a
//! patch's inner grid and its boundary curves, seed 001 §2.1, Figure 2.3)
//! and the OpenGL primitive generator (the rings between concentric
//! triangles or rectangles) need it.
//!
//! ```text
//!   inner   b0 ──── b1 ─────────── b2          each step emits one triangle:
//!           │ ╲    ╱ ╲         ╱╱  │           (a_i, a_i+1, b_j)  when the outer
//!           │  ╲  ╱   ╲    ╱╱      │           polyline advances, or
//!   outer   a0 ─ a1 ─── a2 ─────── a3          (a_i, b_j+1, b_j)  when the inner does
//! ```
//!
//! Both polylines carry a key per vertex, increasing along them (the
//! position along the shared direction); at each step the side whose next
//! vertex has the smaller key advances (the outer on ties). Because both
//! walks are monotone, the connecting edges never cross: the triangles tile
//! the strip. With the inner polyline on the left of the outer one's
//! direction, every triangle is counter-clockwise.

/// Appends the triangles of the strip between `outer` and `inner` (vertex
/// indices, in order) to `triangles`. `outer_keys` and `inner_keys` give
/// each vertex's position along the strip and must be as long as their
/// polylines. A polyline of one vertex is a fan apex; if either polyline is
/// empty, or both have a single vertex, nothing is emitted.
///
/// # Panics
/// If a key slice is shorter than its polyline.
pub fn stitch(
    outer: &[u32],
    outer_keys: &[f64],
    inner: &[u32],
    inner_keys: &[f64],
    triangles: &mut Vec<[u32; 3]>,
) {
    assert!(outer_keys.len() >= outer.len() && inner_keys.len() >= inner.len());
    if outer.is_empty() || inner.is_empty() {
        return;
    }
    let (last_a, last_b) = (outer.len() - 1, inner.len() - 1);
    let (mut i, mut j) = (0, 0);
    while i < last_a || j < last_b {
        let advance_outer = j == last_b || (i < last_a && outer_keys[i + 1] <= inner_keys[j + 1]);
        if advance_outer {
            triangles.push([outer[i], outer[i + 1], inner[j]]);
            i += 1;
        } else {
            triangles.push([outer[i], inner[j + 1], inner[j]]);
            j += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Twice the signed area of the triangle at the points of `positions`.
    fn area2(positions: &[[f64; 2]], [a, b, c]: [u32; 3]) -> f64 {
        let [p, q, r] = [a, b, c].map(|k| positions[k as usize]);
        (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
    }

    #[test]
    fn a_strip_is_tiled_counter_clockwise() {
        // outer a0..a3 on y = 0, inner b0..b2 on y = 1 (left of the outer
        // polyline's direction +x), keys their x.
        let positions = [
            [0.0, 0.0],
            [1.0, 0.0],
            [2.5, 0.0],
            [4.0, 0.0],
            [0.0, 1.0],
            [1.5, 1.0],
            [4.0, 1.0],
        ];
        let (outer, inner) = ([0, 1, 2, 3], [4, 5, 6]);
        let key = |ids: &[u32]| {
            ids.iter()
                .map(|&k| positions[k as usize][0])
                .collect::<Vec<_>>()
        };
        let mut triangles = Vec::new();
        stitch(&outer, &key(&outer), &inner, &key(&inner), &mut triangles);
        // One triangle per step: (4 − 1) + (3 − 1).
        assert_eq!(triangles.len(), 5);
        let total: f64 = triangles.iter().map(|&t| area2(&positions, t)).sum();
        assert!(
            triangles.iter().all(|&t| area2(&positions, t) > 0.0),
            "{triangles:?}"
        );
        // The trapezoid's area, twice: no gap, no overlap.
        assert!((total - 2.0 * 4.0).abs() < 1e-12, "{total}");
    }

    #[test]
    fn a_single_inner_vertex_is_a_fan_apex() {
        let mut triangles = Vec::new();
        stitch(&[0, 1, 2], &[0.0, 1.0, 2.0], &[3], &[1.0], &mut triangles);
        assert_eq!(triangles, vec![[0, 1, 3], [1, 2, 3]]);
    }

    #[test]
    fn an_empty_polyline_gives_nothing() {
        let mut triangles = Vec::new();
        stitch(&[], &[], &[0, 1], &[0.0, 1.0], &mut triangles);
        stitch(&[0], &[0.0], &[1], &[0.0], &mut triangles);
        assert!(triangles.is_empty());
    }
}
