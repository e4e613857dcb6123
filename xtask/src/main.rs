//! `cargo xtask`: the course's tooling, as plain Rust (the xtask pattern).
//!
//! This file only parses the command line and dispatches; each command is
//! its own module.

mod bench;
mod cargo;
mod class;
mod class_workflow;
mod classroom;
mod figures;
mod files;
mod grade;
mod gradescope;
mod hint;
mod release;
mod review;
mod sandbox;
mod setup;
mod similarity;
mod stage;
mod stubs;
mod test;
mod topics;
mod view;
mod watch;
mod wine;

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::{Args, Parser, Subcommand};

/// Course tooling: grade exercises, generate stubs, test the course.
#[derive(Parser)]
#[command(name = "cargo xtask", bin_name = "cargo xtask")]
struct Cli {
    /// The course checkout to work on [default: the workspace xtask belongs to].
    #[arg(long, global = true, value_name = "DIR")]
    root: Option<PathBuf>,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Grade the exercises: points per task, the first failing case, a diff.
    Grade(GradeArgs),
    /// A class's gradebook: `merge` joins the --out folders of a class graded in shards.
    Gradebook {
        #[command(subcommand)]
        action: GradebookAction,
    },
    /// Grade a topic, and again whenever one of its files changes: one screen each time.
    Watch {
        /// The topic (as for `grade`) [default: the first with a `todo!()` left].
        topic: Option<String>,
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
    /// Draw the seeds' figures the course reproduces into target/figures/ with an index:
    /// by the reference solutions, or by your code with --mine.
    Figures {
        /// Draw them with your own code (the student edition has no solutions).
        #[arg(long)]
        mine: bool,
        /// Only the figures of these topics (names as for `grade`); default all.
        topics: Vec<String>,
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
    /// Show the hints of a task, one more each time: the goal first, the exact rule last.
    Hint {
        /// The task: its id (`dda`), or TOPIC/ID (`lines/dda`, `01-lines/dda`).
        task: String,
        /// Show every hint at once.
        #[arg(long)]
        all: bool,
        /// Forget the hints seen of this task.
        #[arg(long)]
        reset: bool,
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
    /// Opens the course viewer: your own pipeline (clipping, lines, fill,
    /// depth test) drawing the shipped meshes or any PLY file. Topics that
    /// do not compile are left out and named.
    ///
    /// `ARGS` go to the viewer: `--screenshot FILE` writes one picture
    /// without a window; `--mesh`, `--mode`, `--no-clip`, `--no-depth`,
    /// `--size` choose it (`cargo xtask view -- --help` lists them).
    View {
        /// Draw with the reference solutions (for tutors).
        #[arg(long)]
        reference: bool,
        /// Passed to the viewer.
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
}

#[derive(Subcommand)]
enum GradebookAction {
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

#[derive(Args)]
struct GradeArgs {
    /// Topics to grade: folder (`01-lines`), its name (`lines`), package or number; default all.
    topics: Vec<String>,
    /// Grade the reference solutions instead of the student code.
    #[arg(long)]
    reference: bool,
    /// Grade a student's checkout with this course's official tests, or every
    /// checkout in a folder of them (a gradebook); changed tests are flagged.
    #[arg(long, value_name = "DIR")]
    submission: Option<PathBuf>,
    /// Where report.json, results.json, junit.xml, logs and images go [default: <root>/target/grade].
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Tests run at the same time [default: the number of CPUs]; in a class, also the
    /// submissions graded side by side [default: one per two CPUs].
    #[arg(long, short, value_name = "N")]
    jobs: Option<usize>,
    /// cargo's target directory for the build [default: cargo's].
    #[arg(long, value_name = "DIR")]
    target_dir: Option<PathBuf>,
    /// The longest a build of student code may take, in seconds; a build over it fails
    /// that submission, and a class goes on with the next [default: 2700].
    #[arg(long, value_name = "SECONDS")]
    build_time_limit: Option<u64>,
    /// Of a class, grade only the I-th of N parts (a member is always in the same part),
    /// e.g. on N machines; `cargo xtask gradebook merge` joins their --out folders.
    #[arg(long, value_name = "I/N", value_parser = grade::submission::Shard::parse)]
    shard: Option<grade::submission::Shard>,
    /// With --submission: grade even where bubblewrap, its seccomp filter or the cgroups
    /// that limit a test's processes together cannot be had (what can be had is still
    /// used), instead of refusing; every report says so.
    #[arg(long)]
    unsandboxed_on_purpose: bool,
}

fn grade(root: PathBuf, args: GradeArgs) -> Result<()> {
    let mut options = grade::GradeOptions::new(root.clone());
    options.topics = args.topics;
    options.reference = args.reference;
    if let Some(out) = args.out {
        options.out = out;
    }
    if let Some(jobs) = args.jobs {
        options.jobs = jobs;
        options.submissions_at_once = Some(jobs);
    }
    // Relative to where the command was given, as cargo's own: the build
    // runs elsewhere (in the stage, in the sandbox).
    options.target_dir = args
        .target_dir
        .map(|dir| {
            std::path::absolute(&dir).with_context(|| format!("cannot find {}", dir.display()))
        })
        .transpose()?;
    if let Some(seconds) = args.build_time_limit {
        options.build_time_limit = std::time::Duration::from_secs(seconds);
    }
    // The grade of record runs someone else's code: it fails closed.
    options.sandbox = match (&args.submission, args.unsandboxed_on_purpose) {
        (Some(_), false) => sandbox::Policy::Required,
        (Some(_), true) => sandbox::Policy::OnPurpose,
        (None, _) => sandbox::Policy::BestEffort,
    };
    if args.submission.is_some() && !args.reference {
        sandbox::enforce(options.sandbox)?;
    }
    match args.submission {
        Some(_) if args.reference => {
            anyhow::bail!("--reference grades this course's solutions; a submission has none")
        }
        Some(dir) => grade::submission::run(&root, &dir, &options, args.shard),
        None if args.shard.is_some() => {
            anyhow::bail!("--shard splits a class: give the class's folder with --submission")
        }
        None => grade::run(&options).map(drop),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let root = match cli.root.map(|dir| {
        dir.canonicalize()
            .with_context(|| format!("cannot find {}", dir.display()))
    }) {
        Some(Ok(root)) => root,
        Some(Err(error)) => {
            eprintln!("error: {error:#}");
            return ExitCode::FAILURE;
        }
        None => cargo::project_root(),
    };
    let result = match cli.command {
        Command::Grade(args) => grade(root, args),
        Command::Watch { topic } => watch::run(&root, topic.as_deref()),
        Command::Stubs { check } => stubs::run(&root, check),
        Command::Test { steps } => test::run(&root, &steps),
        Command::Bench { args } => bench::run(&root, &args),
        Command::Class { dir, size, topics } => class::run(&root, &dir, size, &topics),
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
        Command::View { reference, args } => view::run(&root, reference, &args),
        Command::Stage { reference: _, dir } => stage::write_reference(&root, &dir),
        Command::Figures { mine, topics } => figures::run(&root, mine, &topics),
        Command::Review {
            submission,
            out,
            list,
        } => review::run(&root, out.as_deref(), submission.as_deref(), list),
        Command::Hint { task, all, reset } => hint::run(&root, &task, all, reset),
        Command::Gradebook {
            action: GradebookAction::Merge { parts, out },
        } => grade::submission::merge(&parts, &out),
        Command::Gradescope { dir, topics } => gradescope::run(&root, &dir, &topics),
        Command::Release {
            dir,
            topics,
            classroom,
        } => release::run(&root, &dir, &topics, classroom.as_ref()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            // An error may quote a submission (a file's name, a reason): its
            // lines escaped, as every line the grader prints.
            eprintln!("error: {}", grade::escaped_lines(&format!("{error:#}")));
            ExitCode::FAILURE
        }
    }
}
