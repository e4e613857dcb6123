//! A grade's course of events: set up, build, list, run, judge, draw.
//!
//! A grade whose reader sees each topic as soon as it is graded (a
//! student's `cargo xtask grade`) runs topic by topic: a topic is built,
//! its tests listed and run and its verdicts made before the next topic is
//! built, so that the first topic's rows of the table are on screen after
//! its own build, not after the whole course's (a first build compiles the
//! dependencies, some minutes for the GPU topic's), and the viewer that
//! draws the report's pipeline is built last. Any other grade builds every
//! topic and the viewer first, in one cargo run where they compile, which
//! keeps both cores busy and is quicker in all; a grade in a class's slot
//! (the staff's class) does so while the slot holds its turn, so that its
//! tests run from executables kept apart while the next slot builds.

use std::collections::HashMap;
use std::fs;
#[cfg(feature = "staff")]
use std::path::Path;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result, bail};

use super::build::TestBinary;
use super::build::{self, Build};
use super::events::Events;
use super::plan::{self, Plan};
use super::report::{self, Edition, TopicReport};
use super::{GradeOptions, Graded, PENDING_SNAPSHOTS, Setting, pipeline, pool, table, verdict};
use crate::topics::{self, Topic};

/// A course set up for its grade: the topics chosen, the report folder
/// cleared, the builder ready; and, for a grade in a class's slot, every
/// topic built and its tests listed ([`Prepared::plans`]). The first half
/// of a grade.
pub(crate) struct Prepared {
    options: GradeOptions,
    setting: Setting,
    edition: Edition,
    started: Instant,
    root: PathBuf,
    out: PathBuf,
    topics: Vec<Topic>,
    builder: build::Builder,
    /// Every topic's plan, where all were built up front (a class's slot);
    /// empty where each is built in its turn.
    plans: Vec<Plan>,
    /// The viewer, where it was built up front.
    viewer: Option<pipeline::Viewer>,
    /// Seconds the builds up front took.
    build_s: f64,
}

/// Sets up the grade of the course at `options.root` (every topic but
/// those `setting` says are absent). Unless `events` shows each topic as
/// it is graded, also builds every topic and the pipeline's viewer and
/// lists the tests.
pub(crate) fn prepare(
    options: &GradeOptions,
    edition: Edition,
    setting: Setting,
    events: &dyn Events,
) -> Result<Prepared> {
    let started = Instant::now();
    let root = std::path::absolute(&options.root)
        .with_context(|| format!("cannot find {}", options.root.display()))?;
    let out = std::path::absolute(&options.out)
        .with_context(|| format!("cannot find {}", options.out.display()))?;
    let mut topics = topics::select(&root, &options.topics)?;
    narrow(&mut topics, &options.tasks)?;
    if topics.is_empty() {
        bail!(
            "there are no topics in {}",
            root.join("exercises").display()
        );
    }
    fs::create_dir_all(&out).with_context(|| format!("cannot create {}", out.display()))?;
    if topics.iter().any(|topic| topic.sheet.gpu) {
        crate::setup::ensure_vulkan();
    }
    // (What an earlier grade's tests left may be anything: removed by the
    // grader's bounded removal, never `fs::remove_dir_all`.)
    for stale in [
        out.join(PENDING_SNAPSHOTS),
        out.join("scratch"),
        out.join(plan::SHADER_CACHE),
        out.join("build"),
    ] {
        crate::files::remove_tree(&stale)
            .with_context(|| format!("cannot clear {}", stale.display()))?;
    }
    let target_dir = build::target_dir_of(&root, options.target_dir.as_deref());
    let builder = build::Builder {
        root: root.clone(),
        logs: out.join("build"),
        time_limit: options.build_time_limit,
        // A checkout graded in place builds into its own `target/`, which
        // also holds its stages and reports: not cargo's, not shown.
        emptied: [
            target_dir.join("xtask"),
            target_dir.join("grade"),
            out.clone(),
        ]
        .into_iter()
        .filter(|dir| dir.starts_with(&target_dir))
        .collect(),
        target_dir,
    };
    events.table(&layout_of(&topics));
    let mut prepared = Prepared {
        options: options.clone(),
        setting,
        edition,
        started,
        root,
        out,
        topics,
        builder,
        plans: Vec::new(),
        viewer: None,
        build_s: 0.0,
    };
    #[cfg(feature = "staff")]
    let up_front = prepared.setting.beside.is_some() || !events.topic_by_topic();
    #[cfg(not(feature = "staff"))]
    let up_front = !events.topic_by_topic();
    if up_front {
        prepared.build_everything(events)?;
    }
    Ok(prepared)
}

