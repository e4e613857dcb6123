//! The grade report opened in headless Chromium (step 4): the page loads,
//! its pictures show, and a screenshot is kept to look at.

use std::fs;
use std::path::Path;

use anyhow::{Context, Result, ensure};

use crate::cargo;
use crate::grade::Report;
use crate::setup;
use crate::stage::{self};

use super::tail;

/// Opens the report of `out` in a headless Chromium, as a reader would
/// from the folder (no server): the summary names every topic, and every
/// comparison of pictures became one magnified view with its switch (its
/// pictures load from the folder, and its script ran). A screenshot is
/// kept in `target/xtask/report.png`. Required under CI; elsewhere a
/// missing Chromium is a note.
pub(super) fn report_in_chromium(root: &Path, out: &Path, report: &Report) -> Result<String> {
    let Some(chromium) = setup::chromium() else {
        ensure!(
            std::env::var_os("CI").is_none(),
            "no Chromium to check report.html in (Debian: apt-get install chromium)"
        );
        println!("note: report.html is not checked: no Chromium here");
        return Ok("report.html not checked (no Chromium)".to_owned());
    };
    let page = out.join("report.html");
    let url = format!("file://{}", page.display());
    let profile = stage::home(root).join("chromium-profile");
    let _ = fs::remove_dir_all(&profile);
    let screenshot = stage::home(root).join("report.png");
    let browse = |extra: &[String]| -> Result<std::process::Output> {
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
