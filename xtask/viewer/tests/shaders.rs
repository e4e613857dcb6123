//! Every shader of the course translated by naga for each GPU backend a
//! student's machine may have: SPIR-V (Vulkan, on Linux and Windows), MSL
//! (Metal, on a Mac) and HLSL (DX12, on Windows). wgpu translates WGSL the
//! same way when it makes a shader module, so a shader that a Mac or a
//! Windows machine would refuse fails here first, where neither runs.
//!
//! The shaders are topic 10's, put together as its passes and render pass
//! (and so the viewer's GPU scene) put them together: each task's WGSL with
//! the given WGSL it goes with, the given stand-ins for unwritten shading
//! and trimming included; the task's WGSL is the solution (staged over the
//! stubs, as in `cargo xtask test`; in the course checkout, where the stubs
//! are compiled in, it is read from `reference/`). And the WGSL of the
//! course library's own GPU tests (`crates/gpu/tests`), which a plain
//! `cargo test` runs on the student's machine.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use gpu_tessellation::shaders;
use gpu_tessellation::wgsl::{self, Part, Piece};
use naga::back::{hlsl, msl, spv};
use naga::valid::{Capabilities, ValidationFlags, Validator};

/// The course's root (this crate is `xtask/viewer`).
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The topic whose WGSL files are tasks.
const TOPIC: &str = "10-gpu-tessellation";

/// Every task's WGSL piece.
const PIECES: [Piece; 5] = [
    wgsl::CONTROL,
    wgsl::EVALUATION,
    wgsl::SHADING,
    wgsl::TRIMMING,
    wgsl::PN,
];

/// `piece` with its solution: as compiled in where it is written (the
/// stage), from `reference/` where the stub is.
fn solved(piece: Piece) -> Piece {
    if piece.started() {
        return piece;
    }
    let file = root().join("reference").join(TOPIC).join(piece.file);
    let text = std::fs::read_to_string(&file).unwrap_or_else(|e| {
        panic!(
            "{} is a stub and {} cannot be read ({e}): run this test with the solutions \
             staged (`cargo xtask test --step 2`)",
            piece.file,
            file.display()
        )
    });
    piece.with_text(Box::leak(text.into_boxed_str()))
}

