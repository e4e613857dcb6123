//! The pixel playground with the solutions' stages (this test runs in the
//! course's stage): every primitive matches its definition wherever its
//! handles are, and a wrong, unfinished or runaway stage is shown as such.
#![cfg(all(feature = "lines", feature = "circles", feature = "fill"))]

use std::sync::Arc;

use canvas::{Pixel, Vec2};
use course_viewer::Stages;
use course_viewer::scenes::pixels::{Cell, MAX_PLOTS, Primitive, Setup, draw};
use course_viewer::stages::Status;

/// Handle positions that reach every octant, the axes, a single pixel,
/// a circle off the grid's edge and triangles of both windings with
/// vertices on half pixels.
fn setups() -> Vec<Setup> {
    let mut setups = Vec::new();
    let points = [
        (3.0, 3.0),
        (12.0, 5.0),
        (5.0, 12.0),
        (0.0, 15.0),
        (15.0, 15.0),
        (7.0, 3.0),
        (3.0, 9.5),
        (10.5, 0.0),
    ];
    for primitive in Primitive::ALL {
        for (i, &a) in points.iter().enumerate() {
            for &b in &points[i..] {
                let mut setup = Setup {
                    primitive,
                    ..Setup::default()
                };
                setup.move_handle(0, Vec2::from(a));
                setup.move_handle(1, Vec2::from(b));
                setup.move_handle(2, Vec2::new(b.1, a.0));
                setups.push(setup);
            }
        }
    }
    setups
}

#[test]
fn the_solutions_draw_every_primitive_as_defined() {
    let stages = Stages::yours();
    for setup in setups() {
        let drawing = draw(&setup, &stages);
        assert_eq!(drawing.status, Status::Ok, "{setup:?}");
        let wrong: Vec<_> = drawing
            .cells(drawing.yours.len())
            .into_iter()
            .filter(|(_, c)| matches!(c, Cell::OnlyYours | Cell::OnlyExpected))
            .collect();
        assert!(wrong.is_empty(), "{setup:?}: {wrong:?}");
        assert!(
            drawing.summary().starts_with("all "),
            "{}",
            drawing.summary()
        );
        assert!(
            drawing.yours.iter().all(|s| !s.note.is_empty()),
            "{setup:?}"
        );
        if setup.primitive == Primitive::WuLine {
            // The solution keeps 8 bits of each intensity, as Wu did.
            let off = drawing.intensity_error().unwrap();
            assert!(
                off <= 1.0 / 256.0 + 1e-6,
                "{setup:?}: intensities off by {off}"
            );
        }
    }
}

#[test]
fn an_aliased_line_in_place_of_wus_shows_its_wrong_intensities() {
    let mut stages = Stages::yours();
    // The midpoint line's pixels at full intensity: no antialiasing.
    stages.wu.run = Some(Arc::new(
        |from: Pixel, to: Pixel, plot: &mut dyn FnMut(Pixel, f32)| {
            lines::midpoint::midpoint_line(from, to, |p| plot(p, 1.0));
        },
    ));
    let setup = Setup {
        primitive: Primitive::WuLine,
        ..Setup::default()
    };
    let drawing = draw(&setup, &stages);
    assert_eq!(drawing.status, Status::Ok);
    assert!(
        drawing.intensity_error().unwrap() > 0.4,
        "{}",
        drawing.summary()
    );
    assert!(
        drawing.summary().contains("missing (-)"),
        "the far pixel of each column is missing: {}",
        drawing.summary()
    );
    let step = &drawing.yours[1];
    assert!(
        step.note.starts_with("intensity 1.000, the definition's"),
        "{}",
        step.note
    );
}

#[test]
fn a_wrong_line_shows_its_extra_and_missing_pixels() {
    let mut stages = Stages::yours();
    // Rounds the wrong way: one row too high wherever the line is not flat.
    stages.midpoint.run = Some(Arc::new(
        |from: Pixel, to: Pixel, plot: &mut dyn FnMut(Pixel)| {
            for x in from.x..=to.x {
                let t = f64::from(x - from.x) / f64::from((to.x - from.x).max(1));
                let y = f64::from(from.y) + t * f64::from(to.y - from.y);
                #[allow(clippy::cast_possible_truncation)]
                plot(Pixel::new(x, y.ceil() as i32));
            }
        },
    ));
    let setup = Setup {
        primitive: Primitive::MidpointLine,
        handles: [Vec2::new(1.0, 1.0), Vec2::new(13.0, 6.0), Vec2::ZERO],
        ..Setup::default()
    };
    let drawing = draw(&setup, &stages);
    assert_eq!(drawing.status, Status::Ok);
    let cells = drawing.cells(drawing.yours.len());
    let count = |want: Cell| cells.iter().filter(|(_, c)| *c == want).count();
    assert!(count(Cell::OnlyYours) > 0 && count(Cell::OnlyYours) == count(Cell::OnlyExpected));
    assert!(
        drawing.summary().contains("only yours (+)"),
        "{}",
        drawing.summary()
    );
    // Stepping through: after the first pixel only it is plotted.
    let first = drawing.cells(1);
    assert_eq!(
        first.iter().filter(|(_, c)| *c == Cell::Both).count(),
        1,
        "one pixel after one step"
    );
    assert!(
        drawing.yours[1]
            .note
            .contains("the ideal line crosses column x = 2")
    );
}

#[test]
fn an_unfinished_or_runaway_stage_is_named_and_stopped() {
    let mut stages = Stages::yours();
    stages.circle.run = Some(Arc::new(|_: Pixel, _: i32, _: &mut dyn FnMut(Pixel)| {
        todo!("midpoint_circle: walk the second octant")
    }));
    stages.midpoint.run = Some(Arc::new(
        |from: Pixel, _: Pixel, plot: &mut dyn FnMut(Pixel)| {
            // A loop whose end condition never holds.
            loop {
                plot(from);
            }
        },
    ));
    let circle = draw(
        &Setup {
            primitive: Primitive::Circle,
            ..Setup::default()
        },
        &stages,
    );
    assert_eq!(
        circle.status,
        Status::NotYet("midpoint_circle: walk the second octant".to_owned())
    );
    assert!(circle.yours.is_empty());
    let line = draw(
        &Setup {
            primitive: Primitive::MidpointLine,
            ..Setup::default()
        },
        &stages,
    );
    match &line.status {
        Status::Panicked(message) => assert!(message.contains("endless loop?"), "{message}"),
        other => panic!("{other:?}"),
    }
    assert_eq!(line.yours.len(), MAX_PLOTS);
    assert!(
        line.summary().contains("plotted more than once"),
        "{}",
        line.summary()
    );
}
