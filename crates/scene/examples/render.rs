//! Renders a mesh the way the sheet's `main.m` does: load, transform to
//! clip space, (optionally) clip, divide, map to pixels, rasterize, save.
//!
//! ```text
//! cargo run -p scene --example render -- star.ply --mode fill -o star.png
//! cargo run -p scene --example render -- clipped_torus.ply --mode line --clip -o t.png
//! ```
//!
//! A mesh name that is not an existing path is looked up among the shipped
//! meshes (`crates/scene/data/`). `--clip` drops every polygon that is not
//! entirely inside the view volume (`scene::discard_outside`), a stand-in
//! for the Sutherland–Hodgman clipper of the clipping exercise.

use std::path::PathBuf;
use std::process::ExitCode;

use canvas::{Canvas, Rgba};
use clap::{Parser, ValueEnum};
use scene::{Mode, Pipeline};

#[derive(Clone, Copy, Debug, ValueEnum)]
enum CliMode {
    /// Wireframe (one-pixel bands).
    Line,
    /// Filled polygons (edge functions).
    Fill,
}

/// Renders a PLY mesh to a PNG with the course camera.
#[derive(Debug, Parser)]
struct Args {
    /// A PLY file, or the name of a shipped mesh (e.g. `star.ply`).
    mesh: PathBuf,
    /// How to draw the polygons.
    #[arg(long, value_enum, default_value = "line")]
    mode: CliMode,
    /// Drop polygons that leave the view volume before drawing.
    #[arg(long)]
    clip: bool,
    /// Canvas width in pixels.
    #[arg(long, default_value_t = 512)]
    width: u32,
    /// Canvas height in pixels.
    #[arg(long, default_value_t = 512)]
    height: u32,
    /// The PNG to write.
    #[arg(short, long, default_value = "out.png")]
    output: PathBuf,
}

fn main() -> ExitCode {
    let args = Args::parse();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: &Args) -> Result<(), Box<dyn std::error::Error>> {
    let shipped = scene::data::path(&args.mesh.to_string_lossy());
    let path = if !args.mesh.exists() && shipped.exists() {
        shipped
    } else {
        args.mesh.clone()
    };
    let mesh = scene::ply::load(&path)?;
    let mut canvas = Canvas::try_new(args.width, args.height)?;
    canvas.clear(Rgba::BLACK);
    let pipeline = Pipeline::for_mesh(&mesh, args.width, args.height);
    let mut polygons = pipeline.clip_space(&mesh);
    if args.clip {
        polygons = scene::discard_outside(&polygons);
    }
    let mode = match args.mode {
        CliMode::Line => Mode::Line,
        CliMode::Fill => Mode::Fill,
    };
    pipeline.render(&polygons, mode, &mut canvas);
    canvas.save_png(&args.output)?;
    println!("{}", args.output.display());
    Ok(())
}
