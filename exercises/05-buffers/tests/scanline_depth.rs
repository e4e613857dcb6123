//! Task 2: depth along a scanline, by interpolation between edge
//! intersections and incrementally from the plane equation.

use buffers::scanline_depth::{
    DepthPlane, ScanlineError, SpanEnds, depth_in_span, incremental_depths, row_start_depths,
    span_at,
};
use glam::{DVec2, DVec3};
use proptest::prelude::*;

/// `z = 2x + 3y + 1`, exact in `f64` for the small values used here.
fn plane_z(x: f64, y: f64) -> f64 {
    2.0 * x + 3.0 * y + 1.0
}

/// A triangle on the plane `z = 2x + 3y + 1`:
///
/// ```text
///   hi (2, 6)          vertices sorted by y: lo, mid, hi
///   mid (8, 2)         the long edge lo–hi crosses every scanline
///   lo (0, 0)
/// ```
fn known_triangle() -> [DVec3; 3] {
    [(0.0, 0.0), (8.0, 2.0), (2.0, 6.0)].map(|(x, y)| DVec3::new(x, y, plane_z(x, y)))
}

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance * (1.0 + a.abs().max(b.abs()))
}

#[testkit::test]
fn span_below_the_middle_vertex_has_vertex_1_at_the_bottom() {
    // ys = 1 < 2: vertex 1 = lo (0, 0), 2 = mid (8, 2), 3 = hi (2, 6).
    // a at (y1 − ys)/(y1 − y2) = 1/2 of lo–mid: (4, 1); b at 1/6 of lo–hi: (1/3, 1).
    let span = span_at(known_triangle(), 1.0).expect("ys = 1 crosses the triangle");
    assert_eq!(span.y, 1.0);
    assert!(
        close(span.a.x, 4.0, 1e-15) && close(span.a.y, 12.0, 1e-15),
        "a = {}",
        span.a
    );
    assert!(close(span.b.x, 1.0 / 3.0, 1e-15), "x_b = {}", span.b.x);
    assert!(
        close(span.b.y, plane_z(1.0 / 3.0, 1.0), 1e-15),
        "z_b = {}",
        span.b.y
    );
}

#[testkit::test]
fn span_above_the_middle_vertex_has_vertex_1_at_the_top() {
    // ys = 4 ≥ 2: vertex 1 = hi (2, 6), 2 = mid (8, 2), 3 = lo (0, 0).
    // a at 1/2 of hi–mid: (5, 4); b at 1/3 of hi–lo: (4/3, 4).
    let span = span_at(known_triangle(), 4.0).expect("ys = 4 crosses the triangle");
    assert!(
        close(span.a.x, 5.0, 1e-15) && close(span.a.y, 23.0, 1e-15),
        "a = {}",
        span.a
    );
    assert!(close(span.b.x, 4.0 / 3.0, 1e-15), "x_b = {}", span.b.x);
    assert!(
        close(span.b.y, plane_z(4.0 / 3.0, 4.0), 1e-15),
        "z_b = {}",
        span.b.y
    );
    // At the middle vertex's own scanline, a is that vertex.
    let at_mid = span_at(known_triangle(), 2.0).unwrap();
    assert!(
        close(at_mid.a.x, 8.0, 1e-15) && close(at_mid.a.y, plane_z(8.0, 2.0), 1e-15),
        "at the middle vertex's own scanline y = 2, a is that vertex (8, z = 23); yours \
         (x {}, z {})",
        at_mid.a.x,
        at_mid.a.y
    );
}

#[testkit::test]
fn vertex_order_does_not_change_the_span() {
    let [p, q, r] = known_triangle();
    for triangle in [
        [p, q, r],
        [q, r, p],
        [r, p, q],
        [r, q, p],
        [q, p, r],
        [p, r, q],
    ] {
        assert_eq!(span_at(triangle, 1.5), span_at(known_triangle(), 1.5));
    }
    assert!(
        span_at(known_triangle(), 1.5).is_some(),
        "a scanline through the triangle has a span"
    );
}

