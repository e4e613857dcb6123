//! The pipeline scene without a window: your stages draw the shipped
//! meshes, and a stage that is missing, at `todo!()` or panicking is named
//! while the rest of the frame still draws.

use std::sync::Arc;

use canvas::{Canvas, Rgba};
use course_viewer::scenes::mesh::{Settings, render};
use course_viewer::stages::{Stages, Status};
use scene::{Mesh, Mode};

fn mesh(name: &str) -> Mesh {
    scene::ply::load(scene::data::path(name)).expect("a shipped mesh")
}

fn statuses(stages: &[course_viewer::scenes::mesh::StageReport]) -> Vec<(&str, Status)> {
    stages.iter().map(|s| (s.name, s.status.clone())).collect()
}

/// The same picture drawn by the course's own small rasterizer (DDA lines,
/// edge functions with inclusive edges, `GL_LESS`): an independent check
/// of what the staged solutions draw.
fn by_the_course(mesh: &Mesh, settings: &Settings) -> Canvas {
    let pipeline = settings.pipeline(mesh);
    let mut polygons = pipeline.clip_space(mesh);
    if settings.clip {
        // Only the comparison's own stand-in: faces wholly inside.
        polygons = scene::discard_outside(&polygons);
    }
    let mut canvas = Canvas::new(settings.width, settings.height);
    canvas.clear(Rgba::BLACK);
    pipeline.render(&polygons, settings.mode, &mut canvas);
    canvas
}

fn differing_fraction(a: &Canvas, b: &Canvas) -> f64 {
    let differing = a
        .enumerate()
        .filter(|&(p, colour)| b.get(p).is_none_or(|other| !colour.approx_eq(other, 0.02)))
        .count();
    differing as f64 / f64::from(a.width() * a.height())
}

