//! The lighting stage as a hook (光源処理): the one function the shading modes call, at a face,
//! a vertex or a pixel depending on the mode.
//!
//! | shading | where [`Lighting::light`] is called | what is interpolated |
//! |---|---|---|
//! | [`Shading::Flat`] (フラットシェーディング) | once per face: the lecture's model at its centroid with the face normal; OpenGL's model at its provoking (last) vertex with that vertex's normal and colour, as GL_FLAT | nothing: one colour per face |
//! | [`Shading::Gouraud`] (グローシェーディング) | once per vertex, with the vertex normal | the colours, clamped to `[0, 1]` per vertex |
//! | [`Shading::Phong`] (フォンシェーディング) | once per pixel, with the interpolated, renormalised normal | normals and positions |
//!
//! The renderer decides *where* to light; a [`Lighting`] decides *how*. [`SceneLighting`], the
//! default, evaluates the scene's own light model with [`cg_core::light::shade`]. An exercise can
//! pass its own implementation to [`crate::render_with`] — a closure
//! `|scene: &Scene, point: &SurfacePoint| -> Rgb` is one — and the renderer draws the same image
//! with it, by the same path.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{LightCounts, Material, shade_with_visibility_counted};
use cg_core::scene::{Scene, Shading};

/// A point of a surface to be lit, everything in world space (ワールド座標系), where the lights are.
#[derive(Clone, Copy, Debug)]
pub struct SurfacePoint<'a> {
    /// Where the point is: a face's centroid (flat, the lecture's model) or its last vertex
    /// (flat, OpenGL's model: GL_FLAT's provoking vertex), a vertex (Gouraud) or the point seen
    /// through a pixel centre (Phong).
    pub p_world: Vec3,
    /// The unit normal N, pointing out of the front face (mirrored objects are already flipped
    /// back). The zero vector when the surface has no usable normal there (a degenerate face):
    /// then only the ambient and emitted light remain.
    pub n_world: Vec3,
    /// The unit vector V towards the viewer ([`cg_core::light::LightModel::view_vector`]: for
    /// OpenGL's infinite viewer, the camera's backward axis).
    pub v_world: Vec3,
    /// The surface's material. With per-vertex colours, k_a and k_d are the colour there
    /// (glColor under GL_COLOR_MATERIAL); k_s is 0 when the scene has no specular light at all
    /// ("only what the scene needs").
    pub material: &'a Material,
    /// Which shading mode asks (tells a face, a vertex and a pixel apart).
    pub shading: Shading,
}

/// The lighting stage: the colour of a lit point, *not* clamped (the renderer clamps to
/// `[0, 1]` where OpenGL does: per vertex for Gouraud, per face for flat, per pixel for Phong;
/// a NaN channel becomes 0 there).
///
/// `Sync` because tiles are shaded on all cores at once.
///
/// Closures `Fn(&Scene, &SurfacePoint) -> Rgb` implement it.
pub trait Lighting: Sync {
    /// The colour that `scene`'s lights give `point`.
    fn light(&self, scene: &Scene, point: &SurfacePoint<'_>) -> Rgb;

    /// [`Lighting::light`], adding to `counts` the light-model work it did
    /// ([`LightCounts`]: attenuations, specular terms, …). The renderer calls this one and
    /// reports the counts in [`crate::Stats`]. The default calls [`Lighting::light`] and counts
    /// nothing: the kit cannot see inside a custom hook, so its specular and attenuation
    /// counters stay 0. [`SceneLighting`] counts inside [`cg_core::light`].
    fn light_counted(
        &self,
        scene: &Scene,
        point: &SurfacePoint<'_>,
        counts: &mut LightCounts,
    ) -> Rgb {
        let _ = counts;
        self.light(scene, point)
    }

    /// Whether this is the scene's own light model, [`SceneLighting`], which the renderer then
    /// evaluates for sixteen points at once (the same bits, see `src/span.rs`). Every other hook
    /// is called point by point.
    #[doc(hidden)]
    fn is_scene_lighting(&self) -> bool {
        false
    }
}

/// The default lighting: the scene's light model ([`Scene::light_model`], its global ambient and
/// lights) evaluated term by term by [`cg_core::light::shade`], summed. It counts its work
/// ([`Lighting::light_counted`]) inside the light model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SceneLighting;

impl Lighting for SceneLighting {
    fn is_scene_lighting(&self) -> bool {
        true
    }

    fn light(&self, scene: &Scene, point: &SurfacePoint<'_>) -> Rgb {
        self.light_counted(scene, point, &mut LightCounts::default())
    }

    fn light_counted(
        &self,
        scene: &Scene,
        point: &SurfacePoint<'_>,
        counts: &mut LightCounts,
    ) -> Rgb {
        // No shadows in a rasterizer: every light is visible (this is `shade`, counted).
        shade_with_visibility_counted(
            scene.light_model,
            scene.global_ambient,
            &scene.lights,
            point.material,
            point.p_world,
            point.n_world,
            point.v_world,
            |_, _, _| 1.0,
            counts,
        )
        .total()
    }
}

impl<F> Lighting for F
where
    F: Fn(&Scene, &SurfacePoint<'_>) -> Rgb + Sync,
{
    fn light(&self, scene: &Scene, point: &SurfacePoint<'_>) -> Rgb {
        self(scene, point)
    }
}
