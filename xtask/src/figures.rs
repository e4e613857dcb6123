//! `cargo xtask figures`: the seeds' figures that the course reproduces,
//! drawn by the reference solutions (staged, as `grade --reference`) or,
//! with `--mine`, by the student's own code, copied into
//! `target/figures/` with an index (`index.html`, `index.md`): the seed,
//! its figure, what the picture shows, the test that draws it and the
//! command that runs that test.
//!
//! Which figures exist is the manifest `xtask/figures.toml`; each is a
//! picture a graded test writes (`<grade>/images/<topic>/<task>/<test>/
//! <image>/yours.png`) or one of the report's pipeline renders
//! (`<grade>/pipeline/<image>.png`). A figure whose test failed is listed
//! as missing, with the test's reason.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use serde::Deserialize;

use crate::grade::report::{Report, TestStatus};
use crate::grade::{self, GradeOptions};

/// The manifest, relative to the course root.
pub const MANIFEST: &str = "xtask/figures.toml";

/// The manifest's `test` for the report's pipeline renders.
const PIPELINE: &str = "pipeline";

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Manifest {
    seed: Vec<Seed>,
    figure: Vec<Figure>,
}

/// A document the course follows, as the index cites it.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct Seed {
    /// Its number, as figures name it.
    id: String,
    /// Author, title, kind, institution, year.
    citation: String,
    /// Where it can be read, if it is public.
    #[serde(default)]
    link: Option<String>,
}

impl Seed {
    /// The citation with its link, for the index.
    fn cited(&self) -> String {
        match &self.link {
            Some(link) => format!("{} ({link})", self.citation),
            None => self.citation.clone(),
        }
    }
}

/// One figure of a seed, as the course draws it.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct Figure {
    /// The seed document's number (its `[[seed]]` entry cites it).
    seed: String,
    /// The seed's name for the figure (`Abb. 3`, `Slika 2.2`, a section).
    figure: String,
    /// What the course's picture shows.
    caption: String,
    /// The topic folder whose test draws it.
    topic: String,
    /// `<task>/<test function>`, or `pipeline` for a pipeline render.
    test: String,
    /// The picture's name: the test's image name, or the render's file
    /// name without `.png`.
    image: String,
    /// The topic's package (from its `Cargo.toml`, not the manifest).
    #[serde(skip)]
    package: String,
}

/// Where a figure ended up.
struct Drawn {
    figure: Figure,
    /// The picture in the figures folder, relative to it.
    file: Option<PathBuf>,
    /// Why there is none, or why the picture shown is not the expected
    /// one (its test failed).
    missing: Option<String>,
}

/// Grades the manifest's topics (the solutions, or the student's code for
/// `mine`), copies the figures into `<root>/target/figures/` and writes
/// the index; `topics` narrows the figures to those topics.
pub fn run(root: &Path, mine: bool, topics: &[String]) -> Result<()> {
    if !mine && !root.join(crate::files::SOLUTIONS).is_dir() {
        bail!(
            "this edition has no reference solutions: `cargo xtask figures --mine` draws the figures with your code"
        );
    }
    let (seeds, figures) = manifest(root)?;
    let selected = crate::topics::select(root, topics)?;
    let figures: Vec<Figure> = figures
        .into_iter()
        .filter(|f| selected.iter().any(|t| t.name == f.topic))
        .collect();
    if figures.is_empty() {
        bail!("no figure of {MANIFEST} belongs to the topics asked for");
    }
    let out = root.join("target").join("figures");
    if out.exists() {
        fs::remove_dir_all(&out).with_context(|| format!("cannot clear {}", out.display()))?;
    }
    let mut options = GradeOptions::new(root.to_path_buf());
    options.reference = !mine;
    options.out = out.join("grade");
    options.topics = figures.iter().map(|f| f.topic.clone()).collect();
    options.topics.dedup();
    println!(
        "drawing {} figures with {} (grading {})",
        figures.len(),
        if mine {
            "your code"
        } else {
            "the reference solutions"
        },
        options.topics.join(", ")
    );
    let report = grade::grade(&options)?;
    grade::print_summary(&report, &options.out, false);

    let drawn: Vec<Drawn> = figures
        .into_iter()
        .map(|figure| collect(&report, &options.out, &out, figure))
        .collect::<Result<_>>()?;
    let source = if mine {
        "your code"
    } else {
        "the reference solutions"
    };
    fs::write(out.join("index.md"), markdown(&drawn, &seeds, source))
        .with_context(|| format!("cannot write {}", out.join("index.md").display()))?;
    fs::write(out.join("index.html"), html(&drawn, &seeds, source))
        .with_context(|| format!("cannot write {}", out.join("index.html").display()))?;
    let missing = drawn.iter().filter(|d| d.file.is_none()).count();
    println!(
        "{} of {} figures written to {} (index.html, index.md){}",
        drawn.len() - missing,
        drawn.len(),
        out.display(),
        if missing > 0 {
            format!("; {missing} missing, the index says why")
        } else {
            String::new()
        }
    );
    Ok(())
}

