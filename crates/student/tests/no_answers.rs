//! The students' crate can reach no answer (issue 13; DESIGN.md, the trust boundary).
//!
//! Two proofs, each of which fails when the property does not hold:
//!
//! 1. **The manifests.** `exercises/` depends on `cg-student` alone, and `cg-student` on no crate
//!    of the kit (only glam and serde), so no path from the student's crate leads to an oracle.
//! 2. **Probes that must not compile.** A scratch copy of `exercises/` (its own manifest, its own
//!    sources) gets one extra function that calls a former oracle — the kit's expected product,
//!    its light terms, its reflection, its vertex normals, … — and `cargo check` must reject
//!    each one as an unresolved name. A control probe that uses the students' API must compile,
//!    so a broken scratch set-up cannot pass for a refusal.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().expect("workspace root")
}

fn dependencies(manifest: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(manifest).expect("manifest");
    let value: toml::Table = toml::from_str(&text).expect("manifest parses");
    let mut names: Vec<String> = value
        .get("dependencies")
        .and_then(|d| d.as_table())
        .map(|t| t.keys().cloned().collect())
        .unwrap_or_default();
    names.sort();
    names
}

#[test]
fn exercises_depend_on_the_students_api_alone_and_it_on_no_kit_crate() {
    let root = root();
    assert_eq!(dependencies(&root.join("exercises/Cargo.toml")), ["cg-student"]);
    // The reference solutions are the stubs' source: the same single dependency.
    assert_eq!(dependencies(&root.join("solutions/Cargo.toml")), ["cg-student"]);
    let own = dependencies(&root.join("crates/student/Cargo.toml"));
    assert_eq!(own, ["glam", "serde"], "cg-student must not depend on the kit's crates");
}

/// Former oracles: every one of these computed something a task asks the student to compute,
/// and was reachable from `exercises/` before issue 13. Each line is Rust that uses it.
const ORACLES: &[&str] = &[
    // a1: the expected vertices, the placement product.
    "use cg_a1::SpecExt as _;",
    "let _ = cg_core::shapes::cuboid;",
    // a2: the expected view transform, the wrap of camera_yaw.
    "let _ = cg_a2::expected_product;",
    "let _ = cg_a2::camera_product;",
    "let _ = cg_core::math::wrap_degrees;",
    "let _ = cg_core::camera::OrbitCamera::course_sample;",
    // a3: the poses.
    "let _ = cg_a3::model_product;",
    "let _ = cg_a3::expected_model;",
    "let _ = cg_a3::warmup_model;",
    // a4: the cell names, pixels and the corner table.
    "use cg_a4::SpecExt as _;",
    "use cg_a4::RegionExt as _;",
    "let _ = cg_student::a4::Region::pixels;",
    // s: the light terms, the normals, reflection and refraction.
    "let _ = cg_core::light::ambient;",
    "let _ = cg_core::light::diffuse;",
    "let _ = cg_core::light::specular_phong;",
    "let _ = cg_core::light::attenuation;",
    "let _ = cg_core::light::spot_factor;",
    "let _ = cg_core::normals::face_normal;",
    "let _ = cg_core::normals::vertex_normals;",
    "let _ = cg_core::optics::reflect;",
    "let _ = cg_core::optics::refract;",
    // Through the students' API itself: none of them is re-exported there.
    "let _ = cg_student::a2::expected_product;",
    "let _ = cg_student::a3::model_product;",
    "let _ = cg_student::product::MatrixProduct::matrix;",
    "let _ = cg_student::mesh::Mesh::validate;",
];

