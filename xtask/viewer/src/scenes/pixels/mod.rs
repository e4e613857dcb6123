//! The pixel playground (topics 01–03): one primitive on a magnified
//! grid, drawn by your code, beside the pixels of the course's definition
//! (`testkit::definitions`, what the tests compare with), in the grader's
//! legend: `#` in both, `+` only yours, `-` only expected. Drag its
//! handles; step through your pixels one at a time, in the order you
//! plotted them, each with what decided it.
//!
//! | primitive | your code | its definition |
//! |---|---|---|
//! | DDA line | `01-lines` `dda::dda_line` | the pixel nearest the ideal line in each column of the major axis (at a tie either) |
//! | midpoint line | `01-lines` `midpoint::midpoint_line` | the same pixels |
//! | Wu line | `01-lines` `wu::wu_line` | in each column of the major axis the two pixels that straddle the ideal line, weighted by nearness (one pixel at the ends) |
//! | midpoint circle | `02-circles` `midpoint_circle::midpoint_circle` | the second octant's nearest rows, mirrored |
//! | triangle | `03-fill` `edge_function::fill_triangle` | centres inside, by the top-left rule on the 1/256-pixel grid |

mod draw;
mod notes;
#[cfg(feature = "window")]
mod state;
#[cfg(feature = "window")]
mod ui;

pub use draw::*;
#[cfg(feature = "window")]
pub(crate) use state::PixelsScene;
