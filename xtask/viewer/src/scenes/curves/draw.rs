//! What the curve scene draws: your curve, its construction, and the
//! definition's curve.

use glam::DVec2;
use testkit::oracles;

use crate::stages::{Stages, Status, guarded};
use crate::worker::Worker;

/// The most control points the scene offers (degree 7).
pub const MAX_POINTS: usize = 8;
/// The fewest: a line.
pub const MIN_POINTS: usize = 2;
/// The curve is drawn through this many steps of `t`.
pub const SAMPLES: usize = 128;

/// Which curve the control points make.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CurveKind {
    /// A Bézier curve (topic 07).
    Bezier,
    /// A NURBS curve over the clamped uniform knot vector (topic 08).
    Nurbs,
}

/// The lightest and heaviest weight the scene offers.
pub const WEIGHTS: std::ops::RangeInclusive<f64> = 0.05..=20.0;

/// What to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveSetup {
    /// The control points, `MIN_POINTS ..= MAX_POINTS` of them.
    pub points: Vec<DVec2>,
    /// Where the construction is shown, in `[0, 1]`.
    pub t: f64,
    /// Bézier or NURBS.
    pub kind: CurveKind,
    /// The NURBS curve's degree, `1 ..= points − 1`.
    pub degree: usize,
    /// The NURBS curve's weights, one per control point.
    pub weights: Vec<f64>,
}

impl Default for CurveSetup {
    /// The seed's Abbildung 6: a cubic with four control points, `t = ½`.
    fn default() -> Self {
        Self {
            points: first_points(4),
            t: 0.5,
            kind: CurveKind::Bezier,
            degree: 3,
            weights: vec![1.0; 4],
        }
    }
}

/// `n` control points spread over the square in an arch, to start from.
#[must_use]
pub fn first_points(n: usize) -> Vec<DVec2> {
    let n = n.clamp(MIN_POINTS, MAX_POINTS);
    (0..n)
        .map(|i| {
            let s = i as f64 / (n - 1) as f64;
            let height = if i == 0 || i == n - 1 {
                0.15
            } else {
                0.85 - 0.1 * (i % 2) as f64
            };
            DVec2::new(0.1 + 0.8 * s, height)
        })
        .collect()
}

impl CurveSetup {
    /// Keeps the set-up drawable: the count of points in range (new ones
    /// continue the last), every point and `t` within the unit square.
    pub fn tidy(&mut self) {
        self.points.truncate(MAX_POINTS);
        while self.points.len() < MIN_POINTS {
            let last = self.points.last().copied().unwrap_or(DVec2::splat(0.1));
            self.points
                .push((last + DVec2::new(0.2, 0.3)).min(DVec2::splat(0.9)));
        }
        for p in &mut self.points {
            *p = p.clamp(DVec2::ZERO, DVec2::ONE);
            if !p.is_finite() {
                *p = DVec2::splat(0.5);
            }
        }
        self.t = if self.t.is_finite() {
            self.t.clamp(0.0, 1.0)
        } else {
            0.5
        };
        self.degree = self.degree.clamp(1, self.points.len() - 1);
        self.weights.resize(self.points.len(), 1.0);
        for w in &mut self.weights {
            *w = if w.is_finite() {
                w.clamp(*WEIGHTS.start(), *WEIGHTS.end())
            } else {
                1.0
            };
        }
    }

    /// The clamped uniform knot vector of the NURBS curve (topic 08's
    /// `KnotVector::clamped_uniform`): `p + 1` zeros, the interior knots
    /// `1/k … (k − 1)/k` with `k = points − p`, `p + 1` ones.
    #[must_use]
    pub fn knots(&self) -> Vec<f64> {
        let p = self.degree;
        let spans = self.points.len().saturating_sub(p).max(1);
        let mut knots = vec![0.0; p + 1];
        knots.extend((1..spans).map(|i| i as f64 / spans as f64));
        knots.extend(std::iter::repeat_n(1.0, p + 1));
        knots
    }

    /// Makes it `n` control points: keeps the first ones, adds new ones
    /// between the last and the corner.
    pub fn set_count(&mut self, n: usize) {
        let n = n.clamp(MIN_POINTS, MAX_POINTS);
        if n < self.points.len() {
            self.points.truncate(n);
        }
        while self.points.len() < n {
            let k = self.points.len();
            let last = self.points[k - 1];
            let towards = if k.is_multiple_of(2) {
                DVec2::new(0.9, 0.15)
            } else {
                DVec2::new(0.9, 0.85)
            };
            self.points.push(last.lerp(towards, 0.5));
        }
    }
}

/// What the scene shows.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveDrawing {
    /// What was drawn.
    pub setup: CurveSetup,
    /// Your curve at `t = k / SAMPLES`, as far as your code got.
    pub yours: Vec<DVec2>,
    /// The construction at `setup.t`: level 0 the control points, level
    /// `k` the `n − k` points `b_i^k(t)`, the last level `C(t)` alone; as
    /// far as your code got.
    pub levels: Vec<Vec<DVec2>>,
    /// The definition's curve at the same parameters.
    pub expected: Vec<DVec2>,
    /// The largest distance between your curve and the definition's, when
    /// your code drew all of it.
    pub deviation: Option<f64>,
    /// The NURBS curve's points at its interior knots, as far as your code
    /// got.
    pub knot_points: Vec<DVec2>,
    /// How your `de_casteljau` fared.
    pub status: Status,
}