#[testkit::test]
fn depth_in_span_follows_the_zp_formula() {
    let span = SpanEnds {
        y: 0.0,
        a: DVec2::new(2.0, 0.5),
        b: DVec2::new(10.0, 0.1),
    };
    // z_p = z_b − (z_b − z_a)(x_b − x_p)/(x_b − x_a)
    for (x_p, expected) in [(10.0, 0.1), (2.0, 0.5), (6.0, 0.3)] {
        let yours = depth_in_span(&span, x_p);
        assert!(
            close(yours, expected, 1e-15),
            "z_p at x_p = {x_p} between a = (2, 0.5) and b = (10, 0.1): {expected}; yours {yours}"
        );
    }
    // On the known triangle, the span gives the plane: z(3, 1) = 10.
    let known = span_at(known_triangle(), 1.0).unwrap();
    let yours = depth_in_span(&known, 3.0);
    assert!(
        close(yours, 10.0, 1e-14),
        "on the plane z = 2x + 3y + 1, z_p at (3, 1) is 10; yours {yours}"
    );
    // A span of zero width (at a vertex) gives z_a, never NaN.
    let point = SpanEnds {
        y: 0.0,
        a: DVec2::new(4.0, 0.25),
        b: DVec2::new(4.0, 0.25),
    };
    assert_eq!(depth_in_span(&point, 4.0), 0.25);
    let edge_on = SpanEnds {
        y: 0.0,
        a: DVec2::new(4.0, 0.25),
        b: DVec2::new(4.0, 0.75),
    };
    assert_eq!(depth_in_span(&edge_on, 4.0), 0.25, "z_a for zero width");
}

#[testkit::test]
fn flat_top_and_flat_bottom_have_spans_on_every_scanline() {
    let flat_top = [
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(-4.0, 4.0, 2.0),
        DVec3::new(4.0, 4.0, 3.0),
    ];
    let top = span_at(flat_top, 4.0).expect("the top scanline of a flat top");
    assert!(
        top.a.is_finite() && top.b.is_finite(),
        "a flat top at its own scanline y = 4: edge 1–2 is horizontal (y1 − y2 = 0), so `a` \
         is vertex 2 (mid) itself, not the seed's formula divided by zero; yours a = (x {}, z \
         {}), b = (x {}, z {})",
        top.a.x,
        top.a.y,
        top.b.x,
        top.b.y
    );
    let xs = [top.a.x.min(top.b.x), top.a.x.max(top.b.x)];
    assert_eq!(
        xs,
        [-4.0, 4.0],
        "the span of a flat top's top scanline is the top edge"
    );
    let flat_bottom = flat_top.map(|v| DVec3::new(v.x, -v.y, v.z));
    let bottom = span_at(flat_bottom, -4.0).expect("the bottom scanline of a flat bottom");
    assert!(
        bottom.a.is_finite() && bottom.b.is_finite(),
        "a flat bottom at its own scanline y = −4: from mid up vertex 1 is hi, so no edge \
         1–2 is horizontal; yours a = (x {}, z {}), b = (x {}, z {})",
        bottom.a.x,
        bottom.a.y,
        bottom.b.x,
        bottom.b.y
    );
}

#[testkit::test]
fn scanlines_outside_and_bad_triangles_have_no_span() {
    assert_eq!(span_at(known_triangle(), -0.5), None);
    assert_eq!(span_at(known_triangle(), 6.5), None);
    assert!(
        span_at(known_triangle(), 1.5).is_some(),
        "a scanline through the triangle has a span"
    );
    assert_eq!(span_at(known_triangle(), f64::NAN), None);
    let flat = [
        DVec3::ZERO,
        DVec3::new(5.0, 0.0, 1.0),
        DVec3::new(2.0, 0.0, 2.0),
    ];
    assert_eq!(span_at(flat, 0.0), None, "a triangle without height");
    let mut nan = known_triangle();
    nan[1].z = f64::NAN;
    assert_eq!(span_at(nan, 1.0), None);
    let mut inf = known_triangle();
    inf[2].x = f64::INFINITY;
    assert_eq!(span_at(inf, 1.0), None);
}

#[testkit::test]
fn plane_of_the_known_triangle() {
    let plane = DepthPlane::try_from_triangle(known_triangle()).unwrap();
    let yours = plane.depth_at(DVec2::new(3.0, 1.0));
    assert!(
        close(yours, 10.0, 1e-15),
        "the plane z = 2x + 3y + 1 at (3, 1) is 10; yours {yours}"
    );
    assert!(close(
        plane.depth_at(DVec2::new(-7.0, 11.0)),
        plane_z(-7.0, 11.0),
        1e-15
    ));
    // z(x + 1) = z − A/C, and z grows by 2 per column: A/C = −2.
    assert!(
        close(plane.step_x(), -2.0, 1e-15),
        "A/C = {}",
        plane.step_x()
    );
    let row = incremental_depths(&plane, 1, 1, 4);
    assert_eq!(row, [6.0, 8.0, 10.0, 12.0], "z on row 1 from x = 1");
    assert_eq!(incremental_depths(&plane, 1, 1, 0), Vec::<f64>::new());
}