/// The manifest, checked: every figure names a cited seed, a topic of the
/// course, a `<task>/<test>` or `pipeline`, and a picture.
fn manifest(root: &Path) -> Result<(Vec<Seed>, Vec<Figure>)> {
    let path = root.join(MANIFEST);
    let text =
        fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
    let manifest: Manifest =
        toml::from_str(&text).with_context(|| format!("cannot parse {}", path.display()))?;
    let topics = crate::topics::discover(root)?;
    // An edition released with fewer topics draws the figures it has.
    let mut figures: Vec<Figure> = manifest
        .figure
        .into_iter()
        .filter(|f| topics.iter().any(|t| t.name == f.topic))
        .collect();
    for figure in &mut figures {
        if !manifest.seed.iter().any(|seed| seed.id == figure.seed) {
            bail!(
                "{}: {} of seed {} cites no `[[seed]]` of that id",
                path.display(),
                figure.figure,
                figure.seed
            );
        }
        let topic = topics
            .iter()
            .find(|t| t.name == figure.topic)
            .context("kept above")?;
        figure.package.clone_from(&topic.package);
        if figure.test != PIPELINE {
            let (task, _) = figure.test.split_once('/').with_context(|| {
                format!(
                    "{}: test `{}` is not `<task>/<test>`",
                    path.display(),
                    figure.test
                )
            })?;
            if !topic.sheet.tasks.iter().any(|t| t.id == task) {
                bail!("{}: {} has no task `{task}`", path.display(), figure.topic);
            }
        }
    }
    Ok((manifest.seed, figures))
}

/// The seeds the `drawn` figures come from, cited, in order.
fn cited<'a>(drawn: &[Drawn], seeds: &'a [Seed]) -> Vec<&'a Seed> {
    seeds
        .iter()
        .filter(|seed| drawn.iter().any(|d| d.figure.seed == seed.id))
        .collect()
}

/// Copies `figure`'s picture from the grade in `graded` into `out`, or
/// says why there is none.
fn collect(report: &Report, graded: &Path, out: &Path, figure: Figure) -> Result<Drawn> {
    let (source, missing) = if figure.test == PIPELINE {
        let file = format!("{}.png", figure.image);
        let picture = report.pipeline.iter().find(|p| p.file == file);
        let error = picture
            .and_then(|p| p.error.clone())
            .unwrap_or_else(|| "the pipeline did not draw it".to_owned());
        match picture.and_then(|p| p.yours.as_ref()) {
            Some(yours) => (Some(graded.join(yours)), None),
            None => (None, Some(error)),
        }
    } else {
        let path = graded
            .join("images")
            .join(&figure.topic)
            .join(&figure.test)
            .join(&figure.image)
            .join("yours.png");
        // A failing comparison still writes the picture: shown, with why.
        let failed = test_failure(report, &figure);
        if path.is_file() {
            (Some(path), failed)
        } else {
            (
                None,
                Some(failed.unwrap_or_else(|| why_missing(report, &figure))),
            )
        }
    };
    let Some(source) = source else {
        return Ok(Drawn {
            figure,
            file: None,
            missing,
        });
    };
    let file = PathBuf::from(format!(
        "{}-{}-{}.png",
        figure.seed, figure.topic, figure.image
    ));
    fs::copy(&source, out.join(&file)).with_context(|| {
        format!(
            "cannot copy {} to {}",
            source.display(),
            out.join(&file).display()
        )
    })?;
    Ok(Drawn {
        figure,
        file: Some(file),
        missing,
    })
}