/// Topic 10's shaders, named, as `passes` and `render` compose them.
fn topic_shaders() -> Vec<(String, String)> {
    let [control, evaluation, shading, trimming, pn] = PIECES.map(|p| Part::Yours(solved(p)));
    let common = Part::Given("crate::shaders::COMMON", shaders::COMMON);
    let render = Part::Given("crate::shaders::RENDER", shaders::RENDER);
    let flat = Part::Given("crate::shaders::FLAT_SHADING", shaders::FLAT_SHADING);
    let no_trimming = Part::Given("crate::shaders::NO_TRIMMING", shaders::NO_TRIMMING);
    let given_trimming = Part::Given("crate::shaders::TRIMMING", shaders::TRIMMING);
    let composed: [(&str, Vec<Part<'_>>); 7] = [
        (
            "control pass",
            vec![
                control,
                common,
                Part::Given("crate::shaders::CONTROL", shaders::CONTROL),
            ],
        ),
        (
            "PN pass",
            vec![pn, common, Part::Given("crate::shaders::PN", shaders::PN)],
        ),
        (
            "evaluation pass",
            vec![
                evaluation,
                common,
                Part::Given("crate::shaders::EVALUATION", shaders::EVALUATION),
            ],
        ),
        (
            "render pass, shading and trimming",
            vec![shading, trimming, render, given_trimming],
        ),
        (
            "render pass, shading alone",
            vec![shading, render, no_trimming],
        ),
        (
            "render pass, trimming alone",
            vec![trimming, render, flat, given_trimming],
        ),
        (
            "render pass, neither (the viewer's stand-ins)",
            vec![render, flat, no_trimming],
        ),
    ];
    composed
        .into_iter()
        .map(|(name, parts)| {
            let source = wgsl::compose(&parts).unwrap_or_else(|e| panic!("{name}: {e}"));
            (format!("{TOPIC}: {name}"), source)
        })
        .collect()
}

/// The raw string literals of Rust `code` that hold a WGSL entry point
/// (comments, other strings and character literals skipped).
fn embedded_shaders(code: &str) -> Vec<String> {
    let bytes = code.as_bytes();
    // Where `pattern` next occurs at or after `from` (the end if nowhere).
    let find = |from: usize, pattern: &[u8]| {
        bytes
            .get(from..)
            .and_then(|rest| rest.windows(pattern.len()).position(|w| w == pattern))
            .map_or(bytes.len(), |n| from + n)
    };
    let mut found = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let identifier = |at: usize| bytes[at].is_ascii_alphanumeric() || bytes[at] == b'_';
        match bytes[i] {
            b'/' if bytes.get(i + 1) == Some(&b'/') => {
                i = find(i, b"\n");
            }
            b'r' if i == 0 || !identifier(i - 1) => {
                let hashes = bytes[i + 1..].iter().take_while(|&&b| b == b'#').count();
                if bytes.get(i + 1 + hashes) != Some(&b'"') {
                    i += 1;
                    continue;
                }
                let body = i + 2 + hashes;
                let close = format!("\"{}", "#".repeat(hashes));
                let end = find(body, close.as_bytes());
                let text = String::from_utf8_lossy(&bytes[body.min(end)..end]);
                if ["@vertex", "@fragment", "@compute"]
                    .iter()
                    .any(|stage| text.contains(stage))
                {
                    found.push(text.into_owned());
                }
                i = end + close.len();
            }
            b'"' => {
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
            }
            // A character literal ('"', '\''); a lifetime has no closing quote.
            b'\'' if bytes.get(i + 1) == Some(&b'\\') => {
                i = find(i + 3, b"'") + 1;
            }
            b'\'' if bytes.get(i + 2) == Some(&b'\'') => i += 3,
            _ => i += 1,
        }
    }
    found
}

/// The WGSL of the course library's GPU tests.
fn library_test_shaders() -> Vec<(String, String)> {
    let tests = root().join("crates/gpu/tests");
    let mut shaders = Vec::new();
    let mut files: Vec<PathBuf> = std::fs::read_dir(&tests)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", tests.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "rs"))
        .collect();
    files.sort();
    for file in files {
        let code = std::fs::read_to_string(&file).unwrap();
        for (n, text) in embedded_shaders(&code).into_iter().enumerate() {
            let name = file.file_name().unwrap().to_string_lossy();
            shaders.push((format!("crates/gpu/tests/{name}: shader {}", n + 1), text));
        }
    }
    shaders
}

/// The oldest Metal Shading Language wgpu's Metal backend is asked for on
/// a Mac that runs Rust's `aarch64-apple-darwin` (macOS 11: MSL 2.3) or
/// `x86_64-apple-darwin` (macOS 10.12: MSL 1.2) target.
const MSL_VERSION: (u8, u8) = (1, 2);

