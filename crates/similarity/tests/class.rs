//! A small class made from the kit's own solutions and stubs, written to disk and read as
//! `cg grade` reads a class (folders and a zip), then compared:
//!
//! - alice hands in the solutions; bob hands in alice's code with its local names renamed, its
//!   functions reordered and its comments gone: the pair is flagged;
//! - carol writes her own vertices by hand; dave writes the same numbers in a form of his own
//!   (and puts them in his report): his a1 and his report follow from carol's variant;
//! - frank and grace hand in the stubs untouched: not a pair;
//! - heidi writes her a1 herself: no pair with anyone.
//!
//! And earlier years' submissions (references), two of them the same, are compared with this
//! year's but not with each other.
//!
//! Needs the kit's own repository (solutions/): in a student handout it says so and passes.

use std::collections::BTreeMap;
use std::io::Write as _;
use std::path::{Path, PathBuf};

use cg_assign::Variants;
use cg_core::lang::Lang;
use cg_harness::{StudentNumber, TableVersion};
use cg_similarity::{Analysis, Settings, Submission, analyse, read};

const MODULES: [&str; 5] = ["a1", "a2", "a3", "a4", "s"];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().unwrap()
}

fn has_solutions() -> bool {
    let here = root().join("solutions/src/a1.rs").exists();
    if !here {
        eprintln!("no solutions/ here (a student handout): the class cannot be made; skipped");
    }
    here
}

fn solution(m: &str) -> String {
    std::fs::read_to_string(root().join(format!("solutions/src/{m}.rs"))).unwrap()
}

fn stub(m: &str) -> String {
    std::fs::read_to_string(root().join(format!("exercises/src/{m}.rs"))).unwrap()
}

fn stubs() -> BTreeMap<String, String> {
    read::stubs(&root()).unwrap()
}

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("cg-similarity-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A submission folder `dir/<entry>` holding `exercises/`.
fn folder(dir: &Path, entry: &str, student: &str, files: &BTreeMap<&str, String>) {
    let base = dir.join(entry).join("exercises");
    std::fs::create_dir_all(base.join("src")).unwrap();
    for (m, text) in files {
        std::fs::write(base.join(format!("src/{m}.rs")), text).unwrap();
    }
    std::fs::write(base.join("student.toml"), format!("student = \"{student}\"\ntable = 1\n"))
        .unwrap();
}

/// The same as a zip `dir/<entry>.zip`, one folder down.
fn zipped(dir: &Path, entry: &str, student: &str, files: &BTreeMap<&str, String>) {
    let mut z =
        zip::ZipWriter::new(std::fs::File::create(dir.join(format!("{entry}.zip"))).unwrap());
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for (m, text) in files {
        z.start_file(format!("kit/exercises/src/{m}.rs"), options).unwrap();
        z.write_all(text.as_bytes()).unwrap();
    }
    z.start_file("kit/exercises/student.toml", options).unwrap();
    z.write_all(format!("student = \"{student}\"\n").as_bytes()).unwrap();
    z.finish().unwrap();
}

fn all(f: impl Fn(&str) -> String) -> BTreeMap<&'static str, String> {
    MODULES.iter().map(|m| (*m, f(m))).collect()
}

