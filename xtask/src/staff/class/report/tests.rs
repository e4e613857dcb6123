//! Tests of the class report: its data and its page.

use super::page::{failure_rows, href};
use super::*;
use crate::grade::report::{Edition, TestReport, TopicReport};

fn test(name: &str, reason: Option<&str>) -> TestReport {
    let status = if reason.is_some() {
        TestStatus::Failed
    } else {
        TestStatus::Passed
    };
    let mut test = crate::grade::report::tests::test(name, status);
    test.reason = reason.map(str::to_owned);
    test
}

fn task(id: &str, points: f64, score: f64, tests: Vec<TestReport>) -> TaskReport {
    let failed = tests
        .iter()
        .filter(|t| t.status == TestStatus::Failed)
        .count();
    TaskReport {
        id: id.to_owned(),
        title: format!("The {id} task"),
        points,
        bonus: false,
        score,
        status: if failed == 0 {
            TaskStatus::Ok
        } else {
            TaskStatus::Fail
        },
        error: None,
        hints: Vec::new(),
        passed: tests.len() - failed,
        failed,
        ignored: 0,
        tests,
    }
}

fn topic(name: &str, tasks: Vec<TaskReport>) -> TopicReport {
    TopicReport {
        name: name.to_owned(),
        package: name.to_owned(),
        dir: PathBuf::from("exercises").join(name),
        time_limit_s: 10.0,
        memory_limit_mib: 0,
        compile_error: None,
        errors: Vec::new(),
        score: tasks.iter().map(|t| t.score).sum(),
        max_score: tasks.iter().map(|t| t.points).sum(),
        tasks,
    }
}

fn report(member: &str, topics: Vec<TopicReport>) -> Report {
    Report {
        schema: report::SCHEMA,
        root: Path::new("/class").join(member),
        edition: Edition::Student,
        score: topics.iter().map(|t| t.score).sum(),
        max_score: topics.iter().map(|t| t.max_score).sum(),
        duration_s: 1.0,
        phases: Default::default(),
        complete: topics
            .iter()
            .all(|t| t.compile_error.is_none() && t.errors.is_empty()),
        integrity: None,
        sandboxed: true,
        containment: Default::default(),
        topics,
        pipeline: Vec::new(),
        left_out: Vec::new(),
    }
}

const OUT: &str = "/grades";

/// The class's members as `submission::run` hands them over: each
/// graded one with its gradebook row.
fn graded(members: Vec<(&str, Result<Report>)>) -> (Vec<Graded>, Vec<GradebookRow>) {
    let graded: Vec<Graded> = members
        .into_iter()
        .map(|(name, report)| (name.to_owned(), Path::new(OUT).join(name), report))
        .collect();
    let rows = graded
        .iter()
        .filter_map(|(name, _, report)| {
            Some(GradebookRow::new(name.clone(), report.as_ref().ok()?))
        })
        .collect();
    (graded, rows)
}

/// Four members of a 01-lines with `dda` (4 points) and `wu` (2):
/// anna full marks, ben and cleo failing the same `dda` test with the
/// same first line (other second lines), dan's not compiling, and
/// eve not graded at all.
fn class() -> Class {
    let lines = |dda: (f64, Vec<TestReport>), wu: (f64, Vec<TestReport>)| {
        topic(
            "01-lines",
            vec![task("dda", 4.0, dda.0, dda.1), task("wu", 2.0, wu.0, wu.1)],
        )
    };
    let steep = |second: &str| Some(format!("assertion failed: steep\n{second}"));
    let anna = report(
        "anna",
        vec![lines(
            (4.0, vec![test("dda::flat", None), test("dda::steep", None)]),
            (2.0, vec![test("wu::ends", None)]),
        )],
    );
    let ben = report(
        "ben",
        vec![lines(
            (
                2.0,
                vec![
                    test("dda::flat", None),
                    test("dda::steep", steep("left: 3").as_deref()),
                ],
            ),
            (1.75, vec![test("wu::ends", Some("  \n wrong ink "))]),
        )],
    );
    let cleo = report(
        "cleo",
        vec![lines(
            (
                0.0,
                vec![
                    test("dda::flat", Some("off by one")),
                    test("dda::steep", steep("left: 5").as_deref()),
                ],
            ),
            (2.0, vec![test("wu::ends", None)]),
        )],
    );
    let mut broken = lines((0.0, Vec::new()), (0.0, Vec::new()));
    broken.compile_error = Some("error[E0425]: cannot find value `x`".to_owned());
    for task in &mut broken.tasks {
        task.status = TaskStatus::CompileError;
    }
    let dan = report("dan", vec![broken]);
    let (graded, rows) = graded(vec![
        ("anna", Ok(anna)),
        ("ben", Ok(ben)),
        ("cleo", Ok(cleo)),
        ("dan", Ok(dan)),
        (
            "eve",
            Err(anyhow::anyhow!("cannot stage eve: no space left")),
        ),
    ]);
    class_of(Path::new(OUT), &graded, &rows)
}

