//! The z-buffer algorithm with OpenGL's depth functions, clear value and
//! depth range (seed 002, §6.2 "Depth- bzw. Z-Buffer"; OpenGL 4.6 core
//! specification §14.6.4 "Depth Buffer Test" for `glDepthFunc`,
//! `glDepthMask`, §13.8.1 "Controlling the Viewport" for `glDepthRange`,
//! and §17.4.3 "Clearing the Buffers" for `glClearDepth`).
//!
//! Convention (see `canvas`): pixel centres at integers, y up; depth 0 is
//! nearest, 1 farthest, and a cleared depth plane holds
//! [`canvas::DEPTH_CLEAR`] = 1.
//!
//! ```text
//!   per fragment (x, y, z, colour):
//!     z_w = near + (far − near) · z                 depth range
//!     if func(z_w, stored depth at (x, y)):         depth test
//!         stored depth := z_w   (if writes are on)
//!         colour at (x, y) := colour
//! ```

use canvas::{Canvas, Fragment, Rgba};

/// Why a depth state could not be set.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum DepthError {
    /// A clear value or a depth range bound was NaN.
    #[error("a depth value must be a number, got NaN")]
    NotANumber,
}

/// A comparison of OpenGL's per-fragment tests: the depth function
/// (`glDepthFunc`) and the stencil function (`glStencilFunc`), one enum
/// for both as in OpenGL, where both take the same eight constants
/// `GL_NEVER` … `GL_ALWAYS`. A test passes when `incoming OP stored`
/// holds: for the depth test `incoming` is the fragment's window depth
/// and `stored` the depth buffer's value; for the stencil test (see
/// [`crate::stencil`]) `incoming` is the masked reference value.
///
/// The seed lists `GL_LESS` twice and no other typo; its pseudo-code tests
/// `pz <= readZ` (that is [`Compare::LEqual`]) although OpenGL's default
/// depth function is [`Compare::Less`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Compare {
    /// Never passes (`GL_NEVER`).
    Never,
    /// `incoming < stored` (`GL_LESS`, the default depth function).
    Less,
    /// `incoming = stored` (`GL_EQUAL`).
    Equal,
    /// `incoming ≤ stored` (`GL_LEQUAL`).
    LEqual,
    /// `incoming > stored` (`GL_GREATER`).
    Greater,
    /// `incoming ≠ stored` (`GL_NOTEQUAL`).
    NotEqual,
    /// `incoming ≥ stored` (`GL_GEQUAL`).
    GEqual,
    /// Always passes (`GL_ALWAYS`, the default stencil function).
    Always,
}

impl Compare {
    /// All eight functions, in the order of the OpenGL enum values
    /// (`GL_NEVER` = 0x0200 … `GL_ALWAYS` = 0x0207).
    pub const ALL: [Self; 8] = [
        Self::Never,
        Self::Less,
        Self::Equal,
        Self::LEqual,
        Self::Greater,
        Self::NotEqual,
        Self::GEqual,
        Self::Always,
    ];

    /// Whether `incoming OP stored` holds: here a fragment's depth against
    /// the stored depth (Task 5's stencil test writes the same eight
    /// comparisons out for its masked `u8` values).
    ///
    /// The comparisons are those of `PartialOrd`: for floats NaN compares
    /// unequal to everything, so only `NotEqual` and `Always` pass a NaN
    /// (the z-buffer below never lets a NaN depth get this far).
    #[must_use]
    #[transcript::task]
    pub fn passes<T: PartialOrd>(self, incoming: T, stored: T) -> bool {
        // BEGIN SOLUTION zbuffer: compare incoming OP stored for each of the eight functions
        match self {
            Self::Never => false,
            Self::Less => incoming < stored,
            Self::Equal => incoming == stored,
            Self::LEqual => incoming <= stored,
            Self::Greater => incoming > stored,
            Self::NotEqual => incoming != stored,
            Self::GEqual => incoming >= stored,
            Self::Always => true,
        }
        // END SOLUTION
    }
}

/// The depth range (`glDepthRange(near, far)`): fragment depths `z` in
/// `[0, 1]` are mapped linearly to window depths `near + (far − near) · z`.
///
/// Both bounds lie in `[0, 1]`; `near > far` is allowed and reverses the
/// depth order, as in OpenGL.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthRange {
    near: f32,
    far: f32,
}

impl DepthRange {
    /// The default range `[0, 1]`: window depth = fragment depth.
    pub const DEFAULT: Self = Self {
        near: 0.0,
        far: 1.0,
    };

