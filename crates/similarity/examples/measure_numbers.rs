//! Measures the numbers rules of `cg similarity` (rare single numbers and groups) over a class of
//! generated variants: student B hands in student A's numbers in each of the ways a copy takes
//! (and, as controls, the same with B's own numbers, the solutions, random round literals, and
//! B's own filled report), and each row counts what was found, whether A was named, and whether
//! someone else was.
//!
//! ```sh
//! cargo run --release -p cg-similarity --example measure_numbers --features measure -- [N]
//! ```
//!
//! Needs the kit's own repository (solutions/, and the reports are filled by `cg report fill`'s
//! code on the reference solutions). `--filled` prints the numbers every filled report has
//! (the list `cross::FILLED` comes from).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use cg_core::lang::Lang;
use cg_harness::{StudentNumber, TableVersion};
use cg_report::fill::{self, Context};
use cg_report::template::{self, Format};
use cg_similarity::cross::{self, Bases, Variants};
use cg_similarity::variant::{self, Finding, Key};
use cg_similarity::{Submission, read};

#[path = "../tests/common/literals.rs"]
mod literals;
use literals::{picked, with_literals};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().unwrap()
}

fn solution(m: &str) -> String {
    std::fs::read_to_string(root().join(format!("solutions/src/{m}.rs"))).unwrap()
}

/// `student`'s report as `cg report fill` writes it from the reference solutions.
fn filled(student: &StudentNumber, lang: Lang, format: Format) -> String {
    let a = cg_assign::Variants::for_student(student, TableVersion::DEFAULT);
    let (derived, _missing) = cg_report::derive::derive(&a, &cg_assign::impls!(cg_solutions));
    let assignments = cg_assign::Which::ALL
        .iter()
        .filter(|w| w.in_report())
        .map(|&w| (w.id().to_owned(), a.describe_one(w, lang)))
        .collect();
    let ctx = Context { student: Some(student.to_string()), assignments, ..Context::default() };
    template::fill(template::template(lang, format), &fill::values(&derived, &ctx, lang, format))
        .unwrap()
}

/// A copy form: which file, which numbers of the variant.
struct Form {
    name: &'static str,
    module: &'static str,
    pick: fn(&str) -> bool,
}

const FORMS: &[Form] = &[
    Form { name: "a1 vertices as literals", module: "a1", pick: |l| l.starts_with("a1 V") },
    Form {
        name: "a2 spec numbers (drags, limits)",
        module: "a2",
        pick: |l| {
            l.ends_with("per_px")
                || l.ends_with("_min")
                || l.ends_with("_max")
                || l.ends_with("limit")
        },
    },
    Form { name: "a3 periods", module: "a3", pick: |l| l.ends_with("period_s") },
    Form { name: "a3 spec numbers (motions)", module: "a3", pick: |l| l.contains(".motion.") },
    Form { name: "a4 texture range", module: "a4", pick: |l| l.starts_with("a4 ") },
    Form {
        name: "a4 range + pixel rectangle",
        module: "a4",
        pick: |l| l.starts_with("a4 ") || l.starts_with("a4.region.pixels"),
    },
    Form {
        name: "s spec numbers (material, light)",
        module: "s",
        pick: |l| {
            l.starts_with("s.material") || l.starts_with("s.light") || l.starts_with("s.medium")
        },
    },
];

/// One row's counts.
#[derive(Default)]
struct Row {
    name: String,
    control: bool,
    n: usize,
    found: usize,
    right: usize,
    wrong: usize,
    ambiguous: usize,
    by_groups: usize,
}

