//! `generate_ray`: the primary rays (一次レイ), from the *same* view and projection matrices as
//! the rasterizer, so the two images align pixel for pixel.
//!
//! Pixel `(x, y)` (row 0 at the top) has its centre at window coordinates `(x + ½, y + ½)`, which
//! the viewport transform maps to normalised device coordinates
//!
//! ```text
//! x_ndc = 2·(x + ½)/width − 1,     y_ndc = 1 − 2·(y + ½)/height
//! ```
//!
//! The ray runs from the eye through the points that `(x_ndc, y_ndc)` has at depth 0 (the near
//! plane) and depth 1 (the far plane), unprojected by `(P·V)⁻¹` in f64. It starts at the near
//! plane and ends at the far plane (`t_min`, `t_max`), so it sees exactly what the rasterizer's
//! near- and far-plane clipping leaves.

use cg_core::glam::{DMat4, DVec3, DVec4, Mat4, Vec3};
use cg_core::math::try_normalize_f64;

use crate::ray::Ray;

/// The eye and the unprojection of one image size: makes the primary ray of each pixel.
#[derive(Clone, Debug)]
pub struct RayCamera {
    width: u32,
    height: u32,
    /// `(P·V)⁻¹` in f64: clip space → world space.
    clip_to_world: DMat4,
    /// The eye in world space (`V⁻¹·(0, 0, 0, 1)`), rounded to f32: every primary ray's origin.
    eye: Vec3,
    /// The same in f64, unrounded: the primary rays' directions are taken from it. (From the
    /// rounded eye, the course's camera with a near plane 1e-4 away turned them by up to 2e-3
    /// rad, 1.5 pixels of its window; 1e4 from the origin with a near plane at 1, by 6e-4 rad.)
    eye_exact: DVec3,
    /// The camera's backward axis in world space (`V⁻¹·(0, 0, 1, 0)`, unit): OpenGL's infinite
    /// viewer direction.
    backward: Vec3,
    cull_back_faces: bool,
}

impl RayCamera {
    /// The camera of view matrix `view` and projection `projection` for a `width × height`
    /// image; `None` when `P·V` or `V` cannot be inverted (the scene's camera checks make this
    /// impossible for valid scenes).
    #[must_use]
    pub fn new(
        view: Mat4,
        projection: Mat4,
        width: u32,
        height: u32,
        cull_back_faces: bool,
    ) -> Option<RayCamera> {
        let v = view.as_dmat4();
        let pv = projection.as_dmat4() * v;
        let clip_to_world = pv.inverse();
        let view_to_world = v.inverse();
        if !(clip_to_world.is_finite() && view_to_world.is_finite()) {
            return None;
        }
        let eye = view_to_world.transform_point3(cg_core::glam::DVec3::ZERO);
        let backward = try_normalize_f64(view_to_world.transform_vector3(cg_core::glam::DVec3::Z))?;
        Some(RayCamera {
            width,
            height,
            clip_to_world,
            eye: eye.as_vec3(),
            eye_exact: eye,
            backward: backward.as_vec3(),
            cull_back_faces,
        })
    }

    /// The eye (the origin of every primary ray), in world space.
    #[must_use]
    pub fn eye(&self) -> Vec3 {
        self.eye
    }

    /// The camera's backward axis in world space (unit): the V of OpenGL's infinite viewer.
    #[must_use]
    pub fn backward(&self) -> Vec3 {
        self.backward
    }

    /// `generate_ray`: the primary ray through the centre of pixel `(x, y)`, row 0 at the top,
    /// from the eye, limited to the part between the near and the far plane. The pixel need
    /// not lie inside the image (the formula extends beyond it).
    #[must_use]
    pub fn generate_ray(&self, x: u32, y: u32) -> Ray {
        let x_ndc = 2.0 * (f64::from(x) + 0.5) / f64::from(self.width) - 1.0;
        let y_ndc = 1.0 - 2.0 * (f64::from(y) + 0.5) / f64::from(self.height);
        let unproject = |depth: f64| {
            let p_clip = DVec4::new(x_ndc, y_ndc, depth, 1.0);
            let h = self.clip_to_world * p_clip;
            h.truncate() / h.w
        };
        let p_near_world = unproject(0.0);
        let p_far_world = unproject(1.0);
        let eye = self.eye_exact;
        let to_near = p_near_world - eye;
        let t_near = to_near.length();
        let t_far = (p_far_world - eye).length();
        let direction = (to_near / t_near).as_vec3();
        let ray = Ray {
            origin: self.eye,
            direction,
            t_min: t_near as f32,
            t_max: t_far as f32,
            cull_back_faces: self.cull_back_faces,
        };
        debug_assert!(
            ray.direction.is_finite() && ray.t_min.is_finite() && ray.t_max.is_finite(),
            "generate_ray({x}, {y}) gave {ray:?}"
        );
        ray
    }
}
