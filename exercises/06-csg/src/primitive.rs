//! The convex primitives of a CSG model — cuboid, sphere, cylinder — as
//! analytic solids (seed 003, §2.2 "Klassifikation" and §4.1: Goldfeather's
//! algorithm needs convex primitives).
//!
//! A convex solid meets a line in one segment or not at all. Along a
//! viewing ray `o + t·d` that segment is the [`RayInterval`] `[near, far]`:
//! `near` is where the ray enters through a *front face*, `far` where it
//! leaves through a *back face*. Everything the renderers need from a
//! primitive is this span; it is exact, so "rasterizing" a primitive is
//! computing its span at each pixel's ray.
//!
//! This module is given: you use it, you do not edit it.

use glam::Vec3;

use crate::csg::CsgError;

/// Below this `|component|` a ray direction counts as parallel to an axis
/// or a slab; the slab test then checks the origin instead of dividing.
pub const PARALLEL_EPSILON: f32 = 1e-7;

/// The coordinate axis a cylinder is aligned with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The x axis.
    X,
    /// The y axis.
    Y,
    /// The z axis.
    Z,
}

impl Axis {
    /// The unit vector along the axis.
    #[must_use]
    pub fn unit(self) -> Vec3 {
        match self {
            Self::X => Vec3::X,
            Self::Y => Vec3::Y,
            Self::Z => Vec3::Z,
        }
    }
}

/// A convex, closed, bounded solid. Points on the surface belong to it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Primitive {
    /// The axis-aligned box `min ≤ p ≤ max` (componentwise).
    Cuboid {
        /// The corner with the smallest coordinates.
        min: Vec3,
        /// The corner with the largest coordinates.
        max: Vec3,
    },
    /// The ball `|p − centre| ≤ radius`.
    Sphere {
        /// The centre.
        centre: Vec3,
        /// The radius, `> 0`.
        radius: f32,
    },
    /// The capped cylinder around `centre + s·axis`, `|s| ≤ half_length`,
    /// with distance `≤ radius` from that axis.
    Cylinder {
        /// The midpoint of the axis segment.
        centre: Vec3,
        /// The direction of the axis.
        axis: Axis,
        /// The radius, `> 0`.
        radius: f32,
        /// Half the length of the axis segment, `> 0`.
        half_length: f32,
    },
}

/// An axis-aligned bounding box, `min ≤ p ≤ max` (closed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The corner with the smallest coordinates.
    pub min: Vec3,
    /// The corner with the largest coordinates.
    pub max: Vec3,
}

impl Aabb {
    /// Whether the two closed boxes share at least one point (touching
    /// faces count as sharing).
    #[must_use]
    pub fn intersects(&self, other: &Self) -> bool {
        self.min.cmple(other.max).all() && other.min.cmple(self.max).all()
    }

    /// The common part of two boxes, or `None` if they are disjoint.
    #[must_use]
    pub fn intersection(&self, other: &Self) -> Option<Self> {
        self.intersects(other).then(|| Self {
            min: self.min.max(other.min),
            max: self.max.min(other.max),
        })
    }
}

/// A viewing ray `o + t·d`; `t` is the depth, `d` has unit length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// The point at depth 0.
    pub origin: Vec3,
    /// The unit direction of view.
    pub direction: Vec3,
}

impl Ray {
    /// The point at depth `t`.
    #[must_use]
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.direction
    }
}

/// Where a ray runs through a convex primitive: it enters at depth `near`
/// (a front face) and leaves at depth `far` (a back face), `near < far`.
/// Both are finite for a unit direction: a slab the ray runs parallel to
/// gives the whole line, but some other slab (or the round side of a
/// cylinder) is crossed and bounds the interval.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayInterval {
    /// Depth of the front face.
    pub near: f32,
    /// Depth of the back face.
    pub far: f32,
}

impl RayInterval {
    /// The common part of two intervals, `None` when it is empty or a point.
    #[must_use]
    fn clip(self, other: Self) -> Option<Self> {
        let near = self.near.max(other.near);
        let far = self.far.min(other.far);
        (near < far).then_some(Self { near, far })
    }

    /// The whole line.
    const ALL: Self = Self {
        near: f32::NEG_INFINITY,
        far: f32::INFINITY,
    };
}

/// The span of the slab `lo ≤ x ≤ hi` along a 1-D ray `x = o + t·d`.
fn slab(o: f32, d: f32, lo: f32, hi: f32) -> Option<RayInterval> {
    if d.abs() < PARALLEL_EPSILON {
        // Parallel: all of the line or none of it.
        return (lo <= o && o <= hi).then_some(RayInterval::ALL);
    }
    let (t0, t1) = ((lo - o) / d, (hi - o) / d);
    let (near, far) = if t0 < t1 { (t0, t1) } else { (t1, t0) };
    (near < far).then_some(RayInterval { near, far })
}