/// Keeps of each topic that `tasks` names only the tasks it names there
/// (see [`GradeOptions::tasks`]).
fn narrow(topics: &mut [Topic], tasks: &[(String, String)]) -> Result<()> {
    for (topic_name, task) in tasks {
        let topic = topics
            .iter()
            .find(|topic| topic.name == *topic_name)
            .with_context(|| format!("{topic_name} is not among the topics graded"))?;
        if !topic.sheet.tasks.iter().any(|t| t.id == *task) {
            bail!("{topic_name} has no task {task}");
        }
    }
    for topic in topics {
        let named: Vec<&str> = tasks
            .iter()
            .filter(|(name, _)| *name == topic.name)
            .map(|(_, task)| task.as_str())
            .collect();
        if !named.is_empty() {
            topic
                .sheet
                .tasks
                .retain(|task| named.contains(&task.id.as_str()));
        }
    }
    Ok(())
}

/// The table's columns for the tasks of `topics` (see [`table::Layout`]).
fn layout_of(topics: &[Topic]) -> table::Layout {
    let rows: Vec<table::RowShape> = topics
        .iter()
        .flat_map(|topic| {
            topic.sheet.tasks.iter().map(|task| table::RowShape {
                id: task.id.clone(),
                title: task.title.clone(),
                bonus: task.bonus,
                points: task.points,
            })
        })
        .collect();
    table::Layout::new(topics.iter().map(|topic| topic.name.as_str()), &rows)
}

/// What a build step says it builds: the topics, and, where the build
/// folder holds no build yet, that the dependencies come first.
fn building(builder: &build::Builder, what: &str) -> String {
    if builder.is_first() {
        format!(
            "building {what}: the first build compiles the course's dependencies too (some minutes; later builds take seconds)"
        )
    } else {
        format!("building {what}")
    }
}

/// Runs `build` while a second thread tells `events`, every quarter of a
/// second, how many crates cargo has built so far and which last, as its
/// JSON messages in `log` (the build's stdout) say: a first build takes
/// minutes, and a student sees it move.
fn showing_progress<T>(
    events: &dyn Events,
    what: &str,
    log: &std::path::Path,
    build: impl FnOnce() -> T,
) -> T {
    let done = std::sync::atomic::AtomicBool::new(false);
    std::thread::scope(|scope| {
        scope.spawn(|| {
            let mut built = 0;
            let mut read: u64 = 0;
            let mut last = String::new();
            while !done.load(std::sync::atomic::Ordering::Relaxed) {
                std::thread::sleep(std::time::Duration::from_millis(250));
                // What the log gained since the last look, whole lines only.
                let Some(bytes) = read_from(log, read) else {
                    continue;
                };
                let Some(end) = bytes.iter().rposition(|&b| b == b'\n') else {
                    continue;
                };
                for line in String::from_utf8_lossy(&bytes[..=end]).lines() {
                    let message = crate::cargo::Message::parse(line);
                    if let Some(target) = message.filter(|m| m.is_artifact()).and_then(|m| m.target)
                    {
                        built += 1;
                        last = target.name;
                    }
                }
                read += end as u64 + 1;
                if built > 0 {
                    events.step(&format!(
                        "{what} · {built} crates built, the last {}",
                        table::shown(&last)
                    ));
                }
            }
        });
        let result = build();
        done.store(true, std::sync::atomic::Ordering::Relaxed);
        result
    })
}

