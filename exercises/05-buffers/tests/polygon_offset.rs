//! Task 4: polygon offset for hidden-line drawing.

mod common;

use buffers::polygon_offset::{
    DEPTH_RESOLUTION, HiddenLineOffset, HiddenLineStyle, OffsetError, PolygonOffset, fill_offset,
    hidden_line, max_depth_slope,
};
use buffers::raster::{draw_line, fill_triangle};
use canvas::{Canvas, Pixel, Rgba, Vertex};
use common::vertex;
use proptest::prelude::*;

/// The seed's second remedy, the negative of its `factor = units = 1`.
const PULL: PolygonOffset = PolygonOffset {
    factor: -1.0,
    units: -1.0,
};

const STYLE: HiddenLineStyle = HiddenLineStyle {
    fill: Rgba::BLACK,
    line: Rgba::WHITE,
};

fn grey(x: f32, y: f32, depth: f32) -> Vertex {
    vertex(x, y, depth, Rgba::grey(0.5))
}

/// A triangle whose depth changes quickly across it (m = 0.06 per pixel):
/// enough for the fill to beat the outline at half the edge pixels.
fn tilted() -> [Vertex; 3] {
    [
        grey(2.0, 1.0, 0.2),
        grey(17.0, 3.0, 0.4),
        grey(6.0, 10.0, 0.8),
    ]
}

/// The pixels of the outline, by the given line rasterizer.
fn outline_pixels(canvas: &Canvas, triangle: [Vertex; 3]) -> Vec<Pixel> {
    let mut pixels = Vec::new();
    for k in 0..3 {
        draw_line(triangle[k], triangle[(k + 1) % 3], canvas.viewport(), |f| {
            pixels.push(f.pixel)
        });
    }
    pixels
}

fn drawing(offset: HiddenLineOffset) -> Canvas {
    let mut canvas = Canvas::new(20, 12);
    hidden_line(&mut canvas, &[tilted()], STYLE, offset);
    canvas
}

#[testkit::test]
fn offset_is_m_times_factor_plus_r_times_units() {
    let o = PolygonOffset {
        factor: 2.0,
        units: 3.0,
    };
    assert_eq!(o.offset(0.25), 0.5 + 3.0 * DEPTH_RESOLUTION);
    assert_eq!(PolygonOffset::SLIDES.offset(0.0), DEPTH_RESOLUTION);
    let back = PolygonOffset {
        factor: -1.0,
        units: -2.0,
    };
    assert_eq!(back.offset(0.5), -0.5 - 2.0 * DEPTH_RESOLUTION);
    assert_eq!(DEPTH_RESOLUTION, 2.0f32.powi(-24));
}

#[testkit::test]
fn slope_is_the_larger_partial_derivative() {
    // z = 0.01·x + 0.03·y + 0.1 → m = 0.03
    let z = |x: f32, y: f32| 0.01 * x + 0.03 * y + 0.1;
    let tri = [
        grey(0.0, 0.0, z(0.0, 0.0)),
        grey(8.0, 1.0, z(8.0, 1.0)),
        grey(2.0, 7.0, z(2.0, 7.0)),
    ];
    let m = max_depth_slope(tri).unwrap();
    assert!((m - 0.03).abs() < 1e-6, "m = {m}");
    // z = 0.5 − 0.05·x → m = 0.05 (a magnitude)
    let tri = [
        grey(0.0, 0.0, 0.5),
        grey(4.0, 0.0, 0.3),
        grey(0.0, 4.0, 0.5),
    ];
    let m = max_depth_slope(tri).unwrap();
    assert!(
        (m - 0.05).abs() < 1e-7,
        "z = 0.5 − 0.05·x: m is the magnitude 0.05; yours {m}"
    );
    // A triangle of constant depth has no slope.
    let tri = [
        grey(0.0, 0.0, 0.5),
        grey(4.0, 1.0, 0.5),
        grey(1.0, 4.0, 0.5),
    ];
    assert_eq!(max_depth_slope(tri), Ok(0.0));
    // tilted(): z ≈ 0.126 + 0.0047·x + 0.0646·y
    let m = max_depth_slope(tilted()).unwrap();
    assert!(m > 0.055 && m < 0.07, "m = {m}");
}

