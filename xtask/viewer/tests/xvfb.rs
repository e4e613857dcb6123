//! The real window, under Xvfb (a virtual X server): it opens, shows your
//! picture and saves a screenshot of itself. `cargo xtask test` installs
//! Xvfb where it is missing; without it this test is skipped with a note,
//! except under CI, which must test the window.
#![cfg(feature = "window")]

use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// `xvfb-run`, if it is on the `PATH`.
fn xvfb_run() -> Option<PathBuf> {
    std::env::split_paths(&std::env::var_os("PATH")?)
        .map(|dir| dir.join("xvfb-run"))
        .find(|p| p.is_file())
}

/// Opens the viewer under `xvfb_run` with `args`, lets it save a
/// screenshot of its window and close, and returns the screenshot.
fn window_screenshot(xvfb_run: &std::path::Path, name: &str, args: &[&str]) -> canvas::Canvas {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("xvfb");
    std::fs::create_dir_all(&dir).unwrap();
    let shot = dir.join(name);
    let _ = std::fs::remove_file(&shot);
    let mut child = Command::new(xvfb_run)
        .args(["--auto-servernum", "--server-args=-screen 0 1280x800x24"])
        .arg(env!("CARGO_BIN_EXE_course-viewer"))
        .args(args)
        .arg("--window-screenshot")
        .arg(&shot)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("xvfb-run starts");
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            panic!("the window did not save its screenshot and close within 2 minutes");
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let output = child.wait_with_output().unwrap();
    assert!(
        status.success(),
        "the viewer under Xvfb: {status}\n{}\n{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    let picture = canvas::Canvas::load_png(&shot).expect("a screenshot of the window");
    assert!(
        picture.width() >= 800 && picture.height() >= 600,
        "{} × {}",
        picture.width(),
        picture.height()
    );
    picture
}

#[test]
fn the_window_opens_under_xvfb_and_shows_the_picture() {
    let Some(xvfb_run) = xvfb_run() else {
        assert!(
            std::env::var_os("CI").is_none(),
            "xvfb-run is missing, and CI must test the real window (`cargo xtask test` installs the Debian package xvfb)"
        );
        eprintln!("skipped: no xvfb-run here (Debian: apt-get install xvfb xauth)");
        return;
    };
    let picture = window_screenshot(
        &xvfb_run,
        "window.png",
        &["--mesh", "star.ply", "--size", "200"],
    );
    // The star's top vertex is red: the picture is in the window.
    let reds = picture
        .enumerate()
        .filter(|(_, c)| c.r > 0.8 && c.g < 0.3 && c.b < 0.3)
        .count();
    assert!(
        reds > 20,
        "{reds} red pixels: the star is not in the window"
    );
    // The pixel playground: the DDA line's orange first pixel.
    let picture = window_screenshot(&xvfb_run, "pixels.png", &["--pixels"]);
    let orange = picture
        .enumerate()
        .filter(|(_, c)| c.r > 0.9 && (0.35..0.55).contains(&c.g) && c.b < 0.3)
        .count();
    assert!(
        orange > 100,
        "{orange} orange pixels: the playground's line is not in the window"
    );
    // The curve scene: the red dot of C(t) and the blue first level of
    // the construction.
    let picture = window_screenshot(&xvfb_run, "curves.png", &["--curves"]);
    let count = |(r, g, b): (f32, f32, f32)| {
        picture
            .enumerate()
            .filter(|(_, c)| {
                (c.r - r).abs() < 0.05 && (c.g - g).abs() < 0.05 && (c.b - b).abs() < 0.05
            })
            .count()
    };
    let dot = count((1.0, 60.0 / 255.0, 60.0 / 255.0));
    let level = count((90.0 / 255.0, 170.0 / 255.0, 1.0));
    assert!(
        dot > 20 && level > 20,
        "{dot} red and {level} blue pixels: the curve scene's construction is not in the window"
    );
    // The surface scene: the parameter square beside the hill, the
    // circle cut away (dark) from the rest (light).
    let picture = window_screenshot(&xvfb_run, "surfaces.png", &["--surfaces"]);
    let count = |(r, g, b): (f32, f32, f32)| {
        picture
            .enumerate()
            .filter(|(_, c)| {
                (c.r - r).abs() < 0.03 && (c.g - g).abs() < 0.03 && (c.b - b).abs() < 0.03
            })
            .count()
    };
    let (cut, kept) = (count((0.2, 0.12, 0.12)), count((0.85, 0.8, 0.6)));
    assert!(
        cut > 500 && kept > 5000,
        "{cut} dark and {kept} light pixels: the surface scene's parameter square is not in the window"
    );
    // The tessellation scene: the torus on the renderer's white ground.
    let picture = window_screenshot(&xvfb_run, "tessellation.png", &["--tessellation"]);
    let white = picture
        .enumerate()
        .filter(|(_, c)| c.r > 0.99 && c.g > 0.99 && c.b > 0.99)
        .count();
    let blue = picture
        .enumerate()
        .filter(|(_, c)| c.b > 0.5 && c.b > c.r + 0.2)
        .count();
    assert!(
        white > 40_000 && blue > 20_000,
        "{white} white and {blue} blue pixels: the tessellation scene's torus is not in the window"
    );
    // The GPU scene: the hill's bricks (red-brown) under the yellow
    // wireframe, drawn by topic 10's passes on lavapipe or a GPU.
    let picture = window_screenshot(&xvfb_run, "gpu.png", &["--gpu"]);
    let bricks = picture
        .enumerate()
        .filter(|(_, c)| c.r > 0.3 && c.r > 1.6 * c.g && c.g > 1.2 * c.b)
        .count();
    assert!(
        bricks > 5000,
        "{bricks} brick-coloured pixels: the GPU scene's hill is not in the window"
    );
}
