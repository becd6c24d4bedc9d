//! Nothing panics on a broken file: every truncated prefix and thousands of seeded random edits
//! of the course sample (and of an OBJ model and a PNG image) give `Ok` or `Err`, never a panic.
//! A panic anywhere inside fails the test by itself; the assertions check that the edits really
//! produce both outcomes.

use std::path::Path;

use cg_testkit::Inputs;

fn course_sample() -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/course-sample.toml");
    std::fs::read_to_string(path).unwrap()
}

/// `text` with `edits` random edits: a byte replaced by a random byte or by a character that
/// means something in the format, a byte deleted, or a byte duplicated.
fn mutate(rng: &mut Inputs, text: &[u8], edits: usize) -> Vec<u8> {
    const SIGNIFICANT: &[u8] = b"[]{}=\",.#\n-+0123456789eE_ abcinfx";
    let mut bytes = text.to_vec();
    for _ in 0..edits {
        if bytes.is_empty() {
            break;
        }
        let at = rng.int(0, bytes.len() as i64) as usize;
        match rng.int(0, 4) {
            0 => bytes[at] = rng.int(0, 256) as u8,
            1 => bytes[at] = SIGNIFICANT[rng.int(0, SIGNIFICANT.len() as i64) as usize],
            2 => {
                bytes.remove(at);
            }
            _ => bytes.insert(at, bytes[at]),
        }
    }
    bytes
}

fn cases() -> usize {
    if cfg!(debug_assertions) { 3_000 } else { 30_000 }
}

#[test]
fn truncated_course_samples_never_panic() {
    let text = course_sample();
    let path = Path::new("assets/scenes/course-sample.toml");
    assert!(cg_scene::parse(&text, path).is_ok());
    let (mut ok, mut err) = (0, 0);
    for end in (0..text.len()).filter(|&i| text.is_char_boundary(i)) {
        match cg_scene::parse(&text[..end], path) {
            Ok(_) => ok += 1,
            Err(e) => {
                err += 1;
                // Every error still names the file.
                assert!(e.to_string().starts_with("assets/scenes/course-sample.toml"), "{e}");
            }
        }
    }
    assert!(ok > 0 && err > 0, "{ok} prefixes read, {err} refused");
}

#[test]
fn randomly_edited_course_samples_never_panic() {
    let text = course_sample();
    let path = Path::new("assets/scenes/course-sample.toml");
    let mut rng = Inputs::seeded(0x5CE4E);
    let (mut ok, mut err) = (0, 0);
    for i in 0..cases() {
        let edited = mutate(&mut rng, text.as_bytes(), 1 + i % 4);
        let edited = String::from_utf8_lossy(&edited);
        match cg_scene::parse(&edited, path) {
            Ok(_) => ok += 1,
            Err(e) => {
                err += 1;
                let _ = e.describe(cg_core::lang::Lang::Ja);
            }
        }
    }
    assert!(ok > 0 && err > 0, "{ok} edits read, {err} refused");
}

#[test]
fn broken_obj_files_never_panic() {
    let text = "# a model\nmtllib m.mtl\no a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 -1\nvt 0 0\nvt 1 0\n\
                vt 0 1\nvn 0 0 1\nusemtl red\nf 1/1/1 2/2/1 3/3/1\ng b\nf -1/-1/-1 -2/-2/-1 -3/-3/-1 4/1/1\n\
                l 1 2\nf 2 4 3\n";
    let path = Path::new("model.obj");
    let mut rng = Inputs::seeded(0x0B1);
    let (mut ok, mut err) = (0, 0);
    let prefixes = (0..text.len()).map(|end| text.as_bytes()[..end].to_vec());
    let edits: Vec<Vec<u8>> =
        (0..cases()).map(|i| mutate(&mut rng, text.as_bytes(), 1 + i % 3)).collect();
    for bytes in prefixes.chain(edits) {
        match cg_scene::parse_obj(&String::from_utf8_lossy(&bytes), path) {
            Ok(mesh) => {
                ok += 1;
                mesh.check_indices().unwrap();
            }
            Err(_) => err += 1,
        }
    }
    assert!(ok > 0 && err > 0, "{ok} models read, {err} refused");
}

#[test]
fn broken_png_files_never_panic() {
    let mut png = Vec::new();
    let image =
        image::RgbaImage::from_fn(5, 3, |x, y| image::Rgba([x as u8 * 40, y as u8 * 80, 7, 255]));
    image.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png).unwrap();
    let path = Path::new("texture.png");
    assert!(cg_scene::decode_png(&png, path).is_ok());
    let mut rng = Inputs::seeded(0x914);
    let (mut ok, mut err) = (0, 0);
    let prefixes = (0..png.len()).map(|end| png[..end].to_vec());
    let edits: Vec<Vec<u8>> = (0..cases()).map(|i| mutate(&mut rng, &png, 1 + i % 3)).collect();
    for bytes in prefixes.chain(edits) {
        match cg_scene::decode_png(&bytes, path) {
            Ok(t) => {
                ok += 1;
                assert_eq!(t.texels.len(), (t.width * t.height) as usize);
            }
            Err(_) => err += 1,
        }
    }
    assert!(ok > 0 && err > 0, "{ok} images read, {err} refused");
}
