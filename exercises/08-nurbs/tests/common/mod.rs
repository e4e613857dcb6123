//! What the tests compare with: the definitions, evaluated the slow and
//! obvious way (binomial coefficients, the Cox-de Boor recursion over
//! *all* basis functions, sums over the whole control net), never the
//! algorithms you write; the shapes with exactly known answers (circle,
//! torus); and a small z-buffered triangle renderer for the pictures.
#![allow(dead_code, unused_imports)] // each test file uses a different part

use canvas::{Canvas, Pixel, Rgba};
use glam::{DVec3, DVec4};
use nurbs::{ControlNet, Domain, KnotVector, NurbsCurve, NurbsSurface, RationalPatch, homogeneous};
use proptest::prelude::*;

pub use testkit::oracles::bernstein;

/// `N_{i,p}(u)` by the definition (half-open steps; the last non-empty
/// step of the domain closed at its end, so that the basis sums to 1 at
/// the domain's end): the Cox–de Boor recursion of `testkit::oracles`.
pub fn basis(knots: &KnotVector, i: usize, p: usize, u: f64) -> f64 {
    testkit::oracles::bspline_basis(knots.knots(), knots.domain().end, i, p, u)
}

/// `C(u) = Σ N_{i,p}(u) Pᵢʷ`, projected, over all `i`.
pub fn curve_point(knots: &KnotVector, points: &[DVec4], u: f64) -> DVec3 {
    testkit::oracles::nurbs_curve(knots.knots(), knots.degree(), points, u)
}

/// `S(u, v)` by the double sum over the whole net (seed 001, (1.15)).
pub fn surface_point(surface: &NurbsSurface, u: f64, v: f64) -> DVec3 {
    let (ku, kv) = (surface.knots_u(), surface.knots_v());
    let net = surface.net();
    let nv: Vec<f64> = (0..net.columns())
        .map(|j| basis(kv, j, kv.degree(), v))
        .collect();
    let mut sum = DVec4::ZERO;
    for i in 0..net.rows() {
        let nu = basis(ku, i, ku.degree(), u);
        for (j, &n) in nv.iter().enumerate() {
            sum += net.get(i, j) * (nu * n);
        }
    }
    sum.truncate() / sum.w
}

/// A rational Bézier patch at `(s, t) ∈ [0, 1]²` by Bernstein sums.
pub fn bezier_patch_point(net: &ControlNet, s: f64, t: f64) -> DVec3 {
    let (p, q) = (net.rows() - 1, net.columns() - 1);
    let mut sum = DVec4::ZERO;
    for i in 0..=p {
        for j in 0..=q {
            sum += net.get(i, j) * (bernstein(i, p, s) * bernstein(j, q, t));
        }
    }
    sum.truncate() / sum.w
}

/// The same for the course library's patch: its homogeneous points
/// `(w·P, w)` as a net.
pub fn rational_patch_point(patch: &RationalPatch, s: f64, t: f64) -> DVec3 {
    let (p, q) = (patch.points().degree_u(), patch.points().degree_v());
    let points = (0..=p)
        .flat_map(|i| (0..=q).map(move |j| homogeneous_point(patch, i, j)))
        .collect();
    let net = ControlNet::try_new(p + 1, q + 1, points).expect("a patch's points are a net");
    bezier_patch_point(&net, s, t)
}

/// `Pʷ_ij = (w·P, w)` of a patch, to compare with a net's points.
pub fn homogeneous_point(patch: &RationalPatch, i: usize, j: usize) -> DVec4 {
    homogeneous(patch.points().control_point(i, j), patch.weight(i, j))
}

/// The non-empty spans of a knot vector's domain, in order: the pieces
/// `[u_a, u_{a+1}]` between its distinct knots, which the Bézier patches
/// of a decomposition cover one by one.
pub fn spans(knots: &KnotVector) -> Vec<Domain> {
    let domain = knots.domain();
    let mut values = vec![domain.start];
    values.extend(knots.interior_breakpoints().iter().map(|b| b.value));
    values.push(domain.end);
    values
        .windows(2)
        .map(|w| Domain {
            start: w[0],
            end: w[1],
        })
        .collect()
}