/// The bytes of the file at `path` from `offset` on; `None` when it
/// cannot be read.
fn read_from(path: &std::path::Path, offset: u64) -> Option<Vec<u8>> {
    use std::io::{Read as _, Seek as _};
    let mut file = fs::File::open(path).ok()?;
    file.seek(std::io::SeekFrom::Start(offset)).ok()?;
    let mut bytes = Vec::new();
    file.read_to_end(&mut bytes).ok()?;
    Some(bytes)
}

impl Prepared {
    /// The topics the graded code holds: all but the absent.
    fn held(&self) -> Vec<Topic> {
        self.topics
            .iter()
            .filter(|topic| !self.setting.absent.contains(&topic.name))
            .cloned()
            .collect()
    }

    /// Builds every topic (all at once when they compile, one by one to
    /// tell whose errors they are) and the viewer, and lists the tests
    /// (a class's slot: before it gives up its turn).
    fn build_everything(&mut self, events: &dyn Events) -> Result<()> {
        let building_started = Instant::now();
        let held = self.held();
        let mut together: Option<std::vec::IntoIter<Vec<TestBinary>>> = None;
        let mut stopped: Option<String> = None;
        if held.len() > 1 {
            events.step(&building(&self.builder, &format!("{} topics", held.len())));
            match build::build_all(&self.builder, &held)? {
                Ok(all) => together = Some(all.into_iter()),
                Err(reason) => stopped = reason,
            }
        }
        let mut plans = Vec::new();
        for topic in &self.topics {
            let built = if self.setting.absent.contains(&topic.name) {
                None
            } else {
                match (together.as_mut().and_then(Iterator::next), &stopped) {
                    // (None found: built on its own, which says why.)
                    (Some(binaries), _) if !binaries.is_empty() => Some(Build::Built(binaries)),
                    (_, Some(reason)) => Some(Build::Failed(reason.clone())),
                    _ => None,
                }
            };
            plans.push(self.plan_topic(topic, built, events)?);
        }
        let viewer = self.build_viewer(&plans, events);
        #[cfg(feature = "staff")]
        let viewer = match (&self.setting.beside, viewer) {
            (Some(beside), pipeline::Viewer::Built(binary)) => {
                match keep_binary(&binary, &beside.keep_binaries.join("viewer")) {
                    Ok(kept) => pipeline::Viewer::Built(kept),
                    Err(error) => pipeline::Viewer::Failed(format!("{error:#}")),
                }
            }
            (_, viewer) => viewer,
        };
        self.viewer = Some(viewer);
        self.plans = plans;
        self.build_s = building_started.elapsed().as_secs_f64();
        Ok(())
    }

    /// The plan of `topic`: built (unless `built` says how it was) with its
    /// replay, its tests listed; an absent topic's plan says so.
    fn plan_topic(&self, topic: &Topic, built: Option<Build>, events: &dyn Events) -> Result<Plan> {
        for stale in [
            self.out.join("images").join(&topic.name),
            self.out.join("logs").join(&topic.name),
        ] {
            crate::files::remove_tree(&stale)
                .with_context(|| format!("cannot clear {}", stale.display()))?;
        }
        if self.setting.absent.contains(&topic.name) {
            return Ok(plan::absent(topic));
        }
        let build = match built {
            Some(build) => build,
            None => {
                let what = building(&self.builder, &topic.name);
                events.step(&what);
                let log = self.builder.logs.join(format!("{}.out", topic.name));
                showing_progress(events, &what, &log, || {
                    build::build_among(&self.builder, &self.held(), topic)
                })?
            }
        };
        // Of a topic narrowed to some tasks (see `narrow`), the others'
        // tests are not run.
        let build = match build {
            Build::Built(mut binaries) => {
                binaries.retain(|binary| {
                    self.options
                        .tasks
                        .iter()
                        .all(|(name, _)| *name != topic.name)
                        || topic.sheet.tasks.iter().any(|task| task.id == binary.name)
                });
                Build::Built(binaries)
            }
            failed @ Build::Failed(_) => failed,
        };
        let build = match (crate::stage::replay::package_dir(&self.root, topic), build) {
            (Some(package_dir), Build::Built(mut binaries)) => {
                events.step(&format!("building the replay of {}", topic.name));
                build::add_replays(&self.builder, topic, &package_dir, &mut binaries)?;
                Build::Built(binaries)
            }
            (_, build) => build,
        };
        #[cfg(feature = "staff")]
        let build = match (&self.setting.beside, build) {
            (Some(beside), Build::Built(binaries)) => Build::Built(keep_binaries(
                binaries,
                &beside.keep_binaries.join(&topic.name),
            )?),
            (_, build) => build,
        };
        Ok(plan::plan(&self.root, &self.out, topic, build))
    }

