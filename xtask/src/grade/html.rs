//! `report.html`: the grade report as one page a tutor or student opens in
//! a browser. Per topic a table of tasks; per failing task its first
//! failure (reason, minimal input, raster and snapshot diffs); per test
//! that wrote pictures the pictures side by side (`yours.png`,
//! `reference.png`, `difference.png` ...), linked relative to the page, so
//! the whole `target/grade/` folder can be zipped and mailed.

use super::markup::html as escape;
use std::fmt::Write as _;
use std::path::Path;

use super::report::{
    self, Edition, Report, TaskReport, TaskStatus, TestReport, TestStatus, TopicReport,
};

/// Styles for the page: readable in light and dark mode, monospace diffs.
pub(crate) const STYLE: &str = "body{font-family:system-ui,sans-serif;margin:2em;max-width:96em}\
table{border-collapse:collapse;margin:.5em 0}td,th{padding:.25em .75em;text-align:left;\
border-bottom:1px solid #8884}.ok{color:#197a32}.fail{color:#b3261e}.error{color:#a15c00}\
pre{background:#8881;padding:.75em;overflow-x:auto}figure{display:inline-block;margin:.5em}\
figure img{image-rendering:pixelated;min-width:8em;max-width:24em;border:1px solid #8886}\
figcaption{font-size:.85em;text-align:center}progress{width:10em}\
.task{display:flex;flex-wrap:wrap;gap:0 2em;align-items:flex-start}.task>div{min-width:0;max-width:100%}\
.task>div:first-child{flex:1 1 26em}.task>div:last-child{flex:0 1 auto}\
.compare{display:inline-block;margin:.5em 1em .5em 0;vertical-align:top}\
.compare .view{position:relative;display:inline-block;line-height:0;border:1px solid #8886}\
.compare .view img{image-rendering:pixelated;image-rendering:crisp-edges}\
.compare .grid{position:absolute;inset:0;pointer-events:none;background-image:\
linear-gradient(to right,#8886 1px,transparent 1px),linear-gradient(to bottom,#8886 1px,transparent 1px)}\
.compare .switch{font-size:.9em;margin:.25em 0}.compare .switch label{margin-right:.75em}";

/// Turns each `.compare` (a comparison's pictures, shown side by side
/// without it) into one magnified view with a switch between its pictures:
/// the largest whole magnification that fits 480 pixels, no smoothing, a
/// pixel grid from 6× on. Inline, so the page works from a zip.
const SCRIPT: &str = r#"<script>
document.querySelectorAll('.compare').forEach((box, n) => {
  const figures = [...box.querySelectorAll('figure')];
  const images = figures.map(f => f.querySelector('img'));
  const view = document.createElement('div');
  view.className = 'view';
  const grid = document.createElement('div');
  grid.className = 'grid';
  const shown = images[0].cloneNode();
  view.append(shown, grid);
  const bar = document.createElement('div');
  bar.className = 'switch';
  figures.forEach((figure, k) => {
    const label = document.createElement('label');
    const radio = document.createElement('input');
    radio.type = 'radio';
    radio.name = 'compare-' + n;
    radio.checked = k === 0;
    radio.addEventListener('change', () => { shown.src = images[k].src; shown.alt = images[k].alt; });
    label.append(radio, ' ' + figure.querySelector('figcaption').textContent);
    bar.append(label);
  });
  const fit = () => {
    const w = shown.naturalWidth, h = shown.naturalHeight;
    if (!w) return;
    const scale = Math.max(1, Math.floor(480 / Math.max(w, h)));
    shown.style.width = w * scale + 'px';
    shown.style.height = h * scale + 'px';
    grid.style.backgroundSize = scale + 'px ' + scale + 'px';
    grid.hidden = scale < 6;
    box.dataset.scale = scale;
  };
  shown.addEventListener('load', fit);
  figures.forEach(f => f.remove());
  const title = box.querySelector(':scope > p');
  if (title) title.after(bar, view); else box.prepend(bar, view);
  fit();
});
</script>
"#;

