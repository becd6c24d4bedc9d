//! The files under `assets/`: every shipped scene loads, the OBJ pyramid is the lecture's, and the
//! orientation texture is what its generator below draws.
//!
//! To (re)write `assets/textures/orientation.png` from the generator:
//! `CG_BLESS=1 cargo test -p cg-scene --test assets`.

use std::path::{Path, PathBuf};

use cg_core::scene::Camera;
use cg_core::shapes;
use cg_core::texture::Texture;

fn assets() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets")
}

/// Every shipped scene loads, meshes, files and all.
#[test]
fn every_shipped_scene_loads() {
    let mut names = Vec::new();
    for entry in std::fs::read_dir(assets().join("scenes")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let scene = cg_scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
            for object in &scene.objects {
                object.mesh.check_indices().unwrap_or_else(|e| panic!("{}: {e}", object.name));
            }
            names.push(scene.name);
        }
    }
    names.sort();
    let expected = [
        "course-sample",
        "glass-mirror",
        "pyramid-obj",
        "sphere-phong",
        "spot-specular",
        "textured-ground",
    ];
    assert_eq!(names, expected);
}

#[test]
fn pyramid_obj_is_the_lecture_pyramid_vertex_for_vertex() {
    let mesh = cg_scene::load_obj(&assets().join("models/pyramid.obj")).unwrap();
    // Same V0..V4 in the same order, same F0..F5: the report's tables match the file's lines.
    assert_eq!(mesh, shapes::lecture_pyramid());
}

#[test]
fn pyramid_obj_scene_draws_the_same_pyramid_as_the_course_sample() {
    let obj = cg_scene::load(&assets().join("scenes/pyramid-obj.toml")).unwrap();
    let course = cg_scene::load(&assets().join("scenes/course-sample.toml")).unwrap();
    assert_eq!(obj.objects, course.objects);
    assert_eq!(obj.lights, course.lights);
    assert_eq!(obj.camera, course.camera);
}

#[test]
fn textured_ground_uses_the_orientation_texture_on_the_grid() {
    let scene = cg_scene::load(&assets().join("scenes/textured-ground.toml")).unwrap();
    assert_eq!(scene.textures.len(), 1);
    let ground = &scene.objects[0];
    assert_eq!(ground.name, "ground");
    let used = ground.texture.as_ref().expect("the ground is textured");
    assert_eq!(scene.textures[used.texture], orientation_texture());
    assert!(matches!(scene.camera, Camera::Orbit(c) if c.distance == 15.0));
}

/// The 5 × 7 glyph of the letter F, top row first: it reads wrongly under every flip and turn.
const GLYPH_F: [&str; 7] = ["#####", "#....", "#....", "####.", "#....", "#....", "#...."];

/// The orientation texture, texel (x, y) with y = 0 the *bottom* row: 64 × 64 texels in 8 × 8
/// cells; a cell's red grows with its column (to the right, +s), its green with its row (upwards,
/// +t), its blue alternates like a checkerboard; a white F, 3 texels per glyph pixel, stands with
/// its foot at texel (4, 4).
fn orientation_texture() -> Texture {
    let glyph = |x: u32, y: u32| {
        let (gx, gy) = (x.checked_sub(4)? / 3, y.checked_sub(4)? / 3);
        let row = GLYPH_F.get(6usize.checked_sub(gy as usize)?)?;
        (row.as_bytes().get(gx as usize)? == &b'#').then_some(())
    };
    Texture::from_fn(64, 64, |x, y| {
        if glyph(x, y).is_some() {
            return [255, 255, 255, 255];
        }
        let (cx, cy) = (x / 8, y / 8);
        [(32 * cx + 16) as u8, (32 * cy + 16) as u8, if (cx + cy) % 2 == 0 { 60 } else { 150 }, 255]
    })
    .unwrap()
}

#[test]
fn orientation_png_matches_its_generator() {
    let path = assets().join("textures/orientation.png");
    let expected = orientation_texture();
    if std::env::var_os("CG_BLESS").is_some() {
        // PNG rows run top to bottom: write the texture's rows from the top one down, as RGB.
        let (w, h) = (expected.width, expected.height);
        let rgb: Vec<u8> = (0..h)
            .rev()
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .flat_map(|(x, y)| {
                let [r, g, b, _] = expected.texel(x, y);
                [r, g, b]
            })
            .collect();
        image::save_buffer(&path, &rgb, w, h, image::ColorType::Rgb8).unwrap();
    }
    let loaded = cg_scene::load_texture(&path).unwrap_or_else(|e| {
        panic!("{e}\n(to write it: CG_BLESS=1 cargo test -p cg-scene --test assets)")
    });
    assert_eq!(loaded, expected);
    // Independently of the generator: the F's top bar is white near the *top* of the glyph, its
    // foot at the bottom; the bottom-left cell is dark red/green, the top-right one bright.
    assert_eq!(loaded.texel(4, 4), [255; 4], "foot of the F");
    assert_eq!(loaded.texel(4 + 14, 4 + 20), [255; 4], "right end of the F's top bar");
    assert_ne!(loaded.texel(4 + 14, 4), [255; 4], "no bar at the bottom");
    assert!(loaded.texel(63, 63)[0] > 200 && loaded.texel(63, 63)[1] > 200);
    assert!(loaded.texel(0, 0)[0] < 40 && loaded.texel(0, 0)[1] < 40);
    let size = std::fs::metadata(&path).unwrap().len();
    assert!(size < 8 * 1024, "keep the committed texture small: {size} bytes");
}
