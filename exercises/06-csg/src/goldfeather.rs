//! Goldfeather's image-based CSG rendering with a depth and a stencil
//! buffer (seed 003, §4.3 "Paritätstest", §4.4 "Darstellung von
//! Produkten"; Goldfeather, Molnar, Turk and Fuchs 1989).
//!
//! A sum of products is drawn product by product. In a second framebuffer
//! each primitive `A` of a product draws the face through which the
//! product can be entered: its front face, or its back face if `A` is a
//! complement (the wall of a hole cut by `A`). Every *other* primitive `B`
//! of the product then decides which of those fragments survive, by the
//! **parity test**: count, with the stencil buffer, how many faces of `B`
//! lie in front of the fragment (z-less). For a convex `B` and a viewer
//! outside it:
//!
//! ```text
//!   viewer ──▶   (  B front   ·fragment·   B back  )      1 face in front:  inside B
//!   viewer ──▶   (  B front    B back )  ·fragment·       2 faces in front: outside B
//!   viewer ──▶   ·fragment·  ( B front    B back   )      0 faces in front: outside B
//! ```
//!
//! The parity (count mod 2) is one stencil bit, toggled by `Invert`.
//! Survivors are merged into the frame buffer with z-less; the nearest
//! surviving fragment over all primitives and products is the visible
//! surface of the solid.

use crate::csg::Model;
use crate::raster::{Framebuffer, Solid, State, Stats};

/// The state for drawing a literal's entry face into the second buffer:
/// the z-buffer algorithm, [`State::DEFAULT`].
pub const DRAW: State = State::DEFAULT;

/// Renders `model` into `frame` (merging with z-less into whatever it
/// holds) by the seed's algorithm:
///
/// ```text
///   for each product P:
///     for each literal A in P:
///       clear the second buffer (depth, surfaces, stencil)
///       draw A's entry face (front; back for a complement), depth Less
///       for each other literal B in P:
///         clear the stencil; draw B's front and back faces with depth
///         Less, no depth or colour writes, stencil op Invert on PARITY_BIT
///         erase (Framebuffer::draw_background, depth Always) the pixels
///         whose parity bit is not set — or is set, for a complement B
///       merge the second buffer into `frame` with z-less
/// ```
///
/// A product of `m` literals costs `m·(m − 1)` parity tests; the seed's
/// "n²" for `n` primitives. The seed's prose in §4.4 swaps the two erase
/// cases ("complement: erase 'outside'"); its pseudo-code, followed here,
/// is right. Its remark that `Y ∩ X` need not be drawn after `X ∩ Y` when
/// `Y` is not a complement is wrong too: the lens `X ∩ Y` of two spheres
/// shows both spheres' front faces — every literal draws its own pass.
///
/// Fragments exactly at the depth of a face of `B` count as outside `B`
/// (z-less); the tests avoid such coincident surfaces.
///
/// The model's primitives are any [`Solid`]s: axis-aligned primitives, or
/// primitives moved by the affine maps of a tree's nodes (seed §2.1),
/// which [`Framebuffer::draw`] draws alike.
#[transcript::task]
pub fn render<S: Solid>(model: &Model<S>, frame: &mut Framebuffer) -> Stats {
    // Unused until you write the body:
    let _ = (&model, &frame);
    todo!(
        "goldfeather: per literal, draw its entry face, parity-test it against every other literal, merge z-less"
    )
}
