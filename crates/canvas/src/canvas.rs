//! The canvas: colour, depth and stencil planes of `width × height` pixels.

use std::path::Path;

use glam::Vec2;

use crate::{Pixel, Rgba, Span, Viewport, ascii};

/// The value a cleared depth plane holds: the far end of the depth range
/// `[0, 1]` (OpenGL's default `glClearDepth(1.0)`).
pub const DEPTH_CLEAR: f32 = 1.0;

/// The value a cleared stencil plane holds: 0 (OpenGL's default
/// `glClearStencil(0)`).
pub const STENCIL_CLEAR: u8 = 0;

/// Bits per stencil value: the stencil plane holds one `u8` per pixel, the
/// 8 bits the lecture slides and a `DEPTH24_STENCIL8` framebuffer assume.
pub const STENCIL_BITS: u32 = u8::BITS;

/// A vertex as rasterizers receive it: after projection and viewport
/// transform, in pixel coordinates.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    /// Position in pixel coordinates (pixel centres at integers, y up).
    pub position: Vec2,
    /// Depth in `[0, 1]`, 0 nearest.
    pub depth: f32,
    /// Colour.
    pub colour: Rgba,
}

impl Vertex {
    /// A vertex at `position` with the given depth and colour.
    #[must_use]
    pub const fn new(position: Vec2, depth: f32, colour: Rgba) -> Self {
        Self {
            position,
            depth,
            colour,
        }
    }

    /// Linear interpolation of position, depth and colour:
    /// `self · (1 − t) + other · t` (the sheet's `MeshVertex.mix`).
    #[must_use]
    pub fn mix(&self, other: &Self, t: f32) -> Self {
        Self {
            position: self.position.lerp(other.position, t),
            depth: self.depth * (1.0 - t) + other.depth * t,
            colour: self.colour.lerp(other.colour, t),
        }
    }
}

/// What a rasterizer emits for one covered pixel.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// The pixel.
    pub pixel: Pixel,
    /// Interpolated depth.
    pub depth: f32,
    /// Interpolated colour.
    pub colour: Rgba,
}

/// Why a canvas could not be made, read or written.
#[derive(Debug, thiserror::Error)]
pub enum CanvasError {
    /// Reading or writing a PNG failed.
    #[error("{path}: {source}")]
    Image {
        /// The file.
        path: String,
        /// What the `image` crate reported.
        source: image::ImageError,
    },
    /// Creating the folder for an output file failed.
    #[error("{path}: {source}")]
    Io {
        /// The folder.
        path: String,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The canvas would have more pixels than fit in memory.
    #[error("a canvas of {width} × {height} pixels is too large")]
    TooLarge {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
    },
}

/// A raster of `width × height` pixels with a colour plane, a depth plane
/// and a stencil plane.
///
/// The colour plane holds 8 bits per channel, like an `RGBA8` framebuffer
/// and the PNG it is saved as: [`Canvas::set`] rounds each channel of an
/// [`Rgba`] to the nearest of 256 levels (clamping to `[0, 1]`), and
/// [`Canvas::get`] returns the stored level. The depth plane holds `f32`.
/// The stencil plane holds [`STENCIL_BITS`] = 8 bits per pixel (`u8`);
/// no drawing function of the canvas touches it: only
/// [`Canvas::set_stencil`] and [`Canvas::clear_stencil`] do.
///
/// Pixel `(x, y)` is stored at index `y · width + x`, row 0 at the bottom
/// (see the crate documentation for the full convention). Every write
/// outside the canvas is ignored, so rasterizers need not clip pixels
/// themselves; every read outside returns `None`.
#[derive(Clone, Debug, PartialEq)]
pub struct Canvas {
    width: u32,
    height: u32,
    colour: Vec<[u8; 4]>,
    depth: Vec<f32>,
    stencil: Vec<u8>,
    /// The pixels written during a call the grader records (see
    /// [`transcript::Changes`]); no part of the canvas's value.
    changes: transcript::Changes,
}

impl Canvas {
    /// The largest number of pixels a canvas may have (a 16384² image).
    pub const MAX_PIXELS: u64 = 1 << 28;

