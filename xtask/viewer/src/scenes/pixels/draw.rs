//! What the playground draws: your pixels, the definition's, and how they
//! compare.

use std::collections::{BTreeMap, BTreeSet};

use canvas::{Fragment, Pixel, Rgba, Vec2, Vertex, Viewport};
use testkit::definitions;

use super::notes::{circle_note, line_note, triangle_note, wu_note};
use crate::stages::{Stage, Stages, Status, guarded};
use crate::worker::Worker;

/// A stage that plots more than this many pixels on the grid is stopped:
/// it would otherwise fill the memory (an endless loop that plots).
pub const MAX_PLOTS: usize = 100_000;

/// What the playground draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    /// `01-lines`: `dda::dda_line`, with colour interpolated.
    DdaLine,
    /// `01-lines`: `midpoint::midpoint_line`.
    MidpointLine,
    /// `01-lines`: `wu::wu_line`, an antialiased line: each pixel with its
    /// intensity.
    WuLine,
    /// `02-circles`: `midpoint_circle::midpoint_circle`.
    Circle,
    /// `03-fill`: `edge_function::fill_triangle`, with colour interpolated.
    Triangle,
}

impl Primitive {
    /// Every primitive, in course order.
    pub const ALL: [Self; 5] = [
        Self::DdaLine,
        Self::MidpointLine,
        Self::WuLine,
        Self::Circle,
        Self::Triangle,
    ];

    /// Its name on screen.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::DdaLine => "DDA line (01)",
            Self::MidpointLine => "Midpoint line (01)",
            Self::WuLine => "Wu's antialiased line (01)",
            Self::Circle => "Midpoint circle (02)",
            Self::Triangle => "Edge-function triangle (03)",
        }
    }

    /// How many handles it has: two endpoints, the centre and a point of
    /// the rim, three vertices.
    #[must_use]
    pub fn handles(self) -> usize {
        match self {
            Self::Triangle => 3,
            _ => 2,
        }
    }

    /// The step its handles move in, in pixels: whole pixels where the
    /// code takes pixels, half pixels for the triangle, whose fill rule
    /// decides centres that lie on an edge.
    #[must_use]
    pub fn snap(self) -> f32 {
        match self {
            Self::Triangle => 0.5,
            _ => 1.0,
        }
    }

    /// The stage that draws it.
    fn stage(self, stages: &Stages) -> (&'static str, &'static str) {
        let (name, source) = match self {
            Self::DdaLine => (stages.line.name, stages.line.source),
            Self::MidpointLine => (stages.midpoint.name, stages.midpoint.source),
            Self::WuLine => (stages.wu.name, stages.wu.source),
            Self::Circle => (stages.circle.name, stages.circle.source),
            Self::Triangle => (stages.fill.name, stages.fill.source),
        };
        (name, source)
    }
}

/// What to draw, and where.
#[derive(Clone, Debug, PartialEq)]
pub struct Setup {
    /// The primitive.
    pub primitive: Primitive,
    /// The grid's width and height in pixels; pixel `(0, 0)` is at the
    /// bottom left.
    pub size: i32,
    /// The handles, in pixel coordinates (centres at integers); a line and
    /// the circle use the first two.
    pub handles: [Vec2; 3],
}

impl Default for Setup {
    fn default() -> Self {
        Self {
            primitive: Primitive::DdaLine,
            size: 16,
            handles: Primitive::DdaLine.first_handles(),
        }
    }
}

impl Primitive {
    /// Where its handles start on the 16-pixel grid: a line of every kind
    /// of step, a circle inside the grid, a triangle with a vertex off the
    /// pixel centres.
    #[must_use]
    pub fn first_handles(self) -> [Vec2; 3] {
        match self {
            Self::DdaLine | Self::MidpointLine | Self::WuLine => [
                Vec2::new(2.0, 3.0),
                Vec2::new(13.0, 8.0),
                Vec2::new(5.0, 13.0),
            ],
            Self::Circle => [
                Vec2::new(8.0, 7.0),
                Vec2::new(13.0, 9.0),
                Vec2::new(5.0, 13.0),
            ],
            Self::Triangle => [
                Vec2::new(1.5, 2.0),
                Vec2::new(13.0, 7.5),
                Vec2::new(5.5, 13.0),
            ],
        }
    }
}

impl Setup {
    /// The grid sizes the playground offers.
    pub const SIZES: std::ops::RangeInclusive<i32> = 6..=48;

