//! The texture formula on two hand-made students of a4 (their coordinates from the formula the
//! assignment states): filled in both languages and formats, read back and checked clean; a
//! wrong formula, swapped s and t, a missing `mod` are named at the first wrong vertex; a
//! formula that does not read is a note with its line; the reader takes the usual notations.

use cg_assign::cg_a4::report::texture;
use cg_assign::cg_a4::{CORNER_STEPS, Impl, Region, Sampler, Spec, TexRange};
use cg_core::glam::Vec2;
use cg_core::lang::{Lang, t};

use super::*;
use crate::model::Derived;
use crate::parse::{line_of, parse_report};
use crate::template::Format;
use crate::verify::{Verification, verify};

fn range(_: &Spec) -> TexRange {
    TexRange { s_min: 0.25, s_max: 0.5, t_min: 0.375, t_max: 0.625 }
}

fn sampler() -> Sampler {
    Sampler::default()
}

/// C4–D5, upright, no repeat: s = 0.25 + 0.025·i, t = 0.625 − 0.025·j.
fn upright() -> Spec {
    let region = Region { column: 2, row: 3, columns: 2, rows: 2 };
    Spec { region, rotation_deg: 0, mirrored: false, repeat: 1 }
}

fn upright_coords(_: &Spec, i: u32, j: u32) -> [Vec2; 4] {
    CORNER_STEPS
        .map(|(di, dj)| Vec2::new(0.25 + 0.025 * (i + di) as f32, 0.625 - 0.025 * (j + dj) as f32))
}

/// The same region turned 90° counter-clockwise, 2 × 2 blocks of 5 squares:
/// s = 0.5 − 0.05·(j mod 5), t = 0.625 − 0.05·(i mod 5) (a block's own squares use p = 1, q = 1
/// at its far edges).
fn turned() -> Spec {
    Spec { rotation_deg: 90, repeat: 2, ..upright() }
}

fn turned_coords(_: &Spec, i: u32, j: u32) -> [Vec2; 4] {
    CORNER_STEPS.map(|(di, dj)| {
        let (p, q) = ((i % 5 + di) as f32 / 5.0, (j % 5 + dj) as f32 / 5.0);
        Vec2::new(0.5 - 0.25 * q, 0.625 - 0.25 * p)
    })
}

fn derived(turned_student: bool) -> Derived {
    let (spec, tex_coords) = if turned_student {
        (turned(), turned_coords as fn(&Spec, u32, u32) -> [Vec2; 4])
    } else {
        (upright(), upright_coords as fn(&Spec, u32, u32) -> [Vec2; 4])
    };
    let imp = Impl { tex_range: range, tex_coords, sampler };
    Derived { a4: Some(texture(&spec, &imp).unwrap()), ..Derived::default() }
}

fn filled(d: &Derived, lang: Lang, format: Format) -> String {
    format!("# 4\n\n{}\n# next\n", values(d.a4.as_ref().unwrap(), lang, format))
}

fn check(text: &str, d: &Derived) -> Verification {
    let (report, problems) = parse_report(text);
    assert!(problems.is_empty(), "{problems:?}");
    verify(&report, d)
}

fn items(v: &Verification) -> Vec<(usize, &str)> {
    v.findings.iter().map(|f| (f.line, f.item.as_str())).collect()
}

fn formula_notes(v: &Verification) -> Vec<&str> {
    v.notes.iter().map(|n| n.en.as_str()).filter(|n| n.contains("formula")).collect()
}

const CASES: [(Lang, Format); 4] = [
    (Lang::Ja, Format::Markdown),
    (Lang::En, Format::Markdown),
    (Lang::Ja, Format::Latex),
    (Lang::En, Format::Latex),
];