    /// A canvas cleared to [`Rgba::BLACK`], [`DEPTH_CLEAR`] and
    /// [`STENCIL_CLEAR`].
    ///
    /// # Panics
    /// If `width · height` exceeds [`Canvas::MAX_PIXELS`]; see
    /// [`Canvas::try_new`] for the fallible version.
    #[must_use]
    pub fn new(width: u32, height: u32) -> Self {
        match Self::try_new(width, height) {
            Ok(canvas) => canvas,
            Err(e) => panic!("{e}"),
        }
    }

    /// A cleared canvas, or an error if it would exceed
    /// [`Canvas::MAX_PIXELS`]. A zero width or height gives an empty canvas.
    pub fn try_new(width: u32, height: u32) -> Result<Self, CanvasError> {
        let n = u64::from(width) * u64::from(height);
        if n > Self::MAX_PIXELS {
            return Err(CanvasError::TooLarge { width, height });
        }
        Ok(Self {
            width,
            height,
            colour: vec![Rgba::BLACK.to_rgba8(); n as usize],
            depth: vec![DEPTH_CLEAR; n as usize],
            stencil: vec![STENCIL_CLEAR; n as usize],
            changes: transcript::Changes::default(),
        })
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The whole canvas as a viewport: `[0, width − 1] × [0, height − 1]`.
    #[must_use]
    pub fn viewport(&self) -> Viewport {
        Viewport::new(0, 0, self.width as i32 - 1, self.height as i32 - 1)
    }

    #[inline]
    fn index(&self, p: Pixel) -> Option<usize> {
        // Casting a negative i32 to u32 wraps to a huge value, so one
        // comparison per axis rejects both sides.
        if (p.x as u32) < self.width && (p.y as u32) < self.height {
            Some(p.y as usize * self.width as usize + p.x as usize)
        } else {
            None
        }
    }

    /// Whether the pixel lies on the canvas.
    #[must_use]
    pub fn contains(&self, p: Pixel) -> bool {
        self.index(p).is_some()
    }

    /// Sets every pixel to `colour` and every depth to [`DEPTH_CLEAR`].
    /// The stencil plane is left as it is (see [`Canvas::clear_stencil`]).
    pub fn clear(&mut self, colour: Rgba) {
        self.changes.note_everything();
        self.colour.fill(colour.to_rgba8());
        self.depth.fill(DEPTH_CLEAR);
    }

    /// The colour at `p` (as stored, 8 bits per channel), or `None` outside
    /// the canvas.
    #[must_use]
    pub fn get(&self, p: Pixel) -> Option<Rgba> {
        self.index(p).map(|i| Rgba::from_rgba8(self.colour[i]))
    }

    /// Sets the colour at `p`, rounded to 8 bits per channel; ignored
    /// outside the canvas.
    #[inline]
    pub fn set(&mut self, p: Pixel, colour: Rgba) {
        if let Some(i) = self.index(p) {
            self.changes.note(i);
            self.colour[i] = colour.to_rgba8();
        }
    }

    /// Sets the colour of every pixel of `span`, rounded to 8 bits per
    /// channel; the part outside the canvas is ignored. The same pixels as
    /// [`Canvas::set`] for each of `span.pixels()`, written as one slice.
    #[inline]
    pub fn fill_span(&mut self, span: Span, colour: Rgba) {
        if (span.y as u32) >= self.height {
            return;
        }
        let x_start = span.x_start.max(0);
        let x_end = span.x_end.min(self.width as i32 - 1);
        if x_start > x_end {
            return;
        }
        let row = span.y as usize * self.width as usize;
        self.changes
            .note_range(row + x_start as usize..row + x_end as usize + 1);
        self.colour[row + x_start as usize..=row + x_end as usize].fill(colour.to_rgba8());
    }

    /// The depth at `p`, or `None` outside the canvas.
    #[must_use]
    pub fn depth(&self, p: Pixel) -> Option<f32> {
        self.index(p).map(|i| self.depth[i])
    }

    /// Sets the depth at `p`; ignored outside the canvas.
    pub fn set_depth(&mut self, p: Pixel, depth: f32) {
        if let Some(i) = self.index(p) {
            self.changes.note(i);
            self.depth[i] = depth;
        }
    }

    /// The stencil value at `p`, or `None` outside the canvas.
    #[must_use]
    pub fn stencil(&self, p: Pixel) -> Option<u8> {
        self.index(p).map(|i| self.stencil[i])
    }

    /// Sets the stencil value at `p`; ignored outside the canvas.
    pub fn set_stencil(&mut self, p: Pixel, value: u8) {
        if let Some(i) = self.index(p) {
            self.changes.note(i);
            self.stencil[i] = value;
        }
    }

    /// Sets every stencil value to `value` (OpenGL's `glClearStencil(value)`
    /// followed by `glClear(GL_STENCIL_BUFFER_BIT)`; [`STENCIL_CLEAR`] is
    /// the default).
    pub fn clear_stencil(&mut self, value: u8) {
        self.changes.note_everything();
        self.stencil.fill(value);
    }

    /// Writes a fragment's colour and depth without a depth test; ignored
    /// outside the canvas.
    #[inline]
    pub fn plot(&mut self, fragment: Fragment) {
        if let Some(i) = self.index(fragment.pixel) {
            self.changes.note(i);
            self.colour[i] = fragment.colour.to_rgba8();
            self.depth[i] = fragment.depth;
        }
    }

    /// Blends `colour` over the pixel with the given coverage in `[0, 1]`
    /// (the antialiasing write): with `s = colour.a · coverage`,
    /// `result = colour · s + old · (1 − s)` for the colour channels and
    /// `s + old.a · (1 − s)` for alpha. Coverage is clamped to `[0, 1]`
    /// (NaN counts as 0); ignored outside the canvas.
    ///
    /// Like an `RGBA8` framebuffer's blender it works on the stored 8-bit
    /// levels: `s` is rounded to 8 bits, and each channel is
    /// `(c·s + old·(255 − s)) / 255`, rounded.
    #[inline]
    pub fn blend(&mut self, p: Pixel, colour: Rgba, coverage: f32) {
        if let Some(i) = self.index(p) {
            let coverage = if coverage >= 0.0 {
                coverage.min(1.0)
            } else {
                0.0
            };
            let s = u32::from(Rgba::new(0.0, 0.0, 0.0, colour.a * coverage).to_rgba8()[3]);
            let src = colour.to_rgba8();
            let src = [src[0], src[1], src[2], 255];
            self.changes.note(i);
            let old = &mut self.colour[i];
            for (o, c) in old.iter_mut().zip(src) {
                let mixed = u32::from(c) * s + u32::from(*o) * (255 - s);
                // Division by 255 with rounding, exact for 0 ≤ mixed ≤ 255².
                *o = ((mixed + 128 + ((mixed + 128) >> 8)) >> 8) as u8;
            }
        }
    }

    /// All pixels of the canvas whose colour differs from `background`, in
    /// row-major order from the bottom row.
    #[must_use]
    pub fn pixels_not(&self, background: Rgba) -> Vec<Pixel> {
        self.enumerate()
            .filter(|&(_, c)| c != background)
            .map(|(p, _)| p)
            .collect()
    }

    /// Every pixel with its colour, row-major from the bottom row.
    pub fn enumerate(&self) -> impl Iterator<Item = (Pixel, Rgba)> + '_ {
        let w = self.width.max(1) as usize;
        self.colour.iter().enumerate().map(move |(i, &c)| {
            (
                Pixel::new((i % w) as i32, (i / w) as i32),
                Rgba::from_rgba8(c),
            )
        })
    }

