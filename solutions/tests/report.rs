//! The report checker end to end, with a correct student (the reference solutions): the filled
//! template reads back and verifies clean (the shading section's tables with the student's
//! functions' output included); planted mistakes are named, exactly those; the filled LaTeX
//! compiles where LuaLaTeX is installed (always in CI).

use std::path::{Path, PathBuf};
use std::process::Command;

use cg_assign::Impls;
use cg_assign::Variants;
use cg_core::lang::{Lang, t};
use cg_harness::{StudentNumber, TableVersion};
use cg_report::app::{self, DeriveArgs, FillArgs, Kit, Source};
use cg_report::derive;
use cg_report::fill::{self, Context};
use cg_report::parse;
use cg_report::template::{self, Format};
use cg_report::verify;

const STUDENTS: [&str; 4] = ["20250000", "20250003", "20250017", "12345678"];

fn impls() -> Impls {
    cg_assign::impls!(cg_solutions)
}

fn kit() -> Kit {
    Kit {
        impls: impls(),
        student_file: || PathBuf::from("/nonexistent/student.toml"),
        worker: None,
        time_limit: app::TIME_LIMIT,
    }
}

fn assignment(student: &str) -> Variants {
    let n: StudentNumber = student.parse().unwrap();
    Variants::for_student(&n, TableVersion::DEFAULT)
}

/// The filled Markdown report of a correct student, with its derived data: as `cg report fill`
/// writes it, each assignment's own text quoted in it.
fn filled(student: &str, lang: Lang) -> (String, cg_report::model::Derived) {
    filled_in(student, lang, Format::Markdown)
}

/// [`filled`] in `format`.
fn filled_in(student: &str, lang: Lang, format: Format) -> (String, cg_report::model::Derived) {
    let a = assignment(student);
    let (derived, missing) = derive::derive(&a, &impls());
    assert!(missing.is_empty(), "{student}: the solutions derive everything: {missing:?}");
    let assignments = cg_assign::Which::ALL
        .iter()
        .filter(|w| w.in_report())
        .map(|&w| (w.id().to_owned(), a.describe_one(w, lang)))
        .collect();
    let ctx = Context {
        student: Some(student.to_owned()),
        assignments,
        variants: Some(a),
        ..Context::default()
    };
    let text = template::fill(
        template::template(lang, format),
        &fill::values(&derived, &ctx, lang, format),
    )
    .unwrap();
    (text, derived)
}

/// The report checked as `cg report check` does: against the derived data and the assignment.
fn check(
    student: &str,
    parsed: &parse::ParsedReport,
    derived: &cg_report::model::Derived,
) -> verify::Verification {
    verify::verify_with(parsed, derived, Some(&assignment(student)))
}

fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cg-report-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_filled_report_reads_back_and_every_number_follows_from_the_data() {
    for student in STUDENTS {
        for lang in [Lang::Ja, Lang::En] {
            let (text, derived) = filled(student, lang);
            let (parsed, problems) = parse::parse_report(&text);
            assert!(problems.is_empty(), "{student} {lang}: {problems:?}");
            // a4.t3: the solution's sampler, clamped both ways (the figure's line, not parsed).
            let wrap = t(
                "折り返し: s 方向 GL_CLAMP_TO_EDGE (Wrap::Clamp)、t 方向 GL_CLAMP_TO_EDGE",
                "Wrap: GL_CLAMP_TO_EDGE (Wrap::Clamp) along s, GL_CLAMP_TO_EDGE",
            );
            let wrap = wrap.get(lang);
            assert!(text.contains(wrap), "{student} {lang}: no sampler line");
            let p = derived.a1.as_ref().unwrap();
            assert_eq!(parsed.vertices.len(), p.vertices.len(), "{student}: every vertex row read");
            assert_eq!(parsed.faces.len(), p.faces.len(), "{student}: every face row read");
            assert_eq!(parsed.tex.len(), 121, "{student}: every grid vertex read");
            // Each product and each of its factors (tagged `ID.factors`).
            let with_factors = |m: &cg_core::product::MatrixProduct| {
                1 + cg_report::tables::factor_matrices(m).len()
            };
            let transform = p.transform.as_ref().map_or(0, with_factors);
            let camera: usize = derived
                .a2
                .as_ref()
                .unwrap()
                .matrices
                .iter()
                .map(|m| with_factors(&m.numeric))
                .sum();
            let animation: usize = derived
                .a3
                .as_ref()
                .unwrap()
                .objects
                .iter()
                .flat_map(|o| &o.1)
                .map(|m| with_factors(&m.numeric))
                .sum();
            assert!(
                camera > derived.a2.as_ref().unwrap().matrices.len(),
                "{student}: factors read"
            );
            assert_eq!(
                parsed.matrices.len(),
                transform + camera + animation,
                "{student}: a1.transform, each view matrix and each model matrix read, with their factors"
            );
            // The shading section: its six tables, each function's output filled in beside the
            // kit's (the point P given); the ✍ cells are the student's to write.
            // The periods of a3 in the same notation, before them.
            let ids: Vec<&str> = parsed.tables.iter().map(|t| t.id.as_str()).collect();
            assert_eq!(ids[0], cg_report::periods::TABLE_ID, "{student} {lang}");
            assert_eq!(ids[1..], cg_assign::cg_shading::report::TABLE_IDS, "{student} {lang}");
            let shading = shading_numbers(derived.s.as_ref().unwrap());
            assert!(shading > 40, "{student}: {shading} numbers of the student's functions");
            // The texture formula in i and j, both equations read.
            assert_eq!(parsed.formulas.len(), 1, "{student} {lang}");
            let formula = &parsed.formulas[0];
            for name in ['s', 't'] {
                let eq = formula.equation(name);
                assert!(eq.is_some_and(|e| e.expr.is_ok()), "{student} {lang}: {formula:?}");
            }
            let v = check(student, &parsed, &derived);
            assert!(v.findings.is_empty(), "{student} {lang}: {:#?}", v.findings);
            let notes: Vec<&str> = v.notes.iter().map(|n| n.en.as_str()).collect();
            assert!(notes.is_empty(), "{student} {lang}: {notes:?}");
            let periods = derived.a3.as_ref().unwrap().objects.len() + 1;
            let least = p.vertices.len() * 3
                + p.faces.len() * 3
                + 16 * parsed.matrices.len()
                + 121 * 5
                + 6
                + shading
                + periods
                + 2;
            assert!(
                v.checked >= least,
                "{student}: {} numbers checked, at least {least}",
                v.checked
            );
        }
    }
}

/// How many numbers the filled shading tables hold from the student's functions.
fn shading_numbers(data: &cg_assign::cg_shading::report::ShadingData) -> usize {
    use cg_assign::cg_shading::report::{Cell, Value};
    data.tables()
        .iter()
        .flat_map(|t| &t.rows)
        .flat_map(|r| &r.cells)
        .map(|c| match c {
            Cell::Yours { yours: Ok(Value::Number(_)), .. } => 1,
            Cell::Yours { yours: Ok(Value::Vector(_) | Value::Color(_)), .. } => 3,
            _ => 0,
        })
        .sum()
}

/// Replaces the first occurrence of `from` after `anchor` on the line that starts with
/// `line_start`.
fn plant(text: &str, line_start: &str, from: &str, to: &str) -> (String, usize) {
    let mut out = Vec::new();
    let mut at = 0;
    for (i, line) in text.lines().enumerate() {
        if at == 0 && line.trim_start().starts_with(line_start) && line.contains(from) {
            let k = line.rfind(from).unwrap();
            out.push(format!("{}{to}{}", &line[..k], &line[k + from.len()..]));
            at = i + 1;
        } else {
            out.push(line.to_owned());
        }
    }
    assert!(at > 0, "no line starting with {line_start:?} containing {from:?}");
    (out.join("\n"), at)
}

