//! What the tests compare with: Bézier curves and surfaces by their
//! definition (Pascal's triangle and the double Bernstein sum, no de
//! Casteljau), exact trim regions, and the picture of a trimmed surface
//! drawn with the given rasterizer — not by the algorithms you write.
#![allow(dead_code, unused_imports)] // each test file uses a different part

use bezier::render::{SurfaceSample, checker};
use bezier::zbuffer::{Camera, RasterVertex, rasterize_triangle};
use bezier::{BezierPatch, Trim};
use canvas::{Canvas, Rgba};
use glam::{DVec2, DVec3};
use transcript::{Record as _, Replay as _};

pub use testkit::oracles::{bernstein as bernstein_def, binomial as pascal};

/// `Σ B_{i,n}(t) P_i` for 2-D points.
pub fn curve2(points: &[DVec2], t: f64) -> DVec2 {
    let n = points.len() - 1;
    points
        .iter()
        .enumerate()
        .map(|(i, &p)| p * bernstein_def(i, n, t))
        .sum()
}

/// `Σ B_{i,n}(t) P_i` for 3-D points.
pub fn curve3(points: &[DVec3], t: f64) -> DVec3 {
    let n = points.len() - 1;
    points
        .iter()
        .enumerate()
        .map(|(i, &p)| p * bernstein_def(i, n, t))
        .sum()
}

/// The hodograph: `P'(t) = n Σ B_{i,n−1}(t) (P_{i+1} − P_i)`.
pub fn derivative3(points: &[DVec3], t: f64) -> DVec3 {
    let n = points.len() - 1;
    if n == 0 {
        return DVec3::ZERO;
    }
    let d: Vec<DVec3> = points
        .windows(2)
        .map(|w| (w[1] - w[0]) * n as f64)
        .collect();
    curve3(&d, t)
}

/// Seed eq. (10): `Σ_i Σ_j B_{i,n}(u) B_{j,m}(v) P_{i,j}`.
pub fn surface_def(net: &BezierPatch, uv: DVec2) -> DVec3 {
    let (n, m) = (net.degree_u(), net.degree_v());
    let mut sum = DVec3::ZERO;
    for i in 0..=n {
        for j in 0..=m {
            sum += net.control_point(i, j) * bernstein_def(i, n, uv.x) * bernstein_def(j, m, uv.y);
        }
    }
    sum
}

/// `∂P/∂u` and `∂P/∂v` by differentiating eq. (10) term by term.
pub fn surface_partials_def(net: &BezierPatch, uv: DVec2) -> [DVec3; 2] {
    let (n, m) = (net.degree_u(), net.degree_v());
    let mut du = DVec3::ZERO;
    let mut dv = DVec3::ZERO;
    for i in 0..=n {
        for j in 0..=m {
            let p = net.control_point(i, j);
            // d/dt B_{i,n}(t) = n (B_{i−1,n−1}(t) − B_{i,n−1}(t)).
            let db = |i: usize, n: usize, t: f64| {
                if n == 0 {
                    return 0.0;
                }
                let left = if i > 0 {
                    bernstein_def(i - 1, n - 1, t)
                } else {
                    0.0
                };
                let right = if i < n {
                    bernstein_def(i, n - 1, t)
                } else {
                    0.0
                };
                n as f64 * (left - right)
            };
            du += p * db(i, n, uv.x) * bernstein_def(j, m, uv.y);
            dv += p * bernstein_def(i, n, uv.x) * db(j, m, uv.y);
        }
    }
    [du, dv]
}

/// The surface sample the render task draws: eq. (10) and the normalised
/// cross product of the partial derivatives.
pub fn sample_def(net: &BezierPatch, uv: DVec2) -> SurfaceSample {
    let [du, dv] = surface_partials_def(net, uv);
    SurfaceSample {
        uv,
        position: surface_def(net, uv),
        normal: du.cross(dv).normalize_or_zero(),
    }
}

/// The camera of all pictures: above and in front of the seed's hill.
pub const FIGURE_CAMERA: Camera = Camera {
    eye: DVec3::new(0.0, 1.6, 1.3),
    target: DVec3::new(0.0, 0.1, 0.0),
    up: DVec3::Y,
    fov_y_degrees: 40.0,
};

/// The size of the trim pictures.
pub const FIGURE_SIZE: [u32; 2] = [200, 150];

/// The background of the pictures.
pub const BACKGROUND: Rgba = Rgba::rgb(0.15, 0.2, 0.3);

/// Trims nothing.
pub struct NoTrim;

impl Trim for NoTrim {
    fn trims(&self, _uv: DVec2) -> bool {
        false
    }
}

/// A test's own disc trim (the render task must not depend on the trim task).
pub struct Disc {
    pub centre: DVec2,
    pub radius: f64,
}

impl Trim for Disc {
    fn trims(&self, uv: DVec2) -> bool {
        uv.distance(self.centre) < self.radius
    }
}

