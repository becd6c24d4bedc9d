//! The student's stubs in `exercises/` are exactly what `solutions/` generates (its `BEGIN
//! SOLUTION` blocks removed, its `BEGIN STUB` blocks uncommented). Regenerate them with
//! `cargo run --release -- sync-stubs` (or run this test with `CG_BLESS=1`).

use std::path::Path;

#[test]
fn exercises_are_the_stubs_the_solutions_generate() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let (solutions, exercises) = (root.join("solutions"), root.join("exercises"));
    if std::env::var("CG_BLESS").is_ok_and(|v| v == "1") {
        cg_harness::stubs::write(&solutions, &exercises).unwrap_or_else(|e| panic!("{e}"));
    }
    let stale =
        cg_harness::stubs::out_of_sync(&solutions, &exercises).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        stale.is_empty(),
        "exercises/ differs from what solutions/ generates in {stale:?}: run `cargo run --release -- sync-stubs` (never edit exercises/ by hand in the kit's own repository)"
    );
}

#[test]
fn every_exercise_file_comes_from_a_solution_file() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let generated: Vec<_> = cg_harness::stubs::generate(&root.join("solutions"))
        .unwrap()
        .into_iter()
        .map(|(p, _)| p)
        .collect();
    let mut stack = vec![root.join("exercises/src")];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let relative = path.strip_prefix(root.join("exercises")).unwrap().to_path_buf();
                assert!(
                    generated.contains(&relative),
                    "{} has no solution file",
                    relative.display()
                );
            }
        }
    }
}

/// Every stub's `todo!()` says what its task asks in both languages (`a1.t1: 多面体の頂点… /
/// list the vertices…`), so `check` in Japanese says more than `まだです: a1.t1` (a1's and a4's
/// stubs were English only).
#[test]
fn every_stubs_todo_says_its_task_in_both_languages() {
    use cg_core::lang::Lang;
    use cg_harness::check::stub_message;
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut seen = 0;
    for (path, text) in cg_harness::stubs::generate(&root.join("solutions")).unwrap() {
        let lines: Vec<&str> = text.lines().map(str::trim).collect();
        for (n, line) in lines.iter().enumerate().filter(|(_, l)| l.starts_with("todo!(")) {
            // `todo!("…")`, or rustfmt's `todo!(` with the message on the next line.
            let code = if *line == "todo!(" { lines[n + 1] } else { line };
            let message = code.split('"').nth(1).unwrap_or_default();
            let id = message.split(':').next().unwrap_or_default();
            assert!(id.contains(".t"), "{}: todo!({message:?}) names no task", path.display());
            for lang in [Lang::Ja, Lang::En] {
                let said = stub_message(message, lang);
                assert!(said.len() > id.len() + 3, "{}: {lang} reads {said:?}", path.display());
            }
            seen += 1;
        }
    }
    assert!(seen >= 10, "{seen} todo!()s found");
}