    /// The colour plane as an 8-bit RGBA image, top row first (flipped, so
    /// that y points up in the picture).
    #[must_use]
    pub fn to_image(&self) -> image::RgbaImage {
        image::RgbaImage::from_fn(self.width, self.height, |col, row| {
            let y = self.height - 1 - row;
            image::Rgba(self.colour[(y * self.width + col) as usize])
        })
    }

    /// A canvas holding the image's colours (top image row becomes the top
    /// canvas row); depth is cleared.
    #[must_use]
    pub fn from_image(image: &image::RgbaImage) -> Self {
        let mut canvas = Self::new(image.width(), image.height());
        for (col, row, px) in image.enumerate_pixels() {
            let p = Pixel::new(col as i32, (image.height() - 1 - row) as i32);
            canvas.set(p, Rgba::from_rgba8(px.0));
        }
        canvas
    }

    /// Writes the colour plane as a PNG, creating missing folders.
    pub fn save_png(&self, path: impl AsRef<Path>) -> Result<(), CanvasError> {
        let path = path.as_ref();
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|source| CanvasError::Io {
                path: dir.display().to_string(),
                source,
            })?;
        }
        self.to_image()
            .save_with_format(path, image::ImageFormat::Png)
            .map_err(|source| CanvasError::Image {
                path: path.display().to_string(),
                source,
            })
    }

    /// Reads a PNG into a canvas.
    pub fn load_png(path: impl AsRef<Path>) -> Result<Self, CanvasError> {
        let path = path.as_ref();
        let image = image::open(path).map_err(|source| CanvasError::Image {
            path: path.display().to_string(),
            source,
        })?;
        Ok(Self::from_image(&image.to_rgba8()))
    }

    /// ASCII art of the colour plane's ink (see [`crate::ink_char`]) with
    /// axes and a legend: the form snapshots and diffs use.
    #[must_use]
    pub fn to_ascii(&self) -> String {
        ascii::ascii_grid(self.width, self.height, |p| {
            ascii::ink_char(self.get(p).map_or(0.0, Rgba::ink))
        })
    }
}