#[test]
fn the_filled_formula_reads_back_and_checks_clean() {
    for turned_student in [false, true] {
        let d = derived(turned_student);
        for (lang, format) in CASES {
            let text = filled(&d, lang, format);
            let (report, _) = parse_report(&text);
            assert_eq!(report.formulas.len(), 1, "{text}");
            let f = &report.formulas[0];
            assert!(f.equation('s').is_some_and(|e| e.expr.is_ok()), "{f:?}");
            assert!(f.equation('t').is_some_and(|e| e.expr.is_ok()), "{f:?}");
            let v = check(&text, &d);
            assert!(v.findings.is_empty(), "{lang} {format:?}: {:#?}\n{text}", v.findings);
            assert_eq!(formula_notes(&v), Vec::<&str>::new());
            assert_eq!(v.checked, 2, "s and t");
        }
    }
    // The formula is the assignment's, as its words state it.
    let text = filled(&derived(true), Lang::En, Format::Markdown);
    assert!(text.contains("s &= 0.5 - 0.05 \\cdot (j \\bmod 5) \\\\"), "{text}");
    assert!(text.contains("t &= 0.625 - 0.05 \\cdot (i \\bmod 5)"), "{text}");
}

/// With a repeat, the formula's mod reads as its divisor at a block's far edge: said after it,
/// with the ground's far corner from the table (read literally, the formula gives (0.5, 0.625)
/// there, the corner (0, 0)'s). Without a repeat nothing is said.
#[test]
fn a_formula_with_mod_says_how_it_reads_at_a_blocks_far_edge() {
    let corner = |d: &Derived| {
        let rows = &d.a4.as_ref().unwrap().rows;
        rows.iter().find(|r| (r.i, r.j) == (10, 10)).unwrap().tex.clone()
    };
    // turned_coords at square (9, 9)'s far corner: p = q = 1.
    assert_eq!(corner(&derived(true)), vec![Vec2::new(0.25, 0.375)]);
    for (lang, format) in CASES {
        let text = filled(&derived(true), lang, format);
        let said = t(
            "地面の角 (10, 10) は (s, t) = (0.250, 0.375)",
            "(10, 10), for example, has (s, t) = (0.250, 0.375)",
        );
        assert!(text.contains(said.get(lang)), "{lang} {format:?}: {text}");
        // Plain text in both formats: no `%` (a LaTeX comment) and no backquotes.
        let line = text.lines().find(|l| l.contains("(10, 10)")).unwrap();
        assert!(!line.contains(['%', '`']), "{line}");
        let plain = filled(&derived(false), lang, format);
        assert!(!plain.contains("(10, 10)"), "{lang} {format:?}: {plain}");
    }
}

#[test]
fn a_wrong_formula_is_named_at_its_first_wrong_vertex() {
    let d = derived(false);
    for (lang, format) in CASES {
        let text = filled(&d, lang, format).replace("0.025 \\cdot i", "i/20");
        let v = check(&text, &d);
        let line = line_of(&text, "s &= 0.25 + i/20");
        assert_eq!(items(&v), [(line, "a4.formula s at (1, 0)")], "{lang} {format:?}");
        let f = &v.findings[0];
        assert_eq!((f.written.as_str(), f.derived.as_str()), ("s(1, 0) = 0.3", "0.275"));
        assert_eq!(f.tolerance, Some(check::TOLERANCE));
        assert!(f.why.en.contains("wrong at 110 of the 121 grid vertices"), "{}", f.why.en);
        assert!(f.why.en.contains("the formula `s = 0.25 + i/20` gives"), "{}", f.why.en);
        assert!(f.why.ja.contains("式 `s = 0.25 + i/20` は格子点"), "{}", f.why.ja);
        let m = f.message(lang);
        let item = t("a4.formula s（格子点 (1, 0)）", "a4.formula s at (1, 0)");
        assert!(m.contains(item.get(lang)), "{m}");
    }
    // A wrong t alone: named at the first vertex.
    let text = filled(&d, Lang::En, Format::Markdown).replace("0.625 - 0.025", "0.6 - 0.025");
    let v = check(&text, &d);
    assert_eq!(items(&v), [(line_of(&text, "t &="), "a4.formula t at (0, 0)")]);
}

