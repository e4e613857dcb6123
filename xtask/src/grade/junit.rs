//! `junit.xml`: the grade as JUnit XML, for CI test viewers.

use std::fmt::Write as _;

use super::markup::{xml_attr, xml_text};
use super::report::{self, Report, TaskStatus, TestStatus};

/// One `<testsuite>` per topic, one `<testcase>` per test; a topic that did
/// not compile has one errored case per task.
#[must_use]
pub fn junit(report: &Report) -> String {
    let mut suites = String::new();
    let (mut all_tests, mut all_failures, mut all_errors) = (0, 0, 0);
    for topic in &report.topics {
        let mut cases = String::new();
        let (mut tests, mut failures, mut errors, mut skipped) = (0, 0, 0, 0);
        let mut time = 0.0;
        let mut case = |class: &str, name: &str, time: f64, body: &str| {
            let _ = write!(
                cases,
                "    <testcase classname=\"{}\" name=\"{}\" time=\"{time:.3}\"",
                xml_attr(class),
                xml_attr(name)
            );
            if body.is_empty() {
                cases.push_str("/>\n");
            } else {
                let _ = write!(cases, ">\n{body}    </testcase>\n");
            }
        };
        for error in &topic.errors {
            tests += 1;
            errors += 1;
            let body = format!(
                "      <error message=\"{}\" type=\"test layout\"/>\n",
                xml_attr(error)
            );
            case(&topic.name, "test layout", 0.0, &body);
        }
        for task in &topic.tasks {
            let class = format!("{}.{}", topic.name, task.id);
            let not_graded = match task.status {
                TaskStatus::CompileError => Some((
                    "compile error",
                    topic.compile_error.as_deref().unwrap_or_default(),
                )),
                TaskStatus::Error => {
                    Some(("not graded", task.error.as_deref().unwrap_or_default()))
                }
                TaskStatus::Ok | TaskStatus::Fail => None,
            };
            if let Some((message, details)) = not_graded {
                tests += 1;
                errors += 1;
                let body = format!(
                    "      <error message=\"{}\" type=\"{message}\">{}</error>\n",
                    xml_attr(&format!(
                        "{message}: {}",
                        details.lines().next().unwrap_or_default()
                    )),
                    xml_text(details)
                );
                case(&class, &task.id, 0.0, &body);
            }
            for test in &task.tests {
                tests += 1;
                time += test.duration_s;
                let body = match test.status {
                    TestStatus::Passed => String::new(),
                    TestStatus::Ignored => {
                        skipped += 1;
                        "      <skipped/>\n".to_owned()
                    }
                    TestStatus::Failed => {
                        failures += 1;
                        let reason = test.reason.as_deref().unwrap_or("failed");
                        format!(
                            "      <failure message=\"{}\" type=\"{}\">{}</failure>\n      <system-out>{}</system-out>\n",
                            xml_attr(reason),
                            xml_attr(reason.split(':').next().unwrap_or("failed")),
                            xml_text(&failure_details(test)),
                            xml_text(test.output.as_deref().unwrap_or_default())
                        )
                    }
                };
                case(&class, &test.name, test.duration_s, &body);
            }
        }
        let _ = write!(
            suites,
            "  <testsuite name=\"{}\" tests=\"{tests}\" failures=\"{failures}\" errors=\"{errors}\" skipped=\"{skipped}\" time=\"{time:.3}\">\n{cases}  </testsuite>\n",
            xml_attr(&topic.name)
        );
        all_tests += tests;
        all_failures += failures;
        all_errors += errors;
    }
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"cargo xtask grade\" tests=\"{all_tests}\" failures=\"{all_failures}\" errors=\"{all_errors}\" time=\"{:.3}\">\n{suites}</testsuites>\n",
        report.duration_s
    )
}

fn failure_details(test: &report::TestReport) -> String {
    let mut text = test.reason.clone().unwrap_or_default();
    if let Some(location) = &test.panic_location {
        let _ = write!(text, "\nat {location}");
    }
    text.push_str(&test.evidence());
    text
}
