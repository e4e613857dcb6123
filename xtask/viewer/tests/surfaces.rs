//! The surface scene without a window: what it draws with your topic 07
//! code, right, wrong or unfinished.

use std::sync::Arc;

use canvas::Canvas;
use course_viewer::scenes::surfaces::{
    BACKGROUND, SurfaceDrawing, SurfaceSetup, TrimSetup, TrimShape, UV_SAMPLES, draw,
};
use course_viewer::stages::{SurfaceView, TrimFn};
use course_viewer::{Stages, Status};
use glam::{DVec2, DVec3};

/// How many pixels of the picture are not background (as a canvas stores
/// it, 8 bits per channel).
fn drawn_pixels(canvas: &Canvas) -> usize {
    canvas
        .pixels_not(canvas::Rgba::from_rgba8(BACKGROUND.to_rgba8()))
        .len()
}

/// The centre of parameter-square sample `k` (row by row from `v = 0`).
fn sample(k: usize) -> DVec2 {
    let n = UV_SAMPLES as usize;
    (DVec2::new((k % n) as f64, (k / n) as f64) + 0.5) / n as f64
}

fn with_shape(shape: TrimShape) -> SurfaceSetup {
    SurfaceSetup {
        trim: TrimSetup {
            shape,
            ..TrimSetup::default()
        },
        width: 160,
        height: 120,
        ..SurfaceSetup::default()
    }
}

#[test]
fn the_solutions_draw_the_hill_with_each_trim() {
    course_viewer::stages::quiet_panics();
    let stages = Stages::yours();
    let untrimmed = draw(&with_shape(TrimShape::None), &stages);
    assert_eq!(untrimmed.surface, Status::Ok);
    assert_eq!(untrimmed.render, Status::Ok);
    assert_eq!(untrimmed.trim, Status::Unused);
    assert!(untrimmed.cut.iter().all(|c| !c), "nothing is cut away");
    let whole = drawn_pixels(&untrimmed.canvas);
    assert!(
        whole > 160 * 120 / 4,
        "the hill covers much of the picture: {whole} pixels"
    );
    for shape in &TrimShape::ALL[1..] {
        let drawing = draw(&with_shape(*shape), &stages);
        assert_eq!(
            (&drawing.surface, &drawing.trim, &drawing.render),
            (&Status::Ok, &Status::Ok, &Status::Ok),
            "{shape:?}"
        );
        let cut = drawing.cut.iter().filter(|c| **c).count();
        assert!(
            cut > 100 && cut < drawing.cut.len() - 100,
            "{shape:?}: {cut} samples of the parameter square cut away"
        );
        let left = drawn_pixels(&drawing.canvas);
        assert!(
            left < whole,
            "{shape:?}: a trimmed hill covers fewer pixels ({left}) than the whole ({whole})"
        );
    }
}

#[test]
fn the_parameter_square_shows_the_trim_by_its_definition() {
    let mut setup = with_shape(TrimShape::Circle);
    setup.trim.centre = DVec2::new(0.3, 0.6);
    setup.trim.size.x = 0.25;
    let drawing = draw(&setup, &Stages::yours());
    for (k, &cut) in drawing.cut.iter().enumerate() {
        let uv = sample(k);
        assert_eq!(cut, uv.distance(setup.trim.centre) < 0.25, "{uv}");
    }
    let mut setup = with_shape(TrimShape::Rectangle);
    setup.trim.centre = DVec2::new(0.5, 0.4);
    setup.trim.size = DVec2::new(0.3, 0.1);
    let drawing = draw(&setup, &Stages::yours());
    for (k, &cut) in drawing.cut.iter().enumerate() {
        let uv = sample(k);
        let inside = (0.2..=0.8).contains(&uv.x) && (0.3..=0.5).contains(&uv.y);
        assert_eq!(cut, inside, "{uv}");
    }
}

#[test]
fn controls_change_the_picture() {
    let stages = Stages::yours();
    let base = with_shape(TrimShape::Circle);
    let picture = |setup: &SurfaceSetup| draw(setup, &stages).canvas.to_image();
    let first = picture(&base);
    let changes: [(&str, SurfaceSetup); 4] = [
        ("a coarser level", SurfaceSetup { level: 3, ..base }),
        (
            "the wireframe",
            SurfaceSetup {
                wireframe: true,
                ..base
            },
        ),
        ("turning the camera", SurfaceSetup { yaw: 40.0, ..base }),
        (
            "another trim",
            SurfaceSetup {
                trim: TrimSetup {
                    shape: TrimShape::NewtonQuadratic,
                    ..base.trim
                },
                ..base
            },
        ),
    ];
    let mut raised = base;
    raised.heights[1][2] = 1.2;
    let changes: Vec<(&str, SurfaceSetup)> = changes
        .into_iter()
        .chain([("raising a control point", raised)])
        .collect();
    for (what, setup) in changes {
        assert_ne!(picture(&setup), first, "{what} changes the picture");
    }
    // Newton's steps matter (seed §5.2): one step leaves another region.
    let newton = with_shape(TrimShape::NewtonCubic);
    let one_step = SurfaceSetup {
        trim: TrimSetup {
            iterations: 1,
            ..newton.trim
        },
        ..newton
    };
    assert_ne!(draw(&newton, &stages).cut, draw(&one_step, &stages).cut);
}