/// Fails with both points and `what` if they are farther apart than
/// `tolerance`.
#[track_caller]
pub fn assert_close(expected: DVec3, actual: DVec3, tolerance: f64, what: &str) {
    let distance = expected.distance(actual);
    assert!(
        distance <= tolerance,
        "{what}: expected {expected}, got {actual} (distance {distance:e} > {tolerance:e})"
    );
}

/// `√2 / 2`, the weight of the corner points of a circle's quadrants.
pub const CORNER_WEIGHT: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// The quarter of the unit circle from `(1, 0)` to `(0, 1)` as a rational
/// quadratic Bézier curve: corner `(1, 1)` with weight `√2/2`.
pub fn quarter_circle() -> [DVec4; 3] {
    [
        homogeneous(DVec3::X, 1.0),
        homogeneous(DVec3::new(1.0, 1.0, 0.0), CORNER_WEIGHT),
        homogeneous(DVec3::Y, 1.0),
    ]
}

/// The whole unit circle in the xy plane: 9 control points on the square
/// `[-1, 1]²`, degree 2, knots `0 0 0 ¼ ¼ ½ ½ ¾ ¾ 1 1 1`
/// (The NURBS Book, Example 7.1).
pub fn circle_knots() -> KnotVector {
    KnotVector::try_new(
        2,
        vec![
            0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
        ],
    )
    .expect("valid")
}

/// The 9 circle control points `(x, y)` and weights.
pub fn circle_points() -> Vec<(f64, f64, f64)> {
    let w = CORNER_WEIGHT;
    vec![
        (1.0, 0.0, 1.0),
        (1.0, 1.0, w),
        (0.0, 1.0, 1.0),
        (-1.0, 1.0, w),
        (-1.0, 0.0, 1.0),
        (-1.0, -1.0, w),
        (0.0, -1.0, 1.0),
        (1.0, -1.0, w),
        (1.0, 0.0, 1.0),
    ]
}

/// The unit circle as a NURBS curve.
pub fn circle() -> NurbsCurve {
    let points = circle_points()
        .into_iter()
        .map(|(x, y, w)| homogeneous(DVec3::new(x, y, 0.0), w))
        .collect();
    NurbsCurve::try_new(circle_knots(), points).expect("valid")
}

/// The torus's radii: the tube's centre circle and the tube.
pub const TORUS_R: f64 = 2.0;
/// The tube's radius.
pub const TORUS_TUBE: f64 = 0.75;

/// A torus around the z axis as a biquadratic NURBS surface: `u` runs
/// round the z axis, `v` round the tube; the net is the circle's net
/// (rows) times the tube circle's net (columns), weights multiplied
/// (a surface of revolution, The NURBS Book §8.5): the course's
/// [`freeform::NurbsSurfaceData::torus`].
pub fn torus() -> NurbsSurface {
    NurbsSurface::from_data(&freeform::NurbsSurfaceData::torus(TORUS_R, TORUS_TUBE)).expect("valid")
}

/// How far `p` is from the torus surface (0 on it).
pub fn torus_distance(p: DVec3) -> f64 {
    let ring = (p.x.hypot(p.y) - TORUS_R).hypot(p.z);
    (ring - TORUS_TUBE).abs()
}