/// The instrument of the incremental walk: each depth must be exactly the
/// previous one minus `A/C` (one subtraction per pixel), bit for bit. A
/// walk that evaluates the plane at every pixel, or computes
/// `z_0 − k · A/C`, rounds differently on a long row with a step that
/// `f64` cannot hold exactly, and fails here.
#[testkit::test]
fn each_depth_is_the_previous_one_minus_the_step() {
    // z = 0.1 x + 0.3 y + 0.7: A/C = −0.1 is not a binary fraction.
    let triangle = [(0.0, 0.0), (1000.0, 10.0), (3.0, 400.0)]
        .map(|(x, y)| DVec3::new(x, y, 0.1 * x + 0.3 * y + 0.7));
    let plane = DepthPlane::try_from_triangle(triangle).unwrap();
    let (y, first, count) = (7, -3, 1000);
    let yours = incremental_depths(&plane, y, first, count);
    assert_eq!(yours.len(), count);
    let mut z = plane.depth_at(DVec2::new(f64::from(first), f64::from(y)));
    let step = plane.step_x();
    for (k, &got) in yours.iter().enumerate() {
        assert!(
            got.to_bits() == z.to_bits(),
            "pixel {k} of the row: {got:e}, but z_{k} = z_{} − A/C = {z:e}: the walk \
             starts with the plane equation at the first pixel and then subtracts A/C \
             once per pixel (the seed's acceleration), not evaluating the plane anew",
            k.saturating_sub(1)
        );
        z -= step;
    }
}

/// The seed's "the same holds for the first z value of the next
/// scanline": on `z = 2x + 3y + 1` the known triangle's rows 0 to 5 start
/// where its left edge `lo–hi` (`x = y/3`) crosses them, at the first
/// pixel centre to its right.
///
/// ```text
///   row 5  ..#####       starts at x = 2:  z = 2·2 + 3·5 + 1 = 20
///   row 4  ..######      x = 2: 17
///   row 3  .#######      x = 1: 12
///   row 2  .########     x = 1:  9
///   row 1  .####         x = 1:  6
///   row 0  #             x = 0:  1
/// ```
#[testkit::test]
fn row_starts_of_the_known_triangle() {
    let plane = DepthPlane::try_from_triangle(known_triangle()).unwrap();
    // z(x, y + 1) = z − B/C, and z grows by 3 per row: B/C = −3.
    assert!(
        close(plane.step_y(), -3.0, 1e-15),
        "B/C = {}, but z = 2x + 3y + 1 grows by 3 per row up: B/C = −3",
        plane.step_y()
    );
    assert_eq!(
        row_start_depths(&plane, 0, &[0, 1, 1, 1, 2, 2]),
        [1.0, 6.0, 9.0, 12.0, 17.0, 20.0],
        "the first depth of rows 0 to 5 starting at x = 0, 1, 1, 1, 2, 2: each the one \
         below minus A/C per column moved and minus B/C"
    );
    assert_eq!(
        row_start_depths(&plane, 0, &[]),
        Vec::<f64>::new(),
        "no rows, no depths"
    );
}

/// The instrument of the walk up the rows: each row's first depth must
/// be exactly the row below's minus `A/C · Δx` minus `B/C`, evaluated in
/// that order, starting from `depth_at` at the first row's start; the
/// starts wander left and right as a curved edge's would.
#[testkit::test]
fn each_row_start_is_the_one_below_moved_by_the_steps() {
    // z = 0.1 x + 0.3 y + 0.7: neither A/C = −0.1 nor B/C = −0.3 is a
    // binary fraction.
    let triangle = [(0.0, 0.0), (1000.0, 10.0), (3.0, 400.0)]
        .map(|(x, y)| DVec3::new(x, y, 0.1 * x + 0.3 * y + 0.7));
    let plane = DepthPlane::try_from_triangle(triangle).unwrap();
    let first_y = -5;
    let first_xs: Vec<i32> = (0..600)
        .map(|k| (40.0 * (f64::from(k) / 25.0).sin()).round() as i32 + k / 7)
        .collect();
    let yours = row_start_depths(&plane, first_y, &first_xs);
    assert_eq!(yours.len(), first_xs.len(), "one depth per row start given");
    let (step_x, step_y) = (plane.step_x(), plane.step_y());
    let mut z = plane.depth_at(DVec2::new(f64::from(first_xs[0]), f64::from(first_y)));
    for (k, &got) in yours.iter().enumerate() {
        if k > 0 {
            let dx = f64::from(first_xs[k]) - f64::from(first_xs[k - 1]);
            z = z - step_x * dx - step_y;
        }
        assert!(
            got.to_bits() == z.to_bits(),
            "row {k} (y = {}, starting at x = {}): {got:e}, but z_{k} = z_{} − A/C·Δx − B/C \
             = {z:e}: the first depth of a row comes from the row below (the seed's \
             acceleration), the plane equation is evaluated only at the first row's start",
            first_y + k as i32,
            first_xs[k],
            k.saturating_sub(1)
        );
    }
}