    /// The grid as a viewport.
    #[must_use]
    pub fn viewport(&self) -> Viewport {
        Viewport::new(0, 0, self.size - 1, self.size - 1)
    }

    /// Moves handle `k` to `to`, snapped to the primitive's step and kept
    /// on the grid.
    pub fn move_handle(&mut self, k: usize, to: Vec2) {
        let step = self.primitive.snap();
        let last = (self.size - 1) as f32;
        let snapped = |v: f32| ((v / step).round() * step).clamp(0.0, last);
        if let Some(handle) = self.handles.get_mut(k) {
            *handle = Vec2::new(snapped(to.x), snapped(to.y));
        }
    }

    /// Keeps every handle on the grid and on its step (after the grid
    /// shrank or the primitive changed).
    pub fn tidy(&mut self) {
        self.size = self.size.clamp(*Self::SIZES.start(), *Self::SIZES.end());
        for k in 0..3 {
            let at = self.handles[k];
            self.move_handle(k, at);
        }
    }

    /// Handle `k` as a pixel.
    #[must_use]
    #[allow(clippy::cast_possible_truncation)] // handles lie on the grid
    pub fn pixel(&self, k: usize) -> Pixel {
        let h = self.handles[k];
        Pixel::new(h.x.round() as i32, h.y.round() as i32)
    }

    /// The circle's radius: from its centre (handle 0) to the rim handle,
    /// rounded to whole pixels.
    #[must_use]
    #[allow(clippy::cast_possible_truncation)] // at most the grid's diagonal
    pub fn radius(&self) -> i32 {
        self.handles[0].distance(self.handles[1]).round() as i32
    }
}

/// One pixel you plotted, and what decided it.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// The pixel.
    pub pixel: Pixel,
    /// Its colour, where your code interpolates one (DDA, triangle), or
    /// its intensity as a grey (an antialiased line).
    pub colour: Option<Rgba>,
    /// Its intensity, for an antialiased line.
    pub intensity: Option<f32>,
    /// What decided it, in one line.
    pub note: String,
}

/// How a pixel of the grid compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cell {
    /// Yours and the definition's: `#`.
    Both,
    /// Only yours: `+`.
    OnlyYours,
    /// Only the definition's: `-`.
    OnlyExpected,
    /// Neither.
    Empty,
}

/// One drawing of the playground.
#[derive(Clone, Debug)]
pub struct Drawing {
    /// What was drawn.
    pub setup: Setup,
    /// The stage's name and where it comes from.
    pub stage: (&'static str, &'static str),
    /// How it fared.
    pub status: Status,
    /// Every pixel you plotted, in order (a pixel plotted twice is there
    /// twice).
    pub yours: Vec<Step>,
    /// The pixels of the definition, on the grid.
    pub expected: BTreeSet<Pixel>,
    /// The definition's intensity of each of its pixels, for an
    /// antialiased line (empty otherwise).
    pub expected_intensity: BTreeMap<Pixel, f32>,
}

impl Drawing {
    /// The pixels you plotted among the first `steps` (all: `yours.len()`).
    fn plotted(&self, steps: usize) -> BTreeSet<Pixel> {
        self.yours.iter().take(steps).map(|s| s.pixel).collect()
    }

    /// How pixel `p` compares after your first `steps` pixels.
    #[must_use]
    pub fn cell(&self, p: Pixel, plotted: &BTreeSet<Pixel>) -> Cell {
        match (plotted.contains(&p), self.expected.contains(&p)) {
            (true, true) => Cell::Both,
            (true, false) => Cell::OnlyYours,
            (false, true) => Cell::OnlyExpected,
            (false, false) => Cell::Empty,
        }
    }

    /// Every pixel of the grid with how it compares after `steps` pixels.
    #[must_use]
    pub fn cells(&self, steps: usize) -> Vec<(Pixel, Cell)> {
        let plotted = self.plotted(steps);
        let n = self.setup.size;
        (0..n)
            .flat_map(|y| (0..n).map(move |x| Pixel::new(x, y)))
            .map(|p| (p, self.cell(p, &plotted)))
            .collect()
    }