/// A valid knot vector of degree `1 ..= 4`: clamped or not, with random
/// interior knots (some repeated up to the degree).
pub fn knot_vector() -> impl Strategy<Value = KnotVector> {
    (1usize..=4, 0usize..=5, any::<bool>(), 0u64..u64::MAX).prop_map(
        |(degree, interior, clamped, seed)| {
            let mut state = seed | 1;
            let mut next = move || {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                (state >> 11) as f64 / (1u64 << 53) as f64
            };
            let mut inner: Vec<f64> = Vec::new();
            for _ in 0..interior {
                let value = 0.05 + 0.9 * next();
                let repeat = 1 + (next() * degree as f64) as usize;
                inner.extend(std::iter::repeat_n(value, repeat.min(degree)));
            }
            inner.sort_by(f64::total_cmp);
            let mut knots = Vec::new();
            if clamped {
                knots.extend(std::iter::repeat_n(0.0, degree + 1));
                knots.extend(&inner);
                knots.extend(std::iter::repeat_n(1.0, degree + 1));
            } else {
                // Unclamped: evenly spaced knots outside [0, 1].
                knots.extend((0..=degree).map(|i| -0.3 * (degree - i) as f64));
                knots.extend(&inner);
                knots.extend((0..=degree).map(|i| 1.0 + 0.3 * i as f64));
            }
            match KnotVector::try_new(degree, knots) {
                Ok(k) => k,
                // Two random values that coincide and exceed the degree:
                // fall back to the plain clamped vector.
                Err(_) => KnotVector::clamped_uniform(degree, degree + 2).expect("valid"),
            }
        },
    )
}

/// A point with coordinates in `[-10, 10]`.
pub fn point3() -> impl Strategy<Value = DVec3> {
    prop::array::uniform3(-10.0f64..10.0).prop_map(DVec3::from_array)
}

/// A weight in `[0.2, 5]`.
pub fn weight() -> impl Strategy<Value = f64> {
    0.2f64..5.0
}

/// A homogeneous control point with a weight in `[0.2, 5]`.
pub fn weighted_point() -> impl Strategy<Value = DVec4> {
    (point3(), weight()).prop_map(|(p, w)| homogeneous(p, w))
}

/// A random NURBS curve (degree 1 to 4, clamped or unclamped knots).
pub fn nurbs_curve() -> impl Strategy<Value = NurbsCurve> {
    knot_vector().prop_flat_map(|knots| {
        let count = knots.control_points();
        prop::collection::vec(weighted_point(), count)
            .prop_map(move |points| NurbsCurve::try_new(knots.clone(), points).expect("valid"))
    })
}

/// A random NURBS surface (degrees 1 to 4 in each direction).
pub fn nurbs_surface() -> impl Strategy<Value = NurbsSurface> {
    (knot_vector(), knot_vector()).prop_flat_map(|(ku, kv)| {
        let (rows, columns) = (ku.control_points(), kv.control_points());
        prop::collection::vec(weighted_point(), rows * columns).prop_map(move |points| {
            let net = ControlNet::try_new(rows, columns, points).expect("valid");
            NurbsSurface::try_new(ku.clone(), kv.clone(), net).expect("valid")
        })
    })
}

/// Whether `p` lies in the axis-aligned box of `points` (a necessary
/// condition of the convex hull property), with a tolerance.
pub fn in_bounding_box(p: DVec3, points: impl IntoIterator<Item = DVec3>, tolerance: f64) -> bool {
    let (lo, hi) = points.into_iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), q| (lo.min(q), hi.max(q)),
    );
    p.cmpge(lo - tolerance).all() && p.cmple(hi + tolerance).all()
}

/// The view of the pictures: a rotation tilting the torus towards the
/// viewer, then an orthographic projection to a `WIDTH × HEIGHT` canvas.
pub const WIDTH: u32 = 192;
/// Picture height.
pub const HEIGHT: u32 = 128;
/// Pixels per model unit.
const SCALE: f64 = 32.0;
/// The tilt about the x axis, in radians.
const TILT: f64 = 1.0;

