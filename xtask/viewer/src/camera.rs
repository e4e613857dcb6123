//! The orbiting camera the scenes share.

/// The unit direction from an orbit's centre to a camera `yaw` degrees
/// around the vertical (y) axis and `pitch` degrees above the horizontal
/// plane, `+z` at yaw 0 (every scene's orbiting camera): the back of the
/// course's camera turn, `scene::turn(yaw, −pitch)`, which looks down by
/// `pitch`.
#[must_use]
pub fn orbit_direction(yaw: f64, pitch: f64) -> glam::DVec3 {
    scene::turn(yaw.to_radians(), -pitch.to_radians()).z_axis
}
