//! Every shipped mesh rendered in both modes, without clipping, with the
//! course camera, compared with the reference pictures in `tests/images/`.
//!
//! The `clipped_` meshes show on purpose what unclipped geometry does: lines
//! running off in wrong directions and, filled, polygons reaching behind the
//! eye that cover the whole picture.

use canvas::{Canvas, Rgba};
use scene::{Mode, Pipeline};
use testkit::image::{Tolerance, assert_image_matches};

/// The size of every picture.
const SIZE: u32 = 160;

/// Rasterization is deterministic, but another platform's `f32` maths may
/// move a pixel at a silhouette: allow 0.2 % of the pixels to differ.
const TOLERANCE: Tolerance = Tolerance {
    channel: 2.0 / 255.0,
    mismatched_fraction: 0.002,
};

fn check(name: &str, mode: Mode) {
    let mesh = scene::ply::load(scene::data::path(name)).unwrap_or_else(|e| panic!("{e}"));
    let pipeline = Pipeline::for_mesh(&mesh, SIZE, SIZE);
    let mut canvas = Canvas::new(SIZE, SIZE);
    canvas.clear(Rgba::BLACK);
    pipeline.render(&pipeline.clip_space(&mesh), mode, &mut canvas);
    let stem = name.trim_end_matches(".ply");
    let suffix = match mode {
        Mode::Line => "line",
        Mode::Fill => "fill",
    };
    let picture = format!("{stem}_{suffix}");
    let reference = format!("{}/tests/images/{picture}.png", env!("CARGO_MANIFEST_DIR"));
    assert_image_matches(&format!("scene/{picture}"), &canvas, reference, TOLERANCE);
}

macro_rules! picture_tests {
    ($($test:ident: $mesh:literal, $mode:ident;)*) => {
        $(
            #[test]
            fn $test() {
                check($mesh, Mode::$mode);
            }
        )*
    };
}

picture_tests! {
    plane_line: "plane.ply", Line;
    plane_fill: "plane.ply", Fill;
    star_line: "star.ply", Line;
    star_fill: "star.ply", Fill;
    text_line: "text.ply", Line;
    text_fill: "text.ply", Fill;
    torus_line: "torus.ply", Line;
    torus_fill: "torus.ply", Fill;
    clipped_star_line: "clipped_star.ply", Line;
    clipped_star_fill: "clipped_star.ply", Fill;
    clipped_torus_line: "clipped_torus.ply", Line;
    clipped_torus_fill: "clipped_torus.ply", Fill;
}

#[test]
fn every_shipped_mesh_has_a_picture_test() {
    for name in scene::data::MESHES {
        let stem = name.trim_end_matches(".ply");
        for mode in ["line", "fill"] {
            let path = format!(
                "{}/tests/images/{stem}_{mode}.png",
                env!("CARGO_MANIFEST_DIR")
            );
            assert!(std::path::Path::new(&path).exists(), "{path}");
        }
    }
}