#[testkit::test]
fn degenerate_and_non_finite_triangles_have_no_slope() {
    let line = [
        grey(0.0, 0.0, 0.1),
        grey(2.0, 2.0, 0.5),
        grey(5.0, 5.0, 0.9),
    ];
    assert_eq!(max_depth_slope(line), Err(OffsetError::Degenerate));
    let mut nan = tilted();
    nan[1].depth = f32::NAN;
    assert_eq!(max_depth_slope(nan), Err(OffsetError::NotFinite));
    let mut inf = tilted();
    inf[0].position.x = f32::INFINITY;
    assert_eq!(max_depth_slope(inf), Err(OffsetError::NotFinite));
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn slope_matches_the_plane_and_ignores_vertex_order(
        a in -0.05f32..0.05, b in -0.05f32..0.05, c in 0.3f32..0.5,
        p in prop::array::uniform6(-10i32..10),
        rotate in 0usize..3, flip in any::<bool>(),
    ) {
        let pos = [(p[0], p[1]), (p[2], p[3]), (p[4], p[5])];
        let area = (pos[1].0 - pos[0].0) * (pos[2].1 - pos[0].1) - (pos[2].0 - pos[0].0) * (pos[1].1 - pos[0].1);
        prop_assume!(area.abs() >= 4);
        let mut tri = pos.map(|(x, y)| grey(x as f32, y as f32, a * x as f32 + b * y as f32 + c));
        tri.rotate_left(rotate);
        if flip {
            tri.swap(1, 2);
        }
        let m = max_depth_slope(tri).unwrap();
        let expected = a.abs().max(b.abs());
        prop_assert!((m - expected).abs() < 2e-6, "m = {}, plane slopes {} and {}", m, a, b);
    }
}

/// The plane of `tilted()` is `z ≈ 0.126 + 0.0047·x + 0.0646·y`: depth grows
/// up and to the right. On the edge from (17, 3) to (6, 10) the inside lies
/// below-left, so wherever the line's pixel centre is inside, the fill is
/// nearer than the line and hides it: every other pixel or so of that edge
/// is missing. On the other two edges the inside is deeper and the line wins.
#[testkit::test]
fn without_offset_the_outline_is_stitched() {
    let canvas = drawing(HiddenLineOffset::None);
    let outline = outline_pixels(&canvas, tilted());
    let hidden: Vec<Pixel> = outline
        .iter()
        .copied()
        .filter(|&p| canvas.get(p) != Some(Rgba::WHITE))
        .collect();
    assert!(!hidden.is_empty(), "no stitching without polygon offset");
    testkit::assert_raster_snapshot!("hidden_line_without_offset", canvas);
}

#[testkit::test]
fn with_the_slides_offset_the_outline_is_whole() {
    let canvas = drawing(HiddenLineOffset::Fill(PolygonOffset::SLIDES));
    let outline = outline_pixels(&canvas, tilted());
    testkit::assert_pixels_eq(
        &outline,
        &canvas.pixels_not(Rgba::BLACK),
        "outline with offset",
    );
    testkit::assert_raster_snapshot!("hidden_line_with_offset", canvas);
}

#[testkit::test]
fn offset_moves_the_fill_back_by_o() {
    let mut canvas = Canvas::new(20, 12);
    hidden_line(
        &mut canvas,
        &[tilted()],
        STYLE,
        HiddenLineOffset::Fill(PolygonOffset {
            factor: 1.0,
            units: 0.0,
        }),
    );
    let m = max_depth_slope(tilted()).unwrap();
    let outline = outline_pixels(&canvas, tilted());
    let mut checked = 0;
    fill_triangle(tilted(), canvas.viewport(), |f| {
        if !outline.contains(&f.pixel) {
            let stored = canvas.depth(f.pixel).unwrap();
            assert!(
                (stored - (f.depth + m)).abs() < 1e-6,
                "{}: the fill pushed back by factor 1 stores z + m = {} + {m}; yours {stored}",
                f.pixel,
                f.depth
            );
            checked += 1;
        }
    });
    assert!(checked > 20);
}

#[testkit::test]
fn fill_depth_pulled_past_zero_is_clamped() {
    // A pull towards the viewer of o = 2⁻²⁴ · (−2²⁵) = −2, more than any
    // depth: z + o is clamped to 0, as OpenGL clamps it to [0, 1].
    let pull = PolygonOffset {
        factor: 0.0,
        units: -33_554_432.0,
    };
    let mut canvas = Canvas::new(20, 12);
    hidden_line(
        &mut canvas,
        &[tilted()],
        STYLE,
        HiddenLineOffset::Fill(pull),
    );
    let mut checked = 0;
    fill_triangle(tilted(), canvas.viewport(), |f| {
        assert_eq!(canvas.depth(f.pixel), Some(0.0), "{}", f.pixel);
        checked += 1;
    });
    assert!(checked > 20);
}