/// Whether `c` can be part of an identifier.
fn word(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// `text` with every whole word `from` replaced by `to`.
fn rename(text: &str, from: &str, to: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(at) = rest.find(from) {
        let before = rest[..at].chars().next_back();
        let after = rest[at + from.len()..].chars().next();
        out.push_str(&rest[..at]);
        if before.is_some_and(word) || after.is_some_and(word) {
            out.push_str(from);
        } else {
            out.push_str(to);
        }
        rest = &rest[at + from.len()..];
    }
    out.push_str(rest);
    out
}

/// The local names of `text`: what `let`, `let mut` and `for` bind, and private functions.
fn local_names(text: &str) -> Vec<String> {
    let mut names = Vec::new();
    for marker in ["let mut ", "let ", "for ", "\nfn "] {
        for (at, _) in text.match_indices(marker) {
            let name: String = text[at + marker.len()..].chars().take_while(|c| word(*c)).collect();
            if name.len() > 1 && name.chars().next().is_some_and(|c| c.is_ascii_lowercase()) {
                names.push(name);
            }
        }
    }
    names.sort();
    names.dedup();
    names
}

/// The top-level items of `text` (split at blank lines outside braces), the header first.
fn items(text: &str) -> Vec<String> {
    let (mut items, mut current, mut depth) = (Vec::new(), String::new(), 0i32);
    for line in text.lines() {
        let code = line.split("//").next().unwrap_or("");
        let mut in_string = false;
        for c in code.chars() {
            match c {
                '"' => in_string = !in_string,
                '{' if !in_string => depth += 1,
                '}' if !in_string => depth -= 1,
                _ => {}
            }
        }
        if line.trim().is_empty() && depth == 0 && !current.trim().is_empty() {
            items.push(std::mem::take(&mut current));
        } else {
            current.push_str(line);
            current.push('\n');
        }
    }
    items.push(current);
    items
}

/// Bob's copy: comments dropped, local names renamed, the items after the header reversed.
fn disguised(text: &str) -> String {
    let plain: String = text
        .lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .map(|l| format!("{l}\n"))
        .collect();
    let mut renamed = plain;
    for (n, name) in local_names(&renamed).iter().enumerate() {
        renamed = rename(&renamed, name, &format!("q{n}_{}", name.len()));
    }
    let mut parts = items(&renamed);
    let header = parts.remove(0);
    parts.reverse();
    format!("// my own work\n{header}\n{}", parts.join("\n"))
}

fn number(s: &str) -> StudentNumber {
    s.parse().unwrap()
}

/// `student`'s expected a1 vertices.
fn vertices(student: &str) -> Vec<[f32; 3]> {
    let v = Variants::for_student(&number(student), TableVersion::DEFAULT);
    cg_a1::SpecExt::expected_vertices(&v.a1).iter().map(|p| [p.x, p.y, p.z]).collect()
}

/// The a1 stub with `vertices`' `todo!` replaced by `body`.
fn a1_with_vertices(body: &str) -> String {
    let s = stub("a1");
    // `todo!("a1.t1: …")`, on one line or, as rustfmt writes a long one, on three.
    let message = s.find("\"a1.t1").expect("the a1 stub's vertices todo");
    let at = s[..message].rfind("todo!(").expect("the a1 stub's vertices todo");
    let closed = message + 1 + s[message + 1..].find('"').unwrap();
    let end = closed + s[closed..].find(')').unwrap() + 1;
    format!("{}{body}{}", &s[..at], &s[end..])
}

/// Carol's way: the hint's `vec![Vec3::new(…), …]`.
fn carol_a1(student: &str) -> String {
    let list: Vec<String> = vertices(student)
        .iter()
        .map(|[x, y, z]| format!("Vec3::new({x:?}, {y:?}, {z:?})"))
        .collect();
    a1_with_vertices(&format!("vec![{}]", list.join(", ")))
}

/// Dave's way: a table of rows with four decimals, turned into vectors.
fn dave_a1(student: &str) -> String {
    let rows: Vec<String> = vertices(student)
        .iter()
        .map(|[x, y, z]| format!("    [{x:.4}, {y:.4}, {z:.4}],"))
        .collect();
    a1_with_vertices(&format!(
        "const TABLE: &[[f32; 3]] = &[\n{}\n];\n    TABLE.iter().map(|r| Vec3::from_array(*r)).collect()",
        rows.join("\n")
    ))
}

/// A report's vertex table of `student`'s vertices.
fn report(student: &str) -> String {
    let mut r = "# レポート\n\n| 頂点 | x | y | z |\n|---|---|---|---|\n".to_owned();
    for (k, [x, y, z]) in vertices(student).iter().enumerate() {
        r.push_str(&format!("| V{k} | {x:.3} | {y:.3} | {z:.3} |\n"));
    }
    r
}

/// Heidi's own a1, written apart from the kit's solution (prisms and pyramids only).
const HEIDI_A1: &str = r#"
use cg_student::a1::{Shape, Spec, Turn};
use cg_student::glam::Vec3;
use cg_student::product::{Factor, MatrixProduct};

fn ring(n: u32, r: f32, y: f32, turn: Turn) -> Vec<Vec3> {
    let sign = if turn == Turn::Ccw { -1.0 } else { 1.0 };
    (0..n)
        .map(|k| {
            let a = std::f32::consts::TAU * k as f32 / n as f32;
            Vec3::new(r * a.cos(), y, sign * r * a.sin())
        })
        .collect()
}

pub fn vertices(spec: &Spec) -> Vec<Vec3> {
    match spec.shape {
        Shape::Prism { sides, radius, height } => {
            let mut out = ring(sides, radius, 0.0, spec.numbering.ring);
            out.append(&mut ring(sides, radius, height, spec.numbering.ring));
            out
        }
        Shape::Pyramid { sides, radius, height } => {
            let mut out = vec![Vec3::Y * height];
            out.extend(ring(sides, radius, 0.0, spec.numbering.ring));
            out
        }
        _ => Vec::new(),
    }
}

pub fn faces(spec: &Spec) -> Vec<[u32; 3]> {
    let count = vertices(spec).len() as u32;
    let mut tris = Vec::new();
    let mut i = 1;
    while i + 1 < count {
        tris.push([0, i, i + 1]);
        tris.push([count - 1, i + 1, i]);
        i += 1;
    }
    tris
}

pub fn face_normals(spec: &Spec) -> Vec<Vec3> {
    let p = vertices(spec);
    let mut normals = Vec::with_capacity(p.len());
    for [a, b, c] in faces(spec) {
        let e1 = p[b as usize] - p[a as usize];
        let e2 = p[c as usize] - p[a as usize];
        let n = e1.cross(e2);
        normals.push(if n.length() > 0.0 { n / n.length() } else { Vec3::Y });
    }
    normals
}

pub fn model_transform(spec: &Spec) -> MatrixProduct {
    let where_to = Vec3::new(spec.placement.x, spec.placement.y, spec.placement.z);
    let product = MatrixProduct::identity();
    let moved = product.then(Factor::translate(where_to));
    moved.then(Factor::rotate_y_deg(spec.placement.angle_deg))
}
"#;

const ALICE: &str = "20260003";
const BOB: &str = "20260002";
const CAROL: &str = "20260001";
const DAVE: &str = "20260004";
const FRANK: &str = "20260005";
const GRACE: &str = "20260006";
const HEIDI: &str = "20260007";
// Carol's variant is a hexagonal frustum: its vertices (0.4, 0.693, 1.299, …) are hers alone in
// this class. (Alice's numbers, 0.75, 1, 1.5 and 2, are other students' too: a copy of her a1
// could not be told apart, and would not be flagged.)

/// The class on disk (bob as a zip), read back as `cg grade` reads it, with the reports.
fn class(dir: &Path) -> Vec<Submission> {
    folder(dir, "alice", ALICE, &all(solution));
    zipped(dir, "bob", BOB, &all(|m| disguised(&solution(m))));
    folder(dir, "carol", CAROL, &all(|m| if m == "a1" { carol_a1(CAROL) } else { stub(m) }));
    folder(dir, "dave", DAVE, &all(|m| if m == "a1" { dave_a1(CAROL) } else { stub(m) }));
    folder(dir, "frank", FRANK, &all(stub));
    folder(dir, "grace", GRACE, &all(stub));
    folder(dir, "heidi", HEIDI, &all(|m| if m == "a1" { HEIDI_A1.to_owned() } else { stub(m) }));
    let reports = dir.with_extension("reports");
    let _ = std::fs::remove_dir_all(&reports);
    std::fs::create_dir_all(&reports).unwrap();
    std::fs::write(reports.join(format!("{ALICE}.md")), report(ALICE)).unwrap();
    std::fs::write(reports.join(format!("report-{DAVE}.md")), report(CAROL)).unwrap();
    std::fs::write(reports.join("notes.md"), "no number").unwrap();
    let mut class = read::class(dir, false).unwrap();
    let unmatched = read::reports(&reports, &mut class).unwrap();
    assert_eq!(unmatched, ["notes.md"]);
    class
}

fn index(class: &[Submission], name: &str) -> usize {
    class.iter().position(|s| s.name.starts_with(name)).unwrap_or_else(|| panic!("no {name}"))
}

fn listed(a: &Analysis, x: usize, y: usize) -> Option<&cg_similarity::Pair> {
    a.pairs.iter().find(|p| (p.a, p.b) == (x.min(y), x.max(y)))
}

#[test]
fn a_renamed_and_reordered_copy_is_flagged_and_untouched_stubs_or_honest_work_are_not() {
    if !has_solutions() {
        return;
    }
    let dir = temp("class");
    let class = class(&dir);
    assert_eq!(class.len(), 7);
    assert!(class.iter().all(|s| s.refused.is_none() && s.modules.len() == 5), "{class:?}");
    let a = analyse(&class, &stubs(), Settings::default());
    let [alice, bob, frank, grace, heidi] =
        ["alice", "bob", "frank", "grace", "heidi"].map(|n| index(&class, n));

    // The copy: renamed, reordered, comments gone, and still nearly every fingerprint.
    let pair = listed(&a, alice, bob).unwrap_or_else(|| panic!("alice–bob not listed: {a:#?}"));
    assert!(pair.score > 0.8, "{pair:?}");
    assert!(pair.regions.len() > 5 && pair.lines_a > 100, "{pair:?}");
    assert!(pair.regions.iter().any(|r| r.module_a == "s" && r.module_b == "s"));
    assert_eq!(a.clusters, [vec![alice, bob]]);
    assert_eq!(pair.cluster, Some(1));

    // Untouched stubs share nothing once the stubs are base code.
    assert_eq!(a.fingerprints[frank], 0);
    assert_eq!(a.fingerprints[grace], 0);
    assert!(a.pairs.iter().chain(&a.near).all(|p| ![p.a, p.b].contains(&frank)), "{a:#?}");
    // Without the base, they would be the closest pair of all.
    let unbased = analyse(&class, &BTreeMap::new(), Settings::default());
    assert!(listed(&unbased, frank, grace).is_some_and(|p| p.score > 0.99));

    // Heidi wrote her a1 herself: close to no one.
    assert!(a.fingerprints[heidi] > 20, "{:?}", a.fingerprints);
    for p in a.pairs.iter().chain(&a.near) {
        if p.a == heidi || p.b == heidi {
            assert!(p.score < 0.25, "{p:?}");
        }
    }
    assert!(a.pairs.iter().all(|p| p.a != heidi && p.b != heidi));
    assert_eq!(a.pairs.len(), 1, "{:#?}", a.pairs);

    // The files: the CSV read back, the page with both sides highlighted.
    let out = dir.with_extension("out");
    cg_similarity::output::write(&out, &class, &a, Lang::En).unwrap();
    // UTF-8 after the byte-order mark that Excel on Japanese Windows needs; CSV readers skip it.
    assert!(std::fs::read(out.join("similarity.csv")).unwrap().starts_with(b"\xef\xbb\xbfkind,"));
    let mut csv = csv::Reader::from_path(out.join("similarity.csv")).unwrap();
    assert_eq!(&csv.headers().unwrap()[0], "kind");
    let rows: Vec<csv::StringRecord> = csv.records().map(Result::unwrap).collect();
    let pair_rows: Vec<&csv::StringRecord> = rows.iter().filter(|r| &r[0] == "pair").collect();
    assert_eq!(pair_rows.len(), 1);
    assert_eq!((&pair_rows[0][2], &pair_rows[0][4]), (ALICE, BOB));
    assert_eq!(&pair_rows[0][9], "1");
    let html = std::fs::read_to_string(out.join("similarity.html")).unwrap();
    assert!(html.contains("id=\"pair-1\"") && html.contains("class=\"l r0\""), "regions");
    assert!(
        html.contains("Numbers from another student&#39;s variant")
            || html.contains("Numbers from another student's variant")
    );
    let ja = cg_similarity::html::page(&class, &a, Lang::Ja);
    assert!(ja.contains("しきい値以上の組"));
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_dir_all(dir.with_extension("reports"));
}

#[test]
fn numbers_from_another_students_variant_are_flagged_with_whose() {
    if !has_solutions() {
        return;
    }
    let dir = temp("cross");
    let class = class(&dir);
    let a = analyse(&class, &stubs(), Settings::default());
    let [carol, dave] = ["carol", "dave"].map(|n| index(&class, n));
    // Dave's code is his own form (no code pair with carol) …
    assert!(listed(&a, carol, dave).is_none(), "{a:#?}");
    // … but its numbers, and his report's, are carol's.
    let found: Vec<(&str, String)> = a
        .cross
        .iter()
        .map(|c| (class[c.submission].name.as_str(), c.finding.part.clone()))
        .collect();
    assert_eq!(
        found,
        [("dave", "a1".to_owned()), ("dave", "report:a1".to_owned())],
        "{:#?}",
        a.cross
    );
    for c in &a.cross {
        assert_eq!(c.finding.matches, number(CAROL));
        assert_eq!(c.sources, [carol]);
        assert!(c.finding.numbers.len() >= 3);
    }
    // Alice's report (her own numbers) and carol's own hand-written vertices are not flagged.
    let s = &class[a.cross[0].submission];
    let note = cg_similarity::output::cross_note(&a.cross[0], s, Lang::En);
    assert!(note.contains(CAROL) && note.contains("exercises/src/a1.rs"), "{note}");
    // The report's note names the --reports file it was read from.
    let note = cg_similarity::output::cross_note(&a.cross[1], s, Lang::En);
    assert!(note.contains(&format!("report-{DAVE}.md)")), "{note}");
    let csv = cg_similarity::output::csv_text(&class, &a, Lang::Ja).unwrap();
    assert!(
        csv.lines().any(|l| l.starts_with(&format!("cross-variant,dave,{DAVE},carol,{CAROL},"))),
        "{csv}"
    );
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(dir.with_extension("reports"));
}

#[test]
fn references_are_compared_with_this_year_but_not_with_each_other() {
    if !has_solutions() {
        return;
    }
    let dir = temp("refs");
    let (now, before) = (dir.join("now"), dir.join("before"));
    std::fs::create_dir_all(&now).unwrap();
    std::fs::create_dir_all(&before).unwrap();
    folder(&now, "ivan", "20260011", &all(solution));
    folder(&now, "judy", "20260012", &all(stub));
    // Two earlier submissions, the same as each other and as ivan's.
    folder(&before, "old1", "20250001", &all(solution));
    folder(&before, "old2", "20250002", &all(solution));
    let mut class = read::class(&now, false).unwrap();
    class.extend(read::class(&before, true).unwrap());
    let a = analyse(&class, &stubs(), Settings::default());
    let [ivan, old1, old2] = ["ivan", "old1", "old2"].map(|n| index(&class, n));
    assert!(listed(&a, ivan, old1).is_some() && listed(&a, ivan, old2).is_some(), "{a:#?}");
    assert!(
        a.pairs.iter().chain(&a.near).all(|p| (p.a, p.b) != (old1.min(old2), old1.max(old2))),
        "two references were compared: {a:#?}"
    );
    // Joined through ivan, they are one cluster.
    assert_eq!(a.clusters, [vec![ivan, old1, old2]]);
    assert!(a.mostly_common.is_empty(), "{:?}", a.mostly_common);
    let csv = cg_similarity::output::csv_text(&class, &a, Lang::En).unwrap();
    assert!(
        csv.lines().filter(|l| l.starts_with("pair,")).all(|l| l.contains("reference")),
        "{csv}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Names a student controls (a folder's or zip's name, a Moodle full name) that begin like a
/// spreadsheet formula reach similarity.csv as text (a leading `'`), never as a formula the
/// instructor's spreadsheet would run.
#[test]
fn names_that_look_like_formulas_are_text_in_the_csv() {
    if !has_solutions() {
        return;
    }
    let dir = temp("formulas");
    std::fs::create_dir_all(&dir).unwrap();
    folder(&dir, "=HYPERLINK(\"http:__evil\",\"x\")", "20260021", &all(solution));
    folder(&dir, "+1+2", "20260022", &all(solution));
    let class = read::class(&dir, false).unwrap();
    let a = analyse(&class, &stubs(), Settings::default());
    let csv = cg_similarity::output::csv_text(&class, &a, Lang::En).unwrap();
    let pair = csv.lines().find(|l| l.starts_with("pair,")).expect("the pair is listed");
    let cells: Vec<&str> = pair.split(',').collect();
    assert_eq!(cells[1], "'+1+2", "{pair}");
    assert!(cells[3].starts_with("\"'=HYPERLINK("), "{pair}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A ring of 21 copies lists all 210 pairs, but shows only the first MAX_DETAILED side by side
/// (200 copies once made a page of 5 GB), and says so.
#[test]
fn the_page_shows_at_most_its_limit_of_pairs_side_by_side() {
    if !has_solutions() {
        return;
    }
    let dir = temp("ring");
    std::fs::create_dir_all(&dir).unwrap();
    for k in 0..21 {
        folder(&dir, &format!("s{k:02}"), &format!("202600{k:02}"), &all(solution));
    }
    let class = read::class(&dir, false).unwrap();
    let settings = Settings { max_share: 100, ..Settings::default() };
    let a = analyse(&class, &stubs(), settings);
    assert_eq!(a.pairs.len(), 210);
    let page = cg_similarity::html::page(&class, &a, Lang::En);
    let shown = page.matches("<h3 id=\"pair-").count();
    assert_eq!(shown, cg_similarity::html::MAX_DETAILED);
    assert!(page.contains("the other 10 pairs are not shown side by side"), "the note");
    assert!(!page.contains("href=\"#pair-201\""), "no link to a pair not shown");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Eleven copies of one submission share every fingerprint with more than --max-share (10)
/// submissions, so no pair shows them: they are named as mostly common code instead of
/// disappearing without a word; ten copies are pairs, and named so.
#[test]
fn a_ring_of_more_copies_than_max_share_is_named_not_lost() {
    if !has_solutions() {
        return;
    }
    let dir = temp("ring11");
    std::fs::create_dir_all(&dir).unwrap();
    for k in 0..11 {
        folder(&dir, &format!("s{k:02}"), &format!("202601{k:02}"), &all(solution));
    }
    folder(&dir, "own", "20260199", &all(stub));
    let class = read::class(&dir, false).unwrap();
    let a = analyse(&class, &stubs(), Settings::default());
    assert!(a.pairs.is_empty(), "{:?}", a.pairs.len());
    let names: Vec<&str> = a.mostly_common.iter().map(|&i| class[i].name.as_str()).collect();
    assert_eq!(names.len(), 11, "{names:?}");
    assert!(!names.contains(&"own"));
    // With a --max-share above the ring, they are pairs again and not "mostly common".
    let a = analyse(&class, &stubs(), Settings { max_share: 20, ..Settings::default() });
    assert_eq!(a.pairs.len(), 55);
    assert!(a.mostly_common.is_empty());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Two entries with one student number (a resubmission) are listed, and said to be so in the
/// CSV's flags: student.toml is the student's to write, so skipping such pairs would hide a copy
/// behind another's number.
#[test]
fn a_pair_with_one_student_number_is_listed_and_flagged() {
    if !has_solutions() {
        return;
    }
    let dir = temp("same-number");
    std::fs::create_dir_all(&dir).unwrap();
    folder(&dir, "first", "20260031", &all(solution));
    folder(&dir, "again", "20260031", &all(solution));
    folder(&dir, "other", "20260032", &all(stub));
    let class = read::class(&dir, false).unwrap();
    let a = analyse(&class, &stubs(), Settings::default());
    let csv = cg_similarity::output::csv_text(&class, &a, Lang::En).unwrap();
    let pair = csv.lines().find(|l| l.starts_with("pair,")).expect("the pair is listed");
    assert!(pair.contains("same-number"), "{pair}");
    let _ = std::fs::remove_dir_all(&dir);
}