#[testkit::test]
fn triangles_without_a_depth_plane_are_errors() {
    let edge_on = [
        DVec3::ZERO,
        DVec3::new(1.0, 1.0, 0.5),
        DVec3::new(2.0, 2.0, 0.9),
    ];
    assert_eq!(
        DepthPlane::try_from_triangle(edge_on),
        Err(ScanlineError::Degenerate)
    );
    let mut nan = known_triangle();
    nan[0].y = f64::NAN;
    assert_eq!(
        DepthPlane::try_from_triangle(nan),
        Err(ScanlineError::NotFinite)
    );
}

/// Triangles with vertices in `[-20, 20]²` and depths in `[0, 1]`, with at
/// least a few pixels of area.
fn triangle() -> impl Strategy<Value = [DVec3; 3]> {
    let v = (-20.0f64..20.0, -20.0f64..20.0, 0.0f64..1.0).prop_map(|(x, y, z)| DVec3::new(x, y, z));
    [v.clone(), v.clone(), v].prop_filter("area of at least 4 pixels", |t| {
        (t[1] - t[0]).cross(t[2] - t[0]).z.abs() >= 8.0
    })
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn interpolation_and_the_plane_equation_agree(triangle in triangle(), row in -20i32..=20) {
        let plane = DepthPlane::try_from_triangle(triangle).unwrap();
        let Some(span) = span_at(triangle, f64::from(row)) else {
            let ys: Vec<f64> = triangle.iter().map(|v| v.y).collect();
            let (lo, hi) = (ys.iter().copied().fold(f64::MAX, f64::min), ys.iter().copied().fold(f64::MIN, f64::max));
            prop_assert!(f64::from(row) < lo || f64::from(row) > hi, "no span on row {} inside the triangle", row);
            return Ok(());
        };
        // Both crossings lie on the triangle's plane and on its edges' x range.
        for end in [span.a, span.b] {
            let z = plane.depth_at(DVec2::new(end.x, f64::from(row)));
            prop_assert!(close(end.y, z, 1e-9), "span end {} is off the plane (z = {})", end, z);
        }
        let first = span.a.x.min(span.b.x).ceil() as i32;
        let last = span.a.x.max(span.b.x).floor() as i32;
        if first > last {
            return Ok(());
        }
        let count = (last - first + 1) as usize;
        let incremental = incremental_depths(&plane, row, first, count);
        prop_assert_eq!(incremental.len(), count);
        for (k, z_inc) in incremental.into_iter().enumerate() {
            let x = f64::from(first) + k as f64;
            let z_int = depth_in_span(&span, x);
            prop_assert!(close(z_inc, z_int, 1e-9), "x = {}: incremental {} vs interpolated {}", x, z_inc, z_int);
        }
    }

    /// Up the rows of a random triangle, starting each at the first pixel
    /// centre right of its left crossing: the walk stays on the plane.
    #[testkit::test]
    fn row_starts_stay_on_the_plane(triangle in triangle()) {
        let plane = DepthPlane::try_from_triangle(triangle).unwrap();
        let lo = triangle.iter().map(|v| v.y).fold(f64::MAX, f64::min).ceil() as i32;
        let hi = triangle.iter().map(|v| v.y).fold(f64::MIN, f64::max).floor() as i32;
        let first_xs: Vec<i32> = (lo..=hi)
            .filter_map(|y| span_at(triangle, f64::from(y)))
            .map(|span| span.a.x.min(span.b.x).ceil() as i32)
            .collect();
        prop_assume!(first_xs.len() == (lo..=hi).count());
        let yours = row_start_depths(&plane, lo, &first_xs);
        prop_assert_eq!(yours.len(), first_xs.len(), "one depth per row");
        for (k, (&z, &x)) in yours.iter().zip(&first_xs).enumerate() {
            let y = lo + k as i32;
            let exact = plane.depth_at(DVec2::new(f64::from(x), f64::from(y)));
            prop_assert!(close(z, exact, 1e-9), "row {} from x = {}: {} walked up vs {} from the plane", y, x, z, exact);
        }
    }

    #[testkit::test]
    fn hostile_input_never_panics(
        v in prop::array::uniform9(prop_oneof![Just(f64::NAN), Just(f64::INFINITY), Just(1e300), Just(-1e300), -5.0f64..5.0]),
        ys in prop_oneof![Just(f64::NAN), -5.0f64..5.0],
    ) {
        let triangle = [DVec3::new(v[0], v[1], v[2]), DVec3::new(v[3], v[4], v[5]), DVec3::new(v[6], v[7], v[8])];
        if let Some(span) = span_at(triangle, ys) {
            let _ = depth_in_span(&span, 0.0);
        }
        if let Ok(plane) = DepthPlane::try_from_triangle(triangle) {
            let _ = incremental_depths(&plane, 0, 0, 4);
            let _ = row_start_depths(&plane, i32::MIN, &[i32::MIN, i32::MAX, 0]);
        }
    }
}
