//! Task 7 (bonus): the triangle in lanes over its bounding box — task 5's
//! fragments (pixels, exact edge weights, depth and colour), found a batch
//! of eight pixels at a time, checked against the definition in
//! `tests/common` (not against your task 5).

mod common;

use std::cell::RefCell;

use canvas::{Fragment, Pixel, Rgba, Vec2, Vertex, Viewport};
use common::triangles::{self, WIDE};
use common::{snap, triangle_covers};
use fill::vectorised::{Batch, EdgeWeights, LANES, SUBPIXEL_BITS, fill_triangle_vectorised};
use proptest::prelude::*;

/// Depth and colour must match the definition's barycentric mix to this
/// tolerance (f32 arithmetic on values of order 1).
const MIX_TOLERANCE: f32 = 1e-4;

fn vertex(position: Vec2, depth: f32, colour: Rgba) -> Vertex {
    Vertex::new(position, depth, colour)
}

/// A triangle with distinct depths and colours at its corners.
fn coloured(positions: [Vec2; 3]) -> [Vertex; 3] {
    [
        vertex(positions[0], 0.1, Rgba::RED),
        vertex(positions[1], 0.5, Rgba::GREEN),
        vertex(positions[2], 0.9, Rgba::BLUE),
    ]
}

/// The sheet's exact edge weights at `pixel` and `|D|`, twice the
/// snapped area; `None` where a vertex does not snap.
fn definition_weights(vertices: [Vertex; 3], pixel: Pixel) -> Option<(EdgeWeights, i128)> {
    let mut p = [[0_i64; 2]; 3];
    for (k, v) in vertices.iter().enumerate() {
        p[k] = [snap(v.position.x)?, snap(v.position.y)?];
    }
    let orient = |a: [i64; 2], b: [i64; 2], c: [i64; 2]| {
        i128::from(b[0] - a[0]) * i128::from(c[1] - a[1])
            - i128::from(b[1] - a[1]) * i128::from(c[0] - a[0])
    };
    let one = 1_i64 << SUBPIXEL_BITS;
    let centre = [i64::from(pixel.x) * one, i64::from(pixel.y) * one];
    let area = orient(p[0], p[1], p[2]);
    let weights =
        std::array::from_fn(|k| area.signum() * orient(p[(k + 1) % 3], p[(k + 2) % 3], centre));
    Some((weights, area.abs()))
}

/// The clipped bounding box of the snapped vertices, in pixels (columns,
/// rows), as task 5 walks it; `None` when it is empty or the triangle
/// draws nothing.
fn clipped_box(vertices: [Vertex; 3], viewport: Viewport) -> Option<([i64; 2], [i64; 2])> {
    let mut p = [[0_i64; 2]; 3];
    for (k, v) in vertices.iter().enumerate() {
        p[k] = [snap(v.position.x)?, snap(v.position.y)?];
    }
    let area = i128::from(p[1][0] - p[0][0]) * i128::from(p[2][1] - p[0][1])
        - i128::from(p[1][1] - p[0][1]) * i128::from(p[2][0] - p[0][0]);
    if area == 0 || viewport.is_empty() {
        return None;
    }
    let one = 1_i64 << SUBPIXEL_BITS;
    let range = |k: usize, min: i32, max: i32| {
        let lo = p.iter().map(|q| q[k]).min().unwrap_or(0);
        let hi = p.iter().map(|q| q[k]).max().unwrap_or(0);
        let first = (-(-lo).div_euclid(one)).max(i64::from(min));
        let last = hi.div_euclid(one).min(i64::from(max));
        [first, last]
    };
    let (x, y) = (
        range(0, viewport.x_min, viewport.x_max),
        range(1, viewport.y_min, viewport.y_max),
    );
    (x[0] <= x[1] && y[0] <= y[1]).then_some((x, y))
}

/// What `fill_triangle_vectorised` reports, in order.
enum Event {
    Batch(Box<Batch>),
    Plot(Fragment, EdgeWeights),
}

/// The fragments of `fill_triangle_vectorised`, after checking the batches
/// it reported (see [`check_batches`]) and the exact weights of every
/// fragment: every test grades the lanes, not only the pixels.
#[track_caller]
fn fragments(vertices: [Vertex; 3], viewport: Viewport) -> Vec<Fragment> {
    let events: RefCell<Vec<Event>> = RefCell::default();
    fill_triangle_vectorised(
        vertices,
        viewport,
        |batch| events.borrow_mut().push(Event::Batch(Box::new(*batch))),
        |fragment, weights| events.borrow_mut().push(Event::Plot(fragment, weights)),
    );
    check_batches(vertices, viewport, &events.into_inner())
}