/// Draws the tilted triangle behind a near, flat one (depth 0.1) with
/// `offset` and checks that no remedy pulls the back triangle's edges
/// through the front one, while its edges outside it are all drawn.
fn assert_the_front_triangle_hides_the_edges_behind(offset: HiddenLineOffset) {
    let front = [
        grey(0.0, 4.0, 0.1),
        grey(12.0, 4.0, 0.1),
        grey(6.0, 12.0, 0.1),
    ];
    let mut canvas = Canvas::new(20, 12);
    hidden_line(&mut canvas, &[tilted(), front], STYLE, offset);
    let front_outline = outline_pixels(&canvas, front);
    let (mut front_cover, mut inside_front) = (Vec::new(), 0);
    fill_triangle(front, canvas.viewport(), |f| {
        front_cover.push(f.pixel);
        if !front_outline.contains(&f.pixel) {
            inside_front += 1;
            assert_eq!(
                canvas.get(f.pixel),
                Some(Rgba::BLACK),
                "{offset:?}: {} shows an edge of the triangle behind",
                f.pixel
            );
        }
    });
    assert!(inside_front > 10);
    for p in outline_pixels(&canvas, tilted()) {
        if !front_cover.contains(&p) {
            assert_eq!(
                canvas.get(p),
                Some(Rgba::WHITE),
                "{offset:?}: {p} of the back outline is missing"
            );
        }
    }
}

#[testkit::test]
fn edges_behind_another_triangle_stay_hidden() {
    assert_the_front_triangle_hides_the_edges_behind(HiddenLineOffset::Fill(PolygonOffset::SLIDES));
}

/// The order of the passes: every fill first, then every outline. It
/// shows where depths tie: a quad facing the viewer (depth 0.5 everywhere)
/// cut along its diagonal, without an offset, so each outline fragment
/// ties the fill under it and fails `LESS`. With all fills first, only the
/// outline pixels outside both fills show, and the shared diagonal is
/// hidden. Filling and outlining one triangle at a time lets the first
/// triangle's outline onto the second's pixels before that fill comes,
/// and the fill then ties and loses.
///
/// ```text
///   3 +-------+ 2    first  [0, 1, 2]
///     |     / |      second [0, 2, 3]
///     |   /   |      the diagonal 0–2 lies in both fills
///     | /     |
///   0 +-------+ 1
/// ```
#[testkit::test]
fn every_fill_comes_before_every_outline() {
    let corners = [
        grey(1.3, 1.2, 0.5),
        grey(14.6, 1.4, 0.5),
        grey(14.4, 9.7, 0.5),
        grey(1.5, 9.6, 0.5),
    ];
    let halves = [
        [corners[0], corners[1], corners[2]],
        [corners[0], corners[2], corners[3]],
    ];
    let mut canvas = Canvas::new(16, 11);
    hidden_line(&mut canvas, &halves, STYLE, HiddenLineOffset::None);
    let mut filled = Vec::new();
    for half in halves {
        fill_triangle(half, canvas.viewport(), |f| filled.push(f.pixel));
    }
    let mut expected: Vec<Pixel> = halves
        .iter()
        .flat_map(|&half| outline_pixels(&canvas, half))
        .filter(|p| !filled.contains(p))
        .collect();
    expected.dedup();
    testkit::assert_pixels_eq(
        &expected,
        &canvas.pixels_not(Rgba::BLACK),
        "every fill first, then every outline: without an offset an outline at depth 0.5 \
         ties the fill under it and fails LESS, so only outline pixels outside both fills show",
    );
}

#[testkit::test]
fn degenerate_triangles_are_outlined_only_and_hostile_ones_ignored() {
    let mut canvas = Canvas::new(8, 8);
    let line = [
        grey(1.0, 1.0, 0.5),
        grey(3.0, 3.0, 0.5),
        grey(6.0, 6.0, 0.5),
    ];
    let hostile = [
        grey(f32::NAN, 0.0, 0.5),
        grey(1e30, 1.0, f32::INFINITY),
        grey(2.0, 2.0, 0.5),
    ];
    hidden_line(
        &mut canvas,
        &[line, hostile],
        STYLE,
        HiddenLineOffset::Fill(PolygonOffset::SLIDES),
    );
    let drawn = canvas.pixels_not(Rgba::BLACK);
    let expected: Vec<Pixel> = (1..=6).map(|k| Pixel::new(k, k)).collect();
    testkit::assert_pixels_eq(&expected, &drawn, "a degenerate triangle's outline");
}