    /// Builds the viewer that draws the pipeline with the stages of the
    /// topics of `plans`.
    fn build_viewer(&self, plans: &[Plan], events: &dyn Events) -> pipeline::Viewer {
        let compiled: Vec<&str> = plans
            .iter()
            .filter(|plan| plan.compile_error.is_none())
            .map(|plan| plan.topic.name.as_str())
            .collect();
        let graded: Vec<&str> = plans
            .iter()
            .filter(|plan| !plan.absent)
            .map(|plan| plan.topic.name.as_str())
            .collect();
        let what = building(&self.builder, "the viewer that draws the report's pipeline");
        events.step(&what);
        let log = self.builder.logs.join("viewer.out");
        showing_progress(events, &what, &log, || {
            pipeline::build_viewer(&self.builder, &graded, &compiled)
        })
    }

    /// Runs the tests and draws the pipeline (building each topic in its
    /// turn where it was not built up front): the second half of a grade.
    pub(crate) fn finish(self, events: &dyn Events) -> Result<Graded> {
        #[cfg(feature = "staff")]
        let kept = self
            .setting
            .beside
            .as_ref()
            .map(|b| b.keep_binaries.clone());
        let report = self.run(events);
        #[cfg(feature = "staff")]
        if let Some(kept) = kept {
            let _ = crate::files::remove_tree(&kept);
        }
        report
    }