    /// The range `near ..= far`, each bound clamped to `[0, 1]` as
    /// `glDepthRange` does; an error if either is NaN.
    #[transcript::task]
    pub fn try_new(near: f32, far: f32) -> Result<Self, DepthError> {
        // BEGIN SOLUTION zbuffer: reject NaN, clamp both bounds to [0, 1]
        if near.is_nan() || far.is_nan() {
            return Err(DepthError::NotANumber);
        }
        Ok(Self {
            near: near.clamp(0.0, 1.0),
            far: far.clamp(0.0, 1.0),
        })
        // END SOLUTION
    }

    /// The near bound (the window depth of fragment depth 0).
    #[must_use]
    pub fn near(self) -> f32 {
        self.near
    }

    /// The far bound (the window depth of fragment depth 1).
    #[must_use]
    pub fn far(self) -> f32 {
        self.far
    }

    /// The window depth `near + (far − near) · z` of fragment depth `z`:
    /// `z = 0` gives `near` and `z = 1` gives `far` exactly.
    #[must_use]
    #[transcript::task]
    pub fn map(self, z: f32) -> f32 {
        // BEGIN SOLUTION zbuffer: map z linearly so that 0 gives near and 1 gives far
        // `near·(1 − z) + far·z` hits both ends exactly, which
        // `near + (far − near)·z` does not always do in floats.
        self.near * (1.0 - z) + self.far * z
        // END SOLUTION
    }
}

impl Default for DepthRange {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// The state of the depth stage: the comparison, whether passing
/// fragments write their depth (`glDepthMask`), and the depth range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthState {
    /// The comparison (`glDepthFunc`; default [`Compare::Less`]).
    pub func: Compare,
    /// Whether passing fragments write their depth (`glDepthMask`; default
    /// `true`). Colour is written either way.
    pub write: bool,
    /// The depth range (`glDepthRange`; default `[0, 1]`).
    pub range: DepthRange,
}

impl Default for DepthState {
    fn default() -> Self {
        Self::DEFAULT
    }
}

impl DepthState {
    /// OpenGL's defaults with the depth test enabled: `LESS`, depth writes
    /// on, range `[0, 1]`.
    pub const DEFAULT: Self = Self {
        func: Compare::Less,
        write: true,
        range: DepthRange::DEFAULT,
    };

    /// The default state with another comparison.
    #[must_use]
    pub const fn with_func(func: Compare) -> Self {
        Self {
            func,
            ..Self::DEFAULT
        }
    }
}

/// Clears the colour plane to `colour` and the depth plane to `depth`
/// (`glClearColor`, `glClearDepth`, then `glClear(GL_COLOR_BUFFER_BIT |
/// GL_DEPTH_BUFFER_BIT)`): the first loop of the seed's `zBuffer()`.
///
/// `depth` is clamped to `[0, 1]` as `glClearDepth` does; the seed's
/// tables clear to ∞, which a `[0, 1]` depth buffer stores as 1. A NaN
/// depth is an error and leaves the canvas untouched.
#[transcript::task]
pub fn clear(canvas: &mut Canvas, colour: Rgba, depth: f32) -> Result<(), DepthError> {
    // BEGIN SOLUTION zbuffer: reject NaN, then set every pixel's colour and its clamped depth
    if depth.is_nan() {
        return Err(DepthError::NotANumber);
    }
    let depth = depth.clamp(0.0, 1.0);
    canvas.clear(colour);
    for y in 0..canvas.height() as i32 {
        for x in 0..canvas.width() as i32 {
            canvas.set_depth(canvas::Pixel::new(x, y), depth);
        }
    }
    Ok(())
    // END SOLUTION
}

/// Runs one fragment through the depth stage: the body of the seed's
/// "for each pixel in the polygon's projection" loop, with OpenGL's
/// comparison, mask and range. Returns whether the fragment passed (and
/// its colour was written).
///
/// 1. A fragment outside the canvas, or whose depth is NaN or outside
///    `[0, 1]` (clipping would have removed it), is discarded: `false`.
/// 2. Its window depth is `z_w = state.range.map(fragment.depth)`.
/// 3. If `state.func.passes(z_w, stored)`, the colour is written, and the
///    depth `z_w` too when `state.write` is set.
#[transcript::task]
pub fn depth_test(canvas: &mut Canvas, fragment: Fragment, state: &DepthState) -> bool {
    // BEGIN SOLUTION zbuffer: discard bad fragments, map the depth, test it, then write colour and (if enabled) depth
    let Some(stored) = canvas.depth(fragment.pixel) else {
        return false;
    };
    if !(0.0..=1.0).contains(&fragment.depth) {
        return false;
    }
    let z = state.range.map(fragment.depth);
    // The seed's pseudo-code writes `pz <= readZ` here, fixing LEQUAL; the
    // comparison is a parameter, as in OpenGL.
    if !state.func.passes(z, stored) {
        return false;
    }
    if state.write {
        canvas.set_depth(fragment.pixel, z);
    }
    canvas.set(fragment.pixel, fragment.colour);
    true
    // END SOLUTION
}