/// The slides' advice, "bei größerer Linienstärke sollte factor erhöht
/// werden", rests on this: how far fill and line differ on one pixel
/// grows with the slope `m`, so `units` alone (a fixed `r · units`) is
/// too little for a steep triangle, while `factor = 1` is always enough.
#[testkit::test]
fn units_alone_leave_a_steep_outline_stitched_while_factor_cures_it() {
    let outline = outline_pixels(&Canvas::new(20, 12), tilted());
    let units_only = drawing(HiddenLineOffset::Fill(PolygonOffset {
        factor: 0.0,
        units: 1000.0,
    }));
    assert!(
        outline
            .iter()
            .any(|&p| units_only.get(p) != Some(Rgba::WHITE)),
        "with factor 0 and units 1000 (o = 1000 · 2⁻²⁴ ≈ 0.00006, far below the slope 0.06 \
         per pixel) the outline of the steep triangle must still be stitched"
    );
    let factor_only = drawing(HiddenLineOffset::Fill(PolygonOffset {
        factor: 1.0,
        units: 0.0,
    }));
    testkit::assert_pixels_eq(
        &outline,
        &factor_only.pixels_not(Rgba::BLACK),
        "outline with factor 1, units 0",
    );
}

/// The seed's second remedy: "Offset für Linie < 0 → Linie erscheint
/// weiter vorne". The fill stays where it is, each outline moves forward
/// by its triangle's offset (negative), and the outline is whole.
#[testkit::test]
fn a_negative_line_offset_also_makes_the_outline_whole() {
    let pull = PULL;
    let canvas = drawing(HiddenLineOffset::Line(pull));
    let outline = outline_pixels(&canvas, tilted());
    testkit::assert_pixels_eq(
        &outline,
        &canvas.pixels_not(Rgba::BLACK),
        "outline pulled forward",
    );
    let o = pull.offset(max_depth_slope(tilted()).unwrap());
    let mut line_depth = std::collections::HashMap::new();
    for k in 0..3 {
        draw_line(tilted()[k], tilted()[(k + 1) % 3], canvas.viewport(), |f| {
            line_depth.entry(f.pixel).or_insert(f.depth);
        });
    }
    // An outline pixel drawn once stores its line depth moved by o.
    let mut checked = 0;
    for (pixel, depth) in line_depth {
        let stored = canvas.depth(pixel).unwrap();
        if (stored - (depth + o)).abs() < 1e-6 {
            checked += 1;
        }
    }
    assert!(
        checked >= outline.len() / 2,
        "the outline's stored depths must be the line depths moved by o = {o} \
         (only {checked} of {} are)",
        outline.len()
    );
    // The fill is not offset: inside the triangle the stored depth is the plane's.
    let mut inside = 0;
    fill_triangle(tilted(), canvas.viewport(), |f| {
        if !outline.contains(&f.pixel) {
            assert_eq!(
                canvas.depth(f.pixel),
                Some(f.depth),
                "{}: the fill must not be offset",
                f.pixel
            );
            inside += 1;
        }
    });
    assert!(inside > 20);
}

#[testkit::test]
fn line_depth_pulled_past_zero_is_clamped() {
    let pull = PolygonOffset {
        factor: 0.0,
        units: -33_554_432.0,
    };
    let canvas = drawing(HiddenLineOffset::Line(pull));
    let outline = outline_pixels(&canvas, tilted());
    for &p in &outline {
        assert_eq!(
            canvas.depth(p),
            Some(0.0),
            "{p}: an outline pulled past the viewer (o = −2) is clamped to depth 0"
        );
    }
}

#[testkit::test]
fn a_pulled_outline_still_hides_behind_a_nearer_triangle() {
    assert_the_front_triangle_hides_the_edges_behind(HiddenLineOffset::Line(PULL));
}

/// The plane `z = 0.3 + 0.004·x + 0.006·y` over a 64 × 48 canvas.
fn on_plane(x: f32, y: f32, colour: Rgba) -> Vertex {
    vertex(x, y, 0.3 + 0.004 * x + 0.006 * y, colour)
}