fn counts(stats: &TaskStats) -> Vec<usize> {
    stats.histogram.iter().map(|b| b.count).collect()
}

#[test]
fn each_task_has_its_points_in_bins_with_full_marks_apart() {
    let class = class();
    let [dda, wu] = class.tasks.as_slice() else {
        panic!("two tasks: {:?}", class.tasks);
    };
    assert_eq!((dda.topic.as_str(), dda.task.as_str()), ("01-lines", "dda"));
    // dda: 4, 2, 0, 0 of 4 points.
    assert_eq!(counts(dda), [2, 0, 1, 0, 1]);
    assert_eq!(
        dda.histogram.first(),
        Some(&Bin {
            from: 0.0,
            to: 1.0,
            count: 2
        })
    );
    assert_eq!(
        dda.histogram.last(),
        Some(&Bin {
            from: 4.0,
            to: 4.0,
            count: 1
        })
    );
    assert_eq!((dda.members, dda.full_marks, dda.full_share), (4, 1, 0.25));
    assert_eq!(dda.mean, 1.5);
    // wu: 2, 1.75, 2, 0 of 2 points.
    assert_eq!(counts(wu), [1, 1, 2]);
    assert_eq!((wu.full_marks, wu.full_share), (2, 0.5));
    assert_eq!(wu.mean, 1.44);
}

#[test]
fn bins_are_whole_points_and_wider_for_tasks_worth_many() {
    let scores = [0.0, 0.99, 1.0, 2.5, 2.99, 3.0];
    let bins = histogram(&scores, 3.0);
    let counts: Vec<usize> = bins.iter().map(|b| b.count).collect();
    assert_eq!(counts, [2, 1, 2, 1]);
    let edges: Vec<(f64, f64)> = bins.iter().map(|b| (b.from, b.to)).collect();
    assert_eq!(edges, [(0.0, 1.0), (1.0, 2.0), (2.0, 3.0), (3.0, 3.0)]);
    // A point and a half: a bin stops at the points.
    let half = histogram(&[1.2, 1.5], 1.5);
    let edges: Vec<(f64, f64, usize)> = half.iter().map(|b| (b.from, b.to, b.count)).collect();
    assert_eq!(edges, [(0.0, 1.0, 0), (1.0, 1.5, 1), (1.5, 1.5, 1)]);
    // 50 points: bins of 3, at most MAX_BINS of them and full marks.
    let wide = histogram(&[0.0, 49.0, 50.0], 50.0);
    assert_eq!(wide.len(), 18);
    assert_eq!(wide.iter().map(|b| b.count).sum::<usize>(), 3);
    assert_eq!(wide[16].count, 1, "49 points is in [48, 50)");
}

#[test]
fn the_commonest_failures_come_first_with_their_members() {
    let class = class();
    let shown: Vec<String> = class
        .failures
        .iter()
        .map(|f| {
            format!(
                "{} {}/{} {}: {}",
                f.count,
                f.topic,
                f.task.as_deref().unwrap_or("-"),
                f.test.as_deref().unwrap_or("-"),
                f.reason
            )
        })
        .collect();
    assert_eq!(
        shown,
        [
            "2 01-lines/dda dda::steep: assertion failed: steep",
            "1 01-lines/- -: the topic does not compile",
            "1 01-lines/dda dda::flat: off by one",
            "1 01-lines/wu wu::ends: wrong ink",
        ]
    );
    let steep: Vec<(&str, &str)> = class.failures[0]
        .members
        .iter()
        .map(|m| (m.name.as_str(), m.report.as_str()))
        .collect();
    assert_eq!(
        steep,
        [("ben", "ben/report.html"), ("cleo", "cleo/report.html")]
    );
}

#[test]
fn every_member_has_its_gradebook_row_and_the_ungraded_their_reason() {
    let class = class();
    assert_eq!((class.graded, class.not_graded), (4, 1));
    let members: Vec<(&str, f64, bool, &str)> = class
        .members
        .iter()
        .map(|m| (m.name.as_str(), m.score, m.complete, m.report.as_str()))
        .collect();
    assert_eq!(
        members,
        [
            ("anna", 6.0, true, "anna/report.html"),
            ("ben", 3.75, true, "ben/report.html"),
            ("cleo", 2.0, true, "cleo/report.html"),
            ("dan", 0.0, false, "dan/report.html"),
        ]
    );
    assert_eq!(class.mean_score, Some(2.94));
    assert_eq!(class.median_score, Some(2.88));
    assert_eq!(class.max_score, 6.0);
    assert_eq!(class.incomplete, 1);
    assert_eq!(class.class.as_deref(), Some(Path::new("/class")));
    let [eve] = class.ungraded.as_slice() else {
        panic!("one not graded: {:?}", class.ungraded);
    };
    assert_eq!(eve.name, "eve");
    assert_eq!(eve.why, "cannot stage eve: no space left");
}