    fn run(mut self, events: &dyn Events) -> Result<Graded> {
        let out = self.out.clone();
        // What the tests write into the report folder is kept within one
        // budget for the whole grade, swept after each test (see
        // `files::Keeper`).
        let kept = pool::Kept {
            keeper: std::sync::Mutex::new(crate::files::Keeper::new(
                &out,
                crate::files::KEPT_BUDGET,
            )),
            pending: out.join(PENDING_SNAPSHOTS),
        };
        let workers = pool::Workers {
            threads: self.options.jobs.max(1),
            #[cfg(feature = "staff")]
            permits: self
                .setting
                .beside
                .as_ref()
                .map(|beside| std::sync::Arc::clone(&beside.permits)),
        };
        let mut topics: Vec<TopicReport> = Vec::with_capacity(self.topics.len());
        let mut tests_s = 0.0;
        let mut build_s = self.build_s;
        let plans = if self.plans.is_empty() {
            // Topic by topic: built, run and judged before the next.
            let mut plans = Vec::new();
            for topic in &self.topics {
                let building = Instant::now();
                let plan = self.plan_topic(topic, None, events)?;
                build_s += building.elapsed().as_secs_f64();
                let testing = Instant::now();
                run_tests(
                    std::slice::from_ref(&plan),
                    &out,
                    &workers,
                    &kept,
                    events,
                    &mut topics,
                )?;
                tests_s += testing.elapsed().as_secs_f64();
                plans.push(plan);
            }
            plans
        } else {
            let plans = std::mem::take(&mut self.plans);
            let testing = Instant::now();
            run_tests(&plans, &out, &workers, &kept, events, &mut topics)?;
            tests_s += testing.elapsed().as_secs_f64();
            plans
        };
        let mut keeper = kept
            .keeper
            .into_inner()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let viewer = match self.viewer.take() {
            Some(viewer) => viewer,
            None if !pipeline::worth_drawing(
                &topics
                    .iter()
                    .map(|t| {
                        (
                            t.name.as_str(),
                            t.tasks.iter().map(|task| task.passed).sum(),
                        )
                    })
                    .collect::<Vec<_>>(),
            ) =>
            {
                pipeline::Viewer::NotYet
            }
            None => {
                let building = Instant::now();
                let viewer = self.build_viewer(&plans, events);
                build_s += building.elapsed().as_secs_f64();
                viewer
            }
        };
        events.step("drawing the pipeline with your stages");
        let graded: Vec<&str> = plans
            .iter()
            .filter(|plan| !plan.absent)
            .map(|plan| plan.topic.name.as_str())
            .collect();
        let drawing = Instant::now();
        let pipeline = pipeline::draw_all(
            &pipeline::Plan {
                root: &self.root,
                out: &out,
                graded: &graded,
            },
            &viewer,
        );
        events.done();
        // The shaders the driver compiled are of no use to a reader.
        let _ = crate::files::remove_tree(&out.join(plan::SHADER_CACHE));
        // The builds' logs (the compiler's messages, which quote student
        // code) and what the listings of the tests and the viewer printed
        // into scratch, up to the output limit each, count to the same
        // budget.
        for folder in [out.join("build"), out.join("scratch")] {
            for log in crate::files::listing(&folder) {
                keeper.keep_log(&folder.join(log));
            }
        }
        let left_out = keeper.left_out();
        let phases = report::Phases {
            build_s: report::round2(build_s),
            tests_s: report::round2(tests_s),
            pipeline_s: report::round2(drawing.elapsed().as_secs_f64()),
        };
        Ok(Graded {
            root: self.root,
            edition: self.edition,
            started: self.started,
            phases,
            topics,
            pipeline,
            left_out,
        })
    }
}

/// Runs the tests of `plans` in the pool and judges each topic as soon as
/// its tests have ended, adding its report to `topics` and telling
/// `events`.
fn run_tests(
    plans: &[Plan],
    out: &std::path::Path,
    workers: &pool::Workers,
    kept: &pool::Kept,
    events: &dyn Events,
    topics: &mut Vec<TopicReport>,
) -> Result<()> {
    let mut jobs: Vec<(usize, usize)> = plans
        .iter()
        .enumerate()
        .flat_map(|(p, plan)| {
            let runnable = plan
                .tests
                .iter()
                .enumerate()
                .filter(|(_, test)| test.command.is_some());
            runnable.map(move |(t, _)| (p, t))
        })
        .collect();
    // Topic by topic, so that each topic is judged as soon as its tests
    // have ended; within a topic, first the first test of every task, then
    // the second of every task, and so on: the workers run tests of
    // different tasks side by side, so a task that loops costs one time
    // limit, not one per worker.
    let mut rank: HashMap<(usize, usize), usize> = HashMap::new();
    let mut order: HashMap<(usize, usize), usize> = HashMap::new();
    for &(p, t) in &jobs {
        let task = (p, plans[p].tests[t].task);
        let next = rank.entry(task).or_insert(0);
        order.insert((p, t), *next);
        *next += 1;
    }
    jobs.sort_by_key(|&(p, t)| (p, order[&(p, t)], plans[p].tests[t].task, t));
    events.tests_start(jobs.len());
    pool::run_all(plans, &jobs, workers, kept, events, |p, mut outcomes| {
        let topic = verdict::topic_report(out, &plans[p], |t| outcomes.remove(&t));
        events.topic_graded(&topic);
        topics.push(topic);
    })
}

/// Hard links `binaries` into `dir` (emptied first): cargo replaces an
/// executable it rebuilds with a new file, so the link keeps this build's.
#[cfg(feature = "staff")]
fn keep_binaries(binaries: Vec<TestBinary>, dir: &Path) -> Result<Vec<TestBinary>> {
    crate::files::remove_tree(dir).with_context(|| format!("cannot clear {}", dir.display()))?;
    binaries
        .into_iter()
        .map(|binary| {
            Ok(TestBinary {
                executable: keep_binary(&binary.executable, dir)?,
                replay: match &binary.replay {
                    Some(replay) => Some(keep_binary(replay, &dir.join("replay"))?),
                    None => None,
                },
                name: binary.name,
            })
        })
        .collect()
}

