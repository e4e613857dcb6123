//! `class.html`: the class report as a page, one section each for the
//! tasks (their histograms), the commonest failures, the members and the
//! submissions not graded.

use std::fmt::Write as _;

use super::{Bin, Class, FAILURES_SHOWN, Failure, NOT_GRADED_SHOWN, WHO_SHOWN, ratio};
use crate::grade::markup::html as escape;
pub(super) use crate::grade::markup::url as href;
use crate::grade::report;

/// Styles added to `report.html`'s: the histograms and the members'
/// lists.
const STYLE: &str = ".lead{font-size:1.1em}nav a{margin-right:1em}\
td.num,th.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}\
tr.topic th{padding-top:1em;border-bottom:2px solid #8886}\
svg.histogram{display:block}svg.histogram text{font-size:9px;fill:currentColor}\
svg.histogram .bar{fill:#5b7fbf}svg.histogram .full{fill:#197a32}\
svg.histogram .base{stroke:#8888}.who summary{cursor:pointer;white-space:nowrap}\
.who a{margin-right:.6em;white-space:nowrap}td.reason{min-width:16em;max-width:40em}\
td.where{white-space:nowrap}td.tests{font-size:.9em}td.tests summary{cursor:pointer;white-space:nowrap}td.member{white-space:nowrap}\
td.notes{font-size:.9em;max-width:48em}td.notes summary{cursor:pointer}\
.muted{opacity:.7}";

/// The whole page.
pub(super) fn page(class: &Class) -> String {
    let mut html = String::new();
    let title = match &class.class {
        Some(dir) => format!(
            "Class report: {}",
            dir.file_name().map_or_else(
                || dir.display().to_string(),
                |n| n.to_string_lossy().into_owned()
            )
        ),
        None => "Class report".to_owned(),
    };
    let _ = writeln!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>{title}</title><style>{}{STYLE}</style></head><body>\n<h1>{title}</h1>",
        crate::grade::html::STYLE,
        title = escape(&title),
    );
    if let Some(dir) = &class.class {
        let _ = writeln!(
            html,
            "<p>The submissions in <code>{}</code>; the gradebook is <a href=\"gradebook.csv\">gradebook.csv</a>, \
             this page's data <a href=\"class.json\">class.json</a>.</p>",
            escape(&dir.display().to_string())
        );
    }
    let _ = writeln!(html, "<p class=\"lead\">{}</p>", summary_line(class));
    html.push_str(
        "<nav><a href=\"#tasks\">Tasks</a><a href=\"#failures\">Commonest failures</a>\
         <a href=\"#members\">Members</a>",
    );
    if !class.ungraded.is_empty() {
        html.push_str("<a href=\"#ungraded\">Not graded</a>");
    }
    html.push_str("</nav>\n");
    tasks_section(&mut html, class);
    failures_section(&mut html, class);
    members_section(&mut html, class);
    ungraded_section(&mut html, class);
    html.push_str("</body></html>\n");
    html
}

/// "40 members graded, 2 could not be; mean score 17.5 of 22 (median 19);
/// 1 flagged, 3 incomplete."
fn summary_line(class: &Class) -> String {
    let mut line = format!("{} graded", members(class.graded));
    if class.not_graded > 0 {
        let _ = write!(
            line,
            ", <span class=\"error\">{} could not be</span>",
            class.not_graded
        );
    }
    if let (Some(mean), Some(median)) = (class.mean_score, class.median_score) {
        let _ = write!(
            line,
            "; mean score <strong>{} of {}</strong> (median {})",
            report::points(mean),
            report::points(class.max_score),
            report::points(median)
        );
    }
    if class.flagged > 0 {
        let _ = write!(
            line,
            "; <span class=\"error\">{} flagged</span>",
            class.flagged
        );
    }
    if class.incomplete > 0 {
        let _ = write!(line, "; {} incomplete", class.incomplete);
    }
    line.push('.');
    line
}

