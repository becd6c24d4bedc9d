//! `cg grade` on a folder whose every entry is refused (the wrong folder given, every upload a
//! `.rar`): its results are written, each line says why, and it ends with exit 2 and a line
//! saying that nothing was graded; it ended 0, as a class graded does. No kit build is needed:
//! nothing gets as far as building.
#![cfg(feature = "instructor")]

mod common;
use common::{cg, root, scratch};

#[test]
fn a_folder_of_which_nothing_is_graded_ends_with_exit_2() {
    if !root().join("solutions/src/a1.rs").exists() {
        eprintln!("no solutions/ (a student handout): grading is tested in the kit's repository");
        return;
    }
    let dir = scratch("grade", "nothing-graded");
    let subs = dir.join("submissions");
    std::fs::create_dir_all(subs.join("taro")).unwrap();
    std::fs::write(subs.join("hanako.rar"), b"Rar!\x1a\x07\x00").unwrap();
    std::fs::write(subs.join("taro/report.pdf"), b"%PDF-1.4").unwrap();
    for (lang, words) in
        [("en", "none of the 2 entries of "), ("ja", " の 2 件はどれも採点されていません")]
    {
        let out = dir.join(format!("out-{lang}"));
        let o = cg(
            &root(),
            &[
                "grade",
                subs.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
                "--unsafe-no-sandbox",
                "--jobs",
                "1",
                "--lang",
                lang,
            ],
        );
        let stdout = String::from_utf8_lossy(&o.stdout);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{stdout}\n{stderr}");
        assert!(stderr.contains(words), "{stderr}");
        // The results are written all the same, and each line says why.
        assert!(out.join("class.csv").exists() && out.join("summary.md").exists());
        if lang == "en" {
            assert!(
                stdout.contains("hanako.rar is a .rar archive, not a zip")
                    && stdout.contains("it holds report.pdf"),
                "{stdout}"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