/// A canvas in a record: its size and its three planes. The record of a
/// call that changed it holds only the pixels written (see
/// [`transcript::Changes`]): a depth test per fragment would otherwise
/// write the whole canvas per fragment.
impl transcript::Record for Canvas {
    fn record(&self, out: &mut Vec<u8>) {
        self.width.record(out);
        self.height.record(out);
        self.colour.record(out);
        self.depth.record(out);
        self.stencil.record(out);
    }

    fn begin_changes(&mut self) {
        self.changes.begin();
    }

    fn record_changes(&mut self, out: &mut Vec<u8>) {
        match self.changes.end() {
            transcript::Changed::Whole => {
                out.push(WHOLE);
                self.record(out);
            }
            transcript::Changed::Elements(written) => {
                out.push(PIXELS);
                written.len().record(out);
                let mut previous = 0;
                for i in written {
                    (i - previous).record(out);
                    previous = i;
                    let i = i as usize;
                    self.colour[i].record(out);
                    self.depth[i].record(out);
                    self.stencil[i].record(out);
                }
            }
        }
    }
}

/// [`Canvas`]'s [`transcript::Record::record_changes`]: the whole canvas
/// follows, or the pixels written, each as the step from the previous
/// one's index and its three values.
const WHOLE: u8 = 0;
const PIXELS: u8 = 1;

