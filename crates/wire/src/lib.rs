//! The words the grader (`xtask`) and the code it runs (the test kit, the
//! transcript, their macros) agree on, each written once: the environment
//! variables the grader sets, the lines a test prints for it, and the
//! course's random seed. A dependency of both sides that depends on
//! nothing.

/// The variable naming the file that holds a test run's token: a test
/// marked `#[testkit::test]` that passes prints the token after
/// [`VERDICT_PREFIX`]; outside the grader it is unset.
pub const VERDICT_FILE_VAR: &str = "TESTKIT_VERDICT_FILE";

/// What a passed test prints before its token, on a line of its own.
pub const VERDICT_PREFIX: &str = "testkit verdict: passed ";

/// The variable naming the file a run of the student's code records its
/// task calls into (`transcript`'s record).
pub const RECORD_VAR: &str = "TRANSCRIPT_RECORD";

/// The variable naming the record a replay reads back.
pub const REPLAY_VAR: &str = "TRANSCRIPT_REPLAY";

/// The `cfg` under which a task function is built as its replay.
pub const REPLAY_CFG: &str = "transcript_replay";

/// The line that opens a raster diff in a failure message (the report
/// shows the lines up to [`RASTER_DIFF_END`] as a picture).
pub const RASTER_DIFF_BEGIN: &str = "--- raster diff: expected vs yours ---";

/// The line that closes a raster diff.
pub const RASTER_DIFF_END: &str = "--- end raster diff ---";

/// The course's random seed: every property test draws its cases from it,
/// and the grader hands it to proptest (`PROPTEST_RNG_SEED`) where a
/// test's configuration forgot it, so that a grade repeats.
pub const SEED: u64 = 0x0C0D_E5EE_D000_0001;

/// What the viewer's `--screenshot PICTURE` writes beside the picture, at
/// `PICTURE` with this extension: the stages it drew with, a JSON array
/// of `{"name", "status", "source"}` objects in the pipeline's order, for
/// the grader's report (which reads it instead of the viewer's printed
/// lines).
pub const STAGES_EXTENSION: &str = "stages.json";
