//! The course's sample scene (`assets/scenes/course-sample.toml`), compiled into the kit so
//! every assignment's view starts from exactly the sample program's window, camera, light and
//! ground, wherever the kit runs from.

use std::path::Path;

use cg_core::scene::Scene;

/// The text of `assets/scenes/course-sample.toml`.
pub const COURSE_SAMPLE_TOML: &str = include_str!("../../../assets/scenes/course-sample.toml");

/// The course's sample scene: window 640×640, the orbit camera (distance 15, pitch −30°), the
/// light at (10, 10, 10), the 10×10 ground and the lecture's pyramid.
///
/// # Panics
/// Never in a built kit: the scene file is part of the kit and a test loads it.
#[must_use]
pub fn scene() -> Scene {
    cg_scene::parse(COURSE_SAMPLE_TOML, Path::new("assets/scenes/course-sample.toml"))
        .expect("the kit's course-sample.toml loads (checked by its tests)")
}

/// [`scene`] without its objects: the window, camera, light and light model, for a view that
/// draws its own objects.
#[must_use]
pub fn stage() -> Scene {
    let mut s = scene();
    s.objects.clear();
    s
}

/// [`scene`] with the ground only (the pyramid removed).
#[must_use]
pub fn ground_only() -> Scene {
    let mut s = scene();
    s.objects.retain(|o| o.name == "ground");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_compiled_scene_is_the_course_sample() {
        let s = scene();
        assert_eq!((s.width, s.height), (640, 640));
        let names: Vec<&str> = s.objects.iter().map(|o| o.name.as_str()).collect();
        assert_eq!(names, ["ground", "pyramid"]);
        assert!(stage().objects.is_empty());
        assert_eq!(ground_only().objects.len(), 1);
    }
}
