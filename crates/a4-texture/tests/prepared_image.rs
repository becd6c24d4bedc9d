//! `assets/textures/a4-prepared.png` is exactly what [`cg_a4::prepared_image`] draws.
//!
//! To (re)write it from the generator: `CG_BLESS=1 cargo test -p cg-a4 --test prepared_image`.
//! A missing or different file fails without `CG_BLESS`, so a run never makes its own reference.

use std::path::{Path, PathBuf};

use cg_a4::{CELL_PIXELS, IMAGE_PIXELS, cell_color, prepared_image};
use cg_core::image::Image;

fn path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/textures/a4-prepared.png")
}

#[test]
fn the_committed_png_is_the_generators_image() {
    let expected = prepared_image();
    if std::env::var("CG_BLESS").is_ok_and(|v| v == "1") {
        // PNG rows run top to bottom, a texture's from the bottom up.
        let (w, h) = (expected.width, expected.height);
        let rows_from_top: Vec<[u8; 4]> = (0..h)
            .rev()
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| expected.texel(x, y))
            .collect();
        let image = Image::from_rgba8(w, h, &rows_from_top).expect("w × h pixels");
        cg_scene::save_png(&path(), &image).unwrap_or_else(|e| panic!("{e}"));
    }
    let loaded = cg_scene::load_texture(&path()).unwrap_or_else(|e| {
        panic!("{e}\n(to write it: CG_BLESS=1 cargo test -p cg-a4 --test prepared_image)")
    });
    assert_eq!((loaded.width, loaded.height), (IMAGE_PIXELS, IMAGE_PIXELS));
    let differing = loaded.texels.iter().zip(&expected.texels).filter(|(a, b)| a != b).count();
    assert_eq!(
        differing, 0,
        "{differing} texels differ from the generator (CG_BLESS=1 cargo test -p cg-a4 --test prepared_image rewrites the file)"
    );
    // As an image viewer shows the file: cell A1 at the top left, H8 at the bottom right.
    let top_left = loaded.texel(CELL_PIXELS - 6, IMAGE_PIXELS - 1 - (CELL_PIXELS - 6));
    assert_eq!(top_left, cell_color(0, 0), "A1 at the top left of the file");
    assert_eq!(loaded.texel(IMAGE_PIXELS - 6, 5), cell_color(7, 7), "H8 at the bottom right");
    let size = std::fs::metadata(path()).map(|m| m.len()).unwrap_or(0);
    assert!(size < 64 * 1024, "keep the committed image small: {size} bytes");
}