impl Primitive {
    /// Checks that every number is finite, radii and lengths are positive
    /// and a cuboid's `min < max` in every coordinate.
    ///
    /// # Errors
    /// [`CsgError::InvalidPrimitive`] naming `index` and the reason.
    pub fn validate(&self, index: usize) -> Result<(), CsgError> {
        let fail = |reason: &str| {
            Err(CsgError::InvalidPrimitive {
                index,
                reason: reason.to_owned(),
            })
        };
        match *self {
            Self::Cuboid { min, max } => {
                if !min.is_finite() || !max.is_finite() {
                    return fail("a corner is not finite");
                }
                if !min.cmplt(max).all() {
                    return fail("min must be smaller than max in every coordinate");
                }
            }
            Self::Sphere { centre, radius } => {
                if !centre.is_finite() || !radius.is_finite() || radius <= 0.0 {
                    return fail("the centre must be finite and the radius finite and positive");
                }
            }
            Self::Cylinder {
                centre,
                radius,
                half_length,
                ..
            } => {
                if !centre.is_finite()
                    || !radius.is_finite()
                    || !half_length.is_finite()
                    || radius <= 0.0
                    || half_length <= 0.0
                {
                    return fail(
                        "the centre must be finite, radius and half length finite and positive",
                    );
                }
            }
        }
        Ok(())
    }

    /// The smallest axis-aligned box around the primitive.
    #[must_use]
    pub fn bounds(&self) -> Aabb {
        match *self {
            Self::Cuboid { min, max } => Aabb { min, max },
            Self::Sphere { centre, radius } => Aabb {
                min: centre - Vec3::splat(radius),
                max: centre + Vec3::splat(radius),
            },
            Self::Cylinder {
                centre,
                axis,
                radius,
                half_length,
            } => {
                let e = axis.unit();
                let extent = Vec3::splat(radius) * (Vec3::ONE - e) + half_length * e;
                Aabb {
                    min: centre - extent,
                    max: centre + extent,
                }
            }
        }
    }

    /// Where `ray` runs through the primitive, or `None` when it misses it
    /// or only grazes it (a span of length zero, at a silhouette).
    ///
    /// ```text
    ///   sphere:    |o + t·d − c|² = r²   ⇒  t = −b ± √(b² − q),
    ///              b = (o − c)·d,  q = |o − c|² − r²
    ///   cuboid:    three slabs  min.i ≤ o.i + t·d.i ≤ max.i, intersected
    ///   cylinder:  the infinite cylinder (a quadratic in the components
    ///              across the axis) intersected with the slab along it
    /// ```
    #[must_use]
    pub fn interval(&self, ray: &Ray) -> Option<RayInterval> {
        let (o, d) = (ray.origin, ray.direction);
        match *self {
            Self::Cuboid { min, max } => slab(o.x, d.x, min.x, max.x)?
                .clip(slab(o.y, d.y, min.y, max.y)?)?
                .clip(slab(o.z, d.z, min.z, max.z)?),
            Self::Sphere { centre, radius } => {
                let oc = o - centre;
                let b = oc.dot(d);
                let q = oc.length_squared() - radius * radius;
                let discriminant = b * b - q;
                if discriminant <= 0.0 {
                    return None;
                }
                let root = discriminant.sqrt();
                Some(RayInterval {
                    near: -b - root,
                    far: -b + root,
                })
            }
            Self::Cylinder {
                centre,
                axis,
                radius,
                half_length,
            } => {
                let e = axis.unit();
                let oc = o - centre;
                // Components across the axis: |o' + t·d'|² = r².
                let o_across = oc - oc.dot(e) * e;
                let d_across = d - d.dot(e) * e;
                let a = d_across.length_squared();
                let tube = if a < PARALLEL_EPSILON * PARALLEL_EPSILON {
                    (o_across.length_squared() <= radius * radius).then_some(RayInterval::ALL)?
                } else {
                    let b = o_across.dot(d_across);
                    let c = o_across.length_squared() - radius * radius;
                    let discriminant = b * b - a * c;
                    if discriminant <= 0.0 {
                        return None;
                    }
                    let root = discriminant.sqrt();
                    RayInterval {
                        near: (-b - root) / a,
                        far: (-b + root) / a,
                    }
                };
                tube.clip(slab(oc.dot(e), d.dot(e), -half_length, half_length)?)
            }
        }
    }

    /// The outward unit normal at a surface point `p` (for shading). At
    /// edges and corners one of the adjacent faces' normals is returned.
    #[must_use]
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        match *self {
            Self::Cuboid { min, max } => {
                let half = 0.5 * (max - min);
                let q = (p - 0.5 * (min + max)) / half;
                let a = q.abs();
                if a.x >= a.y && a.x >= a.z {
                    Vec3::X * q.x.signum()
                } else if a.y >= a.z {
                    Vec3::Y * q.y.signum()
                } else {
                    Vec3::Z * q.z.signum()
                }
            }
            Self::Sphere { centre, .. } => (p - centre).normalize_or(Vec3::Z),
            Self::Cylinder {
                centre,
                axis,
                radius,
                half_length,
            } => {
                let e = axis.unit();
                let along = (p - centre).dot(e);
                let across = (p - centre) - along * e;
                if along.abs() / half_length > across.length() / radius {
                    e * along.signum()
                } else {
                    across.normalize_or(Vec3::Z)
                }
            }
        }
    }
}