/// `source` translated for every backend, one entry point at a time as
/// wgpu does: the errors, each naming its backend and entry point.
fn translate(source: &str) -> Result<usize, Vec<String>> {
    let module =
        naga::front::wgsl::parse_str(source).map_err(|e| vec![e.emit_to_string(source)])?;
    let info = Validator::new(ValidationFlags::all(), Capabilities::default())
        .validate(&module)
        .map_err(|e| vec![e.emit_to_string(source)])?;
    if module.entry_points.is_empty() {
        return Err(vec!["no entry point".to_owned()]);
    }
    let mut errors = Vec::new();
    for entry in &module.entry_points {
        let at = |backend: &str, error: &dyn std::fmt::Display| {
            format!("{backend}, entry point `{}`: {error}", entry.name)
        };
        let spv_pipeline = spv::PipelineOptions {
            shader_stage: entry.stage,
            entry_point: entry.name.clone(),
        };
        if let Err(e) = spv::write_vec(
            &module,
            &info,
            &spv::Options::default(),
            Some(&spv_pipeline),
        ) {
            errors.push(at("SPIR-V (Vulkan)", &e));
        }
        let msl_options = msl::Options {
            lang_version: MSL_VERSION,
            ..msl::Options::default()
        };
        let msl_pipeline = msl::PipelineOptions {
            entry_point: Some((entry.stage, entry.name.clone())),
            ..msl::PipelineOptions::default()
        };
        match msl::write_string(&module, &info, &msl_options, &msl_pipeline) {
            Ok((_, translated)) => {
                for name in translated.entry_point_names {
                    if let Err(e) = name {
                        errors.push(at("MSL (Metal)", &e));
                    }
                }
            }
            Err(e) => errors.push(at("MSL (Metal)", &e)),
        }
        let hlsl_pipeline = hlsl::PipelineOptions {
            entry_point: Some((entry.stage, entry.name.clone())),
        };
        let hlsl_options = hlsl::Options::default();
        let mut hlsl_text = String::new();
        let written = hlsl::Writer::new(&mut hlsl_text, &hlsl_options, &hlsl_pipeline)
            .write(&module, &info, None);
        match written {
            Ok(reflection) => {
                for name in reflection.entry_point_names {
                    if let Err(e) = name {
                        errors.push(at("HLSL (DX12)", &e));
                    }
                }
            }
            Err(e) => errors.push(at("HLSL (DX12)", &e)),
        }
    }
    if errors.is_empty() {
        Ok(module.entry_points.len())
    } else {
        Err(errors)
    }
}

#[test]
fn every_shader_translates_to_spirv_msl_and_hlsl() {
    let all: Vec<(String, String)> = topic_shaders()
        .into_iter()
        .chain(library_test_shaders())
        .collect();
    assert!(
        all.len() >= 8,
        "expected topic 10's six shaders and the library tests' (found {})",
        all.len()
    );
    let mut failures = String::new();
    let mut entry_points = 0;
    for (name, source) in &all {
        match translate(source) {
            Ok(count) => entry_points += count,
            Err(errors) => {
                writeln!(failures, "{name}:").unwrap();
                for error in errors {
                    writeln!(failures, "  {error}").unwrap();
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures}");
    println!(
        "{} shaders, {entry_points} entry points: SPIR-V, MSL {}.{} and HLSL (SM 5.1) each",
        all.len(),
        MSL_VERSION.0,
        MSL_VERSION.1
    );
}

/// Every `.wgsl` file of the course is one of the pieces above, so a new
/// one cannot go untranslated.
#[test]
fn every_wgsl_file_of_the_course_is_translated() {
    let mut unknown = Vec::new();
    for folder in ["exercises", "crates", "xtask"] {
        let mut stack = vec![root().join(folder)];
        while let Some(dir) = stack.pop() {
            let Ok(entries) = std::fs::read_dir(&dir) else {
                continue;
            };
            for entry in entries.flatten() {
                let path = entry.path();
                let kind = entry.file_type().unwrap();
                if kind.is_dir() && entry.file_name() != "target" {
                    stack.push(path);
                } else if kind.is_file() && path.extension().is_some_and(|e| e == "wgsl") {
                    let relative = path.strip_prefix(root()).unwrap_or(&path).to_path_buf();
                    let known = PIECES
                        .iter()
                        .any(|p| relative == Path::new("exercises").join(TOPIC).join(p.file));
                    if !known {
                        unknown.push(relative.display().to_string());
                    }
                }
            }
        }
    }
    assert!(
        unknown.is_empty(),
        "WGSL files that tests/shaders.rs does not translate: {unknown:?}"
    );
}

#[test]
fn the_raw_strings_with_an_entry_point_are_found() {
    let code = "let a = r\"@compute fn f() {}\"; let b = r\"fn g() {}\"; \
                let q = '\"'; let s = \"colour\"; // r\"@vertex in a comment\"
                let c = r#\"@fragment fn h() -> @location(0) vec4<f32> { return \"x\"; }\"#;";
    assert_eq!(
        embedded_shaders(code),
        [
            "@compute fn f() {}",
            "@fragment fn h() -> @location(0) vec4<f32> { return \"x\"; }"
        ]
    );
}