fn unwritten_surface() -> Stages {
    let mut stages = Stages::yours();
    stages.surface.run = Some(Arc::new(
        |_: &freeform::BezierPatch, _: DVec2| -> Result<(DVec3, DVec3), String> {
            todo!("surface: check u, v; de Casteljau each column at u")
        },
    ));
    stages
}

#[test]
fn an_unwritten_surface_is_named_and_nothing_is_drawn() {
    course_viewer::stages::quiet_panics();
    let drawing = draw(&with_shape(TrimShape::Circle), &unwritten_surface());
    assert_eq!(
        drawing.surface,
        Status::NotYet("surface: check u, v; de Casteljau each column at u".to_owned())
    );
    assert_eq!(drawing.render, Status::NotReached);
    assert_eq!(
        drawing.trim,
        Status::Ok,
        "the trim still shows in the square"
    );
    assert_eq!(drawn_pixels(&drawing.canvas), 0);
}

#[test]
fn a_panicking_trim_is_named_and_the_surface_still_shows() {
    course_viewer::stages::quiet_panics();
    let mut stages = Stages::yours();
    stages.trim.run = Some(Arc::new(|_: &TrimSetup| -> Result<TrimFn, String> {
        Ok(Arc::new(|uv: DVec2| {
            assert!(uv.x < 0.9, "u = {} is out of my range", uv.x);
            uv.x < 0.5
        }))
    }));
    let drawing: SurfaceDrawing = draw(&with_shape(TrimShape::Ellipse), &stages);
    assert!(
        matches!(&drawing.trim, Status::Panicked(m) if m.contains("out of my range")),
        "{:?}",
        drawing.trim
    );
    assert_eq!(drawing.surface, Status::Ok);
    assert_eq!(drawing.render, Status::Ok);
    assert!(drawn_pixels(&drawing.canvas) > 1000);
}

#[test]
fn a_render_error_is_named_and_without_topic_07_every_stage_is_missing() {
    let mut stages = Stages::yours();
    stages.surface_render.run = Some(Arc::new(
        |_: &mut Canvas,
         _: &dyn Fn(DVec2) -> Result<(DVec3, DVec3), String>,
         _: &dyn Fn(DVec2) -> bool,
         view: &SurfaceView| Err(format!("level {} refused", view.level)),
    ));
    let drawing = draw(&with_shape(TrimShape::None), &stages);
    assert_eq!(
        drawing.render,
        Status::Failed("level 24 refused".to_owned())
    );

    let none = draw(&with_shape(TrimShape::Circle), &Stages::default());
    assert_eq!(
        (&none.surface, &none.trim, &none.render),
        (&Status::Missing, &Status::Missing, &Status::Missing)
    );
    assert_eq!(drawn_pixels(&none.canvas), 0);
}

#[test]
fn a_set_up_is_kept_drawable() {
    let mut heights = SurfaceSetup::default().heights;
    heights[0][0] = f64::NAN;
    heights[3][3] = 40.0;
    let mut setup = SurfaceSetup {
        heights,
        level: 0,
        yaw: f64::NAN,
        distance: 1e9,
        width: 0,
        trim: TrimSetup {
            centre: DVec2::new(f64::INFINITY, -3.0),
            size: DVec2::ZERO,
            iterations: 0,
            epsilon: f64::NAN,
            ..TrimSetup::default()
        },
        ..SurfaceSetup::default()
    };
    setup.tidy();
    assert_eq!(setup.level, 1);
    assert_eq!(setup.yaw, SurfaceSetup::default().yaw);
    assert_eq!(setup.distance, 8.0);
    assert_eq!(setup.width, 16);
    assert!(setup.trim.centre.is_finite() && setup.trim.size.min_element() > 0.0);
    assert_eq!(setup.trim.iterations, 1);
    assert_eq!(setup.heights[0][0], 0.0, "the hill's corner");
    assert_eq!(setup.heights[3][3], 1.5);
    assert!(setup.trim.epsilon > 0.0);
    // Drawn as it is, even unfinished.
    let drawing = draw(&setup, &Stages::yours());
    assert_eq!(drawing.render, Status::Ok);
}