/// Hard links (or, across file systems, copies) `binary` into `dir`.
#[cfg(feature = "staff")]
fn keep_binary(binary: &Path, dir: &Path) -> Result<PathBuf> {
    fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let name = binary
        .file_name()
        .with_context(|| format!("{} has no file name", binary.display()))?;
    let kept = dir.join(name);
    let _ = fs::remove_file(&kept);
    if fs::hard_link(binary, &kept).is_err() {
        fs::copy(binary, &kept)
            .with_context(|| format!("cannot copy {} to {}", binary.display(), kept.display()))?;
    }
    Ok(kept)
}

#[cfg(test)]
mod tests {
    use std::sync::Mutex;

    use super::*;

    /// The steps told.
    #[derive(Default)]
    struct Told(Mutex<Vec<String>>);

    impl Events for Told {
        fn step(&self, what: &str) {
            self.0.lock().unwrap().push(what.to_owned());
        }
    }

    #[test]
    fn a_build_in_progress_says_how_many_crates_are_built() {
        let dir = std::env::temp_dir().join(format!("showing-progress-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let log = dir.join("01-x.out");
        let artifact = |name: &str| {
            format!(
                "{{\"reason\":\"compiler-artifact\",\"target\":{{\"name\":\"{name}\",\"kind\":[\"lib\"]}}}}\n"
            )
        };
        let told = Told::default();
        let built = showing_progress(&told, "building 01-x", &log, || {
            fs::write(&log, artifact("image")).unwrap();
            std::thread::sleep(std::time::Duration::from_millis(600));
            let more = format!(
                "{}{}{{\"reason\":\"build-finished\"}}\n{{\"reason\":\"compiler-artifact\"",
                artifact("image"),
                artifact("lines\\u001b[2J")
            );
            fs::write(&log, more).unwrap();
            std::thread::sleep(std::time::Duration::from_millis(600));
            7
        });
        assert_eq!(built, 7);
        let told = told.0.into_inner().unwrap();
        assert!(
            told.contains(&"building 01-x · 1 crates built, the last image".to_owned()),
            "{told:?}"
        );
        // (A line not yet whole is not read; a name is escaped.)
        assert_eq!(
            told.last().unwrap(),
            "building 01-x · 2 crates built, the last lines\\u{1b}[2J"
        );
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_narrowed_topic_keeps_the_named_tasks_and_the_others_stay_whole() {
        let topic = |name: &str| {
            Topic {
            name: name.to_owned(),
            package: name.to_owned(),
            dir: PathBuf::from(name),
            sheet: topics::TaskSheet::parse(
                "[[tasks]]\nid = \"a\"\ntitle = \"A\"\npoints = 1\n\n[[tasks]]\nid = \"b\"\ntitle = \"B\"\npoints = 1\n",
            )
            .unwrap(),
        }
        };
        let ids = |topic: &Topic| -> Vec<String> {
            topic.sheet.tasks.iter().map(|t| t.id.clone()).collect()
        };
        let mut topics = vec![topic("01-x"), topic("02-y")];
        narrow(&mut topics, &[("01-x".to_owned(), "b".to_owned())]).unwrap();
        assert_eq!(ids(&topics[0]), ["b"]);
        assert_eq!(ids(&topics[1]), ["a", "b"]);
        let unknown = narrow(&mut topics, &[("02-y".to_owned(), "c".to_owned())]);
        assert!(
            unknown
                .unwrap_err()
                .to_string()
                .contains("02-y has no task c")
        );
        let absent = narrow(&mut topics, &[("03-z".to_owned(), "a".to_owned())]);
        assert!(absent.is_err());
    }
}
