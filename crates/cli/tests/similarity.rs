//! `cg similarity` on input it cannot compare: an empty folder, or one whose every entry is
//! refused, is bad input (exit 2) with the reason, never "nothing found" (exit 0).
#![cfg(feature = "instructor")]

mod common;
use common::{cg, root, scratch};

#[test]
fn nothing_to_compare_is_bad_input_not_nothing_found() {
    let dir = scratch("similarity", "nothing");
    let empty = dir.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let refused = dir.join("refused");
    std::fs::create_dir_all(&refused).unwrap();
    std::fs::write(refused.join("notes.txt"), "not a submission").unwrap();
    std::fs::write(refused.join("broken.zip"), "not a zip").unwrap();
    // A name that is an escape sequence for the instructor's terminal (clear the screen).
    std::fs::write(refused.join("\u{1b}[2Jclear.txt"), "x").unwrap();
    for (folder, lang, words) in [
        (&empty, "en", "no submission to compare"),
        (&refused, "ja", "比べられる提出物がありません"),
    ] {
        let out = dir.join(format!("out-{lang}"));
        let o = cg(
            &root(),
            &[
                "similarity",
                folder.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
                "--lang",
                lang,
            ],
        );
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(words), "{err}");
        assert!(!err.contains('\u{1b}'), "an escape reached the terminal: {err:?}");
    }
    let out = dir.join("out-escape");
    let o = cg(
        &root(),
        &["similarity", refused.to_str().unwrap(), "--out", out.to_str().unwrap(), "--lang", "en"],
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("<U+001B>[2Jclear.txt"), "{err}");
    // The output written inside the submissions folder is no submission at the next run.
    let inside = refused.join("similarity-out");
    std::fs::create_dir_all(&inside).unwrap();
    std::fs::write(inside.join("similarity.csv"), "kind\n").unwrap();
    let o =
        cg(&root(), &["similarity", refused.to_str().unwrap(), "--out", inside.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!err.contains("similarity-out:"), "the output was read as an entry: {err}");
    // Settings that mean nothing are refused, not quietly changed.
    for (option, value) in [("--min-shared", "0"), ("--max-share", "1")] {
        let o = cg(&root(), &["similarity", empty.to_str().unwrap(), option, value]);
        assert_eq!(o.status.code(), Some(2), "{option} {value}");
        assert!(String::from_utf8_lossy(&o.stderr).contains(option));
    }
    // This year's folder given again as an earlier year's: refused, not paired with itself.
    let (folder, out) = (empty.to_str().unwrap(), dir.join("out-same"));
    let o =
        cg(&root(), &["similarity", folder, "--reference", folder, "--out", out.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("this year's submissions again"), "{err}");
}