/// Why the test of `figure` failed, `None` if it passed (or is not a
/// test's).
fn test_failure(report: &Report, figure: &Figure) -> Option<String> {
    let (task, test) = figure.test.split_once('/')?;
    let found = report
        .topics
        .iter()
        .filter(|t| t.name == figure.topic)
        .flat_map(|t| &t.tasks)
        .filter(|t| t.id == task)
        .flat_map(|t| &t.tests)
        .find(|t| t.name == test)?;
    (found.status != TestStatus::Passed).then(|| {
        format!(
            "`{}` failed: {}",
            figure.test,
            first_line(found.reason.as_deref().unwrap_or("no reason given"))
        )
    })
}

/// Why the test of `figure` left no picture: it failed (its reason), it
/// does not exist, or it passed without writing one.
fn why_missing(report: &Report, figure: &Figure) -> String {
    let (task, test) = figure.test.split_once('/').unwrap_or((&figure.test, ""));
    let Some(topic) = report.topics.iter().find(|t| t.name == figure.topic) else {
        return format!("{} was not graded", figure.topic);
    };
    if let Some(error) = &topic.compile_error {
        return format!("{} does not compile: {}", figure.topic, first_line(error));
    }
    let found = topic
        .tasks
        .iter()
        .filter(|t| t.id == task)
        .flat_map(|t| &t.tests)
        .find(|t| t.name == test);
    match found {
        None => format!("there is no test `{}` in {}", figure.test, figure.topic),
        Some(t) if t.status == TestStatus::Passed => format!(
            "`{}` passed without writing the picture `{}`",
            figure.test, figure.image
        ),
        Some(t) => format!(
            "`{}` failed: {}",
            figure.test,
            first_line(t.reason.as_deref().unwrap_or("no reason given"))
        ),
    }
}

fn first_line(text: &str) -> &str {
    text.lines().next().unwrap_or_default()
}

/// The command that runs the test drawing `figure`, in the workspace of
/// the graded code.
fn command(figure: &Figure) -> String {
    let package = &figure.package;
    match figure.test.split_once('/') {
        Some((task, test)) => format!("cargo test -p {package} --test {task} {test}"),
        None => format!("cargo xtask grade {} (the report's pipeline)", figure.topic),
    }
}

fn markdown(drawn: &[Drawn], seeds: &[Seed], source: &str) -> String {
    let mut text = format!(
        "# The seeds' figures, drawn by {source}\n\n\
         Made by `cargo xtask figures`. The seeds, the documents the course follows:\n\n"
    );
    for seed in cited(drawn, seeds) {
        text.push_str(&format!("- {}: {}\n", seed.id, seed.cited()));
    }
    text.push_str(
        "\n| seed | figure | the course's picture | made by | file |\n|---|---|---|---|---|\n",
    );
    for d in drawn {
        let f = &d.figure;
        let file = match (&d.file, &d.missing) {
            (Some(file), None) => format!("[{0}]({0})", file.display()),
            (Some(file), Some(why)) => {
                format!("[{0}]({0}); {1}", file.display(), why.replace('|', "\\|"))
            }
            (None, Some(why)) => format!("missing: {}", why.replace('|', "\\|")),
            (None, None) => "missing".to_owned(),
        };
        text.push_str(&format!(
            "| {} | {} | {} | `{}` | {} |\n",
            f.seed,
            f.figure,
            f.caption.replace('|', "\\|"),
            command(f),
            file
        ));
    }
    text
}