/// The whole page.
#[must_use]
pub fn page(report: &Report) -> String {
    let mut html = String::new();
    let edition = match report.edition {
        Edition::Student => "student code",
        Edition::Reference => "reference solutions",
    };
    let name = escape(&report.name());
    let points = points_line(report);
    let _ = writeln!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>{name}: {points}</title><style>{STYLE}</style></head><body>\n\
         <h1>{name}: {points}</h1>\n<p>{edition} in <code>{}</code>, graded in {:.0} s{}{}</p>",
        escape(&report.root.display().to_string()),
        report.duration_s,
        if report.complete {
            ""
        } else {
            "; <span class=\"error\">incomplete: some tasks could not be graded</span>"
        },
        if report.sandboxed {
            ""
        } else {
            "; <span class=\"error\">unsandboxed</span>"
        },
    );
    if let Some(integrity) = report.integrity.as_ref().filter(|i| i.flagged()) {
        let _ = writeln!(
            html,
            "<p class=\"error\"><strong>Flagged:</strong> {}</p>",
            escape(&integrity.summary())
        );
    }
    if !report.left_out.is_empty() {
        let items: String = report
            .left_out
            .iter()
            .map(|line| format!("<li><code>{}</code></li>", escape(line)))
            .collect();
        let _ = writeln!(
            html,
            "<p class=\"error\"><strong>Left out of this report</strong>: what the tests left in it that is no plain file, or past the {} it keeps, was removed:</p>\n<ul>{items}</ul>",
            crate::files::size(crate::files::KEPT_BUDGET)
        );
    }
    let reviewed: Vec<String> = report
        .topics
        .iter()
        .flat_map(|topic| topic.tasks.iter().map(move |task| (topic, task)))
        .flat_map(|(topic, task)| {
            task.tests
                .iter()
                .filter(|t| t.reviewed.is_some())
                .map(move |test| format!("{} / {}: {}", topic.name, task.id, test.name))
        })
        .collect();
    if !reviewed.is_empty() {
        let _ = writeln!(
            html,
            "<p><strong>Reviewed:</strong> {} test(s) pass because a tutor accepted their snapshot in review: {}</p>",
            reviewed.len(),
            escape(&reviewed.join(", "))
        );
    }
    summary(&mut html, report);
    for topic in &report.topics {
        let _ = writeln!(
            html,
            "<h2 id=\"{}\">{} <small>({} of {} points)</small></h2>",
            topic_anchor(&topic.name),
            escape(&topic.name),
            report::points(topic.score),
            report::points(topic.max_score),
        );
        if let Some(error) = &topic.compile_error {
            let _ = writeln!(
                html,
                "<p class=\"error\">The topic does not compile:</p><pre>{}</pre>",
                escape(error)
            );
        }
        for error in &topic.errors {
            let _ = writeln!(html, "<p class=\"error\">{}</p>", escape(error));
        }
        html.push_str(
            "<table><tr><th>task</th><th>points</th><th>tests</th><th>status</th></tr>\n",
        );
        for task in &topic.tasks {
            let _ = writeln!(
                html,
                "<tr><td><a href=\"#{anchor}\">{id}</a>: {title}</td><td>{score} / {points}{bonus}</td>\
                 <td>{passed} of {run}</td><td class=\"{class}\">{status}</td></tr>",
                anchor = anchor(&topic.name, &task.id),
                id = escape(&task.id),
                title = escape(&task.title),
                score = report::points(task.score),
                points = report::points(task.points),
                bonus = if task.bonus { " (bonus)" } else { "" },
                passed = task.passed,
                run = task.passed + task.failed,
                class = status_class(task.status),
                status = status_word(task.status),
            );
        }
        html.push_str("</table>\n");
        for task in &topic.tasks {
            task_section(&mut html, &topic.name, task);
        }
    }
    pipeline_section(&mut html, &report.pipeline);
    html.push_str(SCRIPT);
    html.push_str("</body></html>\n");
    html
}

/// "19 of 22 points + 3 bonus": the points of the tasks that are not
/// bonuses against their maximum, and the bonus apart.
fn points_line(report: &Report) -> String {
    let base: f64 = report.topics.iter().map(TopicReport::base_score).sum();
    let bonus: f64 = report.topics.iter().map(|t| t.bonus().0).sum();
    let mut line = format!(
        "{} of {} points",
        report::points(report::round2(base)),
        report::points(report.max_score)
    );
    if bonus > 0.0 {
        let _ = write!(line, " + {} bonus", report::points(report::round2(bonus)));
    }
    line
}