#[test]
fn swapped_s_and_t_are_named_as_such() {
    let d = derived(false);
    for (lang, format) in CASES {
        let text = filled(&d, lang, format)
            .replace("s &= 0.25 + 0.025 \\cdot i", "s &= 0.625 - 0.025 \\cdot j")
            .replacen("t &= 0.625 - 0.025 \\cdot j", "t &= 0.25 + 0.025 \\cdot i", 1);
        let v = check(&text, &d);
        assert_eq!(items(&v), [(line_of(&text, "s &="), "a4.formula s, t")], "{lang} {format:?}");
        assert!(v.findings[0].why.en.starts_with("s and t are swapped"));
        assert!(v.findings[0].why.ja.starts_with("s と t が入れ替わっています"));
    }
}

#[test]
fn a_missing_mod_is_named_where_the_second_block_starts() {
    let d = derived(true);
    let text = filled(&d, Lang::En, Format::Latex).replace("(j \\bmod 5)", "j");
    let v = check(&text, &d);
    // Vertex (0, 5) is the far edge of the first block and the near edge of the second: the
    // second's s = 0.5 is not what the formula gives there.
    assert_eq!(items(&v), [(line_of(&text, "s &="), "a4.formula s at (0, 5)")]);
    assert_eq!(v.findings[0].derived, "0.250 / 0.500");
}

#[test]
fn a_formula_that_does_not_read_is_a_note_with_its_line_not_a_mistake() {
    let d = derived(false);
    for (lang, format) in CASES {
        let text = filled(&d, lang, format).replace("0.025 \\cdot i", "0.1 \\cdot p");
        let line = line_of(&text, "s &=");
        let v = check(&text, &d);
        assert!(v.findings.is_empty(), "{:#?}", v.findings);
        let note = v.notes.iter().find(|n| n.en.contains("could not read")).unwrap();
        assert!(note.en.starts_with(&format!("could not read the formula at line {line}: s:")));
        assert!(note.en.contains("`p` does not read"), "{}", note.en);
        assert!(
            note.ja.starts_with(&format!("{line} 行目: s の式を読めませんでした")),
            "{}",
            note.ja
        );
        assert_eq!(v.checked, 1, "t is still checked");
    }
    // The tag without a formula after it; no tag at all.
    let text = "<!-- cg: a4.formula -->\n\nnothing here\n";
    let v = check(text, &d);
    assert_eq!(
        formula_notes(&v),
        [
            "line 1: there is no `s = …` after the tag a4.formula, so it was not checked",
            "line 1: there is no `t = …` after the tag a4.formula, so it was not checked"
        ]
    );
    let v = check("# empty\n", &d);
    assert_eq!(formula_notes(&v), ["no tagged texture formula found in the report: a4.formula"]);
    let v = check(&filled(&d, Lang::En, Format::Markdown), &Derived::default());
    assert_eq!(
        formula_notes(&v),
        ["there is no texture data, so the formula a4.formula was not checked"]
    );
}

/// `s = …` and `t = …` written as a student might, after the tag.
fn written(s: &str, t: &str) -> String {
    format!("<!-- cg: a4.formula -->\n{s}\n{t}\n")
}

#[test]
fn the_usual_notations_read() {
    let d = derived(false);
    for (s, t) in [
        ("s = 0.25 + i/40", "t = 0.625 - j/40"),
        ("$s = 0.025 i + 0.25$", "$t = 0.625 − 0.025j$"),
        ("s = (i + 10) / 40", "t = (25 - j) / 8 * 0.2"),
        ("s = 0.25 + 0.025×i", "t = 0.625 − 0.025·j"),
        ("s(i, j) = 0.25 + 0.025*i", "t(i, j) = 0.625 - 0.025*j"),
        ("\\[ s = \\frac{i}{40} + \\frac{1}{4} \\]", "\\[ t = \\dfrac{25 - j}{40} \\]"),
        ("$$s = \\left(10 + i\\right) \\cdot \\frac{1}{40}$$", "$$t = 0.625 - \\frac{1}{40} j$$"),
        ("s = 0.25 + 0.025 i, t = 0.625 - 0.025 j", ""),
        ("s = 0.25 +", "    0.025 i; t = 0.625 - 0.025 j."),
    ] {
        let text = written(s, t);
        let v = check(&text, &d);
        assert!(v.findings.is_empty(), "{s} {t}: {:#?}", v.findings);
        assert_eq!(formula_notes(&v), Vec::<&str>::new(), "{s} {t}");
        assert_eq!(v.checked, 2, "{s} {t}");
    }
    let d = derived(true);
    for (s, t) in [
        ("s = 0.5 - 0.05 (j % 5)", "t = 0.625 - 0.05 (i % 5)"),
        ("s = 0.5 − \\frac{j \\bmod 5}{20}", "t = 0.625 - (i mod 5)/20"),
        ("s = 0.5 - 0.05 (j \\operatorname{mod} 5)", "t = 0.625 - 0.05 (i \\mod 5)"),
    ] {
        let v = check(&written(s, t), &d);
        assert!(v.findings.is_empty(), "{s} {t}: {:#?}", v.findings);
        assert_eq!(v.checked, 2, "{s} {t}");
    }
}