fn out_dir() -> std::path::PathBuf {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("viewer");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn the_staged_stages_draw_star_and_torus_as_the_course_does() {
    let stages = Stages::yours();
    // A wireframe of five edges, a torus filling a good part of the picture.
    for (name, mode, at_least) in [
        ("star.ply", Mode::Line, 1000),
        ("torus.ply", Mode::Fill, 20_000),
    ] {
        let mesh = mesh(name);
        let settings = Settings {
            mode,
            ..Settings::default()
        };
        let frame = render(&mesh, &settings, &stages);
        frame
            .canvas
            .save_png(out_dir().join(name.replace(".ply", ".png")))
            .unwrap();
        for stage in &frame.stages {
            assert!(
                matches!(stage.status, Status::Ok | Status::Unused),
                "{name}: {} {:?}",
                stage.name,
                stage.status
            );
        }
        let lit = frame.canvas.pixels_not(Rgba::BLACK).len();
        assert!(lit > at_least, "{name}: only {lit} pixels drawn");
        // These meshes lie inside the view volume: clipping changes nothing,
        // and the pictures agree with the course's rasterizer but for the
        // pixels on edges shared by two triangles (the fill rule).
        let course = by_the_course(&mesh, &settings);
        let off = differing_fraction(&frame.canvas, &course);
        assert!(
            off < 0.01,
            "{name}: {:.2} % of the pixels differ",
            off * 100.0
        );
        assert_eq!(
            frame.polygons.0, frame.polygons.1,
            "{name}: a polygon was lost"
        );
    }
}

#[test]
fn clipping_cuts_the_polygons_that_cross_the_border() {
    let mesh = mesh("clipped_torus.ply");
    let clipped = render(&mesh, &Settings::default(), &Stages::yours());
    let unclipped = render(
        &mesh,
        &Settings {
            clip: false,
            ..Settings::default()
        },
        &Stages::yours(),
    );
    assert_eq!(clipped.stages[0].status, Status::Ok);
    assert_eq!(unclipped.stages[0].status, Status::Unused);
    let (total, drawn) = clipped.polygons;
    assert!(
        drawn < total,
        "{drawn} of {total}: some faces lie wholly outside"
    );
    assert_ne!(
        clipped.canvas.pixels_not(Rgba::BLACK),
        unclipped.canvas.pixels_not(Rgba::BLACK),
        "without clipping, faces behind the eye are drawn mirrored"
    );
}

#[test]
fn a_stage_at_todo_is_named_and_the_others_still_run() {
    let mut stages = Stages::yours();
    stages.line.run = Some(Arc::new(
        |_: &canvas::Vertex, _: &canvas::Vertex, _: &mut dyn FnMut(canvas::Fragment)| {
            todo!("dda: plot one fragment per major-axis column")
        },
    ));
    let frame = render(&mesh("star.ply"), &Settings::default(), &stages);
    assert_eq!(
        statuses(&frame.stages),
        [
            ("clipping", Status::Ok),
            (
                "lines",
                Status::NotYet("dda: plot one fragment per major-axis column".to_owned())
            ),
            ("fill", Status::Unused),
            ("depth test", Status::NotReached),
        ]
    );
    assert!(
        frame.canvas.pixels_not(Rgba::BLACK).is_empty(),
        "nothing drawn, nothing made up"
    );
}

#[test]
fn a_panicking_depth_test_is_named_and_a_missing_topic_too() {
    let mut stages = Stages::yours();
    stages.depth.run = Some(Arc::new(|_: &mut Canvas, _: canvas::Fragment| -> bool {
        panic!("index out of bounds: the len is 0 but the index is 3")
    }));
    stages.clip.run = None;
    let settings = Settings {
        mode: Mode::Fill,
        ..Settings::default()
    };
    let frame = render(&mesh("torus.ply"), &settings, &stages);
    assert_eq!(frame.stages[0].status, Status::Missing);
    assert_eq!(
        frame.stages[2].status,
        Status::NotReached,
        "nothing reaches the fill"
    );
    // Without clipping asked for, the fill runs and the depth test panics.
    let frame = render(
        &mesh("torus.ply"),
        &Settings {
            clip: false,
            ..settings
        },
        &stages,
    );
    assert_eq!(frame.stages[2].status, Status::Ok);
    assert_eq!(
        frame.stages[3].status,
        Status::Panicked("index out of bounds: the len is 0 but the index is 3".to_owned())
    );
    // A build without any topic names all four.
    let frame = render(
        &mesh("torus.ply"),
        &Settings {
            clip: true,
            ..settings
        },
        &Stages::default(),
    );
    assert_eq!(frame.stages[0].status, Status::Missing);
    assert!(frame.canvas.pixels_not(Rgba::BLACK).is_empty());
}

#[test]
fn stages_of_topics_not_in_the_edition_are_drawn_by_the_given_code_and_say_so() {
    let given: Vec<String> = ["04-clipping", "01-lines", "03-fill", "05-buffers"]
        .map(String::from)
        .to_vec();
    let mesh = mesh("torus.ply");
    // Without clipping, the given code draws what the course's own small
    // rasterizer draws (the same band, coverage and `LESS`).
    let settings = Settings {
        mode: Mode::Fill,
        clip: false,
        ..Settings::default()
    };
    let frame = render(&mesh, &settings, &Stages::default().with_given(&given));
    assert_eq!(
        statuses(&frame.stages),
        vec![
            ("clipping", Status::Unused),
            ("lines", Status::Unused),
            ("fill", Status::Given),
            ("depth test", Status::Given),
        ]
    );
    let expected = by_the_course(&mesh, &settings);
    assert!(frame.canvas.pixels_not(Rgba::BLACK).len() > 20_000);
    assert!(
        differing_fraction(&frame.canvas, &expected) < 0.001,
        "the given stand-ins draw the course's picture"
    );
    // A topic that is not given (it is graded and does not compile) stays
    // missing and draws nothing.
    let stages = Stages::default().with_given(&given[..1]);
    let frame = render(&mesh, &Settings::default(), &stages);
    assert_eq!(frame.stages[0].status, Status::Given);
    let frame = render(
        &mesh,
        &Settings {
            mode: Mode::Fill,
            ..Settings::default()
        },
        &stages,
    );
    assert_eq!(frame.stages[2].status, Status::Missing);
    assert!(frame.canvas.pixels_not(Rgba::BLACK).is_empty());
}

/// The report's expected pictures are what the solutions draw (this suite
/// runs with them staged): regenerate them with `cargo xtask view
/// --reference -- --screenshot xtask/viewer/expected/<file> --size 200 ...`
/// when the pipeline changes, and look at them.
#[test]
fn the_reports_expected_pictures_are_what_the_solutions_draw() {
    use course_viewer::scenes::mesh::{REPORT_SCENES, REPORT_SIZE};
    for (file, mesh_name, mode, clip) in REPORT_SCENES {
        let settings = Settings {
            mode,
            clip,
            width: REPORT_SIZE,
            height: REPORT_SIZE,
            ..Settings::default()
        };
        let frame = render(&mesh(mesh_name), &settings, &Stages::yours());
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("expected")
            .join(file);
        let expected =
            Canvas::load_png(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(
            frame.canvas.to_image(),
            expected.to_image(),
            "{file} is not what the solutions draw"
        );
    }
}