impl Row {
    fn add(&mut self, a: Option<&StudentNumber>, findings: &[Finding]) {
        self.n += 1;
        if findings.is_empty() {
            return;
        }
        self.found += 1;
        if findings.iter().any(|f| !f.groups.is_empty()) {
            self.by_groups += 1;
        }
        let named: BTreeSet<&StudentNumber> =
            findings.iter().filter(|f| !f.ambiguous).map(|f| &f.matches).collect();
        let candidates =
            |f: &Finding| std::iter::once(&f.matches).chain(&f.also).any(|s| Some(s) == a);
        // Wrong: someone other than A named alone, or an ambiguous list without A.
        let wrong = named.iter().any(|s| Some(*s) != a)
            || findings.iter().any(|f| f.ambiguous && !candidates(f));
        if wrong {
            self.wrong += 1;
        } else if named.len() == 1 && named.iter().all(|s| Some(*s) == a) {
            self.right += 1;
        } else {
            self.ambiguous += 1;
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = args.iter().find_map(|a| a.parse().ok()).unwrap_or(200);
    let students: Vec<StudentNumber> =
        (0..n).map(|i| format!("{}", 20260001 + i * 7).parse().unwrap()).collect();
    let files: Vec<cg_assign::StudentFile> = students
        .iter()
        .map(|s| cg_assign::StudentFile { student: s.clone(), table: TableVersion::DEFAULT })
        .collect();
    let langs = [Lang::Ja, Lang::En];
    let reports: Vec<String> = students
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let format = if i % 3 == 2 { Format::Latex } else { Format::Markdown };
            filled(s, langs[i % 2], format)
        })
        .collect();
    if args.iter().any(|a| a == "--filled") {
        let mut common: Option<BTreeSet<Key>> = None;
        for (s, lang, format) in students.iter().flat_map(|s| {
            [Lang::Ja, Lang::En].into_iter().flat_map(move |l| {
                [Format::Markdown, Format::Latex].into_iter().map(move |f| (s, l, f))
            })
        }) {
            let found = cross::report_numbers(&filled(s, lang, format));
            common = Some(match common {
                None => found,
                Some(c) => c.intersection(&found).copied().collect(),
            });
        }
        let template = cross::report_base(&[]);
        let shown: Vec<String> = common
            .unwrap_or_default()
            .into_iter()
            .map(|k| {
                let t = if template.contains(&k) { "" } else { " (fill)" };
                format!("{}{t}", variant::show(k))
            })
            .collect();
        println!("in every filled report: {}", shown.join(", "));
        return;
    }
    let variants = Variants::new(&files);
    let stubs = read::stubs(&root()).unwrap();
    // The class as `cg similarity` would read it: everyone's honest files (the solutions) and
    // reports, whose common numbers are base.
    let honest: std::collections::BTreeMap<String, String> =
        ["a1", "a2", "a3", "a4", "s"].iter().map(|m| ((*m).to_owned(), solution(m))).collect();
    let class: Vec<Submission> = students
        .iter()
        .zip(&reports)
        .map(|(s, r)| Submission {
            student: Some(cg_assign::StudentFile {
                student: s.clone(),
                table: TableVersion::DEFAULT,
            }),
            modules: honest.clone(),
            report: Some(r.clone()),
            ..Submission::default()
        })
        .collect();
    let with_class_base = Bases::new(&class, &stubs);
    let template_base = Bases::new(&[], &stubs);
    // B = students[i] copies A = students[source(i)].
    let source = |i: usize| (i * 37 + 11 + n / 2) % n;
    let run =
        |own: &StudentNumber, modules: &[(&str, String)], report: Option<&str>, base: &Bases| {
            let s = Submission {
                modules: modules.iter().map(|(m, t)| ((*m).to_owned(), t.clone())).collect(),
                report: report.map(str::to_owned),
                ..Submission::default()
            };
            variants.findings(own, &cross::numbers(&s, base), base)
        };

    let mut rows: Vec<Row> = Vec::new();
    let mut row = |name: String, control: bool| {
        rows.push(Row { name, control, ..Row::default() });
        rows.len() - 1
    };
    let copies: Vec<usize> =
        FORMS.iter().map(|f| row(format!("copy: {}", f.name), false)).collect();
    let report_copy = row("copy: A's whole filled report".to_owned(), false);
    let report_copy_bare = row(
        "copy: A's whole report, no class base (stubs' and template's numbers only)".to_owned(),
        false,
    );
    let owns: Vec<usize> =
        FORMS.iter().map(|f| row(format!("honest: {}, own numbers", f.name), true)).collect();
    let solutions = row("honest: the solutions (all files)".to_owned(), true);
    let random = row("honest: 15 random round literals per file".to_owned(), true);
    let honest_report = row("honest: own filled report".to_owned(), true);
    let solutions_bare =
        row("honest: the solutions, no class base (stubs' numbers only)".to_owned(), true);
    let honest_report_bare =
        row("honest: own report, no class base (template's numbers only)".to_owned(), true);

