//! Task 9: translucent surfaces with the z-buffer — opaque first, then the
//! translucent ones back to front, tested but not written.

mod common;

use buffers::translucent::{centroid_depth, draw_with_translucency};
use canvas::{Canvas, DEPTH_CLEAR, Pixel, Rgba, Vertex};
use common::{assert_same_canvas, fragments_of, vertex};
use proptest::prelude::*;

/// The sheet's key: the centroid's depth, `(d₀ + d₁ + d₂) / 3` in `f32`.
fn key(t: &[Vertex; 3]) -> Option<f32> {
    t.iter()
        .all(|v| v.depth.is_finite())
        .then(|| (t[0].depth + t[1].depth + t[2].depth) / 3.0)
}

/// The picture the sheet defines, by brute force over the given
/// rasterizer's fragments: per pixel the nearest opaque fragment (the
/// first drawn on a tie) and its depth, then, over it, every translucent
/// fragment nearer than that depth, blended in the order of the triangles
/// sorted by key, farthest first, ties in input order.
fn translucent_picture(
    width: u32,
    height: u32,
    opaque: &[[Vertex; 3]],
    translucent: &[[Vertex; 3]],
) -> Canvas {
    let mut picture = Canvas::new(width, height);
    let mut nearest: Vec<Option<(f32, Rgba)>> = vec![None; (width * height) as usize];
    let index = |p: Pixel| (p.y as u32 * width + p.x as u32) as usize;
    for &t in opaque {
        for f in fragments_of(&picture, t) {
            let slot = &mut nearest[index(f.pixel)];
            if slot.is_none_or(|(depth, _)| f.depth < depth) && f.depth < DEPTH_CLEAR {
                *slot = Some((f.depth, f.colour));
            }
        }
    }
    for (i, slot) in nearest.iter().enumerate() {
        if let Some((depth, colour)) = *slot {
            let p = Pixel::new((i as u32 % width) as i32, (i as u32 / width) as i32);
            picture.set(p, colour);
            picture.set_depth(p, depth);
        }
    }
    let mut order: Vec<usize> = (0..translucent.len())
        .filter(|&i| key(&translucent[i]).is_some())
        .collect();
    order.sort_by(|&a, &b| {
        key(&translucent[b])
            .unwrap()
            .total_cmp(&key(&translucent[a]).unwrap())
    });
    for i in order {
        for f in fragments_of(&picture, translucent[i]) {
            if picture
                .depth(f.pixel)
                .is_some_and(|stored| f.depth < stored)
            {
                picture.blend(f.pixel, f.colour, 1.0);
            }
        }
    }
    picture
}

/// Yours on a cleared canvas.
fn yours(width: u32, height: u32, opaque: &[[Vertex; 3]], translucent: &[[Vertex; 3]]) -> Canvas {
    let mut canvas = Canvas::new(width, height);
    draw_with_translucency(&mut canvas, opaque, translucent);
    canvas
}

/// A triangle of one colour and one depth.
fn flat(corners: [(f32, f32); 3], depth: f32, colour: Rgba) -> [Vertex; 3] {
    corners.map(|(x, y)| vertex(x, y, depth, colour))
}

/// The scene of the sheet: a grey opaque floor at depth 0.9, a blue
/// translucent triangle at 0.5 and a red one at 0.2 nearer the eye,
/// overlapping over the floor around (20, 20); on a 41 × 41 canvas, or
/// `scale` times as large.
fn scene_at(scale: f32) -> ([[Vertex; 3]; 1], [[Vertex; 3]; 2]) {
    let at = |corners: [(f32, f32); 3]| corners.map(|(x, y)| (x * scale, y * scale));
    let floor = flat(
        at([(0.0, 0.0), (40.0, 0.0), (0.0, 40.0)]),
        0.9,
        Rgba::grey(0.5),
    );
    let red = flat(
        at([(6.0, 10.0), (34.0, 10.0), (20.0, 34.0)]),
        0.2,
        Rgba::new(1.0, 0.0, 0.0, 0.5),
    );
    let blue = flat(
        at([(10.0, 4.0), (38.0, 16.0), (12.0, 30.0)]),
        0.5,
        Rgba::new(0.0, 0.0, 1.0, 0.5),
    );
    ([floor], [red, blue])
}

fn scene() -> ([[Vertex; 3]; 1], [[Vertex; 3]; 2]) {
    scene_at(1.0)
}

#[testkit::test]
fn the_key_is_the_centroid_depth() {
    let w = Rgba::WHITE;
    let t = [
        vertex(0.0, 0.0, 0.3, w),
        vertex(5.0, 0.0, 0.6, w),
        vertex(0.0, 5.0, 0.9, w),
    ];
    assert_eq!(
        centroid_depth(&t),
        Some((0.3_f32 + 0.6 + 0.9) / 3.0),
        "the key of depths 0.3, 0.6, 0.9: (d₀ + d₁ + d₂) / 3 in f32"
    );
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let mut u = t;
        u[1].depth = bad;
        assert_eq!(
            centroid_depth(&u),
            None,
            "a triangle with a depth of {bad} has no key"
        );
    }
}

