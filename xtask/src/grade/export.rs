//! The report files of a grade, each written by its format: `report.json`
//! (ours, [`super::report`]), `results.json` (Gradescope's autograder
//! format, [`super::results_json`]), `junit.xml` (for CI test viewers,
//! [`super::junit`]), `report.html` (for people, [`super::html`]) and
//! `classroom/<task>.json` (GitHub Classroom's, [`super::classroom`]). The
//! formats read the report model and nothing of each other.

use std::fs;
use std::path::Path;

use anyhow::{Context, Result};

use super::report::Report;

/// Writes all the files into `out`.
pub fn write_all(report: &Report, out: &Path) -> Result<()> {
    let write = |name: &str, contents: String| {
        let path = out.join(name);
        fs::write(&path, contents).with_context(|| format!("cannot write {}", path.display()))
    };
    write(
        "report.json",
        serde_json::to_string_pretty(report).context("cannot serialise the report")?,
    )?;
    write(
        "results.json",
        serde_json::to_string_pretty(&super::results_json::gradescope(report))
            .context("cannot serialise results.json")?,
    )?;
    write("junit.xml", super::junit::junit(report))?;
    write("report.html", super::html::page(report))?;
    let classroom = out.join("classroom");
    fs::create_dir_all(&classroom)
        .with_context(|| format!("cannot create {}", classroom.display()))?;
    for (id, result) in super::classroom::results(report) {
        write(
            &format!("classroom/{id}.json"),
            serde_json::to_string_pretty(&result).context("cannot serialise a task's result")?,
        )?;
    }
    Ok(())
}