/// The summary across topics, first: points (bonus points apart, so that
/// a bonus never hides a lost point), a bar, and how many tasks are done,
/// each topic linked to its section.
fn summary(html: &mut String, report: &Report) {
    html.push_str(
        "<table id=\"summary\"><tr><th>topic</th><th>points</th><th></th><th>bonus</th><th>tasks done</th></tr>\n",
    );
    let bonus_cell = |(earned, possible): (f64, f64)| {
        if possible > 0.0 {
            format!(
                "+{} of {}",
                report::points(earned),
                report::points(possible)
            )
        } else {
            String::new()
        }
    };
    let (mut base, mut bonus) = (0.0, (0.0, 0.0));
    for topic in &report.topics {
        let done = topic
            .tasks
            .iter()
            .filter(|t| t.status == TaskStatus::Ok)
            .count();
        let score = topic.base_score();
        let topic_bonus = topic.bonus();
        base += score;
        bonus = (bonus.0 + topic_bonus.0, bonus.1 + topic_bonus.1);
        let _ = writeln!(
            html,
            "<tr><td><a href=\"#{anchor}\">{name}</a></td><td>{score} / {max}</td>\
             <td><progress value=\"{score}\" max=\"{max}\"></progress></td><td>{bonus}</td>\
             <td class=\"{class}\">{done} of {tasks}</td></tr>",
            anchor = topic_anchor(&topic.name),
            name = escape(&topic.name),
            score = report::points(score),
            max = report::points(topic.max_score),
            bonus = bonus_cell(topic_bonus),
            class = if done == topic.tasks.len() {
                "ok"
            } else {
                "fail"
            },
            tasks = topic.tasks.len(),
        );
    }
    let _ = writeln!(
        html,
        "<tr><th>total</th><th>{} / {}</th><th></th><th>{}</th><th></th></tr></table>",
        report::points(report::round2(base)),
        report::points(report.max_score),
        bonus_cell(bonus)
    );
    if !report.pipeline.is_empty() {
        html.push_str("<p><a href=\"#pipeline\">Your pipeline</a>: the shipped meshes and the NURBS chain drawn by your stages.</p>\n");
    }
}

/// "Your pipeline": the shipped meshes and the NURBS chain drawn by the
/// graded stages, beside what the solutions draw, with how each stage
/// fared.
fn pipeline_section(html: &mut String, pictures: &[super::pipeline::PipelinePicture]) {
    if pictures.is_empty() {
        return;
    }
    html.push_str(
        "<h2 id=\"pipeline\">Your pipeline</h2>\n<p>The shipped meshes transformed by the course, then clipped, \
         drawn and depth-tested by your stages; the NURBS chain split and tessellated by your \
         stages (no points; <code>cargo xtask view</code> shows them in a window). A picture is \
         drawn when the assignment holds its topics.</p>\n",
    );
    for picture in pictures {
        let _ = writeln!(html, "<div><p>{}</p>", escape(&picture.what));
        for (path, caption) in [(&picture.yours, "yours"), (&picture.expected, "expected")] {
            if let Some(path) = path {
                let _ = writeln!(
                    html,
                    "<figure><a href=\"{src}\"><img src=\"{src}\" alt=\"{caption}\"></a>\
                     <figcaption>{caption}</figcaption></figure>",
                    src = escape(&url(path)),
                );
            }
        }
        if let Some(error) = &picture.error {
            let _ = writeln!(html, "<p class=\"error\">{}</p>", escape(error));
        }
        if !picture.stages.is_empty() {
            let _ = writeln!(html, "<pre>{}</pre>", escape(&picture.stages.join("\n")));
        }
        html.push_str("</div>\n");
    }
}