fn html(drawn: &[Drawn], seeds: &[Seed], source: &str) -> String {
    let escape = grade::markup::html;
    let citations: String = cited(drawn, seeds)
        .iter()
        .map(|seed| format!("<li>{}: {}</li>", escape(&seed.id), escape(&seed.cited())))
        .collect();
    let mut rows = String::new();
    for d in drawn {
        let f = &d.figure;
        let picture = match (&d.file, &d.missing) {
            (Some(file), note) => {
                let name = escape(&file.to_string_lossy());
                let note = note.as_deref().map_or_else(String::new, |why| {
                    format!("<p class=\"missing\">{}</p>", escape(why))
                });
                format!(
                    "<a href=\"{name}\"><img src=\"{name}\" alt=\"{}\"></a>{note}",
                    escape(&f.caption)
                )
            }
            (None, why) => format!(
                "<p class=\"missing\">missing: {}</p>",
                escape(why.as_deref().unwrap_or("no picture"))
            ),
        };
        rows.push_str(&format!(
            "<tr><td>{}</td><td>{}</td><td>{}<br><code>{}</code></td><td>{picture}</td></tr>\n",
            escape(&f.seed),
            escape(&f.figure),
            escape(&f.caption),
            escape(&command(f)),
        ));
    }
    format!(
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>The seeds' figures</title>\n<style>\
         body{{font-family:sans-serif;margin:2em}}table{{border-collapse:collapse}}\
         td{{border-top:1px solid #ccc;padding:.5em;vertical-align:top}}\
         img{{width:320px;image-rendering:pixelated;background:#000}}.missing{{color:#b00}}\
         </style></head><body>\n<h1>The seeds' figures, drawn by {}</h1>\n\
         <p>Made by <code>cargo xtask figures</code>. Each picture is written by the test named \
         beside it; click it for full size. The seeds, the documents the course follows:</p>\n\
         <ul>{citations}</ul>\n<table>\n\
         <tr><th>seed</th><th>figure</th><th>the course's picture</th><th></th></tr>\n{rows}</table>\n\
         </body></html>\n",
        escape(source)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_figure_of_the_manifest_names_a_task_of_its_topic_and_a_test_that_draws_it() {
        let root = crate::cargo::project_root();
        let (seeds, figures) = manifest(&root).unwrap();
        for seed in &seeds {
            assert!(
                !seed.citation.contains("shared/") && !seed.citation.contains("DESIGN"),
                "seed {} is cited by a path no edition holds",
                seed.id
            );
        }
        assert!(figures.len() >= 20, "{} figures", figures.len());
        for figure in figures.iter().filter(|f| f.test != PIPELINE) {
            let (task, test) = figure.test.split_once('/').unwrap();
            let source = fs::read_to_string(
                root.join("exercises")
                    .join(&figure.topic)
                    .join("tests")
                    .join(format!("{task}.rs")),
            )
            .unwrap();
            assert!(
                source.contains(&format!("fn {test}(")),
                "{}: tests/{task}.rs has no test `{test}`",
                figure.topic
            );
            assert!(
                source.contains(&format!("\"{}\"", figure.image)),
                "{}: tests/{task}.rs never names the picture `{}`",
                figure.topic,
                figure.image
            );
        }
    }

    #[test]
    fn commands_run_the_one_test() {
        let figure = Figure {
            seed: "004".into(),
            figure: "Abb. 4".into(),
            caption: "c".into(),
            topic: "01-lines".into(),
            test: "dda/star".into(),
            image: "dda_star".into(),
            package: "lines".into(),
        };
        assert_eq!(command(&figure), "cargo test -p lines --test dda star");
    }
}
