//! The curve scene without a window: what it draws with your
//! `de_casteljau`, right, wrong or unfinished.

use std::sync::Arc;

use course_viewer::scenes::curves::{CurveSetup, SAMPLES, definition, draw};
use course_viewer::{Stages, Status};
use glam::DVec2;

#[test]
fn the_solutions_curve_is_the_definitions() {
    course_viewer::stages::quiet_panics();
    for n in 2..=course_viewer::scenes::curves::MAX_POINTS {
        let setup = CurveSetup {
            points: course_viewer::scenes::curves::first_points(n),
            t: 0.3,
            ..CurveSetup::default()
        };
        let drawing = draw(&setup, &Stages::yours());
        assert_eq!(drawing.status, Status::Ok, "{n} points");
        assert!(drawing.deviation.unwrap() < 1e-12, "{n} points");
        let last = drawing.levels.last().unwrap();
        assert_eq!(last.len(), 1, "{n} points: the construction ends in C(t)");
        assert!(last[0].distance(definition(&setup.points, 0.3)) < 1e-12);
    }
}

#[test]
fn a_wrong_curve_shows_how_far_it_lies_from_the_definition() {
    let mut stages = Stages::yours();
    // Linear interpolation between the end points: a common slip.
    stages.curve.run = Some(Arc::new(|points: &[DVec2], t: f64| {
        Ok(points[0].lerp(points[points.len() - 1], t))
    }));
    let drawing = draw(&CurveSetup::default(), &stages);
    assert_eq!(drawing.status, Status::Ok);
    assert_eq!(drawing.yours.len(), SAMPLES + 1);
    assert!(
        drawing.deviation.unwrap() > 0.3,
        "the straight line lies far from the arch: {:?}",
        drawing.deviation
    );
}

#[test]
fn an_error_or_a_panic_is_named_and_stops_the_drawing() {
    course_viewer::stages::quiet_panics();
    let mut stages = Stages::yours();
    stages.curve.run = Some(Arc::new(|_: &[DVec2], t: f64| {
        if t > 0.5 {
            Err("t out of range".to_owned())
        } else {
            Ok(DVec2::ZERO)
        }
    }));
    let drawing = draw(&CurveSetup::default(), &stages);
    assert_eq!(drawing.status, Status::Failed("t out of range".to_owned()));
    assert_eq!(drawing.yours.len(), SAMPLES / 2 + 1, "drawn up to t = ½");
    assert_eq!(drawing.deviation, None);

    stages.curve.run = Some(Arc::new(|points: &[DVec2], _: f64| Ok(points[7])));
    let drawing = draw(&CurveSetup::default(), &stages);
    assert!(
        matches!(&drawing.status, Status::Panicked(m) if m.contains("index out of bounds")),
        "{:?}",
        drawing.status
    );
    assert!(drawing.yours.is_empty());

    let none = draw(&CurveSetup::default(), &Stages::default());
    assert_eq!(
        none.status,
        Status::Missing,
        "without topic 07 in the build"
    );
}

#[test]
fn a_set_up_is_kept_drawable() {
    let mut setup = CurveSetup {
        points: vec![DVec2::new(2.0, -1.0)],
        t: f64::NAN,
        ..CurveSetup::default()
    };
    setup.tidy();
    assert_eq!(setup.points.len(), 2);
    assert!(
        setup
            .points
            .iter()
            .all(|p| (0.0..=1.0).contains(&p.x) && (0.0..=1.0).contains(&p.y))
    );
    assert_eq!(setup.t, 0.5);
    setup.set_count(20);
    assert_eq!(
        setup.points.len(),
        course_viewer::scenes::curves::MAX_POINTS
    );
    setup.set_count(3);
    assert_eq!(setup.points.len(), 3);
}

fn nurbs(n: usize, degree: usize, weights: Vec<f64>) -> CurveSetup {
    CurveSetup {
        points: course_viewer::scenes::curves::first_points(n),
        kind: course_viewer::scenes::curves::CurveKind::Nurbs,
        degree,
        weights,
        ..CurveSetup::default()
    }
}

#[test]
fn the_solutions_nurbs_curve_is_the_definitions() {
    course_viewer::stages::quiet_panics();
    for n in 2..=course_viewer::scenes::curves::MAX_POINTS {
        for degree in 1..n {
            let weights = (0..n).map(|k| 0.5 + (k % 3) as f64).collect();
            let drawing = draw(&nurbs(n, degree, weights), &Stages::yours());
            assert_eq!(drawing.status, Status::Ok, "{n} points, degree {degree}");
            assert!(
                drawing.deviation.unwrap() < 1e-12,
                "{n} points, degree {degree}: {:?}",
                drawing.deviation
            );
            assert_eq!(
                drawing.knot_points.len(),
                n - degree - 1,
                "one point per interior knot"
            );
        }
    }
}

#[test]
fn a_nurbs_curve_of_the_highest_degree_and_equal_weights_is_the_bezier_curve() {
    let setup = nurbs(5, 4, vec![2.0; 5]);
    let drawing = draw(&setup, &Stages::yours());
    for (k, p) in drawing.yours.iter().enumerate() {
        let t = k as f64 / SAMPLES as f64;
        assert!(p.distance(definition(&setup.points, t)) < 1e-12, "t = {t}");
    }
}

#[test]
fn a_heavier_weight_pulls_the_curve_to_its_point() {
    let light = draw(&nurbs(4, 2, vec![1.0; 4]), &Stages::yours());
    let heavy = draw(&nurbs(4, 2, vec![1.0, 6.0, 1.0, 1.0]), &Stages::yours());
    let p1 = light.setup.points[1];
    let nearest = |d: &course_viewer::scenes::curves::CurveDrawing| {
        d.yours
            .iter()
            .map(|p| p.distance(p1))
            .fold(f64::INFINITY, f64::min)
    };
    assert!(
        nearest(&heavy) < 0.5 * nearest(&light),
        "{} vs {}",
        nearest(&heavy),
        nearest(&light)
    );
}

#[test]
fn an_unwritten_nurbs_curve_is_named() {
    course_viewer::stages::quiet_panics();
    let mut stages = Stages::yours();
    stages.nurbs.run = Some(Arc::new(
        |_: &[DVec2], _: &[f64], _: usize, _: f64| -> Result<DVec2, String> {
            todo!("nurbs: find the span, combine p + 1 homogeneous points, project")
        },
    ));
    let drawing = draw(&nurbs(4, 2, vec![1.0; 4]), &stages);
    assert_eq!(
        drawing.status,
        Status::NotYet(
            "nurbs: find the span, combine p + 1 homogeneous points, project".to_owned()
        )
    );
    assert!(drawing.yours.is_empty() && drawing.knot_points.is_empty());
    assert_eq!(
        drawing.expected.len(),
        SAMPLES + 1,
        "the definition still shows"
    );
    let none = draw(&nurbs(4, 2, vec![1.0; 4]), &Stages::default());
    assert_eq!(
        none.status,
        Status::Missing,
        "without topic 08 in the build"
    );
}
