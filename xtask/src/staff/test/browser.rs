//! The grade report opened in headless Chromium (step 4): the page loads,
//! its pictures show, and a screenshot is kept to look at.

use std::fs;
use std::path::Path;

use anyhow::{Context, Result, ensure};

use crate::cargo;
use crate::grade::Report;
use crate::stage::{self};

use super::tail;

/// Opens the report of `out` in a headless Chromium, as a reader would
/// from the folder (no server): the summary names every topic, and every
/// comparison of pictures became one magnified view with its switch (its
/// pictures load from the folder, and its script ran). A screenshot is
/// kept in `target/xtask/report.png`. Required under CI; elsewhere a
/// missing Chromium is a note.
pub(super) fn report_in_chromium(root: &Path, out: &Path, report: &Report) -> Result<String> {
    let screenshot = stage::home(root).join("report.png");
    let Some(browse) = browser(root, &out.join("report.html"))? else {
        return Ok("report.html not checked (no Chromium)".to_owned());
    };
    let dumped = browse(&["--dump-dom".to_owned()])?;
    ensure!(
        dumped.status.success(),
        "Chromium could not open report.html: {}",
        tail(&String::from_utf8_lossy(&dumped.stderr), 10)
    );
    let dom = String::from_utf8_lossy(&dumped.stdout);
    ensure!(dom.contains("id=\"summary\""), "report.html has no summary");
    for topic in &report.topics {
        ensure!(
            dom.contains(&format!("href=\"#topic-{}\"", topic.name)),
            "the summary of report.html does not link {}",
            topic.name
        );
    }
    let comparisons: usize = report
        .topics
        .iter()
        .flat_map(|t| &t.tasks)
        .flat_map(|t| &t.tests)
        .map(|t| {
            let mut folders: Vec<_> = t.images.iter().map(|i| i.parent()).collect();
            folders.sort();
            folders.dedup();
            folders.len()
        })
        .sum();
    let boxes = dom.matches("class=\"compare\"").count();
    let shown = dom.matches("data-scale=\"").count();
    ensure!(
        boxes == comparisons && shown == boxes,
        "report.html: {comparisons} comparisons of pictures, {boxes} on the page, {shown} of them shown magnified"
    );
    let shot = browse(&[
        "--window-size=1280,2400".to_owned(),
        format!("--screenshot={}", screenshot.display()),
    ])?;
    ensure!(
        shot.status.success() && screenshot.is_file(),
        "Chromium could not take a screenshot of report.html"
    );
    Ok(format!(
        "report.html in Chromium: a summary of {} topics, {boxes} comparisons shown magnified (screenshot {})",
        report.topics.len(),
        screenshot.display()
    ))
}

/// Chromium, headless, on the page `page` (as a reader opens it from its
/// folder, no server), run with extra arguments; `None` where this
/// machine has none (an error under CI, which must check the page).
fn browser(
    root: &Path,
    page: &Path,
) -> Result<Option<impl Fn(&[String]) -> Result<std::process::Output> + use<>>> {
    let name = page
        .file_name()
        .unwrap_or_default()
        .to_string_lossy()
        .into_owned();
    let Some(chromium) = crate::staff::setup::chromium() else {
        ensure!(
            std::env::var_os("CI").is_none(),
            "no Chromium to check {name} in (Debian: apt-get install chromium)"
        );
        println!("note: {name} is not checked: no Chromium here");
        return Ok(None);
    };
    let url = format!("file://{}", page.display());
    let profile = stage::home(root).join("chromium-profile");
    let _ = fs::remove_dir_all(&profile);
    Ok(Some(
        move |extra: &[String]| -> Result<std::process::Output> {
            let mut command = std::process::Command::new("timeout");
            command
                .arg("120")
                .arg(&chromium)
                .args([
                    "--headless",
                    "--no-sandbox",
                    "--disable-gpu",
                    "--disable-quic",
                    "--no-first-run",
                    "--disable-background-networking",
                    "--disable-component-update",
                    "--disable-sync",
                    "--hide-scrollbars",
                    "--virtual-time-budget=20000",
                ])
                .arg(format!("--user-data-dir={}", profile.display()))
                .args(extra)
                .arg(&url);
            println!("$ {}", cargo::display(&command));
            command
                .output()
                .with_context(|| format!("cannot run {}", chromium.display()))
        },
    ))
}

/// Opens a class's report (`class.html` in `out`) in headless Chromium:
/// every task of `tasks` has its histogram (an SVG), the commonest
/// failures name `failing` (a member who lost points) with a link to its
/// report. A screenshot is kept in `target/xtask/class.png`.
pub(super) fn class_report_in_chromium(
    root: &Path,
    out: &Path,
    tasks: usize,
    failing: &str,
) -> Result<String> {
    let screenshot = stage::home(root).join("class.png");
    let Some(browse) = browser(root, &out.join("class.html"))? else {
        return Ok("class.html not checked (no Chromium)".to_owned());
    };
    let dumped = browse(&["--dump-dom".to_owned()])?;
    ensure!(
        dumped.status.success(),
        "Chromium could not open class.html: {}",
        tail(&String::from_utf8_lossy(&dumped.stderr), 10)
    );
    let dom = String::from_utf8_lossy(&dumped.stdout);
    let histograms = dom.matches("<svg").count();
    ensure!(
        histograms >= tasks,
        "class.html shows {histograms} histograms for {tasks} tasks"
    );
    ensure!(
        dom.contains(&format!("href=\"./{failing}/report.html\"")),
        "class.html does not link {failing}'s report"
    );
    let shot = browse(&[
        "--window-size=1280,2000".to_owned(),
        format!("--screenshot={}", screenshot.display()),
    ])?;
    ensure!(
        shot.status.success() && screenshot.is_file(),
        "Chromium could not take a screenshot of class.html"
    );
    Ok(format!(
        "class.html in Chromium: {histograms} histograms, {failing}'s failures linked (screenshot {})",
        screenshot.display()
    ))
}
