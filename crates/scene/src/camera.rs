//! The course's cameras. [`turn`]: the one way a camera is turned by
//! angles (the world's up is +y), for topic 06's rays, topic 09's pictures
//! and the viewer's orbits. [`Camera`]: a pinhole camera for world points
//! in `f64` (eye, target, up and a vertical field of view), projected as the
//! pipeline projects ([`crate::pipeline`]: glam's right-handed look-at view
//! looking down −z, OpenGL's perspective and clip volume, the near plane at
//! depth 0). The surface topics render with it.

use glam::dcamera::rh::{proj::opengl, view};
use glam::{DMat3, DVec3};

/// The camera turned by `yaw` and `pitch` (radians), as a rotation from
/// camera to world: its columns are the camera's right, up and back (the
/// opposite of where it looks) in world space.
///
/// Unturned, a camera looks along −z with +y up (glam's and OpenGL's eye
/// space); `pitch` tilts it about its own x axis (negative: it looks down),
/// then `yaw` turns it about the world's up axis, +y:
///
/// ```text
///   turn(yaw, pitch) = R_y(yaw) · R_x(pitch)
///   forward = −turn·z,   up = turn·y,   right = turn·x
/// ```
///
/// An orbit around a target at distance `d` puts the eye at
/// `target + d · turn·z`; `turn` transposed takes world directions into
/// the camera's.
#[must_use]
pub fn turn(yaw: f64, pitch: f64) -> DMat3 {
    DMat3::from_rotation_y(yaw) * DMat3::from_rotation_x(pitch)
}

/// A pinhole camera looking from `eye` at `target`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Where the eye is (world space).
    pub eye: DVec3,
    /// The point in the centre of the picture.
    pub target: DVec3,
    /// Which way is up in the picture.
    pub up: DVec3,
    /// The vertical field of view in degrees.
    pub fov_y_degrees: f64,
}

impl Camera {
    /// The near plane distance: geometry closer to the eye is dropped.
    pub const NEAR: f64 = 0.1;
    /// The far plane distance.
    pub const FAR: f64 = 100.0;

    /// Maps a world point to the canvas: `x, y` in pixel coordinates
    /// (the canvas spans `[−½, width − ½] × [−½, height − ½]`), `z` the depth
    /// in `[0, 1]` (0 on the near plane). `None` for a point nearer than
    /// [`Camera::NEAR`] (or behind the eye) or a non-finite result.
    ///
    /// The pipeline of this crate (its conventions: glam's right-handed eye
    /// space looking down −z, OpenGL's clip volume, the near plane at depth
    /// 0), with the GPU's viewport transform:
    ///
    /// ```text
    ///   eye  = view::look_at_mat4(eye, target, up) · p   (f = normalize(target − eye),
    ///                                                     r = normalize(f × up), s = r × f)
    ///   clip = opengl::perspective(fov, aspect, NEAR, FAR) · eye
    ///   ndc  = clip.xyz / clip.w                     (clip.w = f·(p − eye), the distance along the view)
    ///   x, y = canvas::ndc_to_window(ndc.xy),  depth = canvas::ndc_depth(ndc.z)
    /// ```
    ///
    /// In terms of the distance `z = clip.w` the depth is
    /// `(FAR / (FAR − NEAR)) · (1 − NEAR / z)`: OpenGL's perspective depth.
    #[must_use]
    pub fn to_screen(&self, world: DVec3, width: u32, height: u32) -> Option<DVec3> {
        let aspect = f64::from(width) / f64::from(height.max(1));
        let view = view::look_at_mat4(self.eye, self.target, self.up);
        let projection = opengl::perspective(
            self.fov_y_degrees.to_radians(),
            aspect,
            Self::NEAR,
            Self::FAR,
        );
        let clip = projection * view * world.extend(1.0);
        // NaN fails this test too.
        if clip.w.is_nan() || clip.w < Self::NEAR {
            return None;
        }
        let ndc = clip.truncate() / clip.w;
        let pixel = canvas::ndc_to_window(ndc.truncate(), width, height);
        let depth = f64::from(canvas::ndc_depth(ndc.z as f32));
        let screen = pixel.extend(depth);
        screen.is_finite().then_some(screen)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CAMERA: Camera = Camera {
        eye: DVec3::new(0.0, 0.0, 5.0),
        target: DVec3::ZERO,
        up: DVec3::Y,
        fov_y_degrees: 60.0,
    };

    #[test]
    fn the_target_lands_in_the_middle_with_opengl_depth() {
        let screen = CAMERA.to_screen(DVec3::ZERO, 9, 5).unwrap();
        assert!((screen.truncate() - glam::DVec2::new(4.0, 2.0)).length() < 1e-12);
        // OpenGL's depth at the distance z = 5: (FAR / (FAR − NEAR)) · (1 − NEAR / z).
        let (near, far) = (Camera::NEAR, Camera::FAR);
        let expected = far / (far - near) * (1.0 - near / 5.0);
        assert!(
            (screen.z - expected).abs() < 1e-6,
            "{} vs {expected}",
            screen.z
        );
    }

    #[test]
    fn a_turned_camera_looks_down_and_around_the_y_axis() {
        let close = |a: DVec3, b: DVec3| (a - b).length() < 1e-12;
        // Unturned: glam's eye space.
        let rest = turn(0.0, 0.0);
        assert!(close(-rest.z_axis, DVec3::NEG_Z) && close(rest.y_axis, DVec3::Y));
        // Tilted by −90°: it looks straight down, its up along −z.
        let down = turn(0.0, -std::f64::consts::FRAC_PI_2);
        assert!(close(-down.z_axis, DVec3::NEG_Y) && close(down.y_axis, DVec3::NEG_Z));
        // Turned by +90° about y: it looks along −x (counter-clockwise
        // seen from above), and a tilt keeps its right horizontal.
        let left = turn(std::f64::consts::FRAC_PI_2, -0.3);
        assert!(close(left.x_axis, DVec3::NEG_Z));
        assert!(-left.z_axis.x < -0.9 && -left.z_axis.y < 0.0);
        // A rotation: right-handed and orthonormal.
        assert!((left.determinant() - 1.0).abs() < 1e-12);
        assert!(close(left.x_axis.cross(left.y_axis), left.z_axis));
    }

    #[test]
    fn up_is_up_and_points_behind_the_eye_are_dropped() {
        let above = CAMERA.to_screen(DVec3::new(0.0, 1.0, 0.0), 9, 9).unwrap();
        assert!(above.y > 4.0);
        assert_eq!(CAMERA.to_screen(DVec3::new(0.0, 0.0, 6.0), 9, 9), None);
        assert_eq!(CAMERA.to_screen(DVec3::NAN, 9, 9), None);
    }
}