/// Model → (pixel x, pixel y, depth in [0, 1]).
pub fn to_screen(p: DVec3) -> DVec3 {
    let (s, c) = TILT.sin_cos();
    // Rotate about x, the top (+z) towards the viewer and the near side
    // (−y) down: y' = c·y + s·z, z' = −s·y + c·z; view along −z'.
    let y = c * p.y + s * p.z;
    let z = -s * p.y + c * p.z;
    DVec3::new(
        f64::from(WIDTH) / 2.0 + SCALE * p.x,
        f64::from(HEIGHT) / 2.0 + SCALE * y,
        0.5 - z / 8.0,
    )
}

/// The direction towards the light.
pub fn light() -> DVec3 {
    DVec3::new(-0.4, 0.5, 1.0).normalize()
}

/// Lambert shading of a surface with unit normal `n` (in model space),
/// both sides lit, on a warm base colour.
pub fn shade(n: DVec3) -> Rgba {
    let (s, c) = TILT.sin_cos();
    let view_normal = DVec3::new(n.x, c * n.y + s * n.z, -s * n.y + c * n.z);
    let lambert = view_normal.dot(light()).abs();
    let i = (0.15 + 0.85 * lambert) as f32;
    Rgba::rgb(0.95 * i, 0.75 * i, 0.45 * i)
}

/// Renders a grid of `samples_u × samples_v` points (row-major, as
/// `NurbsSurface::sample_grid`) with one colour per point, as triangles
/// with Gouraud colour, a depth test (less) and pixel centres at integers.
pub fn render_grid(
    points: &[DVec3],
    colours: &[Rgba],
    samples_u: usize,
    samples_v: usize,
) -> Canvas {
    let mut canvas = Canvas::new(WIDTH, HEIGHT);
    canvas.clear(Rgba::BLACK);
    let screen: Vec<DVec3> = points.iter().map(|&p| to_screen(p)).collect();
    let at = |i: usize, j: usize| i * samples_v + j;
    for i in 0..samples_u - 1 {
        for j in 0..samples_v - 1 {
            let quad = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            for tri in [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]] {
                let v = tri.map(|k| (screen[k], colours[k]));
                fill_triangle(&mut canvas, v);
            }
        }
    }
    canvas
}

/// One triangle, both windings, centres on an edge included: the pixels
/// of the course's given rasterizer, `scene::raster::cover`, with colour
/// and depth interpolated and depth-tested here.
fn fill_triangle(canvas: &mut Canvas, v: [(DVec3, Rgba); 3]) {
    let [(a, ca), (b, cb), (c, cc)] = v;
    let corners = [a, b, c].map(DVec3::truncate);
    let viewport = canvas.viewport();
    scene::raster::cover(corners, viewport, |pixel, [la, lb, lc]| {
        let depth = (la * a.z + lb * b.z + lc * c.z) as f32;
        if canvas.depth(pixel).is_some_and(|d| depth < d) {
            let colour = Rgba::new(
                (la as f32) * ca.r + (lb as f32) * cb.r + (lc as f32) * cc.r,
                (la as f32) * ca.g + (lb as f32) * cb.g + (lc as f32) * cc.g,
                (la as f32) * ca.b + (lb as f32) * cb.b + (lc as f32) * cc.b,
                1.0,
            );
            canvas.plot(canvas::Fragment {
                pixel,
                depth,
                colour,
            });
        }
    });
}

/// Plots a dot of `colour` at the screen position of `p` if it is in
/// front of what is there (depth test against the shaded surface, with a
/// small bias so that curves on the surface stay visible).
pub fn plot_on_top(canvas: &mut Canvas, p: DVec3, colour: Rgba) {
    /// Depth bias of lines drawn on a surface (polygon offset, seed 002).
    const LINE_BIAS: f32 = 0.01;
    let s = to_screen(p);
    let pixel = Pixel::new(s.x.round() as i32, s.y.round() as i32);
    if canvas
        .depth(pixel)
        .is_some_and(|d| (s.z as f32) - LINE_BIAS < d)
    {
        canvas.set(pixel, colour);
    }
}
