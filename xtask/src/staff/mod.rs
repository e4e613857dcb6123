//! The staff's tools, in the course repository only (no edition holds
//! this folder): grading a class (`grade --submission CLASS`: its slots,
//! gradebook, report, shards and their merge) and a generated class to try
//! it on, review of a grade's snapshots, similarity, the Classroom
//! workflow and the Gradescope bundle, releasing an edition, writing the
//! stubs, the self-test, the benchmarks. They build on the grader
//! (`crate::grade`, `crate::stage`, `crate::edition`), which imports
//! nothing from here.

mod bench;
pub mod class;
pub mod class_workflow;
pub mod classroom;
mod gradescope;
pub mod release;
mod review;
mod setup;
mod similarity;
pub mod stubs;
mod test;
mod wine;

use std::path::{Path, PathBuf};

use anyhow::Result;
use clap::Subcommand;

use crate::stage;

/// The staff's commands.
#[derive(Subcommand)]
pub enum Command {
    /// A class's gradebook: `merge` joins the --out folders of a class graded in shards.
    Gradebook {
        #[command(subcommand)]
        action: GradebookAction,
    },
    /// Write exercises/*/src from the solutions in reference/*/src.
    Stubs {
        /// Write nothing; fail if any student file is not what would be generated.
        #[arg(long)]
        check: bool,
    },
    /// The project's test command: stubs in sync, reference scores 100 %, stubs and a
    /// do-nothing edition score 0, the student edition builds.
    Test {
        /// Run only these steps (numbers as the summary shows them, e.g. `--step 7`).
        #[arg(long = "step", value_name = "N")]
        steps: Vec<usize>,
    },
    /// Write the solution workspace (the course with reference/ laid over the stubs) to DIR,
    /// to open in an editor.
    Stage {
        /// Lay the reference solutions over the stubs (the only edition there is to stage).
        #[arg(long, required = true)]
        reference: bool,
        /// A new or empty folder, or one written by an earlier `stage`.
        dir: PathBuf,
    },
    /// Write the student edition (no reference/, no benchmarks) to DIR, ready to push.
    Release {
        /// A new or empty folder, or an earlier release (updated in place, its .git kept).
        dir: PathBuf,
        /// Topics to release: names as for `grade`, or a range such as `01..=03`; default all.
        #[arg(long, value_delimiter = ',', num_args = 1..)]
        topics: Vec<String>,
        /// Also write a GitHub Classroom workflow that grades every push with the official
        /// tests of this GitHub repository (the edition, pushed and tagged) and reports one
        /// result per task.
        #[arg(long, value_name = "OWNER/REPO[@TAG]")]
        classroom: Option<classroom::CourseRepo>,
    },
    /// Review the snapshots the last grade found different with cargo-insta (installed when
    /// missing): accept, reject or skip each; the course's snapshots are never changed.
    Review {
        /// The submission whose grade to review (its folder name in a class's gradebook).
        #[arg(long, value_name = "NAME")]
        submission: Option<String>,
        /// Where the grade was written [default: <root>/target/grade].
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Print every snapshot and its diff instead of stepping through them.
        #[arg(long)]
        list: bool,
    },
    /// Write the Gradescope autograder to DIR: the student edition as the official tests,
    /// setup.sh, run_autograder, and autograder.zip to upload.
    Gradescope {
        /// A new or empty folder, or an earlier bundle (updated in place).
        dir: PathBuf,
        /// Topics to grade: names as for `grade`, or a range such as `01..=03`; default all.
        #[arg(long, value_delimiter = ',', num_args = 1..)]
        topics: Vec<String>,
    },
    /// Write a generated class to DIR, to try and measure grading a folder of submissions:
    /// editions of the topics in which members solved everything, planted a mistake, solved
    /// every other topic, rewrote a test, or left a syntax error, in turn.
    Class {
        /// A new or empty folder.
        dir: PathBuf,
        /// How many submissions.
        #[arg(long, default_value_t = 30)]
        size: usize,
        /// Topics of the edition: names as for `grade`, or a range such as `01..=03`; default all.
        #[arg(long, value_delimiter = ',', num_args = 1..)]
        topics: Vec<String>,
    },
    /// Rank the pairs of members of a class whose task files are unusually alike (the
    /// course's stubs excluded), with copydetect (installed when missing): writes
    /// similarity.html, the matching passages side by side, and similarity.json.
    Similarity {
        /// The class: a folder of checkouts (as for `grade --submission`).
        class: PathBuf,
        /// Where similarity.html and similarity.json go [default: <root>/target/similarity].
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// The score from which a pair is flagged: the share of one member's own code that
        /// matches the other's, from 0 to 1.
        #[arg(long, value_name = "T", default_value_t = similarity::DEFAULT_THRESHOLD)]
        threshold: f64,
        /// Topics to compare: names as for `grade`; default all.
        #[arg(long, value_delimiter = ',', num_args = 1..)]
        topics: Vec<String>,
    },
    /// Run the benchmarks of the reference solutions (`cargo bench -p course-bench` in the
    /// stage), passing ARGS through.
    Bench {
        /// Arguments for `cargo bench` (e.g. `-- dda`).
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
}

#[derive(Subcommand)]
pub enum GradebookAction {
    /// Join the --out folders of a class graded in shards (`grade --submission CLASS --shard
    /// I/N`) into one: the members' report folders, the gradebook and the class's report.
    Merge {
        /// The --out folders of the shards.
        #[arg(required = true)]
        parts: Vec<PathBuf>,
        /// Where the class's grade goes.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
    },
}

/// Runs one of the staff's commands.
pub fn run(root: &Path, command: Command) -> Result<()> {
    let root = root.to_path_buf();
    match command {
        Command::Stubs { check } => stubs::run(&root, check),
        Command::Test { steps } => test::run(&root, &steps),
        Command::Bench { args } => bench::run(&root, &args),
        Command::Class { dir, size, topics } => class::generated::run(&root, &dir, size, &topics),
        Command::Similarity {
            class,
            out,
            threshold,
            topics,
        } => similarity::run(
            &root,
            &similarity::Options {
                out: out.unwrap_or_else(|| root.join("target").join("similarity")),
                class,
                threshold,
                topics,
            },
        ),
        Command::Stage { reference: _, dir } => stage::write_reference(&root, &dir),
        Command::Review {
            submission,
            out,
            list,
        } => review::run(&root, out.as_deref(), submission.as_deref(), list),
        Command::Gradebook {
            action: GradebookAction::Merge { parts, out },
        } => class::merge(&parts, &out),
        Command::Gradescope { dir, topics } => gradescope::run(&root, &dir, &topics),
        Command::Release {
            dir,
            topics,
            classroom,
        } => release::run(&root, &dir, &topics, classroom.as_ref()),
    }
}