/// `text` with cell `k` (split at `sep`) of the first line that starts with `line_start`
/// replaced by `to` of what it holds (trimmed); and the line.
fn edit_cell(
    text: &str,
    line_start: &str,
    sep: char,
    k: usize,
    to: impl Fn(&str) -> String,
) -> (String, usize) {
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    let at = lines.iter().position(|l| l.starts_with(line_start)).unwrap();
    let mut cells: Vec<String> = lines[at].split(sep).map(str::to_owned).collect();
    cells[k] = format!(" {} ", to(cells[k].trim()));
    lines[at] = cells.join(&sep.to_string());
    (lines.join("\n"), at + 1)
}

fn tuple_text(s: &str) -> Vec<f64> {
    s.split(',').map(|x| x.trim().parse::<f64>().unwrap()).collect()
}

#[test]
fn planted_mistakes_are_named_exactly_and_nothing_else() {
    for student in STUDENTS {
        let (text, derived) = filled(student, Lang::En);
        let p = derived.a1.as_ref().unwrap();

        // 1. A wrong normal: F1's normal, its first component moved by 0.2.
        let line = text.lines().find(|l| l.starts_with("| F1 |")).unwrap().to_owned();
        let normal = line.rsplit('{').next().unwrap().split('}').next().unwrap().to_owned();
        let mut n = tuple_text(&normal);
        n[0] += 0.2;
        let wrong = format!(" {:.3}, {:.3}, {:.3} ", n[0], n[1], n[2]);
        let (text, normal_line) = plant(&text, "| F1 |", &normal, &wrong);

        // 2. Swapped vertex order: F2 { Va, Vb, Vc } written { Va, Vc, Vb }.
        let [a, b, c] = p.faces[2];
        let (text, order_line) = plant(
            &text,
            "| F2 |",
            &format!("{{ V{a}, V{b}, V{c} }}"),
            &format!("{{ V{a}, V{c}, V{b} }}"),
        );

        // 3. A wrong matrix entry: the first view matrix, row 1 column 4 (the x translation).
        let id = derived.a2.as_ref().unwrap().matrices[0].id.clone();
        let tag = format!("<!-- cg: {id} -->");
        let lines: Vec<&str> = text.lines().collect();
        let tag_at = lines.iter().position(|l| l.contains(&tag)).unwrap();
        // The tagged matrix's first row: after the first `\begin{pmatrix}` following the tag,
        // up to the first `\\`; its last entry is row 1, column 4.
        let row_at = tag_at + lines[tag_at..].iter().position(|l| l.contains('&')).unwrap();
        let row = lines[row_at];
        let begin = row.find("\\begin{pmatrix}").map_or(0, |k| k + "\\begin{pmatrix}".len());
        let end = begin + row[begin..].find("\\\\").unwrap();
        let at = begin + row[begin..end].rfind('&').unwrap() + 1;
        let entry = row[at..end].trim().to_owned();
        let bumped = format!("{:.3}", entry.parse::<f64>().unwrap() + 1.0);
        let k = at + row[at..end].find(&entry).unwrap();
        let mut edited: Vec<String> = lines.iter().map(|l| (*l).to_owned()).collect();
        edited[row_at].replace_range(k..k + entry.len(), &bumped);
        let text = edited.join("\n");

        // 4. A wrong texture coordinate: grid vertex (3, 5), its first s moved by 0.25.
        let line = text.lines().find(|l| l.starts_with("| 3 | 5 |")).unwrap().to_owned();
        let tex = line.split('|').nth(4).unwrap().trim().to_owned();
        let first = tex.split('/').next().unwrap().trim().trim_matches(['(', ')']).to_owned();
        let st = tuple_text(&first);
        let moved = format!("{:.3}, {:.3}", (st[0] + 0.25) % 1.0 + 0.001, st[1]);
        let (text, tex_line) = plant(&text, "| 3 | 5 |", &first, &moved);

        // 5. A wrong number in a shading table: the attenuation at d = 5 (the student's
        // function's output, filled in) moved by 0.05, and one by hand at d = 10 written right.
        let line = text.lines().find(|l| l.starts_with("| d = 5 |")).unwrap().to_owned();
        let yours = line.split('|').nth(3).unwrap().trim().to_owned();
        let moved = format!("{:.3}", yours.parse::<f64>().unwrap() + 0.05);
        let (text, shading_line) = plant(&text, "| d = 5 |", &yours, &moved);
        let line = text.lines().find(|l| l.starts_with("| d = 10 |")).unwrap().to_owned();
        let at_10 = line.split('|').nth(3).unwrap().trim().to_owned();
        let (text, _) =
            plant(&text, "| d = 10 |", "✍", &format!("1/(kc + 10·kl + 100·kq) = {at_10}"));

        // 6. A wrong period: object 2's, one second more.
        let (text, period_line) = edit_cell(&text, "| object 2 |", '|', 3, |p| {
            format!("{} s", p.parse::<f64>().unwrap() + 1.0)
        });

        // 7. A wrong texture formula: s moved by 0.1 everywhere.
        let (text, formula_line) = plant(&text, "s &= ", " \\\\", " + 0.1 \\\\");

        let (parsed, problems) = parse::parse_report(&text);
        assert!(problems.is_empty(), "{student}: {problems:?}");
        let v = check(student, &parsed, &derived);
        let mut found: Vec<(usize, String)> =
            v.findings.iter().map(|f| (f.line, f.item.clone())).collect();
        found.sort();
        let matrix_item = v.findings.iter().find(|f| f.item.starts_with(&id));
        assert_eq!(
            v.findings.len(),
            7,
            "{student}: exactly the seven planted mistakes: {found:#?}"
        );
        assert!(
            found.contains(&(period_line, "a3.periods object 2 (column 3)".to_owned())),
            "{student}: {found:?}"
        );
        assert!(
            found.contains(&(formula_line, "a4.formula s at (0, 0)".to_owned())),
            "{student}: {found:?}"
        );
        assert!(
            found.contains(&(shading_line, "s.attenuation d = 5 (column 3)".to_owned())),
            "{student}: {found:?}"
        );
        assert!(found.contains(&(normal_line, "F1 normal".to_owned())), "{student}: {found:?}");
        assert!(found.contains(&(order_line, "F2 order".to_owned())), "{student}: {found:?}");
        assert!(
            matrix_item.is_some_and(|f| f.item.contains("row 1") && f.item.contains("column 4")),
            "{student}: {found:?}"
        );
        assert!(
            found.iter().any(|(l, i)| *l == tex_line && i.starts_with("tex (3, 5)")),
            "{student}: {found:?}"
        );
        // Each says what it derived and how far off a number may be.
        for f in &v.findings {
            let m = f.message(Lang::En);
            assert!(m.contains(&f.derived), "{m}");
            assert!(!f.message(Lang::Ja).is_empty());
        }
        let normal = v.findings.iter().find(|f| f.item == "F1 normal").unwrap();
        assert!(normal.tolerance.is_some_and(|t| t > 0.0 && t <= 0.01), "{normal:?}");
    }
}