/// The seed's hill (Fig. 14) with `trim` cut away, drawn by test code:
/// a 48 × 48 grid, the given rasterizer, diffuse light from above-front
/// on the checker texture, so that the trim figures do not depend on the
/// render task.
pub fn trim_figure(trim: &dyn Trim) -> Canvas {
    const LEVEL: usize = 48;
    let [w, h] = FIGURE_SIZE;
    let net = BezierPatch::seed_hill();
    let mut canvas = Canvas::new(w, h);
    canvas.clear(BACKGROUND);
    let vertex = |i: usize, j: usize| {
        let uv = DVec2::new(i as f64, j as f64) / LEVEL as f64;
        let s = sample_def(&net, uv);
        FIGURE_CAMERA
            .to_screen(s.position, w, h)
            .map(|screen| RasterVertex {
                screen,
                uv,
                world: s.position,
                normal: s.normal,
            })
    };
    let light = DVec3::new(0.3, 1.0, 0.6).normalize();
    for i in 0..LEVEL {
        for j in 0..LEVEL {
            let c = [
                vertex(i, j),
                vertex(i + 1, j),
                vertex(i + 1, j + 1),
                vertex(i, j + 1),
            ];
            for [p, q, r] in [[0, 1, 2], [0, 2, 3]] {
                if let (Some(a), Some(b), Some(c)) = (c[p], c[q], c[r]) {
                    rasterize_triangle(&mut canvas, [a, b, c], |f| {
                        let uv = f.uv.clamp(DVec2::ZERO, DVec2::ONE);
                        if trim.trims(uv) {
                            return None;
                        }
                        let lambert = f.normal.normalize_or_zero().dot(light).abs();
                        let colour = checker(uv) * (0.25 + 0.75 * lambert);
                        Some(Rgba::rgb(colour.x as f32, colour.y as f32, colour.z as f32))
                    });
                }
            }
        }
    }
    canvas
}

/// The parameter square as ASCII art, `size × size` samples at cell
/// centres, top row first (v up): `#` trimmed, `.` kept.
pub fn ascii_trim(size: usize, trimmed: impl Fn(DVec2) -> bool) -> String {
    let mut out = String::new();
    for row in (0..size).rev() {
        for col in 0..size {
            let uv = DVec2::new(col as f64 + 0.5, row as f64 + 0.5) / size as f64;
            out.push(if trimmed(uv) { '#' } else { '.' });
        }
        out.push('\n');
    }
    out
}

/// Path of a committed reference picture.
pub fn image_path(name: &str) -> String {
    format!("{}/tests/images/{name}.png", env!("CARGO_MANIFEST_DIR"))
}

/// A 1-D control point that records every multiplication of a point by a
/// scalar (the point's value and the factor), so that a test can tell how
/// an evaluation combines the control points: de Casteljau's triangle of
/// degree `n` has `n(n + 1)/2` interpolations of neighbours, each at least
/// one multiplication; the Bernstein form scales each of the `n + 1`
/// control points once, by its polynomial (plain `f64` work).
///
/// The multiplications happen in your code, which the grader's replay
/// does not run (see the `transcript` crate): a `Counted` point your
/// function returns is therefore recorded with the multiplications made
/// so far, and replayed with them (they are what [`scalings`] reports).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Counted(pub f64);

thread_local! {
    static SCALINGS: std::cell::RefCell<Vec<(f64, f64)>> = const { std::cell::RefCell::new(Vec::new()) };
}

impl std::ops::Add for Counted {
    type Output = Self;
    fn add(self, other: Self) -> Self {
        Self(self.0 + other.0)
    }
}

impl std::ops::Sub for Counted {
    type Output = Self;
    fn sub(self, other: Self) -> Self {
        Self(self.0 - other.0)
    }
}

impl std::ops::Mul<f64> for Counted {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        SCALINGS.with(|all| all.borrow_mut().push((self.0, s)));
        Self(self.0 * s)
    }
}

impl transcript::Record for Counted {
    fn record(&self, out: &mut Vec<u8>) {
        self.0.record(out);
        SCALINGS.with(|all| all.borrow().record(out));
    }
}

impl transcript::Replay for Counted {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        let value = f64::replay(input)?;
        let scalings = Vec::<(f64, f64)>::replay(input)?;
        SCALINGS.with(|all| *all.borrow_mut() = scalings);
        Ok(Self(value))
    }
}

impl bezier::ControlPoint for Counted {
    const ZERO: Self = Self(0.0);
    fn is_finite_point(self) -> bool {
        self.0.is_finite()
    }
}

/// What `evaluate` returns, and the `(point, factor)` of every
/// multiplication of a [`Counted`] point it did, in order.
pub fn scalings<T>(evaluate: impl FnOnce() -> T) -> (T, Vec<(f64, f64)>) {
    SCALINGS.with(|all| all.borrow_mut().clear());
    let value = evaluate();
    (value, SCALINGS.with(|all| all.borrow_mut().split_off(0)))
}