/// The batches tile the clipped box row by row, bottom to top, each row
/// from its left end in batches of [`LANES`] (fewer only at the right end);
/// every lane is checked (see [`check_lane`]); after each batch come
/// exactly its covered lanes' fragments, in lane order, with their lane's
/// depth and colour and the exact edge weights.
#[track_caller]
fn check_batches(vertices: [Vertex; 3], viewport: Viewport, events: &[Event]) -> Vec<Fragment> {
    let call = format!(
        "fill_triangle_vectorised({:?}, {viewport:?})",
        vertices.map(|v| v.position)
    );
    // The tiling the sheet prescribes.
    let mut tiling = Vec::new();
    if let Some((xs, ys)) = clipped_box(vertices, viewport) {
        for y in ys[0]..=ys[1] {
            let mut x = xs[0];
            while x <= xs[1] {
                let len = (xs[1] - x + 1).min(LANES as i64) as usize;
                tiling.push((x as i32, y as i32, len));
                x += LANES as i64;
            }
        }
    }
    let reported: Vec<(i32, i32, usize)> = events
        .iter()
        .filter_map(|e| match e {
            Event::Batch(b) => Some((b.x, b.y, b.len)),
            Event::Plot(..) => None,
        })
        .collect();
    assert!(
        reported == tiling,
        "{call}: the batches (x, y, len) are {:?}…, the clipped box cut row by row into \
         batches of {LANES} from its left end gives {:?}…",
        &reported[..reported.len().min(6)],
        &tiling[..tiling.len().min(6)]
    );
    let mut fragments = Vec::new();
    let mut current: Option<(Batch, Vec<Pixel>)> = None;
    let finish = |current: &mut Option<(Batch, Vec<Pixel>)>| {
        if let Some((batch, plotted)) = current.take() {
            let wanted: Vec<Pixel> = (0..batch.len)
                .filter(|&k| batch.covered[k])
                .map(|k| Pixel::new(batch.x + k as i32, batch.y))
                .collect();
            assert_eq!(
                plotted, wanted,
                "{call}: after {batch:?} come its covered lanes' fragments, in lane order"
            );
        }
    };
    for event in events {
        match event {
            Event::Batch(batch) => {
                finish(&mut current);
                for k in 0..LANES {
                    check_lane(&call, vertices, batch, k);
                }
                current = Some((**batch, Vec::new()));
            }
            Event::Plot(fragment, weights) => {
                let Some((batch, plotted)) = current.as_mut() else {
                    panic!("{call}: {fragment:?} is plotted before any batch was reported");
                };
                let k = (fragment.pixel.x - batch.x) as usize;
                let (expected, _) =
                    definition_weights(vertices, fragment.pixel).expect("a triangle that snaps");
                assert_eq!(
                    *weights, expected,
                    "{call}: the edge weights at {} (exact integers in 1/256-pixel units, \
                     weights[k] for vertex k as given: see the sheet, task 5)",
                    fragment.pixel
                );
                assert!(
                    k < LANES
                        && fragment.depth.to_bits() == batch.depth[k].to_bits()
                        && bits(fragment.colour) == bits(batch.colour[k]),
                    "{call}: {fragment:?} does not carry the depth and colour of its lane {k} \
                     in its batch (depth {}, colour {:?}): plot each covered lane with what the \
                     batch holds",
                    batch.depth[k],
                    batch.colour[k]
                );
                plotted.push(fragment.pixel);
                fragments.push(*fragment);
            }
        }
    }
    finish(&mut current);
    fragments
}

/// A colour's channels as bits, for comparing two colours exactly.
fn bits(colour: Rgba) -> [u32; 4] {
    [colour.r, colour.g, colour.b, colour.a].map(f32::to_bits)
}