/// A scratch copy of `exercises/` outside the workspace, with `probe` appended to its lib.rs,
/// checked with the workspace's lock file; returns (success, compiler output).
fn check_probe(scratch: &Path, target: &Path, probe: &str) -> (bool, String) {
    let root = root();
    let lib = std::fs::read_to_string(root.join("exercises/src/lib.rs")).expect("lib.rs");
    std::fs::write(
        scratch.join("src/lib.rs"),
        format!("{lib}\n#[allow(unused_imports, dead_code)]\npub fn probe() {{\n    {probe}\n}}\n"),
    )
    .expect("write probe");
    let out = Command::new(env!("CARGO"))
        .args(["check", "--quiet", "--offline", "--message-format=short"])
        .current_dir(scratch)
        .env("CARGO_TARGET_DIR", target)
        .env_remove("RUSTFLAGS")
        .output()
        .expect("cargo runs");
    (out.status.success(), String::from_utf8_lossy(&out.stderr).into_owned())
}

fn scratch_copy() -> (tempfile_dir::Dir, PathBuf) {
    let root = root();
    let dir = tempfile_dir::Dir::new();
    let scratch = dir.path().join("exercises");
    std::fs::create_dir_all(scratch.join("src")).expect("scratch dir");
    for entry in std::fs::read_dir(root.join("exercises/src")).expect("exercises/src") {
        let entry = entry.expect("entry");
        std::fs::copy(entry.path(), scratch.join("src").join(entry.file_name())).expect("copy");
    }
    // The manifest as the student's: the same [dependencies], each resolved to where the
    // workspace says it is (a scratch copy is outside the workspace).
    let manifest = std::fs::read_to_string(root.join("exercises/Cargo.toml")).expect("manifest");
    let value: toml::Table = toml::from_str(&manifest).expect("manifest parses");
    let workspace: toml::Table =
        toml::from_str(&std::fs::read_to_string(root.join("Cargo.toml")).expect("root manifest"))
            .expect("root manifest parses");
    let mut deps = String::new();
    for name in value["dependencies"].as_table().expect("dependencies").keys() {
        let path = workspace["workspace"]["dependencies"][name]["path"].as_str().expect("path");
        deps.push_str(&format!("{name} = {{ path = {:?} }}\n", root.join(path)));
    }
    std::fs::write(
        scratch.join("Cargo.toml"),
        format!(
            "[package]\nname = \"cg-exercises\"\nversion = \"0.0.0\"\nedition = \"2024\"\n\n\
             [dependencies]\n{deps}\n[workspace]\n"
        ),
    )
    .expect("manifest");
    std::fs::copy(root.join("Cargo.lock"), scratch.join("Cargo.lock")).expect("lock file");
    (dir, scratch)
}

#[test]
fn no_former_oracle_compiles_from_the_students_crate() {
    let (_dir, scratch) = scratch_copy();
    // One target folder for every probe (the students' API is compiled once).
    let target = root().join("target/probe-no-answers");

    // The control: the students' API itself is reachable, so a refusal below means something.
    let (ok, output) = check_probe(
        &scratch,
        &target,
        "let _: Option<cg_student::a1::Spec> = None; let _ = cg_student::gl::Gl::new();",
    );
    assert!(ok, "the control probe must compile; the scratch copy is broken:\n{output}");

    let mut reached = Vec::new();
    for probe in ORACLES {
        let (ok, output) = check_probe(&scratch, &target, probe);
        let unresolved = ["E0432", "E0433", "E0425", "E0599", "unresolved", "cannot find"]
            .iter()
            .any(|code| output.contains(code));
        if ok || !unresolved {
            reached.push(format!("{probe}\n{output}"));
        }
    }
    assert!(reached.is_empty(), "reachable from exercises/:\n{}", reached.join("\n"));
}

/// A temporary folder removed on drop (std only: the kit's crates are not ours to use here).
mod tempfile_dir {
    use std::path::{Path, PathBuf};

    pub struct Dir(PathBuf);

    impl Dir {
        pub fn new() -> Dir {
            let nanos = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map(|d| d.as_nanos())
                .unwrap_or(0);
            let path =
                std::env::temp_dir().join(format!("cg-no-answers-{}-{nanos}", std::process::id()));
            std::fs::create_dir_all(&path).expect("temporary folder");
            Dir(path)
        }

        pub fn path(&self) -> &Path {
            &self.0
        }
    }

    impl Drop for Dir {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}