/// A task's heading, its first failure and its pictures.
fn task_section(html: &mut String, topic: &str, task: &TaskReport) {
    let pictures: Vec<&TestReport> = task.tests.iter().filter(|t| !t.images.is_empty()).collect();
    let failure = task.first_failure();
    if failure.is_none() && pictures.is_empty() && task.error.is_none() {
        return;
    }
    let _ = writeln!(
        html,
        "<h3 id=\"{}\">{} / {}</h3>",
        anchor(topic, &task.id),
        escape(topic),
        escape(&task.id)
    );
    if let Some(error) = &task.error {
        let _ = writeln!(html, "<p class=\"error\">Not graded: {}</p>", escape(error));
    }
    // The failing case on the left, the pictures beside it (the first
    // failing test's first).
    html.push_str("<div class=\"task\"><div>\n");
    if let Some(test) = failure {
        let _ = writeln!(
            html,
            "<p class=\"fail\">First failing test: <code>{}</code>{}</p>",
            escape(&test.name),
            test.panic_location
                .as_deref()
                .map(|at| format!(" at <code>{}</code>", escape(at)))
                .unwrap_or_default()
        );
        let blocks = [
            ("Reason", &test.reason),
            ("Minimal failing input", &test.minimal_input),
            (
                "Raster diff: # in both, + only yours, - only expected",
                &test.raster_diff,
            ),
            ("Snapshot diff: - expected, + yours", &test.snapshot_diff),
        ];
        for (title, text) in blocks {
            if let Some(text) = text {
                let _ = writeln!(html, "<p>{title}:</p><pre>{}</pre>", escape(text));
            }
        }
        if task.failed > 1 {
            let _ = writeln!(
                html,
                "<p>{} other test(s) of this task failed too.</p>",
                task.failed - 1
            );
        }
        if !task.hints.is_empty() {
            let _ = writeln!(
                html,
                "<details class=\"hints\"><summary>Hints ({}): open one at a time, or <code>cargo xtask hint {}/{}</code></summary><ol>",
                task.hints.len(),
                escape(topic),
                escape(&task.id)
            );
            for hint in &task.hints {
                let _ = writeln!(
                    html,
                    "<li><details><summary>next hint</summary>{}</details></li>",
                    escape(hint)
                );
            }
            let _ = writeln!(html, "</ol></details>");
        }
    }
    html.push_str("</div><div>\n");
    let mut pictures = pictures;
    pictures.sort_by_key(|t| failure.is_none_or(|f| f.name != t.name));
    for test in pictures {
        let Some(dir) = &test.images_dir else {
            continue;
        };
        let _ = writeln!(
            html,
            "<div><p><code>{}</code> <span class=\"{}\">{}</span></p>",
            escape(&test.name),
            if test.status == TestStatus::Failed {
                "fail"
            } else {
                "ok"
            },
            match test.status {
                TestStatus::Passed => "passed",
                TestStatus::Failed => "failed",
                TestStatus::Ignored => "ignored",
            }
        );
        // One comparison per folder the test wrote (`dda_star/yours.png`,
        // `dda_star/reference.png`, ...).
        let mut images: Vec<&std::path::PathBuf> = test.images.iter().collect();
        images.sort_by_key(|image| (image.parent(), picture_rank(image), image.as_path()));
        for group in images.chunk_by(|a, b| a.parent() == b.parent()) {
            let name = group[0]
                .parent()
                .filter(|p| !p.as_os_str().is_empty())
                .map(|p| p.display().to_string());
            html.push_str("<div class=\"compare\">");
            if let Some(name) = name {
                let _ = write!(html, "<p><small>{}</small></p>", escape(&name));
            }
            for image in group {
                let path = dir.join(image);
                let caption = image
                    .file_stem()
                    .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
                let _ = write!(
                    html,
                    "<figure><a href=\"{src}\"><img src=\"{src}\" alt=\"{caption}\"></a>\
                     <figcaption>{caption}</figcaption></figure>",
                    src = escape(&url(&path)),
                    caption = escape(&caption),
                );
            }
            html.push_str("</div>\n");
        }
        html.push_str("</div>\n");
    }
    html.push_str("</div></div>\n");
}

/// Pictures of one comparison in reading order: yours, then the
/// reference, then the difference; other files after them.
fn picture_rank(image: &Path) -> u8 {
    match image.file_stem().and_then(|stem| stem.to_str()) {
        Some("yours") => 0,
        Some("reference") => 1,
        Some("difference") => 2,
        _ => 3,
    }
}

fn status_word(status: TaskStatus) -> &'static str {
    match status {
        TaskStatus::Ok => "ok",
        TaskStatus::Fail => "failed",
        TaskStatus::CompileError => "does not compile",
        TaskStatus::Error => "not graded",
    }
}

fn status_class(status: TaskStatus) -> &'static str {
    match status {
        TaskStatus::Ok => "ok",
        TaskStatus::Fail => "fail",
        TaskStatus::CompileError | TaskStatus::Error => "error",
    }
}

/// An id for a topic's section: `topic-01-lines`.
fn topic_anchor(topic: &str) -> String {
    format!("topic-{}", anchor(topic, "").trim_end_matches('-'))
}

/// An id for a task's section: `01-lines--dda`.
fn anchor(topic: &str, task: &str) -> String {
    format!("{topic}--{task}")
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// A relative path as a URL ([`super::markup::path_url`]).
fn url(path: &Path) -> String {
    super::markup::path_url(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escape_makes_markup_inert() {
        assert_eq!(
            escape("<b>\"x\" & 'y'</b>"),
            "&lt;b&gt;&quot;x&quot; &amp; &apos;y&apos;&lt;/b&gt;"
        );
    }

    #[test]
    fn anchors_keep_only_safe_characters() {
        assert_eq!(anchor("01-lines", "wu::steep"), "01-lines--wu__steep");
    }
}