/// Lane `k` of `batch`, as the sheet defines it: below `len`, covered or
/// not, its coverage is the definition's and its weights, depth and colour
/// the barycentric mix at its pixel; from `len` on, all zero.
#[track_caller]
fn check_lane(call: &str, vertices: [Vertex; 3], batch: &Batch, k: usize) {
    let pixel = Pixel::new(batch.x + k as i32, batch.y);
    let lambda = [0, 1, 2].map(|v| batch.lambda[v][k]);
    if k >= batch.len {
        assert!(
            !batch.covered[k]
                && lambda == [0.0; 3]
                && batch.depth[k] == 0.0
                && bits(batch.colour[k])
                    .iter()
                    .all(|&c| f32::from_bits(c) == 0.0),
            "{call}: lane {k} of the batch at ({}, {}) lies past its len {}: it is off, with \
             weights {lambda:?}, depth {} and colour {:?} all 0 (Rgba::TRANSPARENT)",
            batch.x,
            batch.y,
            batch.len,
            batch.depth[k],
            batch.colour[k]
        );
        return;
    }
    let positions = vertices.map(|v| v.position);
    let covers = triangle_covers(positions, pixel);
    assert_eq!(
        batch.covered[k],
        covers,
        "{call}: lane {k} of the batch at ({}, {}) is {pixel}, whose centre the triangle {} \
         (top-left rule)",
        batch.x,
        batch.y,
        if covers { "covers" } else { "does not cover" }
    );
    let (weights, area) = definition_weights(vertices, pixel).expect("a triangle that snaps");
    let exact = weights.map(|w| w as f64 / area as f64);
    let scale = exact.iter().map(|l| l.abs()).sum::<f64>().max(1.0);
    for v in 0..3 {
        assert!(
            (f64::from(lambda[v]) - exact[v]).abs() <= 1e-6 * scale,
            "{call}: lane {k} ({pixel}, {}) holds λ{v} = {}, the exact weight of vertex {v} \
             over twice the area is {} (every lane below len is mixed, covered or not: \
             λ(i+2) = (base_i + offset)·(1/D), rounded to f32)",
            if covers { "covered" } else { "not covered" },
            lambda[v],
            exact[v]
        );
    }
    let mix = |value: fn(&Vertex) -> f32| -> f64 {
        (0..3)
            .map(|v| exact[v] * f64::from(value(&vertices[v])))
            .sum()
    };
    let tolerance = f64::from(MIX_TOLERANCE) * scale;
    let depth = mix(|v| v.depth);
    assert!(
        (f64::from(batch.depth[k]) - depth).abs() <= tolerance,
        "{call}: lane {k} ({pixel}, {}) has depth {}, the barycentric mix Σ λ_v·depth_v \
         gives {depth} (every lane below len is mixed, covered or not)",
        if covers { "covered" } else { "not covered" },
        batch.depth[k]
    );
    let colour = batch.colour[k];
    let wanted = [
        mix(|v| v.colour.r),
        mix(|v| v.colour.g),
        mix(|v| v.colour.b),
        mix(|v| v.colour.a),
    ];
    let yours = [colour.r, colour.g, colour.b, colour.a];
    assert!(
        (0..4).all(|c| (f64::from(yours[c]) - wanted[c]).abs() <= tolerance),
        "{call}: lane {k} ({pixel}, {}) has colour {colour:?}, the barycentric mix channel by \
         channel gives {wanted:?} (every lane below len is mixed, covered or not)",
        if covers { "covered" } else { "not covered" }
    );
}

fn pixels(positions: [Vec2; 3], viewport: Viewport) -> Vec<Pixel> {
    fragments(coloured(positions), viewport)
        .iter()
        .map(|f| f.pixel)
        .collect()
}

#[testkit::test]
fn right_triangle_in_batches_of_eight() {
    // The box is 21 × 21 pixels: each row is two batches of 8 and one of 5.
    triangles::right_triangle(&pixels);
}

#[testkit::test]
fn far_from_the_origin_the_lanes_stay_exact() {
    // Near ±MAX_COORD edge functions reach 2⁶⁶: a batch's base needs
    // i128, its lanes' offsets do not.
    triangles::far_from_the_origin(&pixels);
}

#[testkit::test]
fn degenerate_and_hostile_triangles_draw_nothing() {
    triangles::degenerate_and_hostile(&pixels);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn covered_pixels_match_the_definition(tri in triangles::any_triangle()) {
        triangles::covers_as_defined(&pixels, tri)?;
    }

    #[testkit::test]
    fn both_windings_give_the_same_fragments(tri in triangles::any_triangle()) {
        let [a, b, c] = coloured(tri);
        let forward = fragments([a, b, c], WIDE);
        let backward = fragments([a, c, b], WIDE);
        prop_assert_eq!(forward.len(), backward.len());
        for (f, g) in forward.iter().zip(&backward) {
            prop_assert_eq!(f.pixel, g.pixel);
            prop_assert!((f.depth - g.depth).abs() <= MIX_TOLERANCE, "{:?} against {:?}", f, g);
        }
    }

    #[testkit::test]
    fn clipping_keeps_exactly_the_pixels_in_the_viewport(
        tri in triangles::any_triangle(), x in -40..20, y in -40..20, w in 0..30, h in 0..30,
    ) {
        triangles::clipped_as_defined(&pixels, tri, Viewport::new(x, y, x + w, y + h));
    }

    #[testkit::test]
    fn hostile_vertices_never_panic(tri in triangles::hostile_triangle()) {
        triangles::survives_hostile_vertices(&pixels, tri)?;
    }
}