/// A grey floor of two triangles, and a red decal of two triangles on the
/// same plane, split along the other diagonal: the same depths, each
/// interpolated from other vertices.
fn floor_and_decal() -> ([[Vertex; 3]; 2], [[Vertex; 3]; 2]) {
    let g = Rgba::grey(0.6);
    let r = Rgba::rgb(0.9, 0.2, 0.2);
    let floor = [
        [
            on_plane(1.0, 1.0, g),
            on_plane(62.0, 1.0, g),
            on_plane(62.0, 46.0, g),
        ],
        [
            on_plane(1.0, 1.0, g),
            on_plane(62.0, 46.0, g),
            on_plane(1.0, 46.0, g),
        ],
    ];
    let decal = [
        [
            on_plane(16.0, 10.0, r),
            on_plane(50.0, 14.0, r),
            on_plane(12.0, 34.0, r),
        ],
        [
            on_plane(50.0, 14.0, r),
            on_plane(46.0, 38.0, r),
            on_plane(12.0, 34.0, r),
        ],
    ];
    (floor, decal)
}

const DECAL: Rgba = Rgba::rgb(0.9, 0.2, 0.2);

/// The floor, then the decal with `offset`, by `fill_offset`; and the
/// pixels the decal covers.
fn decal_picture(offset: Option<PolygonOffset>) -> (Canvas, Vec<Pixel>) {
    let (floor, decal) = floor_and_decal();
    let mut canvas = Canvas::new(64, 48);
    for triangle in floor {
        fill_offset(&mut canvas, triangle, Rgba::grey(0.6), None);
    }
    for triangle in decal {
        fill_offset(&mut canvas, triangle, DECAL, offset);
    }
    let mut covered = Vec::new();
    for triangle in decal {
        fill_triangle(triangle, canvas.viewport(), |f| covered.push(f.pixel));
    }
    (canvas, covered)
}

/// z-fighting: without an offset the decal shows only where its depth
/// happens to round below the floor's.
#[testkit::test]
fn a_coplanar_decal_fights_the_floor_without_an_offset() {
    let (canvas, covered) = decal_picture(None);
    // The picture first, so that a failing check below still leaves it.
    let picture = testkit::image::check_image(
        "zfighting_decal_without_offset",
        &canvas,
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/zfighting_decal_without_offset.png"
        ),
        testkit::image::Tolerance::EXACT,
    );
    // Pixel by pixel: without an offset the decal shows exactly where its
    // own interpolated depth is less than the floor's (LESS).
    let (floor, decal) = floor_and_decal();
    let mut floor_depth = std::collections::HashMap::new();
    for triangle in floor {
        fill_triangle(triangle, canvas.viewport(), |f| {
            floor_depth.entry(f.pixel).or_insert(f.depth);
        });
    }
    for triangle in decal {
        fill_triangle(triangle, canvas.viewport(), |f| {
            let under = floor_depth[&f.pixel];
            let wins = f.depth < under;
            let shows = canvas
                .get(f.pixel)
                .is_some_and(|c| c.approx_eq(DECAL, 0.01));
            assert!(
                shows == wins,
                "{}: the decal's depth {} is {} the floor's {under}, so LESS must {}; yours \
                 shows the {}",
                f.pixel,
                f.depth,
                if wins { "less than" } else { "not less than" },
                if wins {
                    "draw the decal"
                } else {
                    "keep the floor"
                },
                if shows { "decal" } else { "floor" },
            );
        });
    }
    let shown = covered
        .iter()
        .filter(|&&p| canvas.get(p).is_some_and(|c| c.approx_eq(DECAL, 0.01)))
        .count();
    assert!(
        shown > 0 && shown < covered.len(),
        "without an offset the decal must show at some of its pixels and not at others \
         (z-fighting); it shows at {shown} of {}",
        covered.len()
    );
    picture.assert_matches();
}

/// A negative offset brings the decal in front at every pixel; a positive
/// one hides it everywhere.
#[testkit::test]
fn a_negative_offset_brings_the_whole_decal_in_front() {
    let (canvas, covered) = decal_picture(Some(PULL));
    // The picture first, so that a failing check below still leaves it.
    let picture = testkit::image::check_image(
        "zfighting_decal_with_offset",
        &canvas,
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/zfighting_decal_with_offset.png"
        ),
        testkit::image::Tolerance::EXACT,
    );
    for &p in &covered {
        assert!(
            canvas.get(p).is_some_and(|c| c.approx_eq(DECAL, 0.01)),
            "{p}: the decal pulled forward by factor −1, units −1 must show"
        );
    }
    let (pushed, covered) = decal_picture(Some(PolygonOffset::SLIDES));
    for &p in &covered {
        assert_eq!(
            pushed.get(p).map(Rgba::to_rgba8),
            Some(Rgba::grey(0.6).to_rgba8()),
            "{p}: the decal pushed back by the slides' offset must hide behind the floor"
        );
    }
    picture.assert_matches();
}
