//! `cargo xtask`: the course's tooling, as plain Rust (the xtask pattern).
//!
//! This file only parses the command line and dispatches; each command is
//! its own module. The student's commands (grade, watch, hint, view,
//! figures) and the grader they run are in every edition; the staff's
//! (`staff`) only in the course repository.

mod cargo;
mod edition;
mod figures;
mod files;
mod grade;
mod hint;
mod sandbox;
mod setup;
mod stage;
mod stubs;
mod topics;
mod view;
mod watch;

// The staff's tools: a class, review, similarity, the Classroom workflow
// and the Gradescope bundle, releasing an edition, stubs, the self-test,
// benchmarks. No edition holds them (`src/staff/` and this feature are
// the course repository's only).
#[cfg(feature = "staff")]
mod staff;

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::{Args, Parser, Subcommand};

/// The course's tooling: grade the exercises, watch, hints, the figures and the viewer (and, in
/// the course repository, the staff's tools).
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
    /// Grade a topic, and again whenever one of its files changes: one screen each time.
    Watch {
        /// The topic (as for `grade`) [default: the first with a `todo!()` left].
        topic: Option<String>,
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
    /// The staff's commands (the course repository only).
    #[cfg(feature = "staff")]
    #[command(flatten)]
    Staff(staff::Command),
}

#[derive(Args)]
struct GradeArgs {
    /// Topics to grade: folder (`01-lines`), its name (`lines`), package or number; default all.
    topics: Vec<String>,
    /// Grade the reference solutions instead of the student code.
    #[arg(long)]
    reference: bool,
    /// Grade a student's checkout with this course's official tests; changed tests are
    /// flagged. (In the course repository, also every checkout in a folder of them: a class,
    /// with its gradebook.)
    #[arg(long, value_name = "DIR")]
    submission: Option<PathBuf>,
    /// Where report.json, results.json, junit.xml, logs and images go [default: <root>/target/grade].
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Tests run at the same time [default: the number of CPUs]; in a class (the course
    /// repository's), also the submissions graded side by side [default: one per two CPUs].
    #[arg(long, short, value_name = "N")]
    jobs: Option<usize>,
    /// cargo's target directory for the build [default: cargo's].
    #[arg(long, value_name = "DIR")]
    target_dir: Option<PathBuf>,
    /// The longest a build of student code may take, in seconds; a build over it fails
    /// that submission (and a class goes on with the next) [default: 2700].
    #[arg(long, value_name = "SECONDS")]
    build_time_limit: Option<u64>,
    /// Of a class, grade only the I-th of N parts (a member is always in the same part),
    /// e.g. on N machines; `cargo xtask gradebook merge` joins their --out folders.
    #[cfg(feature = "staff")]
    #[arg(long, value_name = "I/N", value_parser = staff::class::Shard::parse)]
    shard: Option<staff::class::Shard>,
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
        // One checkout, or (the staff's) a class.
        #[cfg(feature = "staff")]
        Some(dir) => staff::class::run(&root, &dir, &options, args.jobs, args.shard),
        // One checkout: an edition's grader grades no class.
        #[cfg(not(feature = "staff"))]
        Some(dir) => grade::submission::run(&root, &dir, &options).map(drop),
        #[cfg(feature = "staff")]
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
        Command::View { reference, args } => view::run(&root, reference, &args),
        Command::Figures { mine, topics } => figures::run(&root, mine, &topics),
        Command::Hint { task, all, reset } => hint::run(&root, &task, all, reset),
        #[cfg(feature = "staff")]
        Command::Staff(command) => staff::run(&root, command),
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