/// Per topic its tasks: points, mean, full marks and the histogram.
fn tasks_section(html: &mut String, class: &Class) {
    html.push_str(
        "<h2 id=\"tasks\">Tasks</h2>\n<p>Each task's points across the class: per bar the members \
         with at least that many points and less than the next bar's, the green bar full marks.</p>\n",
    );
    if class.tasks.is_empty() {
        html.push_str("<p class=\"muted\">No task was graded.</p>\n");
        return;
    }
    html.push_str(
        "<table><tr><th>task</th><th class=\"num\">points</th><th class=\"num\">mean</th>\
         <th class=\"num\">full marks</th><th>members by points</th></tr>\n",
    );
    let mut topic = None;
    for task in &class.tasks {
        if topic != Some(&task.topic) {
            topic = Some(&task.topic);
            // The topic's mean: its tasks' means, bonuses apart.
            let tasks = || {
                class
                    .tasks
                    .iter()
                    .filter(|t| t.topic == task.topic && !t.bonus)
            };
            let _ = writeln!(
                html,
                "<tr class=\"topic\"><th>{}</th><th class=\"num\">{}</th><th class=\"num\">{}</th>\
                 <th colspan=\"2\"></th></tr>",
                escape(&task.topic),
                report::points(report::round2(tasks().map(|t| t.points).sum())),
                report::points(report::round2(tasks().map(|t| t.mean).sum())),
            );
        }
        let _ = writeln!(
            html,
            "<tr><td><code>{id}</code>: {title}</td><td class=\"num\">{points}{bonus}</td>\
             <td class=\"num\">{mean}</td><td class=\"num {class}\">{share:.0}% <span class=\"muted\">({full} of {members})</span></td>\
             <td>{svg}</td></tr>",
            id = escape(&task.task),
            title = escape(&task.title),
            points = report::points(task.points),
            bonus = if task.bonus { " (bonus)" } else { "" },
            mean = report::points(task.mean),
            class = if task.full_marks == task.members {
                "ok"
            } else if task.full_share < 0.5 {
                "fail"
            } else {
                ""
            },
            share = task.full_share * 100.0,
            full = task.full_marks,
            members = task.members,
            svg = histogram_svg(&task.histogram),
        );
    }
    html.push_str("</table>\n");
}

/// A histogram as inline SVG: a bar a bin, its count above it, its lowest
/// points below, a tooltip that says it in words.
fn histogram_svg(bins: &[Bin]) -> String {
    const BAR: f64 = 22.0;
    const GAP: f64 = 4.0;
    const TALL: f64 = 32.0;
    const TOP: f64 = 12.0;
    let most = bins.iter().map(|b| b.count).max().unwrap_or(0).max(1);
    let width = bins.len() as f64 * (BAR + GAP);
    let base = TOP + TALL;
    let mut svg = format!(
        "<svg class=\"histogram\" xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{}\" \
         viewBox=\"0 0 {width} {}\" role=\"img\"><line class=\"base\" x1=\"0\" y1=\"{base}\" x2=\"{width}\" y2=\"{base}\"/>",
        base + 12.0,
        base + 12.0,
    );
    for (i, bin) in bins.iter().enumerate() {
        let x = i as f64 * (BAR + GAP) + GAP / 2.0;
        let tall = (TALL * bin.count as f64 / most as f64).round();
        let full = bin.from == bin.to;
        let what = if full {
            format!("full marks ({} points)", report::points(bin.to))
        } else {
            format!(
                "at least {} and less than {} points",
                report::points(bin.from),
                report::points(bin.to)
            )
        };
        let _ = write!(
            svg,
            "<g><title>{count}: {what}</title>\
             <rect class=\"{class}\" x=\"{x}\" y=\"{y}\" width=\"{BAR}\" height=\"{tall}\"/>",
            count = members(bin.count),
            what = escape(&what),
            class = if full { "full" } else { "bar" },
            y = base - tall,
        );
        let middle = x + BAR / 2.0;
        if bin.count > 0 {
            let _ = write!(
                svg,
                "<text x=\"{middle}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
                base - tall - 2.0,
                bin.count
            );
        }
        let _ = write!(
            svg,
            "<text x=\"{middle}\" y=\"{}\" text-anchor=\"middle\" class=\"muted\">{}</text></g>",
            base + 10.0,
            report::points(bin.from)
        );
    }
    svg.push_str("</svg>");
    svg
}

/// The failures most members hit, each with the members' reports. The
/// tests of a task that failed with the same reason for the same members
/// (a stub's `todo!`, say) share a row.
fn failures_section(html: &mut String, class: &Class) {
    html.push_str("<h2 id=\"failures\">Commonest failures</h2>\n");
    if class.failures.is_empty() {
        html.push_str("<p class=\"ok\">No member failed a test.</p>\n");
        return;
    }
    let rows = failure_rows(&class.failures);
    let _ = writeln!(
        html,
        "<p>A failing test with the first line of its reason, or a task or topic that could not be \
         graded, by how many members hit it; the tests of a task that failed with the same reason \
         for the same members share a row{}.</p>",
        if rows.len() > FAILURES_SHOWN {
            format!(
                "; the {FAILURES_SHOWN} commonest rows of {} (<a href=\"class.json\">class.json</a> lists every test)",
                rows.len()
            )
        } else {
            String::new()
        }
    );
    html.push_str(
        "<table><tr><th class=\"num\">members</th><th>task</th><th>tests</th><th>reason</th><th>who</th></tr>\n",
    );
    for (failure, tests) in rows.iter().take(FAILURES_SHOWN) {
        let task = match &failure.task {
            Some(task) => format!("{}/{}", escape(&failure.topic), escape(task)),
            None => escape(&failure.topic),
        };
        let names: Vec<String> = tests
            .iter()
            .map(|t| format!("<code>{}</code>", escape(t)))
            .collect();
        let links: Vec<String> = failure
            .members
            .iter()
            .map(|m| {
                format!(
                    "<a href=\"{}\">{}</a>",
                    escape(&href(&m.report)),
                    escape(&m.name)
                )
            })
            .collect();
        let _ = writeln!(
            html,
            "<tr><td class=\"num\">{count} <span class=\"muted\">({share:.0}%)</span></td>\
             <td class=\"where\">{task}</td><td class=\"tests\">{tests}</td>\
             <td class=\"reason fail\">{reason}</td><td class=\"who\">{who}</td></tr>",
            count = failure.count,
            share = ratio(failure.count, class.graded) * 100.0,
            tests = folded(&names, "<br>", 1, |n| {
                if n == 1 {
                    "1 test".to_owned()
                } else {
                    format!("{n} tests")
                }
            }),
            reason = escape(&failure.reason),
            who = folded(&links, " ", WHO_SHOWN, members),
        );
    }
    html.push_str("</table>\n");
}