#[test]
fn expressions_evaluate_and_bad_ones_are_refused_without_panicking() {
    let read = |e: &str| {
        let toks: Vec<expr::Tok> = body(e);
        expr::parse(&toks)
    };
    let at = |e: &str, i: f64, j: f64| read(e).unwrap().eval(i, j);
    assert_eq!(at("0.25 + i/16", 4.0, 0.0), [0.5]);
    assert_eq!(at("(j + 2) / 8 * 0.5", 0.0, 2.0), [0.25]);
    assert_eq!(at("0.125 i", 2.0, 0.0), [0.25]);
    assert_eq!(at("-i + -(-j)", 1.0, 3.0), [2.0]);
    assert_eq!(at("2(i + 1)j", 1.0, 3.0), [12.0]);
    assert_eq!(at("i mod 5", 7.0, 0.0), [2.0]);
    // At a block's far edge a mod gives both ends; at 0 only 0.
    assert_eq!(at("(i mod 5)/5", 5.0, 0.0), [0.0, 1.0]);
    assert_eq!(at("(i mod 5)/5", 0.0, 0.0), [0.0]);
    assert!(at("1/(i - 1)", 1.0, 0.0)[0].is_nan());
    for bad in [
        "",
        "0.25 +",
        "(i + 1",
        "i + 1)",
        "p",
        "0.25 where",
        "\\sqrt{i}",
        "{i",
        "i ++",
        "= 1",
        "\\frac{i}",
    ] {
        assert!(read(bad).is_err(), "{bad:?} reads");
    }
    let deep = format!("{}i{}", "(".repeat(5000), ")".repeat(5000));
    assert!(read(&deep).is_err());
    let long = "i + ".repeat(1000) + "1";
    assert!(read(&long).is_err());
    let signs = "-".repeat(5000) + "i";
    assert!(read(&signs).is_err());
    let nested = format!("{}i{}", "(".repeat(100), ")".repeat(100));
    assert!(read(&nested).unwrap_err().en.contains("nested"));
    assert!(read(&("-".repeat(100) + "i")).unwrap_err().en.contains("nested"));
    let why = read("0.1 p").unwrap_err();
    assert!(why.en.contains("`p`") && why.ja.contains("`p`"), "{why:?}");
}