    /// The comparison in one line, for the whole drawing (on the grid;
    /// pixels off it are counted apart).
    #[must_use]
    pub fn summary(&self) -> String {
        let all = self.plotted(self.yours.len());
        let viewport = self.setup.viewport();
        let (plotted, outside): (BTreeSet<Pixel>, BTreeSet<Pixel>) =
            all.iter().partition(|p| viewport.contains(**p));
        let outside = outside.len();
        let both = plotted.intersection(&self.expected).count();
        let only_yours = plotted.difference(&self.expected).count();
        let missing = self.expected.difference(&plotted).count();
        let twice = self.yours.len() - all.len();
        let mut text = if only_yours == 0 && missing == 0 {
            format!("all {both} pixels as defined")
        } else {
            format!("{both} as defined (#), {only_yours} only yours (+), {missing} missing (-)")
        };
        if outside > 0 {
            text.push_str(&format!("; {outside} off the grid"));
        }
        if twice > 0 {
            text.push_str(&format!("; {twice} plotted more than once"));
        }
        if let Some(off) = self.intensity_error() {
            text.push_str(&format!(
                "; intensities within {off:.3} of the definition's"
            ));
        }
        text
    }

    /// For an antialiased line, the largest difference between an
    /// intensity you plotted and the definition's for that pixel.
    #[must_use]
    pub fn intensity_error(&self) -> Option<f32> {
        if self.expected_intensity.is_empty() {
            return None;
        }
        self.yours
            .iter()
            .filter_map(|s| Some((s.intensity?, *self.expected_intensity.get(&s.pixel)?)))
            .map(|(yours, expected)| (yours - expected).abs())
            .reduce(f32::max)
    }
}

/// The worker that draws the playground.
pub type PlaygroundWorker = Worker<Setup, Drawing>;

/// Starts a worker that draws the playground with `stages`.
#[must_use]
pub fn worker(stages: Stages) -> PlaygroundWorker {
    Worker::start(move |setup: Setup| draw(&setup, &stages))
}

/// Calls `call` with a `plot` that panics after [`MAX_PLOTS`] pixels, and
/// returns what it plotted, or how it failed.
fn collect<T, F: ?Sized>(
    stage: &Stage<F>,
    size: i32,
    call: impl FnOnce(&F, &mut dyn FnMut(T)),
) -> (Status, Vec<T>) {
    let Some(run) = &stage.run else {
        return (Status::Missing, Vec::new());
    };
    let mut plotted = Vec::new();
    let mut status = Status::NotReached;
    guarded(&mut status, || {
        call(run, &mut |item| {
            assert!(
                plotted.len() < MAX_PLOTS,
                "plotted more than {MAX_PLOTS} pixels on a {size} × {size} grid: an endless loop?"
            );
            plotted.push(item);
        });
    });
    (status, plotted)
}