/// The failures as the page's rows: each with the names of its tests,
/// the tests of one task with the same reason and the same members
/// together, in the order of the first.
pub(super) fn failure_rows(failures: &[Failure]) -> Vec<(&Failure, Vec<&str>)> {
    let mut rows: Vec<(&Failure, Vec<&str>)> = Vec::new();
    for failure in failures {
        let same = rows.iter_mut().find(|(row, _)| {
            failure.test.is_some()
                && row.test.is_some()
                && row.topic == failure.topic
                && row.task == failure.task
                && row.reason == failure.reason
                && row.members == failure.members
        });
        match same {
            Some((_, tests)) => tests.extend(failure.test.as_deref()),
            None => rows.push((failure, failure.test.as_deref().into_iter().collect())),
        }
    }
    rows
}

/// `items` joined by `between`, or, when there are more than `few`,
/// behind a click that says how many (`count`).
fn folded(items: &[String], between: &str, few: usize, count: impl Fn(usize) -> String) -> String {
    if items.len() <= few {
        items.join(between)
    } else {
        format!(
            "<details><summary>{}</summary>{}</details>",
            count(items.len()),
            items.join(between)
        )
    }
}

/// The gradebook: a row a member, linked to its report.
fn members_section(html: &mut String, class: &Class) {
    html.push_str("<h2 id=\"members\">Members</h2>\n");
    if class.members.is_empty() {
        html.push_str("<p class=\"muted\">No member was graded.</p>\n");
        return;
    }
    html.push_str(
        "<table><tr><th>member</th><th class=\"num\">points</th><th></th><th class=\"num\">bonus</th>\
         <th>complete</th><th>flagged</th><th>notes</th></tr>\n",
    );
    for member in &class.members {
        let _ = writeln!(
            html,
            "<tr><td class=\"member\"><a href=\"{href}\">{name}</a></td><td class=\"num\">{score} / {max}</td>\
             <td><progress value=\"{score}\" max=\"{max}\"></progress></td><td class=\"num\">{bonus}</td>\
             <td class=\"{complete_class}\">{complete}</td><td>{flag}</td><td class=\"notes\">{notes}</td></tr>",
            href = escape(&href(&member.report)),
            name = escape(&member.name),
            score = report::points(member.score),
            max = report::points(member.max_score),
            bonus = if member.bonus > 0.0 {
                format!("+{}", report::points(member.bonus))
            } else {
                String::new()
            },
            complete_class = if member.complete { "ok" } else { "error" },
            complete = if member.complete { "yes" } else { "no" },
            flag = if member.flagged {
                "<span class=\"error\">flagged</span>"
            } else {
                ""
            },
            // Why it is flagged, then the topics not graded, a line each
            // (many behind a click).
            notes = member
                .flag
                .iter()
                .map(|why| format!("<span class=\"error\">{}</span>", escape(why)))
                .chain(
                    Some(folded(
                        &member
                            .not_graded
                            .iter()
                            .map(|topic| escape(topic))
                            .collect::<Vec<_>>(),
                        "<br>",
                        NOT_GRADED_SHOWN,
                        |n| format!("{n} topics not graded"),
                    ))
                    .filter(|topics| !topics.is_empty()),
                )
                .collect::<Vec<_>>()
                .join("<br>"),
        );
    }
    html.push_str("</table>\n");
}

/// The submissions that could not be graded, and why.
fn ungraded_section(html: &mut String, class: &Class) {
    if class.ungraded.is_empty() {
        return;
    }
    html.push_str(
        "<h2 id=\"ungraded\">Could not be graded</h2>\n<table><tr><th>member</th><th>why</th></tr>\n",
    );
    for member in &class.ungraded {
        let _ = writeln!(
            html,
            "<tr><td>{}</td><td class=\"error\">{}</td></tr>",
            escape(&member.name),
            escape(&member.why)
        );
    }
    html.push_str("</table>\n");
}

/// "1 member", "3 members".
fn members(count: usize) -> String {
    if count == 1 {
        "1 member".to_owned()
    } else {
        format!("{count} members")
    }
}