impl transcript::Replay for Canvas {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        let width = u32::replay(input)?;
        let height = u32::replay(input)?;
        let colour = Vec::replay(input)?;
        let depth = Vec::replay(input)?;
        let stencil = Vec::replay(input)?;
        let n = u64::from(width) * u64::from(height);
        if n > Self::MAX_PIXELS
            || [colour.len(), depth.len(), stencil.len()]
                .iter()
                .any(|&len| len as u64 != n)
        {
            return Err(format!(
                "a {width} × {height} canvas whose planes do not have {n} pixels"
            ));
        }
        Ok(Self {
            width,
            height,
            colour,
            depth,
            stencil,
            changes: transcript::Changes::default(),
        })
    }

    fn replay_changes(&mut self, input: &mut &[u8]) -> Result<(), String> {
        let (&kind, rest) = input
            .split_first()
            .ok_or("a canvas's changes are missing")?;
        *input = rest;
        match kind {
            WHOLE => {
                *self = Self::replay(input)?;
                Ok(())
            }
            PIXELS => {
                let count = usize::replay(input)?;
                let mut i = 0usize;
                for _ in 0..count {
                    i = i
                        .checked_add(u32::replay(input)? as usize)
                        .filter(|&i| i < self.colour.len())
                        .ok_or("a canvas's changes name a pixel outside it")?;
                    self.colour[i] = <[u8; 4]>::replay(input)?;
                    self.depth[i] = f32::replay(input)?;
                    self.stencil[i] = u8::replay(input)?;
                }
                Ok(())
            }
            _ => Err(format!("a canvas's changes of unknown kind {kind}")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fill_span_writes_the_pixels_set_would_write() {
        // Spans inside, across either border, outside, empty and huge.
        let spans = [
            Span::new(1, 1, 3),
            Span::new(0, -5, 1),
            Span::new(2, 3, 9),
            Span::new(-1, 0, 4),
            Span::new(3, 0, 4),
            Span::new(1, 4, 2),
            Span::new(0, i32::MIN, i32::MAX),
        ];
        for span in spans {
            let (mut by_span, mut by_pixel) = (Canvas::new(5, 3), Canvas::new(5, 3));
            by_span.fill_span(span, Rgba::RED);
            // Pixel by pixel over the span's part of columns −1 ..= 6 (the
            // canvas and one column either side).
            for x in span.x_start.max(-1)..=span.x_end.min(6) {
                by_pixel.set(Pixel::new(x, span.y), Rgba::RED);
            }
            assert_eq!(
                by_span.pixels_not(Rgba::BLACK),
                by_pixel.pixels_not(Rgba::BLACK),
                "{span:?}"
            );
        }
    }

    #[test]
    fn writes_outside_are_ignored_and_reads_are_none() {
        let mut c = Canvas::new(3, 2);
        c.set(Pixel::new(-1, 0), Rgba::WHITE);
        c.set(Pixel::new(3, 0), Rgba::WHITE);
        c.set(Pixel::new(0, 2), Rgba::WHITE);
        c.blend(Pixel::new(i32::MIN, i32::MAX), Rgba::WHITE, 1.0);
        assert!(c.pixels_not(Rgba::BLACK).is_empty());
        assert_eq!(c.get(Pixel::new(0, -1)), None);
        assert_eq!(c.depth(Pixel::new(5, 5)), None);
        c.set_stencil(Pixel::new(-1, 0), 7);
        assert_eq!(c.stencil(Pixel::new(3, 0)), None);
        assert_eq!(c.stencil(Pixel::new(2, 1)), Some(STENCIL_CLEAR));
    }

    #[test]
    fn stencil_plane_is_set_and_cleared_on_its_own() {
        let mut c = Canvas::new(2, 2);
        c.set_stencil(Pixel::new(1, 0), 200);
        assert_eq!(c.stencil(Pixel::new(1, 0)), Some(200));
        assert_eq!(c.stencil(Pixel::new(0, 0)), Some(STENCIL_CLEAR));
        c.clear(Rgba::WHITE);
        c.plot(Fragment {
            pixel: Pixel::new(1, 0),
            depth: 0.5,
            colour: Rgba::RED,
        });
        assert_eq!(c.stencil(Pixel::new(1, 0)), Some(200));
        c.clear_stencil(3);
        assert!((0..2).all(|y| (0..2).all(|x| c.stencil(Pixel::new(x, y)) == Some(3))));
    }

    #[test]
    fn image_rows_are_flipped_so_y_points_up() {
        let mut c = Canvas::new(2, 2);
        c.set(Pixel::new(0, 1), Rgba::WHITE); // top-left in the picture
        let img = c.to_image();
        assert_eq!(img.get_pixel(0, 0).0, [255, 255, 255, 255]);
        assert_eq!(img.get_pixel(0, 1).0, [0, 0, 0, 255]);
        assert_eq!(Canvas::from_image(&img), c);
    }

    #[test]
    fn blend_with_half_coverage_mixes_half() {
        let mut c = Canvas::new(1, 1);
        c.blend(Pixel::new(0, 0), Rgba::WHITE, 0.5);
        let half = Rgba::from_rgba8([128, 128, 128, 255]);
        assert_eq!(c.get(Pixel::new(0, 0)), Some(half));
        c.blend(Pixel::new(0, 0), Rgba::WHITE, f32::NAN);
        assert_eq!(c.get(Pixel::new(0, 0)), Some(half));
    }

    #[test]
    fn too_large_canvas_is_an_error() {
        assert!(Canvas::try_new(u32::MAX, u32::MAX).is_err());
        assert_eq!(Canvas::new(0, 5).pixels_not(Rgba::BLACK), vec![]);
    }

    /// What a recorded call changes, and the replay of those changes on
    /// the canvas as it was before the call.
    fn recorded_and_replayed(change: impl FnOnce(&mut Canvas)) -> (Vec<u8>, Canvas, Canvas) {
        use transcript::{Record, Replay};
        let mut before = Canvas::new(5, 4);
        before.set(Pixel::new(1, 1), Rgba::WHITE);
        let mut canvas = before.clone();
        canvas.begin_changes();
        change(&mut canvas);
        let mut record = Vec::new();
        canvas.record_changes(&mut record);
        let mut replayed = before;
        let mut input = &record[..];
        replayed.replay_changes(&mut input).unwrap();
        assert!(input.is_empty(), "the changes are read to their end");
        (record, canvas, replayed)
    }

    #[test]
    fn a_call_that_writes_a_few_pixels_records_only_those() {
        let (record, canvas, replayed) = recorded_and_replayed(|c| {
            c.set(Pixel::new(4, 3), Rgba::new(1.0, 0.5, 0.0, 1.0));
            c.set_depth(Pixel::new(0, 0), 0.25);
            c.set_stencil(Pixel::new(0, 0), 7);
            c.plot(Fragment {
                pixel: Pixel::new(2, 1),
                depth: 0.5,
                colour: Rgba::WHITE,
            });
            c.blend(Pixel::new(2, 1), Rgba::BLACK, 0.5);
            c.fill_span(Span::new(2, 1, 3), Rgba::WHITE);
            c.set(Pixel::new(9, 9), Rgba::WHITE);
        });
        assert_eq!(replayed, canvas);
        assert_eq!(record[0], PIXELS);
        // Six of the twenty pixels, each at most its index step (1 byte)
        // and its values (a colour of four LEB128 bytes of up to 2 bytes,
        // depth 4, stencil up to 2): less than the 20 pixels of the whole.
        assert!(record.len() <= 2 + 6 * 15, "{} bytes", record.len());
        let mut whole = Vec::new();
        transcript::Record::record(&canvas, &mut whole);
        assert!(whole.len() > 20 * 9, "{} bytes", whole.len());
    }

    #[test]
    fn a_clear_or_a_canvas_put_in_its_place_is_recorded_whole() {
        let (record, canvas, replayed) = recorded_and_replayed(|c| c.clear(Rgba::WHITE));
        assert_eq!((record[0], replayed), (WHOLE, canvas));
        let (record, canvas, replayed) = recorded_and_replayed(|c| c.clear_stencil(3));
        assert_eq!((record[0], replayed), (WHOLE, canvas));
        let (record, canvas, replayed) = recorded_and_replayed(|c| {
            let mut other = Canvas::new(2, 2);
            other.set(Pixel::new(0, 0), Rgba::WHITE);
            *c = other;
        });
        assert_eq!((record[0], replayed), (WHOLE, canvas));
        // Two journaled canvases swapped: each holds the other's journal.
        let mut other = Canvas::new(5, 4);
        let (record, canvas, replayed) = recorded_and_replayed(|c| {
            transcript::Record::begin_changes(&mut other);
            std::mem::swap(c, &mut other);
        });
        assert_eq!((record[0], replayed), (WHOLE, canvas));
        // A clone starts without the call's journal.
        let (record, canvas, replayed) = recorded_and_replayed(|c| {
            let mut other = c.clone();
            other.set(Pixel::new(0, 0), Rgba::WHITE);
            *c = other;
        });
        assert_eq!((record[0], replayed), (WHOLE, canvas));
    }

    #[test]
    fn changes_that_do_not_fit_the_canvas_are_refused() {
        use transcript::{Record, Replay};
        let mut big = Canvas::new(50, 50);
        big.begin_changes();
        big.set(Pixel::new(49, 49), Rgba::WHITE);
        let mut record = Vec::new();
        big.record_changes(&mut record);
        let mut small = Canvas::new(5, 5);
        let error = small.replay_changes(&mut &record[..]).unwrap_err();
        assert!(error.contains("outside"), "{error}");
        let mut whole = Vec::new();
        Canvas::new(3, 3).record(&mut whole);
        whole[0] = 4; // a width of 4 with planes of 9 pixels
        let error = Canvas::replay(&mut &whole[..]).unwrap_err();
        assert!(error.contains("do not have"), "{error}");
    }
}