#[test]
fn the_page_draws_the_histograms_and_links_the_reports() {
    let html = page(&class());
    assert!(html.contains("4 members graded"), "{html}");
    assert!(html.contains("1 could not be"));
    assert!(html.contains("mean score <strong>2.94 of 6</strong> (median 2.88)"));
    assert_eq!(html.matches("<svg class=\"histogram\"").count(), 2);
    assert!(html.contains("<a href=\"./ben/report.html\">ben</a>"));
    assert!(html.contains("cannot stage eve: no space left"));
    assert!(!html.contains("<script"));
}

#[test]
fn the_page_says_why_a_member_is_flagged_and_folds_long_lists_of_members() {
    let mut class = class();
    class.members[1].flagged = true;
    class.members[1].flag = Some("1 grading file(s) differ".to_owned());
    let many: Vec<Link> = (0..=WHO_SHOWN)
        .map(|i| {
            link(
                Path::new(OUT),
                &format!("m{i}"),
                &Path::new(OUT).join(format!("m{i}/report.html")),
            )
        })
        .collect();
    class.failures[0].count = many.len();
    class.failures[0].members = many;
    let html = page(&class);
    assert!(html.contains("<span class=\"error\">1 grading file(s) differ</span>"));
    assert!(html.contains("01-lines: does not compile"));
    // Many topics not graded are folded.
    class.members[3].not_graded = (1..=NOT_GRADED_SHOWN + 1)
        .map(|n| format!("0{n}-x: does not compile"))
        .collect();
    let html = page(&class);
    assert!(html.contains(&format!(
        "<details><summary>{} topics not graded</summary>01-x: does not compile<br>",
        NOT_GRADED_SHOWN + 1
    )));
    assert!(html.contains(&format!(
        "<details><summary>{} members</summary><a href=\"./m0/report.html\">m0</a>",
        WHO_SHOWN + 1
    )));
    // The other failures name their one member at once.
    assert!(html.contains("<td class=\"who\"><a href=\"./cleo/report.html\">cleo</a></td>"));
}

#[test]
fn tests_failing_alike_share_a_row_of_the_page() {
    let who = |names: &[&str]| -> Vec<Link> {
        names
            .iter()
            .map(|n| {
                link(
                    Path::new(OUT),
                    n,
                    &Path::new(OUT).join(n).join("report.html"),
                )
            })
            .collect()
    };
    let failure = |task: &str, test: Option<&str>, reason: &str, members: &[&str]| Failure {
        topic: "02-circles".to_owned(),
        task: Some(task.to_owned()),
        test: test.map(str::to_owned),
        reason: reason.to_owned(),
        count: members.len(),
        members: who(members),
    };
    let todo = "not implemented yet: filled_circle";
    let failures = [
        failure("filled", Some("a"), todo, &["ann", "ben"]),
        failure("filled", Some("b"), todo, &["ann", "ben"]),
        failure("filled", None, todo, &["ann", "ben"]),
        failure("filled", Some("c"), todo, &["ann"]),
        failure("other", Some("d"), todo, &["ann"]),
        failure("filled", Some("e"), todo, &["ann"]),
    ];
    let rows: Vec<(Option<&str>, Vec<&str>)> = failure_rows(&failures)
        .into_iter()
        .map(|(f, tests)| (f.task.as_deref(), tests))
        .collect();
    assert_eq!(
        rows,
        [
            (Some("filled"), vec!["a", "b"]),
            (Some("filled"), vec![]),
            (Some("filled"), vec!["c", "e"]),
            (Some("other"), vec!["d"]),
        ]
    );
}

#[test]
fn member_names_and_reasons_cannot_add_markup_or_links() {
    assert_eq!(href("a b#1/report.html"), "./a%20b%231/report.html");
    assert_eq!(
        href("javascript:alert(1)/report.html"),
        "./javascript:alert(1)/report.html"
    );
    let mut class = class();
    class.failures[0].reason = "<img src=x onerror=alert(1)>".to_owned();
    class.members[0].name = "<b>anna</b>".to_owned();
    let html = page(&class);
    assert!(!html.contains("<img"));
    assert!(!html.contains("<b>anna"));
    assert!(html.contains("&lt;img src=x"));
}