/// Draws `setup` with your stage and the definition.
#[must_use]
pub fn draw(setup: &Setup, stages: &Stages) -> Drawing {
    let viewport = setup.viewport();
    let size = setup.size;
    let mut expected_intensity = BTreeMap::new();
    let (status, yours, expected): (Status, Vec<Step>, Vec<Pixel>) = match setup.primitive {
        Primitive::DdaLine => {
            let (from, to) = (setup.pixel(0), setup.pixel(1));
            let vertex = |p: Pixel, colour| Vertex::new(p.centre(), 0.5, colour);
            let (a, b) = (vertex(from, FROM_COLOUR), vertex(to, TO_COLOUR));
            let (status, fragments) = collect(&stages.line, size, |run, plot| {
                run(&a, &b, &mut |f: Fragment| plot(f));
            });
            let ties = definitions::line_ties(from, to);
            let steps: Vec<Step> = fragments
                .into_iter()
                .map(|f| {
                    let mut note = line_note(from, to, f.pixel);
                    if ties.iter().any(|t| t.contains(&f.pixel)) {
                        note.push_str(": a tie, which your float sum decides");
                    }
                    Step {
                        pixel: f.pixel,
                        colour: Some(f.colour),
                        intensity: None,
                        note,
                    }
                })
                .collect();
            // At a tie the sheet rounds half away from zero, but the sum
            // of slopes in floating point lands a hair off the half: either
            // pixel is as defined (the tests leave ties out).
            let mut expected = definitions::line_pixels(from, to, None);
            for [lower, upper] in ties {
                if steps.iter().any(|s| s.pixel == upper) && !steps.iter().any(|s| s.pixel == lower)
                {
                    for p in &mut expected {
                        if *p == lower {
                            *p = upper;
                        }
                    }
                }
            }
            (status, steps, expected)
        }
        Primitive::MidpointLine => {
            let (from, to) = (setup.pixel(0), setup.pixel(1));
            let (status, pixels) = collect(&stages.midpoint, size, |run, plot| run(from, to, plot));
            let steps = uncoloured(pixels, |p| line_note(from, to, p));
            (status, steps, definitions::line_pixels(from, to, None))
        }
        Primitive::WuLine => {
            let (from, to) = (setup.pixel(0), setup.pixel(1));
            let (status, plotted) = collect(&stages.wu, size, |run, plot| {
                run(from, to, &mut |p: Pixel, c: f32| plot((p, c)));
            });
            expected_intensity = definitions::wu_pixels(from, to).into_iter().collect();
            let steps = plotted
                .into_iter()
                .map(|(pixel, c)| Step {
                    pixel,
                    colour: Some(Rgba::grey(c.clamp(0.0, 1.0))),
                    intensity: Some(c),
                    note: wu_note(from, to, pixel, c, expected_intensity.get(&pixel)),
                })
                .collect();
            (status, steps, expected_intensity.keys().copied().collect())
        }
        Primitive::Circle => {
            let (centre, radius) = (setup.pixel(0), setup.radius());
            let (status, pixels) =
                collect(&stages.circle, size, |run, plot| run(centre, radius, plot));
            let steps = uncoloured(pixels, |p| circle_note(centre, radius, p));
            (status, steps, definitions::circle_pixels(centre, radius))
        }
        Primitive::Triangle => {
            let colours = [
                TRIANGLE_COLOURS[0],
                TRIANGLE_COLOURS[1],
                TRIANGLE_COLOURS[2],
            ];
            let vertices: [Vertex; 3] =
                std::array::from_fn(|k| Vertex::new(setup.handles[k], 0.5, colours[k]));
            let (status, fragments) = collect(&stages.fill, size, |run, plot| {
                run(vertices, viewport, &mut |f: Fragment, w: [i128; 3]| {
                    plot((f, w))
                });
            });
            let steps = fragments
                .into_iter()
                .map(|(f, w)| Step {
                    pixel: f.pixel,
                    colour: Some(f.colour),
                    intensity: None,
                    note: triangle_note(f.pixel, w),
                })
                .collect();
            let positions = [setup.handles[0], setup.handles[1], setup.handles[2]];
            (
                status,
                steps,
                definitions::triangle_pixels(positions, viewport),
            )
        }
    };
    Drawing {
        setup: setup.clone(),
        stage: setup.primitive.stage(stages),
        status,
        yours,
        expected: expected
            .into_iter()
            .filter(|p| viewport.contains(*p))
            .collect(),
        expected_intensity,
    }
}

/// The steps of code that plots pixels without a colour, each with its
/// note.
fn uncoloured(pixels: Vec<Pixel>, note: impl Fn(Pixel) -> String) -> Vec<Step> {
    pixels
        .into_iter()
        .map(|pixel| Step {
            pixel,
            colour: None,
            intensity: None,
            note: note(pixel),
        })
        .collect()
}

/// The colours of a line's endpoints (the DDA interpolates between them).
pub const FROM_COLOUR: Rgba = Rgba::rgb(1.0, 0.45, 0.2);
/// See [`FROM_COLOUR`].
pub const TO_COLOUR: Rgba = Rgba::rgb(0.25, 0.55, 1.0);
/// The colours of the triangle's vertices.
pub const TRIANGLE_COLOURS: [Rgba; 3] = [
    Rgba::rgb(1.0, 0.3, 0.3),
    Rgba::rgb(0.3, 0.9, 0.3),
    Rgba::rgb(0.3, 0.4, 1.0),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn handles_snap_to_their_step_and_stay_on_the_grid() {
        let mut setup = Setup::default();
        setup.move_handle(0, Vec2::new(3.4, -2.0));
        assert_eq!(setup.handles[0], Vec2::new(3.0, 0.0));
        setup.primitive = Primitive::Triangle;
        setup.move_handle(1, Vec2::new(7.3, 99.0));
        assert_eq!(setup.handles[1], Vec2::new(7.5, 15.0));
        setup.size = 8;
        setup.tidy();
        assert_eq!(setup.handles[1], Vec2::new(7.0, 7.0));
    }

    #[test]
    fn a_missing_stage_draws_nothing_and_says_so() {
        let drawing = draw(&Setup::default(), &Stages::default());
        assert_eq!(drawing.status, Status::Missing);
        assert!(drawing.yours.is_empty());
        assert!(!drawing.expected.is_empty());
        assert!(
            drawing.summary().contains("missing (-)"),
            "{}",
            drawing.summary()
        );
    }
}