#[test]
fn a_filled_latex_report_checks_clean_too() {
    for student in STUDENTS {
        for lang in [Lang::Ja, Lang::En] {
            let (text, derived) = filled_in(student, lang, Format::Latex);
            let (parsed, _) = parse::parse_report(&text);
            assert_eq!(parsed.formulas.len(), 1, "{student} {lang}");
            assert!(parsed.tables.iter().any(|t| t.id == cg_report::periods::TABLE_ID));
            let v = check(student, &parsed, &derived);
            assert!(v.findings.is_empty(), "{student} {lang}: {:#?}", v.findings);
            let notes: Vec<&str> = v
                .notes
                .iter()
                .map(|n| n.en.as_str())
                .filter(|n| n.contains("a3.periods") || n.contains("a4.formula"))
                .collect();
            assert!(notes.is_empty(), "{student} {lang}: {notes:?}");
            // A wrong period and a wrong formula are named in LaTeX too.
            let object = t("物体2 &", "object 2 &");
            let object = object.get(lang);
            let (text, period_line) = edit_cell(&text, object, '&', 2, |p| {
                format!("${}$", p.trim_matches('$').parse::<f64>().unwrap() + 1.0)
            });
            let (text, formula_line) = plant(&text, "t &= ", "t &= ", "t &= 0.1 + ");
            let (parsed, problems) = parse::parse_report(&text);
            assert!(problems.is_empty(), "{student}: {problems:?}");
            let v = check(student, &parsed, &derived);
            let items: Vec<(usize, &str)> =
                v.findings.iter().map(|f| (f.line, f.item.as_str())).collect();
            let label = t("物体2", "object 2");
            let period_item = format!("a3.periods {} (column 3)", label.get(lang));
            assert_eq!(
                items,
                [(period_line, period_item.as_str()), (formula_line, "a4.formula t at (0, 0)")],
                "{student} {lang}"
            );
        }
    }
}

