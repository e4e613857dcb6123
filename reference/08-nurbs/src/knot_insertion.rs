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

use glam::DVec4;

use freeform::{BezierPatch, RationalPatch};

use crate::knots::{KnotVector, NurbsError};
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
        // BEGIN SOLUTION knot_insertion: A5.1 on the homogeneous points, r rounds of αᵢ Pᵢ + (1 − αᵢ) Pᵢ₋₁
        let (knots, points) = insert(self.knots(), self.points(), u, times)?;
        NurbsCurve::try_new(knots, points)
        // END SOLUTION
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
        // BEGIN SOLUTION knot_insertion: insert into every column (a curve in u) of the net
        let net = self.net();
        let mut knots = self.knots_u().clone();
        let mut columns = Vec::with_capacity(net.columns());
        for j in 0..net.columns() {
            let column: Vec<DVec4> = (0..net.rows()).map(|i| net.get(i, j)).collect();
            let (new_knots, new_column) = insert(self.knots_u(), &column, u, times)?;
            knots = new_knots;
            columns.push(new_column);
        }
        let rows = knots.control_points();
        let points = (0..rows)
            .flat_map(|i| columns.iter().map(move |c| c[i]))
            .collect();
        let net = ControlNet::try_new(rows, net.columns(), points)?;
        NurbsSurface::try_new(knots, self.knots_v().clone(), net)
        // END SOLUTION
    }

    /// The same surface with `v` inserted `times` times into the knot vector
    /// along `v` (A5.1 applied to every row of the net): `times` more
    /// columns.
    ///
    /// Errors: as [`NurbsCurve::insert_knot`].
    #[transcript::task]
    pub fn insert_knot_v(&self, v: f64, times: usize) -> Result<NurbsSurface, NurbsError> {
        // BEGIN SOLUTION knot_insertion: insert into every row (a curve in v) of the net
        let net = self.net();
        let mut knots = self.knots_v().clone();
        let mut points = Vec::new();
        for i in 0..net.rows() {
            let (new_knots, new_row) = insert(self.knots_v(), net.row(i), v, times)?;
            knots = new_knots;
            points.extend(new_row);
        }
        let net = ControlNet::try_new(net.rows(), knots.control_points(), points)?;
        NurbsSurface::try_new(self.knots_u().clone(), knots, net)
        // END SOLUTION
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
        // BEGIN SOLUTION knot_insertion: raise every interior knot to multiplicity p (q), then cut the net into blocks
        if !self.knots_u().is_clamped() || !self.knots_v().is_clamped() {
            return Err(NurbsError::NotClamped);
        }
        let mut refined = self.clone();
        for b in self.knots_u().interior_breakpoints() {
            let missing = self.knots_u().degree() - b.multiplicity;
            refined = refined.insert_knot_u(b.value, missing)?;
        }
        for b in self.knots_v().interior_breakpoints() {
            let missing = self.knots_v().degree() - b.multiplicity;
            refined = refined.insert_knot_v(b.value, missing)?;
        }
        let (p, q) = (refined.knots_u().degree(), refined.knots_v().degree());
        let spans_u = refined.knots_u().interior_breakpoints().len() + 1;
        let spans_v = refined.knots_v().interior_breakpoints().len() + 1;
        let mut patches = Vec::with_capacity(spans_u * spans_v);
        for a in 0..spans_u {
            for b in 0..spans_v {
                let block: Vec<DVec4> = (0..=p)
                    .flat_map(|i| {
                        let row = refined.net().row(a * p + i);
                        row[b * q..=b * q + q].to_vec()
                    })
                    .collect();
                let points = BezierPatch::try_new(p, q, block.iter().map(|&pw| project(pw)).collect())?;
                patches.push(RationalPatch::try_new(points, block.iter().map(|pw| pw.w).collect())?);
            }
        }
        Ok(patches)
        // END SOLUTION
    }
}

// BEGIN SOLUTION
/// A5.1 `CurveKnotIns` on homogeneous points: the refined knot vector and
/// control points.
fn insert(
    knots: &KnotVector,
    points: &[DVec4],
    u: f64,
    times: usize,
) -> Result<(KnotVector, Vec<DVec4>), NurbsError> {
    let domain = knots.domain();
    if !(domain.start < u && u < domain.end) {
        return Err(NurbsError::OutOfDomain {
            value: u,
            start: domain.start,
            end: domain.end,
        });
    }
    let (p, k) = (knots.degree(), knots.knots());
    let s = knots.multiplicity(u);
    if s + times > p {
        return Err(NurbsError::MultiplicityTooHigh {
            value: u,
            multiplicity: s + times,
            degree: p,
        });
    }
    if times == 0 {
        return Ok((knots.clone(), points.to_vec()));
    }
    let r = times;
    // The span: u_k ≤ u < u_{k+1} (u is strictly inside the domain).
    let span = k.partition_point(|&x| x <= u) - 1;
    let mut new_knots = Vec::with_capacity(k.len() + r);
    new_knots.extend_from_slice(&k[..=span]);
    new_knots.extend(std::iter::repeat_n(u, r));
    new_knots.extend_from_slice(&k[span + 1..]);
    let n = points.len() - 1;
    let mut q = vec![DVec4::ZERO; n + 1 + r];
    // Unchanged at the start and (shifted by r) at the end.
    q[..=span - p].copy_from_slice(&points[..=span - p]);
    q[span - s + r..].copy_from_slice(&points[span - s..]);
    // The p − s + 1 points that change, refined r times in place.
    let mut rw: Vec<DVec4> = points[span - p..=span - s].to_vec();
    let mut last = span - p;
    for j in 1..=r {
        last = span - p + j;
        for i in 0..=p - j - s {
            let alpha = (u - k[last + i]) / (k[i + span + 1] - k[last + i]);
            rw[i] = rw[i + 1] * alpha + rw[i] * (1.0 - alpha);
        }
        q[last] = rw[0];
        q[span + r - j - s] = rw[p - j - s];
    }
    // The points between the two ends of the triangle.
    if last + 1 < span - s {
        q[last + 1..span - s].copy_from_slice(&rw[1..span - s - last]);
    }
    Ok((KnotVector::try_new(p, new_knots)?, q))
}
// END SOLUTION
