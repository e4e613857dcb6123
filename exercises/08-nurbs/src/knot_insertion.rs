//! Knot insertion (Boehm's algorithm) and the decomposition of a NURBS
//! surface into rational Bézier patches, after The NURBS Book (Piegl &
//! Tiller), §5.2 and §5.4: A5.1 `CurveKnotIns` and the idea of A5.7
//! `DecomposeSurface`; seed 001 (NURBS tessellation thesis), §2.1, names
//! the decomposition as the first step of every tessellation ("NURBS
//! plohe … podijeljena u skup Bézierovih ploha").
//!
//! **Insertion.** Inserting `ū ∈ [u_k, u_{k+1})`, already of multiplicity
//! `s`, `r` times (`s + r ≤ p`) changes only the control points
//! `P_{k−p+1} … P_{k−s}`; round `j = 1 … r` replaces them by
//!
//! ```text
//!   Qᵢ = αᵢ Pᵢ + (1 − αᵢ) P_{i−1},   αᵢ = (ū − uᵢ) / (u_{i+p−j+1} − uᵢ)
//! ```
//!
//! on the homogeneous `Pʷ` (The NURBS Book (5.15), A5.1): the curve, as a
//! function of `u`, does not change; only its description does.
//!
//! **Decomposition.** Raise every interior knot of a *clamped* vector to
//! multiplicity `p`: then span `[u_k, u_{k+1})` is described by exactly
//! `p + 1` consecutive control points, which are its Bézier points. For a
//! surface, do it along `u` for every column of the net (each column is a
//! NURBS curve in `u`) and along `v` for every row. Departure from A5.7,
//! which computes the patches strip by strip in one pass without the
//! refined net: this is the same arithmetic, spelled as repeated A5.1.
//!
//! The span search this needs is a private helper of this file (tasks
//! are graded on their own).
//!
//! ```text
//!   U = 0 0 0 0 ½ 1 1 1 1   (p = 3)  ──insert ½ twice──▶  0 0 0 0 ½ ½ ½ 1 1 1 1
//!   7 control points = 2 cubic Bézier pieces sharing P₃
//! ```

#[allow(unused_imports)]
use glam::DVec4;

#[allow(unused_imports)]
use freeform::{BezierPatch, RationalPatch};

#[allow(unused_imports)]
use crate::knots::{KnotVector, NurbsError};
#[allow(unused_imports)]
use crate::net::{ControlNet, NurbsCurve, NurbsSurface, project};

impl NurbsCurve {
    /// The same curve with `u` inserted `times` times into its knot vector
    /// (Boehm's algorithm, The NURBS Book A5.1): `times` more control
    /// points, the same point `C(t)` for every `t`.
    ///
    /// `times = 0` returns a copy.
    ///
    /// Errors: `u` not strictly inside the domain, or NaN
    /// ([`NurbsError::OutOfDomain`]; inserting at an end of the domain is
    /// not supported); `u`'s multiplicity would exceed the degree
    /// ([`NurbsError::MultiplicityTooHigh`]).
    #[transcript::task]
    pub fn insert_knot(&self, u: f64, times: usize) -> Result<NurbsCurve, NurbsError> {
        // Unused until you write the body:
        let _ = (&u, &times);
        todo!("knot_insertion: A5.1 on the homogeneous points, r rounds of αᵢ Pᵢ + (1 − αᵢ) Pᵢ₋₁")
    }
}

impl NurbsSurface {
    /// The same surface with `u` inserted `times` times into the knot vector
    /// along `u` (A5.1 applied to every column of the net, each a curve in
    /// `u`): `times` more rows.
    ///
    /// Errors: as [`NurbsCurve::insert_knot`].
    #[transcript::task]
    pub fn insert_knot_u(&self, u: f64, times: usize) -> Result<NurbsSurface, NurbsError> {
        // Unused until you write the body:
        let _ = (&u, &times);
        todo!("knot_insertion: insert into every column (a curve in u) of the net")
    }

    /// The same surface with `v` inserted `times` times into the knot vector
    /// along `v` (A5.1 applied to every row of the net): `times` more
    /// columns.
    ///
    /// Errors: as [`NurbsCurve::insert_knot`].
    #[transcript::task]
    pub fn insert_knot_v(&self, v: f64, times: usize) -> Result<NurbsSurface, NurbsError> {
        // Unused until you write the body:
        let _ = (&v, &times);
        todo!("knot_insertion: insert into every row (a curve in v) of the net")
    }

    /// The rational Bézier patches of a surface with clamped knot vectors,
    /// as the course library's [`RationalPatch`] (the type topics 09 and 10
    /// take), one per non-empty span pair, ordered by `u` span, then `v`
    /// span (row-major); patch `(a, b)` has `(p + 1) × (q + 1)` control
    /// points and weights and reproduces the piece
    /// `[u_a, u_{a+1}] × [v_b, v_{b+1}]` of the surface (between the
    /// distinct knots) over `[0, 1]²`: `patch(s, t) = S(u_a + s·(u_{a+1} −
    /// u_a), v_b + t·(v_{b+1} − v_b))`.
    ///
    /// Every interior knot is raised to multiplicity `p` (along `u`) and `q`
    /// (along `v`) by insertion; then the patches are the overlapping
    /// `(p + 1) × (q + 1)` blocks of the refined net, starting at rows
    /// `a·p` and columns `b·q`, each homogeneous point `Pʷ = (w·P, w)`
    /// handed over as its point `P` and weight `w`.
    ///
    /// Errors: an unclamped knot vector ([`NurbsError::NotClamped`]); a
    /// degree above the library's `freeform::patch::MAX_DEGREE`
    /// ([`NurbsError::Patch`]).
    #[transcript::task]
    pub fn decompose(&self) -> Result<Vec<RationalPatch>, NurbsError> {
        todo!(
            "knot_insertion: raise every interior knot to multiplicity p (q), then cut the net into blocks"
        )
    }
}