#[test]
fn the_words_leave_the_formula_in_i_and_j_to_the_tagged_one() {
    for turned_student in [false, true] {
        let d = derived(turned_student);
        for (lang, format) in CASES {
            let text = filled(&d, lang, format);
            let words = d.a4.as_ref().unwrap().formula.get(lang);
            let said = t("i と j で書くと", "In i and j:");
            assert!(words.contains(said.get(lang)), "{words}");
            assert!(!text.contains(said.get(lang)), "{lang} {format:?}: {text}");
            // The rest of the words stay: the formula in p and q, and the range.
            let range = t("範囲:", "Range:");
            assert!(text.contains(range.get(lang)), "{text}");
            assert!(text.contains("q = j / 10") || text.contains("(j mod 5) / 5"), "{text}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Hostile sizes: a formula line of megabytes is read in memory that does not grow with it.

fn too_long(e: &Equation) -> bool {
    e.expr.as_ref().is_err_and(|why| why.en == "the expression is too long")
}

#[test]
fn a_formula_of_megabytes_is_too_long_and_its_tokens_are_bounded() {
    // `s = ------…` (5 MB): the tokens were all kept (a char and a token each, 2.3 GB for 30 MB).
    let text = format!("s = {}\nt = 0.5 + j / 40", "-".repeat(5_000_000));
    let toks = expr::tokens(&text, 3);
    assert!(toks.len() < 2 * expr::MAX_TOKENS, "{} tokens kept", toks.len());
    let eqs = equations(&text, 3);
    assert_eq!(eqs.len(), 2, "{eqs:?}");
    assert_eq!((eqs[0].name, eqs[0].line), ('s', 3));
    assert!(too_long(&eqs[0]), "{:?}", eqs[0].expr);
    assert!(eqs[0].text.ends_with('…') && eqs[0].text.chars().count() == 80);
    assert_eq!((eqs[1].name, eqs[1].line), ('t', 4));
    assert!(eqs[1].expr.is_ok(), "{:?}", eqs[1].expr);
}

#[test]
fn an_expression_past_the_limit_ends_where_it_did() {
    // A long expression, then the next equation on the same line, after a separator or not:
    // what follows the expression reads as it did when every token was kept.
    for sep in [", ", " ", "; "] {
        let text = format!("s = 0.25{}{sep}t = 0.625 - j / 40", " + i".repeat(20_000));
        let eqs = equations(&text, 1);
        assert_eq!(eqs.len(), 2, "{sep:?}: {eqs:?}");
        assert!(too_long(&eqs[0]), "{sep:?}");
        assert_eq!(eqs[1].name, 't');
        assert!(eqs[1].expr.is_ok(), "{sep:?}: {:?}", eqs[1].expr);
    }
    // Just within the limit: every token is there.
    let text = format!("s = i{}", " + i".repeat((expr::MAX_TOKENS - 1) / 2));
    let eqs = equations(&text, 1);
    assert_eq!(eqs[0].expr.as_ref().map(|e| e.eval(1.0, 0.0)), Ok(vec![200.0]));
    // A line that continues after an operator, past the limit: too long, then the next line.
    let text = format!("s = 0.25 +\n{} +\n0.5\nt = j", "i + ".repeat(300));
    let eqs = equations(&text, 1);
    assert_eq!(eqs.len(), 2, "{eqs:?}");
    assert!(too_long(&eqs[0]));
    assert_eq!((eqs[1].name, eqs[1].line), ('t', 4));
}

#[test]
fn unclosed_environments_and_words_read_in_one_pass() {
    // `\begin{\begin{…` and `\text{ \text{ …` without their `}`: each looked to the end.
    let text = format!("{}\ns = i / 40", "\\begin{".repeat(200_000));
    let eqs = equations(&text, 1);
    assert_eq!(eqs.len(), 1, "{eqs:?}");
    assert_eq!(eqs[0].expr.as_ref().map(|e| e.eval(4.0, 0.0)), Ok(vec![0.1]));
    let text = format!("s = i {}", "\\text{ ".repeat(200_000));
    let toks = expr::tokens(&text, 1);
    assert!(toks.len() < 2 * expr::MAX_TOKENS, "{} tokens kept", toks.len());
    // The words inside the braces, spaces and line breaks aside, as before.
    let text = "s = (i \\operatorname{ mod } 5) \\text{\n j \n} \\begin{aligned} \\end{aligned}";
    let toks: Vec<Tok> = expr::tokens(text, 1).into_iter().map(|(_, t)| t).collect();
    assert_eq!(
        toks,
        [
            Tok::Word("s".to_owned()),
            Tok::Eq,
            Tok::Open('('),
            Tok::Var('i'),
            Tok::Op('%'),
            Tok::Num(5.0),
            Tok::Close(')'),
            Tok::Var('j'),
        ]
    );
}