#[testkit::test]
fn a_far_translucent_triangle_shows_through_a_near_one_in_either_order() {
    let (opaque, [red, blue]) = scene();
    // Where all three overlap: floor, then blue over it, then red over that.
    let p = Pixel::new(20, 14);
    let over = |layers: &[Rgba]| {
        let mut c = Canvas::new(1, 1);
        c.set(Pixel::new(0, 0), layers[0]);
        for &l in &layers[1..] {
            c.blend(Pixel::new(0, 0), l, 1.0);
        }
        c.get(Pixel::new(0, 0)).unwrap().to_rgba8()
    };
    let (grey, r, b) = (Rgba::grey(0.5), red[0].colour, blue[0].colour);
    let right = over(&[grey, b, r]);
    for (translucent, given) in [([red, blue], "red, blue"), ([blue, red], "blue, red")] {
        let canvas = yours(41, 41, &opaque, &translucent);
        let got = canvas.get(p).map(Rgba::to_rgba8);
        assert!(
            got == Some(right),
            "at {p} the grey floor, the far blue (depth 0.5) and the near red (depth 0.2) \
             overlap, the translucent ones given as [{given}]: back to front gives blue over \
             the floor, then red over that, {right:?}; yours is {got:?} (red hiding blue, as \
             after a depth write by red, would be {:?}; blue blended over red, unsorted, \
             {:?})",
            over(&[grey, r]),
            over(&[grey, r, b]),
        );
        assert_same_canvas(
            &translucent_picture(41, 41, &opaque, &translucent),
            &canvas,
            &format!("the scene of the sheet, translucent given as [{given}]"),
        );
    }
}

#[testkit::test]
fn translucent_surfaces_write_no_depth_and_opaque_ones_in_front_hide_them() {
    let (floor, [red, _]) = scene();
    // An opaque green triangle in front of the red one (depth 0.1) covers
    // its left part.
    let green = flat([(0.0, 8.0), (18.0, 8.0), (0.0, 36.0)], 0.1, Rgba::GREEN);
    let opaque = [floor[0], green];
    let canvas = yours(41, 41, &opaque, &[red]);
    // Only the opaque surfaces are in the depth plane.
    for y in 0..41 {
        for x in 0..41 {
            let p = Pixel::new(x, y);
            let expected = translucent_picture(41, 41, &opaque, &[]).depth(p);
            assert!(
                canvas.depth(p) == expected,
                "at {p} the depth plane holds {:?}; only the opaque surfaces write depth, the \
                 nearest of them there is {expected:?} (a translucent surface hides nothing, \
                 so it stores no depth)",
                canvas.depth(p)
            );
        }
    }
    let hidden = Pixel::new(10, 14);
    assert!(
        canvas.get(hidden).map(Rgba::to_rgba8) == Some(Rgba::GREEN.to_rgba8()),
        "at {hidden} the opaque green triangle (depth 0.1) is in front of the translucent red \
         one (depth 0.2): the red fragment fails the depth test, the pixel stays green; yours \
         is {:?}",
        canvas.get(hidden).map(Rgba::to_rgba8)
    );
    assert_same_canvas(
        &translucent_picture(41, 41, &opaque, &[red]),
        &canvas,
        "an opaque triangle in front of a translucent one",
    );
}

#[testkit::test]
fn equal_keys_keep_their_input_order_and_bad_depths_are_left_out() {
    let half = |colour: Rgba| Rgba { a: 0.5, ..colour };
    let corners = [(2.0, 2.0), (14.0, 2.0), (2.0, 14.0)];
    let red = flat(corners, 0.5, half(Rgba::RED));
    let green = flat(corners, 0.5, half(Rgba::GREEN));
    let mut nan = flat(corners, 0.3, half(Rgba::BLUE));
    nan[0].depth = f32::NAN;
    for translucent in [[red, green, nan], [green, nan, red]] {
        let canvas = yours(16, 16, &[], &translucent);
        assert_same_canvas(
            &translucent_picture(16, 16, &[], &translucent),
            &canvas,
            "two translucent triangles with the same key (blended in input order) and one \
             with a NaN depth (left out)",
        );
    }
}

#[testkit::test]
fn the_scene_of_the_sheet_matches_the_reference_image() {
    // Four times the size; the translucent pair given near first.
    let (opaque, translucent) = scene_at(4.0);
    testkit::image::assert_image_matches(
        "translucent_scene",
        &yours(161, 161, &opaque, &translucent),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/translucent_scene.png"
        ),
        testkit::image::Tolerance::EXACT,
    );
}

/// A random scene: opaque and translucent flat triangles at random depths,
/// with random colours and alphas.
fn any_scene() -> impl Strategy<Value = (Vec<[Vertex; 3]>, Vec<[Vertex; 3]>)> {
    let triangle = |alpha: std::ops::RangeInclusive<f32>| {
        (
            prop::array::uniform3((0.0f32..24.0, 0.0f32..24.0, 0.0f32..1.0)),
            (0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0, alpha),
        )
            .prop_map(|(corners, (r, g, b, a))| {
                corners.map(|(x, y, depth)| vertex(x, y, depth, Rgba::new(r, g, b, a)))
            })
    };
    (
        prop::collection::vec(triangle(1.0..=1.0), 0..4),
        prop::collection::vec(triangle(0.1..=0.9), 0..5),
    )
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn random_scenes_match_the_definition((opaque, translucent) in any_scene()) {
        assert_same_canvas(
            &translucent_picture(24, 24, &opaque, &translucent),
            &yours(24, 24, &opaque, &translucent),
            &format!("opaque {opaque:?}, translucent {translucent:?}"),
        );
    }
}
