//! The ground truth: a per-pixel ray caster that evaluates the CSG tree
//! on sets of intervals along each viewing ray (seed 003, §3.3 "Ray
//! Casting": "choose the point nearest to the viewer that is inside").
//!
//! Along a ray a convex primitive is one interval `[near, far]`; a tree is
//! a sorted list of disjoint intervals, combined bottom-up:
//!
//! ```text
//!   A      ────[=======]──────────────      ∪ : inside A or inside B
//!   B      ─────────[========]────────      ∩ : inside A and inside B
//!   A − B  ────[====]─────────────────      − : inside A and not inside B
//! ```
//!
//! Every interval end remembers the face it lies on, so the first entry
//! point is both the visible depth and the visible surface: for `A − B`
//! the entry may be `B`'s back face.
//!
//! This module is given: you use it (the tests compare with it), you do
//! not edit it.

use crate::csg::{Csg, Scene};
use crate::primitive::{Primitive, Ray, RayInterval};
use crate::raster::{Face, Framebuffer, Surface};

/// One end of an interval: a depth and the face it lies on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Boundary {
    /// The depth along the ray.
    pub t: f32,
    /// The face there.
    pub surface: Surface,
}

/// A piece of a ray inside the solid, `enter.t < exit.t`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Where the ray enters.
    pub enter: Boundary,
    /// Where it leaves.
    pub exit: Boundary,
}

/// Disjoint intervals sorted by depth: the part of a ray inside a solid.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IntervalSet {
    /// The intervals, nearest first.
    pub intervals: Vec<Interval>,
}

impl IntervalSet {
    /// Where `ray` runs through primitive `index`.
    #[must_use]
    pub fn of_primitive(index: usize, primitive: &Primitive, ray: &Ray) -> Self {
        Self::of_span(index, primitive.interval(ray))
    }

    /// The one interval `span` (if any) of primitive `index`, entered at
    /// its front face and left at its back face.
    #[must_use]
    pub fn of_span(index: usize, span: Option<RayInterval>) -> Self {
        let intervals = span
            .map(|span| Interval {
                enter: Boundary {
                    t: span.near,
                    surface: Surface {
                        primitive: index,
                        face: Face::Front,
                    },
                },
                exit: Boundary {
                    t: span.far,
                    surface: Surface {
                        primitive: index,
                        face: Face::Back,
                    },
                },
            })
            .into_iter()
            .collect();
        Self { intervals }
    }

    /// The set operation `inside(a, b)` on two sets, by a sweep over all
    /// interval ends in depth order. Pieces of length zero are dropped.
    #[must_use]
    pub fn combine(&self, other: &Self, inside: impl Fn(bool, bool) -> bool) -> Self {
        // (boundary, which set, entering?)
        let mut events: Vec<(Boundary, bool, bool)> = Vec::new();
        for (set, is_a) in [(self, true), (other, false)] {
            for iv in &set.intervals {
                events.push((iv.enter, is_a, true));
                events.push((iv.exit, is_a, false));
            }
        }
        events.sort_by(|x, y| x.0.t.total_cmp(&y.0.t));
        let (mut in_a, mut in_b) = (false, false);
        let mut start: Option<Boundary> = None;
        let mut out = Vec::new();
        for (boundary, is_a, entering) in events {
            if is_a {
                in_a = entering;
            } else {
                in_b = entering;
            }
            match (start, inside(in_a, in_b)) {
                (None, true) => start = Some(boundary),
                (Some(enter), false) => {
                    if enter.t < boundary.t {
                        out.push(Interval {
                            enter,
                            exit: boundary,
                        });
                    }
                    start = None;
                }
                _ => {}
            }
        }
        Self { intervals: out }
    }

    /// The first entry: the visible boundary of the solid.
    #[must_use]
    pub fn first(&self) -> Option<Boundary> {
        self.intervals.first().map(|iv| iv.enter)
    }
}

/// Evaluates `tree` along `ray`.
#[must_use]
pub fn intervals(tree: &Csg, primitives: &[Primitive], ray: &Ray) -> IntervalSet {
    intervals_by(tree, &|i| primitives.get(i).and_then(|p| p.interval(ray)))
}

/// Evaluates `tree` along a ray through whose leaf `i` it runs in
/// `span(i)` (`None`: it misses that leaf).
#[must_use]
pub fn intervals_by(tree: &Csg, span: &impl Fn(usize) -> Option<RayInterval>) -> IntervalSet {
    match tree {
        Csg::Primitive(i) => IntervalSet::of_span(*i, span(*i)),
        Csg::Union(x, y) => intervals_by(x, span).combine(&intervals_by(y, span), |a, b| a || b),
        Csg::Intersection(x, y) => {
            intervals_by(x, span).combine(&intervals_by(y, span), |a, b| a && b)
        }
        Csg::Difference(x, y) => {
            intervals_by(x, span).combine(&intervals_by(y, span), |a, b| a && !b)
        }
    }
}

/// Renders `scene` into `frame` by ray casting: at every pixel the first
/// entry point of the tree's intervals, depth and surface, where it is
/// nearer than what `frame` holds (z-less). The stencil is untouched.
pub fn raycast(scene: &Scene, frame: &mut Framebuffer) {
    let camera = *frame.camera();
    for p in camera.pixels() {
        let ray = camera.ray(p);
        if let Some(b) = intervals(scene.tree(), scene.primitives(), &ray).first()
            && b.t.is_finite()
        {
            frame.write_less(p, b.t, b.surface);
        }
    }
}