fn lualatex() -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path).map(|d| d.join("lualatex")).find(|p| p.is_file())
}

#[test]
fn the_filled_latex_report_compiles() {
    let Some(lualatex) = lualatex() else {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI installs TeX Live (scripts/setup.sh): lualatex must be on PATH"
        );
        eprintln!("note: lualatex is not installed; the LaTeX compile test is skipped");
        return;
    };
    for lang in [Lang::Ja, Lang::En] {
        let dir = scratch(&format!("latex-{lang}"));
        let args = FillArgs {
            derive: DeriveArgs {
                source: Source { student: Some(STUDENTS[1].to_owned()), ..Source::default() },
                output: dir.clone(),
                no_render: false,
            },
            force: false,
        };
        let written = app::fill_to(&args, &kit(), lang).unwrap();
        assert!(written.missing.is_empty(), "{:?}", written.missing);
        for name in [
            "report.tex",
            "report.md",
            "render-a1.png",
            "a1-front.svg",
            "a4-texture.png",
            "render-s.png",
        ] {
            assert!(dir.join(name).is_file(), "{name} written");
        }
        let out = Command::new(&lualatex)
            .args(["-interaction=nonstopmode", "-halt-on-error", "report.tex"])
            .current_dir(&dir)
            .output()
            .unwrap();
        let log = std::fs::read_to_string(dir.join("report.log")).unwrap_or_default();
        assert!(
            out.status.success() && dir.join("report.pdf").is_file(),
            "{lang}: lualatex failed:\n{}\n… {}",
            String::from_utf8_lossy(&out.stdout),
            &log[log.len().saturating_sub(3000)..]
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}

#[test]
fn fill_keeps_a_report_the_student_has_edited() {
    let dir = scratch("keep");
    let args = FillArgs {
        derive: DeriveArgs {
            source: Source { student: Some(STUDENTS[0].to_owned()), ..Source::default() },
            output: dir.clone(),
            no_render: true,
        },
        force: false,
    };
    std::fs::write(dir.join("report.md"), "my own words").unwrap();
    let written = app::fill_to(&args, &kit(), Lang::En).unwrap();
    assert_eq!(written.kept, ["report.md"]);
    assert_eq!(std::fs::read_to_string(dir.join("report.md")).unwrap(), "my own words");
    assert!(dir.join("report.tex").is_file());
    let forced = app::fill_to(&FillArgs { force: true, ..args }, &kit(), Lang::En).unwrap();
    assert!(forced.kept.is_empty());
    assert!(std::fs::read_to_string(dir.join("report.md")).unwrap().contains("| V0 |"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_runs_on_a_report_file_and_names_the_line() {
    let dir = scratch("check");
    let (text, _) = filled(STUDENTS[2], Lang::Ja);
    let report = dir.join("report.md");
    std::fs::write(&report, &text).unwrap();
    let args = app::CheckArgs {
        report: Some(report.clone()),
        source: Source { student: Some(STUDENTS[2].to_owned()), ..Source::default() },
        json: false,
    };
    let clean = app::check(&args, &kit(), Lang::Ja).unwrap();
    assert!(clean.ok(), "{}", clean.render(Lang::Ja));
    // A face row that does not parse: the line and what was expected.
    let (broken, line) = plant(&text, "| F0 |", "}", "");
    std::fs::write(&report, broken).unwrap();
    let out = app::check(&args, &kit(), Lang::En).unwrap();
    assert!(!out.ok());
    assert_eq!(out.problems.len(), 1, "{}", out.render(Lang::En));
    assert_eq!(out.problems[0].line, line);
    assert!(out.render(Lang::En).contains(&format!("line {line}")), "{}", out.render(Lang::En));
    let _ = std::fs::remove_dir_all(&dir);
    let _: &Path = &dir;
}

/// The filled LaTeX report, in both languages, fits its page: LuaLaTeX reports no line, table or
/// figure wider than the text (an `Overfull \hbox` over 1 pt). The pictures are left out (each
/// `\includegraphics` becomes a box): their width is the template's. Where LuaLaTeX is not
/// installed this passes with a note; CI installs it.
#[test]
fn the_filled_latex_report_fits_the_page_in_both_languages() {
    let found = std::process::Command::new("lualatex")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        assert!(std::env::var_os("CI").is_none(), "CI installs LuaLaTeX (scripts/setup.sh)");
        eprintln!("note: lualatex is not on PATH; the page width is not checked here");
        return;
    }
    let student = STUDENTS[0];
    let a = assignment(student);
    let (derived, _) = derive::derive(&a, &impls());
    let ctx =
        Context { student: Some(student.to_owned()), variants: Some(a), ..Context::default() };
    for lang in [Lang::En, Lang::Ja] {
        let text = template::fill(
            template::template(lang, Format::Latex),
            &fill::values(&derived, &ctx, lang, Format::Latex),
        )
        .unwrap();
        let mut tex = String::new();
        let mut rest = text.as_str();
        while let Some(at) = rest.find("\\includegraphics") {
            tex.push_str(&rest[..at]);
            let after = &rest[at..];
            let end = after.find('}').map_or(after.len(), |e| e + 1);
            tex.push_str("\\fbox{image}");
            rest = &after[end..];
        }
        tex.push_str(rest);
        let dir = scratch(&format!("width-{lang}"));
        std::fs::write(dir.join("report.tex"), tex).unwrap();
        let out = std::process::Command::new("lualatex")
            .args(["-interaction=nonstopmode", "-halt-on-error", "report.tex"])
            .current_dir(&dir)
            .output()
            .unwrap();
        let log = std::fs::read_to_string(dir.join("report.log")).unwrap_or_default();
        assert!(
            out.status.success(),
            "{lang}: lualatex failed:\n{}",
            &log[log.len().saturating_sub(3000)..]
        );
        let wide: Vec<&str> = log
            .lines()
            .filter(|l| l.starts_with("Overfull \\hbox ("))
            .filter(|l| {
                l["Overfull \\hbox (".len()..]
                    .split("pt")
                    .next()
                    .and_then(|n| n.parse::<f64>().ok())
                    .is_some_and(|pt| pt > 1.0)
            })
            .collect();
        assert!(wide.is_empty(), "{lang}: wider than the page:\n{}", wide.join("\n"));
    }
}

/// With `--data`, the report is still the student's: the student number recorded in
/// `exercises/student.toml` fills the `student` placeholder (it said "not set: cg assignment
/// --save" beside a recorded number); with none recorded, it says so.
#[test]
fn a_data_files_report_keeps_the_recorded_student_number() {
    fn recorded() -> PathBuf {
        std::env::temp_dir().join(format!("cg-report-data-student-{}", std::process::id()))
    }
    let dir = recorded();
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("student.toml"), "student = \"20250017\"\ntable = 1\n").unwrap();
    let kit = Kit { student_file: || recorded().join("student.toml"), ..self::kit() };
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/report/lecture-pyramid.md");
    let source = Source { student: None, table: None, data: Some(data), encoding: None };
    let gathered = app::gather(&source, &kit, Lang::En).unwrap();
    assert_eq!(gathered.context.student.as_deref(), Some("20250017"));
    assert_eq!(gathered.context.table.as_deref(), Some("1"));
    let gathered = app::gather(&source, &self::kit(), Lang::En).unwrap();
    assert_eq!(gathered.context.student, None, "nothing recorded");
    std::fs::remove_dir_all(&dir).ok();
}

/// `report fill --no-render`: the places of the rendered images say that drawing was turned off
/// (they said "not derived yet: a2" of a correct student), and each fragment ends its line.
#[test]
fn no_render_says_the_images_are_not_drawn_not_that_they_are_not_derived() {
    for lang in [Lang::Ja, Lang::En] {
        let dir = scratch(&format!("no-render-{lang}"));
        let args = FillArgs {
            derive: DeriveArgs {
                source: Source { student: Some(STUDENTS[2].to_owned()), ..Source::default() },
                output: dir.clone(),
                no_render: true,
            },
            force: false,
        };
        let written = app::fill_to(&args, &kit(), lang).unwrap();
        assert!(written.missing.is_empty(), "{:?}", written.missing);
        let said = t("（描いていません: --no-render）", "(not drawn: --no-render)");
        let said = said.get(lang);
        for id in ["a1", "a2", "a3", "a4", "s"] {
            let md =
                std::fs::read_to_string(dir.join(format!("fragments/{id}.render.md"))).unwrap();
            assert_eq!(md, format!("> {said}\n"), "{lang} {id}");
            let tex =
                std::fs::read_to_string(dir.join(format!("fragments/{id}.render.tex"))).unwrap();
            assert!(tex.ends_with('\n') && tex.contains("-{}-no-render"), "{lang} {id}: {tex:?}");
        }
        let report = std::fs::read_to_string(dir.join("report.md")).unwrap();
        assert!(report.contains(said), "{lang}");
        for name in written.files.iter().filter(|f| f.starts_with("fragments/")) {
            let text = std::fs::read_to_string(dir.join(name)).unwrap();
            assert!(text.ends_with('\n'), "{lang} {name}: {text:?}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// a4's sampler (a4.t3) needs nothing of a4.t1 and a4.t2: with texture coordinates that are not
/// finite, its fragment still shows the student's sampler (it said "not derived yet: a4.t2: …
/// not finite"); with a sampler not written either, it says that of the sampler.
#[test]
fn the_sampler_fragment_needs_only_the_sampler() {
    let mut impls = impls();
    impls.a4.tex_coords = |_, _, _| [cg_student::glam::Vec2::NAN; 4];
    let source = Source { student: Some(STUDENTS[0].to_owned()), ..Source::default() };
    let g = app::gather(&source, &Kit { impls, ..kit() }, Lang::En).unwrap();
    assert!(g.derived.a4.is_none());
    let tasks: Vec<&str> = g.context.missing.iter().map(|m| m.task.as_str()).collect();
    assert_eq!(tasks, ["a4.t2"], "{:?}", g.context.missing);
    for (lang, format) in [(Lang::En, Format::Markdown), (Lang::Ja, Format::Latex)] {
        let values = fill::values(&g.derived, &g.context, lang, format);
        let sampler = &values["a4.sampler"];
        let wrap = t("GL\\_CLAMP\\_TO\\_EDGE (Wrap::Clamp)", "GL_CLAMP_TO_EDGE (Wrap::Clamp)");
        assert!(sampler.contains(wrap.get(lang)), "{lang}: {sampler}");
        assert!(!sampler.contains("a4.t2:"), "{lang}: {sampler}");
        // The rest of a4 is still not derived, and says why.
        assert!(values["a4.table"].contains("a4.t2"), "{lang}");
    }
    impls.a4.sampler = || panic!("no sampler yet");
    let g = app::gather(&source, &Kit { impls, ..kit() }, Lang::En).unwrap();
    let sampler = &fill::values(&g.derived, &g.context, Lang::En, Format::Markdown)["a4.sampler"];
    assert!(
        sampler.starts_with("> (not derived yet: a4.t3: sampler() panicked: no sampler yet"),
        "{sampler}"
    );
    assert!(!sampler.contains("a4.t2"), "{sampler}");
}
