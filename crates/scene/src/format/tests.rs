use super::*;
use cg_core::lang::Lang;

/// Every shipped scene passes every check that does not build a mesh. (The integration test
/// `every_shipped_scene_loads` builds the meshes too.)
#[test]
fn every_shipped_scene_reads() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let text = std::fs::read_to_string(&path).unwrap();
            let src = Source { text: &text, file: &path };
            let spec = read(&src, path.parent().unwrap()).unwrap_or_else(|e| panic!("{e}"));
            assert!(!spec.objects.is_empty(), "{}", path.display());
            for object in &spec.objects {
                if let Geometry::Obj(file, _) = &object.geometry {
                    assert!(file.exists(), "{}", file.display());
                }
                if let Some(t) = &object.texture {
                    assert!(t.image.exists(), "{}", t.image.display());
                }
            }
            count += 1;
        }
    }
    assert!(count >= 6, "found {count} scenes in {}", dir.display());
}

fn read_text(text: &str) -> Result<SceneSpec, SceneError> {
    let path = Path::new("t.toml");
    read(&Source { text, file: path }, Path::new(""))
}

#[test]
fn reflectances_may_not_sum_above_one() {
    // kr + kt > 1 in the green channel: an error at kt, naming the channel and the sum.
    let text = "format = 1\n[materials.glass]\nkr = [0.1, 0.5, 0.1]\nkt = [0.9, 0.6, 0.9]\n";
    let e = read_text(text).unwrap_err();
    assert_eq!(e.key.as_deref(), Some("materials.glass.kt"), "{e}");
    assert_eq!(e.position.map(|p| p.line), Some(4));
    assert!(
        matches!(*e.kind, ErrorKind::ReflectanceSum { channel: 1, kr, kt } if kr == 0.5 && kt == 0.6),
        "{e}"
    );
    let en = e.describe(Lang::En);
    assert!(en.contains("channel g") && en.contains("energy conservation"), "{en}");
    assert!(e.describe(Lang::Ja).contains("エネルギー保存"), "{}", e.describe(Lang::Ja));
    // Only kr given (a mirror of kr = 1.5): the error is at kr.
    let e = read_text("format = 1\n[materials.m]\nkr = [1.5, 0.0, 0.0]\n").unwrap_err();
    assert_eq!(e.key.as_deref(), Some("materials.m.kr"));
    // Exactly 1 in decimal (0.1 + 0.9, 0.3 + 0.7) is allowed, as the shipped glass is.
    read_text("format = 1\n[materials.g]\nkr = [0.1, 0.3, 0.5]\nkt = [0.9, 0.7, 0.5]\n").unwrap();
    // So is an inline material of an object.
    let inline = "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\nmaterial = { kr = [1, 1, 1], kt = [1, 1, 1] }\n";
    assert!(matches!(*read_text(inline).unwrap_err().kind, ErrorKind::ReflectanceSum { .. }));
}

#[test]
fn colours_are_bounded_and_windows_have_at_most_64_m_pixels() {
    let e = read_text(
        "format = 1\n[[lights]]\nkind = \"point\"\nposition = [0, 1, 0]\ndiffuse = [1, 3e38, 1]\n",
    )
    .unwrap_err();
    assert_eq!(e.key.as_deref(), Some("lights[0].diffuse[1]"));
    assert!(
        matches!(*e.kind, ErrorKind::BadValue { rule: Rule::AtMost { max }, .. } if max == 1e6),
        "{e}"
    );
    assert!(e.describe(Lang::Ja).contains("以下"), "{}", e.describe(Lang::Ja));
    read_text("format = 1\n[window]\nclear_color = [1e6, 0, 0]\n").unwrap();
    // 16384 × 4097: each side allowed, too many pixels in all; reported at height.
    let e = read_text("format = 1\n[window]\nwidth = 16384\nheight = 4097\n").unwrap_err();
    assert_eq!(e.key.as_deref(), Some("window.height"), "{e}");
    assert!(matches!(*e.kind, ErrorKind::TooManyPixels { width: 16384, height: 4097 }));
    assert!(e.describe(Lang::En).contains("too many pixels"), "{e}");
    read_text("format = 1\n[window]\nwidth = 16384\nheight = 4096\n").unwrap();
}