    let round = [
        0.1, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.75, 0.8, 1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0,
        8.0, 10.0, 12.0, 15.0, 20.0, 30.0, 45.0, 60.0, 90.0, 180.0, 360.0,
    ];
    let mut seed = 0x2545_f491_u64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    let all: Vec<(&str, String)> =
        ["a1", "a2", "a3", "a4", "s"].iter().map(|m| (*m, solution(m))).collect();
    let mut wrong_examples = Vec::new();
    for (i, b) in students.iter().enumerate() {
        let a = &students[source(i)];
        for (form, r) in FORMS.iter().zip(&copies) {
            let code = with_literals(&solution(form.module), &picked(a, form.module, form.pick));
            let f = run(b, &[(form.module, code)], None, &with_class_base);
            rows[*r].add(Some(a), &f);
            if f.iter().any(|f| !f.ambiguous && &f.matches != a) && wrong_examples.len() < 12 {
                wrong_examples.push(format!("{} {b} <- {a}: {f:?}", form.name));
            }
        }
        for (form, r) in FORMS.iter().zip(&owns) {
            let code = with_literals(&solution(form.module), &picked(b, form.module, form.pick));
            rows[*r].add(None, &run(b, &[(form.module, code)], None, &with_class_base));
        }
        let theirs = &reports[source(i)];
        let f = run(b, &[], Some(theirs), &with_class_base);
        if f.iter().any(|f| !f.ambiguous && &f.matches != a) && wrong_examples.len() < 24 {
            wrong_examples.push(format!("report {b} <- {a}: {f:?}"));
        }
        rows[report_copy].add(Some(a), &f);
        rows[report_copy_bare].add(Some(a), &run(b, &[], Some(theirs), &template_base));
        rows[solutions].add(None, &run(b, &all, None, &with_class_base));
        rows[solutions_bare].add(None, &run(b, &all, None, &template_base));
        let randoms: Vec<(&str, String)> = ["a1", "a2", "a3", "a4", "s"]
            .iter()
            .map(|m| {
                let values: Vec<f64> =
                    (0..15).map(|_| round[(next() % round.len() as u64) as usize]).collect();
                (*m, with_literals(&solution(m), &values))
            })
            .collect();
        rows[random].add(None, &run(b, &randoms, None, &with_class_base));
        let f = run(b, &[], Some(&reports[i]), &with_class_base);
        if !f.is_empty() && wrong_examples.len() < 30 {
            wrong_examples.push(format!("honest report {b}: {f:?}"));
        }
        rows[honest_report].add(None, &f);
        rows[honest_report_bare].add(None, &run(b, &[], Some(&reports[i]), &template_base));
    }

    println!(
        "{n} variants (students 20260001 + 7k); B copies A; numbers of B's submission read against all {n} variants\n"
    );
    println!(
        "| case | found | A named | someone else named | found, not named (ambiguous) | found by groups |"
    );
    println!("|---|---|---|---|---|---|");
    for r in &rows {
        if r.control {
            println!(
                "| {} | {} false positives / {} | — | {} | {} | {} |",
                r.name,
                r.found,
                r.n,
                r.wrong + r.right,
                r.ambiguous,
                r.by_groups
            );
        } else {
            println!(
                "| {} | {} / {} | {} | {} | {} | {} |",
                r.name, r.found, r.n, r.right, r.wrong, r.ambiguous, r.by_groups
            );
        }
    }
    if args.iter().any(|a| a == "-v") {
        for w in wrong_examples {
            println!("{w}");
        }
    }
}
