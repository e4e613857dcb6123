//! The orbiting camera the scenes share.

/// The unit direction from an orbit's centre to a camera `yaw` degrees
/// around the vertical (y) axis and `pitch` degrees above the horizontal
/// plane, `+z` at yaw 0 (every scene's orbiting camera).
#[must_use]
pub fn orbit_direction(yaw: f64, pitch: f64) -> glam::DVec3 {
    let (yaw, pitch) = (yaw.to_radians(), pitch.to_radians());
    glam::DVec3::new(
        yaw.sin() * pitch.cos(),
        pitch.sin(),
        yaw.cos() * pitch.cos(),
    )
}
