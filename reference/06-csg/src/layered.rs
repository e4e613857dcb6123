//! Layered Goldfeather: depth complexity counted in the stencil buffer,
//! layer extraction, one parity test per layer and primitive (seed 003,
//! §6 "Layered Goldfeather"; Stewart, Leach and John 1998).
//!
//! Plain Goldfeather tests every literal's fragments against every other
//! literal: `m·(m − 1)` parity tests for a product of `m` literals. But a
//! pixel is covered by only a few of their faces — the *depth
//! complexity* `k`, often far below `m`. Layered Goldfeather draws all
//! entry faces at once and peels them into `k` layers, the n-th layer
//! holding at each pixel the n-th fragment drawn there:
//!
//! ```text
//!   pixel column:   A front  C back  B front        (drawn in this order)
//!   layer 1:        A front
//!   layer 2:                 C back
//!   layer 3:                         B front
//! ```
//!
//! Each layer is parity-tested once against each literal: `k·m` tests.

use crate::csg::{Model, Product};
use crate::raster::{Framebuffer, Solid, Stats};
// BEGIN SOLUTION
use crate::csg::Literal;
use crate::raster::{Compare, Face, PARITY_BIT, State, StencilState, StencilOp, Surface};
// END SOLUTION

/// Counts, in `buffer`'s stencil plane, how many entry faces of
/// `product`'s literals (front faces of primitives, back faces of
/// complements) cover each pixel, and returns the largest count: the
/// product's depth complexity `k` (seed §6.2).
///
/// `buffer` is cleared first. Draw every entry face with the depth test
/// `Always`, depth and colour writes off, and the stencil operation
/// `Increment`. Drawing one face per primitive is the seed's "culling one
/// side": with both faces every count would be twice as large. Products
/// have at most `MAX_LITERALS` = 254 literals, so a count never saturates.
/// Literals naming a primitive `model` does not have are skipped.
#[transcript::task]
pub fn depth_complexity<S: Solid>(
    model: &Model<S>,
    product: &Product,
    buffer: &mut Framebuffer,
) -> u8 {
    // BEGIN SOLUTION layered: draw every entry face with stencil op Increment and no other writes; return the largest count
    buffer.clear();
    let count = State {
        depth_func: Compare::Always,
        depth_write: false,
        colour_write: false,
        stencil: StencilState {
            depth_pass: StencilOp::Incr,
            ..StencilState::DEFAULT
        },
    };
    draw_entry_faces(model, product, buffer, &count);
    buffer.max_stencil()
    // END SOLUTION
}

/// Renders `model` into `frame` (merging with z-less) by layered
/// Goldfeather:
///
/// ```text
///   for each product P:
///     k = depth_complexity(P)
///     for n in 1..=k:                                   (layer extraction)
///       clear the second buffer
///       draw every entry face of P, in a fixed order, with depth Always,
///       depth and colour writes on, stencil func Equal to n − 1 and op
///       Increment whether the test passes or fails: the fragment that
///       finds the count at n − 1 is the n-th one and the only one written
///       for each literal A in P:                        (parity tests)
///         clear the stencil; draw A's front and back faces with depth
///         LessEqual, no writes, op Invert on PARITY_BIT
///         erase the pixels whose parity bit is not set — or is set, for
///         a complement A
///       merge the second buffer into `frame` with z-less
/// ```
///
/// `LessEqual` instead of plain Goldfeather's `Less` is the seed's §6.4:
/// a layer holds fragments of `A` itself, which must count as inside
/// `A` — a front fragment of `A` sees `A`'s front face at equal depth
/// (parity 1: inside); a back fragment of a complement `A` sees both
/// faces (parity 0: outside `A`, so kept). Counts: `k` layers and `k·m`
/// parity tests per product of `m` literals.
///
/// The seed reserves one of the 8 stencil bits for the parity during the
/// extraction (at most 2⁷ = 128 layers); here the stencil is cleared
/// between extraction and parity tests, so the count may use all 8 bits.
///
/// Like plain Goldfeather, it draws any [`Solid`]s: primitives moved by
/// the affine maps of a tree's nodes as well.
#[transcript::task]
pub fn render<S: Solid>(model: &Model<S>, frame: &mut Framebuffer) -> Stats {
    // BEGIN SOLUTION layered: count k, extract each layer by stencil Equal n − 1 with Increment, test it against every literal, merge
    let mut stats = Stats::default();
    let mut second = Framebuffer::new(*frame.camera());
    let extract = |n: u8| State {
        depth_func: Compare::Always,
        depth_write: true,
        colour_write: true,
        stencil: StencilState {
            func: Compare::Equal,
            reference: n - 1,
            stencil_fail: StencilOp::Incr,
            depth_pass: StencilOp::Incr,
            ..StencilState::DEFAULT
        },
    };
    for product in model.products() {
        let k = depth_complexity(model, product, &mut second);
        for n in 1..=k {
            second.clear();
            draw_entry_faces(model, product, &mut second, &extract(n));
            stats.layers += 1;
            for &a in &product.literals {
                second.clear_stencil(0);
                parity_test(model, a, &mut second);
                stats.parity_tests += 1;
                erase_outside(&mut second, a);
            }
            frame.merge_less(&second);
        }
    }
    stats
    // END SOLUTION
}

// BEGIN SOLUTION
/// Draws the entry face of every literal, in product order.
fn draw_entry_faces<S: Solid>(
    model: &Model<S>,
    product: &Product,
    buffer: &mut Framebuffer,
    state: &State,
) {
    for l in &product.literals {
        if let Some(primitive) = model.primitives().get(l.primitive) {
            let surface = Surface {
                primitive: l.primitive,
                face: l.entry_face(),
            };
            buffer.draw(primitive, surface, state);
        }
    }
}

/// Toggles the parity bit wherever a face of `a`'s primitive lies in front
/// of or at the stored depth.
fn parity_test<S: Solid>(model: &Model<S>, a: Literal, buffer: &mut Framebuffer) {
    let state = State {
        depth_func: Compare::LEqual,
        depth_write: false,
        colour_write: false,
        stencil: StencilState {
            write_mask: PARITY_BIT,
            depth_pass: StencilOp::Invert,
            ..StencilState::DEFAULT
        },
    };
    let primitive = &model.primitives()[a.primitive];
    for face in [Face::Front, Face::Back] {
        let surface = Surface {
            primitive: a.primitive,
            face,
        };
        buffer.draw(primitive, surface, &state);
    }
}

/// Erases the fragments on the wrong side of `a`.
fn erase_outside(buffer: &mut Framebuffer, a: Literal) {
    let state = State {
        depth_func: Compare::Always,
        depth_write: true,
        colour_write: true,
        stencil: StencilState {
            func: if a.complement {
                Compare::NotEqual
            } else {
                Compare::Equal
            },
            reference: 0,
            value_mask: PARITY_BIT,
            ..StencilState::DEFAULT
        },
    };
    buffer.draw_background(&state);
}
// END SOLUTION