/// The worker that draws curves.
pub type CurveWorker = Worker<CurveSetup, CurveDrawing>;

/// A worker drawing with `stages`.
#[must_use]
pub fn worker(stages: Stages) -> CurveWorker {
    Worker::start(move |setup: CurveSetup| draw(&setup, &stages))
}

/// The curve of the definition at `t`: `Σ B_i^n(t) P_i`.
#[must_use]
pub fn definition(points: &[DVec2], t: f64) -> DVec2 {
    let n = points.len().saturating_sub(1);
    points
        .iter()
        .enumerate()
        .map(|(i, &p)| oracles::bernstein(i, n, t) * p)
        .sum()
}

/// The NURBS curve of the definition at `u`: `Σ N_{i,p}(u) Pᵢʷ`, projected.
#[must_use]
pub fn nurbs_definition(setup: &CurveSetup, u: f64) -> DVec2 {
    let homogeneous: Vec<glam::DVec4> = setup
        .points
        .iter()
        .zip(&setup.weights)
        .map(|(p, &w)| (p.extend(0.0) * w).extend(w))
        .collect();
    oracles::nurbs_curve(&setup.knots(), setup.degree, &homogeneous, u).truncate()
}

/// Draws `setup` with your code.
#[must_use]
pub fn draw(setup: &CurveSetup, stages: &Stages) -> CurveDrawing {
    let mut setup = setup.clone();
    setup.tidy();
    match setup.kind {
        CurveKind::Bezier => draw_bezier(&setup, stages),
        CurveKind::Nurbs => draw_nurbs(&setup, stages),
    }
}

/// The NURBS curve by your `NurbsCurve::point`, with its knots' points.
fn draw_nurbs(setup: &CurveSetup, stages: &Stages) -> CurveDrawing {
    let parameters = (0..=SAMPLES).map(|k| k as f64 / SAMPLES as f64);
    let mut drawing = CurveDrawing {
        setup: setup.clone(),
        yours: Vec::new(),
        levels: vec![setup.points.clone()],
        expected: parameters
            .clone()
            .map(|u| nurbs_definition(setup, u))
            .collect(),
        deviation: None,
        knot_points: Vec::new(),
        status: Status::Missing,
    };
    let Some(run) = &stages.nurbs.run else {
        return drawing;
    };
    let mut status = Status::Unused;
    let mut evaluate = |u: f64| match guarded(&mut status, || {
        run(&setup.points, &setup.weights, setup.degree, u)
    })? {
        Ok(p) => Some(p),
        Err(error) => {
            status = Status::Failed(error);
            None
        }
    };
    for u in parameters {
        match evaluate(u) {
            Some(p) => drawing.yours.push(p),
            None => break,
        }
    }
    let knots = setup.knots();
    let interior = &knots[setup.degree + 1..knots.len() - setup.degree - 1];
    for &u in interior {
        match evaluate(u) {
            Some(p) => drawing.knot_points.push(p),
            None => break,
        }
    }
    drawing.deviation = deviation(&drawing.yours, &drawing.expected);
    drawing.status = status;
    drawing
}

/// The largest distance between the two curves, when yours is whole.
fn deviation(yours: &[DVec2], expected: &[DVec2]) -> Option<f64> {
    if yours.len() != expected.len() {
        return None;
    }
    yours
        .iter()
        .zip(expected)
        .map(|(a, b)| a.distance(*b))
        .reduce(f64::max)
}

/// The Bézier curve by your `de_casteljau`, with its construction at `t`.
fn draw_bezier(setup: &CurveSetup, stages: &Stages) -> CurveDrawing {
    let parameters = (0..=SAMPLES).map(|k| k as f64 / SAMPLES as f64);
    let expected: Vec<DVec2> = parameters
        .clone()
        .map(|t| definition(&setup.points, t))
        .collect();
    let mut drawing = CurveDrawing {
        setup: setup.clone(),
        yours: Vec::new(),
        levels: vec![setup.points.clone()],
        expected,
        deviation: None,
        knot_points: Vec::new(),
        status: Status::Missing,
    };
    let Some(run) = &stages.curve.run else {
        return drawing;
    };
    let mut status = Status::Unused;
    let evaluate =
        |status: &mut Status, points: &[DVec2], t: f64| match guarded(status, || run(points, t))? {
            Ok(p) => Some(p),
            Err(error) => {
                *status = Status::Failed(error);
                None
            }
        };
    for t in parameters {
        match evaluate(&mut status, &setup.points, t) {
            Some(p) => drawing.yours.push(p),
            None => break,
        }
    }
    let n = setup.points.len();
    'levels: for k in 1..n {
        let mut level = Vec::with_capacity(n - k);
        for i in 0..n - k {
            match evaluate(&mut status, &setup.points[i..=i + k], setup.t) {
                Some(p) => level.push(p),
                None => break 'levels,
            }
        }
        drawing.levels.push(level);
    }
    drawing.deviation = deviation(&drawing.yours, &drawing.expected);
    drawing.status = status;
    drawing
}
