//! The seed's trim regions (seed 000 §4.3): regions of the parameter
//! square bounded by two Bézier curves with common ends, an upper and a
//! lower one, in the order the seed's `NewtonTrim` takes their control
//! points. Data only: deciding whether a point lies inside is topic 07's
//! task (by Newton's method and by ray parity).
//!
//! ```text
//!    v ↑        P1 ·      · P2             (the cubic region)
//!      │       ╱‾‾‾‾‾‾‾‾‾‾‾‾‾‾╲            upper curve P0 P1 P2 P3
//!      │  P0 ·                  · P3
//!      │       ╲______________╱            lower curve P0 P4 P5 P3
//!      │          P4 ·      · P5
//!      └──────────────────────────→ u
//! ```

use glam::DVec2;

/// The region between two quadratic curves of Fig. 11: the upper curve
/// `P0 P1 P2`, the lower `P0 P3 P2`; ends `(0.2, 0.5)` and `(0.8, 0.5)`,
/// so that
///
/// ```text
///   v_upper(t) = 0.5 + 0.8 t (1 − t),   v_lower(t) = 0.5 − 0.8 t (1 − t)
/// ```
///
/// along `u = 0.2 + 0.6 t`.
pub const QUADRATIC_REGION: [DVec2; 4] = [
    DVec2::new(0.2, 0.5),
    DVec2::new(0.5, 0.9),
    DVec2::new(0.8, 0.5),
    DVec2::new(0.5, 0.1),
];

/// The region between two cubic curves of Fig. 24 (Listing 9): the upper
/// curve `P0 P1 P2 P3`, the lower `P0 P4 P5 P3` (from left to right, not
/// clockwise as §4.3 says); ends `(0.1, 0.5)` and `(0.9, 0.5)`, the inner
/// control points at thirds of the way in `u`, so that `u = 0.1 + 0.8 t`
/// is linear along both curves.
pub const CUBIC_REGION: [DVec2; 6] = [
    DVec2::new(0.1, 0.5),
    DVec2::new(0.1 + 0.8 / 3.0, 0.95),
    DVec2::new(0.1 + 1.6 / 3.0, 0.75),
    DVec2::new(0.9, 0.5),
    DVec2::new(0.1 + 0.8 / 3.0, 0.2),
    DVec2::new(0.1 + 1.6 / 3.0, 0.05),
];

/// The region kept inside [`QUADRATIC_REGION`] in the seed's nested trim
/// (Fig. 12, Listing 12): ends `(0.35, 0.5)` and `(0.65, 0.5)`, controls
/// `(0.5, 0.7)` and `(0.5, 0.3)`, so that `|v − 0.5| < 0.4 t (1 − t)`
/// along `u = 0.35 + 0.3 t`.
pub const INNER_REGION: [DVec2; 4] = [
    DVec2::new(0.35, 0.5),
    DVec2::new(0.5, 0.7),
    DVec2::new(0.65, 0.5),
    DVec2::new(0.5, 0.3),
];
