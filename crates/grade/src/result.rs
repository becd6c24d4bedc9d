//! A submission's result in the shape of Gradescope's `results.json` — `{score, max_score,
//! output, tests: [{name, number, score, max_score, status, output}]}` plus a `cg` object (the
//! student, the hash, the isolation, timings, per-assignment scores) — and the class's table
//! and summary built from those files.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::time::Duration;

use cg_core::lang::{Lang, t};
use cg_sandbox::Isolation;
use serde_json::{Value, json};

use crate::{AssignmentRun, Baseline, Config, Text};

/// What grading one submission found.
#[derive(Clone, Debug, Default)]
pub struct Facts {
    /// The submission was refused before building (why).
    pub refused: Option<Text>,
    /// Grading could not finish (why): the kit does not build, the build ran over its limit…
    pub fatal: Option<Text>,
    /// Whether the problem was the machine's (a work copy, cargo): the result is not kept for
    /// resuming, so the next run grades it again.
    pub retry: bool,
    /// Modules replaced by their stubs, with their compiler errors.
    pub compile_errors: BTreeMap<String, Vec<String>>,
    /// Modules the submission did not hold (graded as their stubs: each check failed, said as
    /// not handed in rather than as the stub's "delete the line `not_started`").
    pub not_submitted: std::collections::BTreeSet<String>,
    /// Modules saved in another encoding than UTF-8, with it, converted to be built
    /// ([`crate::submission::Files::converted`]): said in the output.
    pub converted: BTreeMap<String, String>,
    /// Each assignment's run.
    pub runs: BTreeMap<String, AssignmentRun>,
    /// The checks of each assignment whose run died, as the kit lists them.
    pub baseline: Baseline,
    /// The submission's builds.
    pub build: Option<Duration>,
    /// The runs of its checks.
    pub run: Option<Duration>,
    /// Its report, checked but not scored ([`crate::report`]).
    pub report: crate::report::Facts,
}

/// What the roster (`cg grade --roster`) says of one entry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RosterMark {
    /// Whether the roster has a row for the entry (by its name or Moodle participant ID).
    pub listed: bool,
    /// The student's name on the roster.
    pub name: Option<String>,
    /// The number the submission's `student.toml` claimed, when it is not the roster's.
    pub claimed: Option<String>,
    /// The roster's student number for the entry (a refused entry is still the roster's
    /// student: its result, class.csv and summary.md name them).
    pub student: Option<String>,
}

/// Who and how.
#[derive(Clone, Copy, Debug)]
pub struct Meta<'a> {
    /// The entry name in the submissions folder.
    pub entry: &'a str,
    /// The student number, when the submission had a readable one.
    pub student: Option<&'a str>,
    /// The variant table the submission's `student.toml` names (its variants were graded),
    /// when it had a readable one.
    pub table: Option<cg_harness::TableVersion>,
    /// The submission's hash (files, config, kit).
    pub hash: &'a str,
    /// The isolation of the runs.
    pub isolation: Isolation,
    /// The other entries of the submissions folder that claim the same student number (empty
    /// when none does): none of them is taken for the student without the instructor.
    pub same_number: &'a [String],
    /// What the roster says of the entry (with `--roster`).
    pub roster: Option<&'a RosterMark>,
    /// The whole time spent on it.
    pub total: Duration,
}

/// The end of `text`, at most `max` bytes (on a character boundary).
#[must_use]
pub fn tail(text: &str, max: usize) -> String {
    if text.len() <= max {
        return text.to_owned();
    }
    let mut start = text.len() - max;
    while !text.is_char_boundary(start) {
        start += 1;
    }
    format!("…{}", &text[start..])
}

fn text_of(v: &Value) -> Text {
    match v {
        Value::String(s) => Text::new(s.clone(), s.clone()),
        Value::Object(_) => {
            Text::new(v["ja"].as_str().unwrap_or_default(), v["en"].as_str().unwrap_or_default())
        }
        _ => Text::default(),
    }
}

/// The checks of a report (`Report::to_json`): ID and title.
#[must_use]
pub fn check_list(report: &Value) -> Vec<(String, Text)> {
    report["checks"]
        .as_array()
        .map(|checks| {
            checks
                .iter()
                .map(|c| (c["id"].as_str().unwrap_or("?").to_owned(), text_of(&c["title"])))
                .collect()
        })
        .unwrap_or_default()
}

/// What a failed check's JSON says, in `lang`.
fn explain(check: &Value, lang: Lang) -> String {
    let field = |k: &str| text_of(&check[k]).get(lang).to_owned();
    match check["status"].as_str().unwrap_or("") {
        "pass" => String::new(),
        "not_done" => format!(
            "{}: {}",
            t("未実装", "not done yet").get(lang),
            cg_harness::check::stub_message(check["message"].as_str().unwrap_or(""), lang)
        ),
        "panicked" => format!(
            "{}: {}{}",
            t("パニックしました", "panicked").get(lang),
            check["message"].as_str().unwrap_or(""),
            check["location"].as_str().map(|w| format!(" ({w})")).unwrap_or_default()
        ),
        "timed_out" => format!(
            "{}: {} s",
            t("制限時間を超えました（無限ループ？）", "ran over the time limit (an endless loop?)")
                .get(lang),
            check["limit_ms"].as_u64().unwrap_or(0) as f64 / 1000.0
        ),
        "broken" => format!(
            "{}: {}",
            t("関数の結果を受け取れませんでした", "no result came back from the function")
                .get(lang),
            field("why")
        ),
        "crashed" => {
            let stderr = check["stderr"].as_str().unwrap_or("").trim_end();
            let mut s = format!(
                "{}: {}",
                t(
                    "関数を実行していたプロセスが終了しました（exit()、スタックの溢れ、メモリ上限？）",
                    "the process running the function ended (exit(), a stack overflow, the memory limit?)",
                ).get(lang),
                check["how"].as_str().unwrap_or("")
            );
            if !stderr.is_empty() {
                let _ = write!(s, "\n{}", tail(stderr, 500));
            }
            s
        }
        _ => {
            let mut s = format!(
                "{}: {}\n{}: {}",
                t("期待", "expected").get(lang),
                field("expected"),
                t("実際", "found").get(lang),
                field("actual")
            );
            if check["where"].is_object() || check["where"].is_string() {
                let _ = write!(s, "\n{}: {}", t("場所", "where").get(lang), field("where"));
            }
            for (k, ja, en) in [("cause", "原因", "cause"), ("hint", "ヒント", "hint")] {
                let v = field(k);
                if !v.is_empty() {
                    let _ = write!(s, "\n{}: {v}", t(ja, en).get(lang));
                }
            }
            s
        }
    }
}

fn round(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}

/// The result JSON of one submission.
#[must_use]
pub fn build(meta: &Meta<'_>, facts: &Facts, config: &Config, lang: Lang) -> Value {
    let mut output = format!(
        "{}: {}\n{}: {}\n",
        t("学生番号", "student").get(lang),
        meta.student.unwrap_or("?"),
        t("提出物", "submission").get(lang),
        meta.entry
    );
    // A table other than the default is said: the student's variants are that table's.
    if let Some(table) = meta.table.filter(|&v| v != cg_harness::TableVersion::DEFAULT) {
        let _ = writeln!(output, "{}: {table}", t("課題表の版", "table").get(lang));
    }
    let mut tests = Vec::new();
    let mut per: BTreeMap<String, (f64, f64)> = BTreeMap::new();
    let ended_early = facts.refused.as_ref().or(facts.fatal.as_ref());
    if let Some(why) = ended_early {
        let head = if facts.refused.is_some() {
            t("受け付けられません", "refused")
        } else {
            t("採点できませんでした", "could not be graded")
        };
        let _ = writeln!(output, "{}: {}", head.get(lang), why.get(lang));
    }
    for (m, encoding) in &facts.converted {
        let said = Text::new(
            format!(
                "{m}.rs は {encoding} で保存されていたので、UTF-8 に直して採点しました（Rust のソースファイルは UTF-8 で保存してください）"
            ),
            format!(
                "{m}.rs was saved as {encoding}: graded converted to UTF-8 (save Rust source files as UTF-8)"
            ),
        );
        let _ = writeln!(output, "{}", said.get(lang));
    }
    for (m, run) in &facts.runs {
        let entry = per.entry(m.clone()).or_insert((0.0, 0.0));
        let compile = facts.compile_errors.get(m);
        let missing = facts.not_submitted.contains(m);
        let checks: Vec<(String, Text, bool, String)> = match (run, compile) {
            (AssignmentRun::Report(r), None) if !missing => r["checks"]
                .as_array()
                .cloned()
                .unwrap_or_default()
                .iter()
                .map(|c| {
                    let passed = c["status"] == "pass";
                    (
                        c["id"].as_str().unwrap_or("?").to_owned(),
                        text_of(&c["title"]),
                        passed,
                        explain(c, lang),
                    )
                })
                .collect(),
            (run, compile) => {
                let list = match run {
                    AssignmentRun::Report(r) => check_list(r),
                    AssignmentRun::Died { .. } => {
                        facts.baseline.get(m).cloned().unwrap_or_default()
                    }
                };
                let why = match (compile, run) {
                    (_, _) if missing => Text::new(
                        format!("{m}.rs は提出物にありません（exercises/src/{m}.rs）"),
                        format!("{m}.rs is not in the submission (exercises/src/{m}.rs)"),
                    )
                    .get(lang)
                    .to_owned(),
                    (Some(errors), _) => format!(
                        "{} ({m}.rs):\n{}",
                        t("コンパイルエラー", "compile errors").get(lang),
                        errors.join("\n")
                    ),
                    (None, AssignmentRun::Died { how, stderr }) => {
                        if stderr.trim().is_empty() {
                            how.get(lang).to_owned()
                        } else {
                            format!("{}\n{}", how.get(lang), stderr.trim_end())
                        }
                    }
                    (None, AssignmentRun::Report(_)) => String::new(),
                };
                // The first line that says something: for compile errors the heading and the
                // first error (`a1: compile errors (a1.rs): exercises/src/a1.rs:3: …`), not the
                // heading alone ending in a colon.
                let mut lines = why.lines().filter(|l| !l.trim().is_empty());
                let first = match (lines.next(), lines.next()) {
                    (Some(head), Some(next)) if head.ends_with(':') => format!("{head} {next}"),
                    (Some(head), _) => head.to_owned(),
                    (None, _) => String::new(),
                };
                let _ = writeln!(output, "{m}: {first}");
                if list.is_empty() {
                    // Not even the list of checks is known: one line for the assignment.
                    vec![(format!("{m}.run"), Text::new(m.clone(), m.clone()), false, why)]
                } else {
                    list.into_iter().map(|(id, title)| (id, title, false, why.clone())).collect()
                }
            }
        };
        // `[totals]`: the assignment weighs the same whatever the number of its checks.
        let scale = config.scale(m, checks.iter().map(|c| c.0.as_str()));
        for (id, title, passed, text) in checks {
            let max = config.points(&id) * scale;
            let score = if passed { max } else { 0.0 };
            entry.0 += score;
            entry.1 += max;
            tests.push(json!({
                "name": format!("{id}: {}", title.get(lang)),
                "number": id,
                "score": round(score),
                "max_score": round(max),
                "status": if passed { "passed" } else { "failed" },
                "output": text,
            }));
        }
    }
    let score = per.values().fold(0.0, |a, p| a + p.0);
    let max = per.values().fold(0.0, |a, p| a + p.1);
    for (m, (s, x)) in &per {
        let _ = writeln!(output, "{m}: {} / {}", round(*s), round(*x));
    }
    let report = crate::report::to_json(&facts.report, lang);
    if let Some(line) = crate::report::line(&report, lang) {
        let _ = writeln!(output, "{line}");
    }
    let secs = |d: Option<Duration>| d.map(|d| round(d.as_secs_f64()));
    let assignments: serde_json::Map<String, Value> = per
        .iter()
        .map(|(m, (s, x))| (m.clone(), json!({"score": round(*s), "max_score": round(*x)})))
        .collect();
    let mut value = json!({
        "score": round(score),
        "output": output,
        "tests": tests,
        "cg": {
            "student": meta.student,
            "table": meta.table.map(|v| v.number()),
            "submission": meta.entry,
            "hash": meta.hash,
            "isolation": meta.isolation.describe(Lang::En),
            "sandboxed": meta.isolation == Isolation::Bubblewrap,
            "same_number": meta.same_number,
            "roster": meta.roster.map(|m| json!({
                "listed": m.listed,
                "name": m.name,
                "claimed": m.claimed,
            })),
            "refused": facts.refused.as_ref().map(|m| m.en.clone()),
            "error": facts.fatal.as_ref().map(|m| m.en.clone()),
            // The same in Japanese, for the Japanese summary and Moodle's comment.
            "refused_ja": facts.refused.as_ref().map(|m| m.ja.clone()),
            "error_ja": facts.fatal.as_ref().map(|m| m.ja.clone()),
            "compile_errors": facts.compile_errors,
            "converted": facts.converted,
            "assignments": assignments,
            "report": report,
            "timings": {
                "build_s": secs(facts.build),
                "run_s": secs(facts.run),
                "report_s": secs(facts.report.time),
                "total_s": round(meta.total.as_secs_f64()),
            },
        },
    });
    if !per.is_empty() {
        value["max_score"] = json!(round(max));
    }
    value
}

/// Why a result was not graded (its `refused` or `error`), in `lang` when the result has it
/// (results written before the Japanese was kept have only the English).
#[must_use]
pub fn not_graded(cg: &Value, lang: Lang) -> Option<&str> {
    let ja = || cg["refused_ja"].as_str().or(cg["error_ja"].as_str());
    let en = || cg["refused"].as_str().or(cg["error"].as_str());
    match lang {
        Lang::Ja => ja().or_else(en),
        Lang::En => en(),
    }
}

/// Why a result was not graded, in both languages, its first line after "refused" or "could
/// not be graded": for the line `cg grade` prints of it (a refused entry's line read as a
/// graded 0).
#[must_use]
pub fn problem(result: &Value) -> Option<Text> {
    let cg = &result["cg"];
    let head = if cg["refused"].is_string() {
        t("受け付けられません", "refused")
    } else {
        t("採点できませんでした", "could not be graded")
    };
    let first = |lang| not_graded(cg, lang).map(|w| w.lines().next().unwrap_or("").to_owned());
    Some(Text::new(
        format!("{}: {}", head.ja, first(Lang::Ja)?),
        format!("{}: {}", head.en, first(Lang::En)?),
    ))
}

/// Text from a submission (an entry's name, a refusal that quotes one) as Markdown shows it:
/// a code span, so that nothing in it is read as Markdown or HTML (`<img src=…>`, `![](…)`,
/// a heading after a newline), its control characters by their code and a long one shortened
/// ([`cg_core::quote::shown`]).
#[must_use]
pub fn md_code(text: &str, lang: Lang) -> String {
    md_span(&cg_core::quote::shown(text, lang))
}

/// The kit's own words (a refusal's reason) as a code span, whole: the student's names in them
/// are already shortened, and the reason was cut at 64 characters, often before it said why.
pub(crate) fn md_words(text: &str) -> String {
    md_span(&cg_core::quote::visible(text))
}

fn md_span(text: &str) -> String {
    let longest = text.split(|c| c != '`').map(str::len).max().unwrap_or(0);
    let fence = "`".repeat(longest + 1);
    let pad =
        if text.starts_with('`') || text.ends_with('`') || text.is_empty() { " " } else { "" };
    format!("{fence}{pad}{text}{pad}{fence}")
}

fn csv_field(s: &str) -> String {
    // A lone carriage return ends a row to some readers: quoted too, or a name could start a
    // row of its own (and a formula in its first cell).
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_owned()
    }
}

/// What the instructor should look at in a result (`None`: nothing): the number its
/// `student.toml` claims when the roster says another (a Moodle participant bound to one
/// student who hands in another's number), an entry not on the roster, a report filled for
/// another student number ([`crate::report::Facts::claims`]), the other entries that claim the same
/// number; for the class table and the progress lines.
#[must_use]
pub fn flag(result: &Value) -> Option<Text> {
    let cg = &result["cg"];
    let mut parts = Vec::new();
    if let Some(claimed) = cg["roster"]["claimed"].as_str() {
        let roster = cg["student"].as_str().unwrap_or("?");
        parts.push(Text::new(
            format!("student.toml は {claimed}、名簿では {roster}"),
            format!("student.toml claims {claimed}, the roster says {roster}"),
        ));
    }
    if cg["roster"]["listed"] == false {
        parts.push(t("名簿にない", "not on the roster"));
    }
    if let Some(other) = cg["report"]["claims"].as_str() {
        parts.push(Text::new(
            format!("レポートの学生番号は {other}"),
            format!("the report is {other}'s"),
        ));
    }
    if let Some(others) = cg["same_number"].as_array().filter(|a| !a.is_empty()) {
        let others: Vec<&str> = others.iter().filter_map(Value::as_str).collect();
        let others = others.join(", ");
        parts.push(Text::new(
            format!("{others} と同じ番号"),
            format!("the same number as {others}"),
        ));
    }
    let join =
        |lang: Lang, sep: &str| parts.iter().map(|p| p.get(lang)).collect::<Vec<_>>().join(sep);
    (!parts.is_empty()).then(|| Text::new(join(Lang::Ja, "。"), join(Lang::En, "; ")))
}

/// `class.csv`: one row per result — student, submission, each assignment's score (a column
/// per ID of the kit's list), score, max_score, the report's file, numbers checked and mistakes
/// ([`crate::report::csv_cells`], not scored), and the result's [`flag`] (empty when none).
#[must_use]
pub fn class_csv(results: &[Value], lang: Lang) -> String {
    let columns: Vec<&str> = ["student", "submission"]
        .into_iter()
        .chain(crate::submission::MODULES.iter().copied())
        .chain(["score", "max_score"])
        .chain(crate::report::CSV_COLUMNS)
        .chain(["flag"])
        .collect();
    let mut out = columns.join(",") + "\n";
    for r in results {
        let cg = &r["cg"];
        let mut row = vec![
            csv_field(cg["student"].as_str().unwrap_or("")),
            // The entry's name is the student's (a zip's name, a Moodle full name).
            csv_field(&cg_core::quote::spreadsheet_cell(cg["submission"].as_str().unwrap_or(""))),
        ];
        for &m in crate::submission::MODULES {
            row.push(
                cg["assignments"][m]["score"].as_f64().map(|s| s.to_string()).unwrap_or_default(),
            );
        }
        row.push(r["score"].as_f64().unwrap_or(0.0).to_string());
        row.push(r["max_score"].as_f64().map(|s| s.to_string()).unwrap_or_default());
        let [file, checked, mistakes, not_checked] = crate::report::csv_cells(r);
        row.push(csv_field(&cg_core::quote::spreadsheet_cell(&file)));
        row.extend([checked, mistakes, not_checked]);
        // A refused entry is marked too: its empty scores read as a graded 0 when sorted.
        let flag = flag(r).or_else(|| problem(r));
        row.push(csv_field(&cg_core::quote::spreadsheet_cell(
            flag.as_ref().map_or("", |f| f.get(lang)),
        )));
        out.push_str(&row.join(","));
        out.push('\n');
    }
    out
}

/// `summary.md`: how many students failed each check, most failed first — the class's most
/// common mistakes — and the submissions that could not be graded.
#[must_use]
pub fn summary_md(results: &[Value], absent: &[(String, String)], lang: Lang) -> String {
    let mut counts: BTreeMap<String, (String, usize, usize)> = BTreeMap::new();
    let mut problems = Vec::new();
    let mut shared: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut unsandboxed = 0;
    for r in results {
        if r["cg"]["sandboxed"] == false {
            unsandboxed += 1;
        }
        if r["cg"]["same_number"].as_array().is_some_and(|a| !a.is_empty()) {
            shared
                .entry(r["cg"]["student"].as_str().unwrap_or("?").to_owned())
                .or_default()
                .push(r["cg"]["submission"].as_str().unwrap_or("").to_owned());
        }
        for t in r["tests"].as_array().map(Vec::as_slice).unwrap_or_default() {
            let id = t["number"].as_str().unwrap_or("?").to_owned();
            let e = counts
                .entry(id)
                .or_insert_with(|| (t["name"].as_str().unwrap_or("").to_owned(), 0, 0));
            e.2 += 1;
            if t["status"] != "passed" {
                e.1 += 1;
            }
        }
        let cg = &r["cg"];
        if let Some(why) = not_graded(cg, lang) {
            problems.push(format!(
                "- {} ({}): {}",
                md_code(cg["submission"].as_str().unwrap_or(""), lang),
                md_code(cg["student"].as_str().unwrap_or("?"), lang),
                md_words(why.lines().next().unwrap_or(""))
            ));
        }
    }
    let mut rows: Vec<(String, (String, usize, usize))> = counts.into_iter().collect();
    rows.sort_by(|a, b| b.1.1.cmp(&a.1.1).then_with(|| a.0.cmp(&b.0)));
    let mut out = format!(
        "# {}\n\n{}: {}\n\n| {} | {} | {} |\n|---|---:|---:|\n",
        t("採点のまとめ", "Grading summary").get(lang),
        t("提出数", "submissions").get(lang),
        results.len(),
        t("チェック", "check").get(lang),
        t("不合格", "failed").get(lang),
        t("採点数", "graded").get(lang),
    );
    for (_, (name, failed, of)) in &rows {
        let _ = writeln!(out, "| {} | {failed} | {of} |", name.replace('|', "\\|"));
    }
    out.push_str(&crate::report::summary_section(results, lang));
    let uneven = uneven_maxima(results);
    if !uneven.is_empty() {
        let _ = write!(
            out,
            "\n## {}\n\n{}\n\n{}\n",
            t("学生によって満点が違う課題", "Assignments worth more for some students").get(lang),
            uneven.join("\n"),
            t(
                "課題の組み合わせによってチェックの数が違うためです。採点設定の [totals]（例: a2 = 20）で、その課題の点をどの学生でも同じにできます（docs/instructor-guide.md）。",
                "Their number of checks depends on the variant. The grading config's [totals] (a2 = 20, say) makes such an assignment worth the same for every student (docs/instructor-guide.md).",
            )
            .get(lang)
        );
    }
    if unsandboxed > 0 {
        let _ = write!(
            out,
            "\n## {}\n\n{unsandboxed} {}\n",
            t("サンドボックスなしの採点", "Graded without a sandbox").get(lang),
            t(
                "件の提出物を --unsafe-no-sandbox で採点しました。学生のコードは採点者の権限で、ファイルとネットワークを隔離せずに動いています。",
                "submissions were graded with --unsafe-no-sandbox: the students' code ran as the grader, its files and network not isolated.",
            ).get(lang)
        );
    }
    if !shared.is_empty() {
        let list: Vec<String> = shared
            .iter()
            .map(|(n, entries)| {
                let entries: Vec<String> = entries.iter().map(|e| md_code(e, lang)).collect();
                format!("- {}: {}", md_code(n, lang), entries.join(", "))
            })
            .collect();
        let _ = write!(
            out,
            "\n## {}\n\n{}\n\n{}\n",
            t("同じ学生番号の提出物", "Entries that claim the same student number").get(lang),
            t(
                "どれも <学生番号>~<提出物>.json に採点しました。どれがその学生のものかを確かめてください。",
                "Each is graded as <student>~<entry>.json; check which one is the student's.",
            ).get(lang),
            list.join("\n")
        );
    }
    let tables = tables_section(results, lang);
    if !tables.is_empty() {
        let _ = write!(
            out,
            "\n## {}\n\n{tables}",
            t("課題表の版が違う提出物", "Submissions on different tables").get(lang)
        );
    }
    let roster = roster_section(results, absent, lang);
    if !roster.is_empty() {
        let _ =
            write!(out, "\n## {}\n\n{roster}", t("名簿との照合", "Against the roster").get(lang));
    }
    if !problems.is_empty() {
        let _ = write!(
            out,
            "\n## {}\n\n{}\n",
            t("採点できなかった提出物", "Not graded").get(lang),
            problems.join("\n")
        );
    }
    out
}

/// When the class's submissions name more than one variant table: how many are on each, and
/// which are on the fewer (a student who saved their number with another `--table` than the
/// class was told is graded on that table's variants). Empty when all name one table.
fn tables_section(results: &[Value], lang: Lang) -> String {
    let mut on: BTreeMap<u64, Vec<String>> = BTreeMap::new();
    for r in results {
        let cg = &r["cg"];
        let Some(table) = cg["table"].as_u64() else { continue };
        let who = format!(
            "{} ({})",
            md_code(cg["student"].as_str().unwrap_or("?"), lang),
            md_code(cg["submission"].as_str().unwrap_or(""), lang)
        );
        on.entry(table).or_default().push(who);
    }
    if on.len() < 2 {
        return String::new();
    }
    let most =
        on.iter().max_by_key(|(v, who)| (who.len(), std::cmp::Reverse(**v))).map(|(v, _)| *v);
    let mut out = String::new();
    for (table, who) in &on {
        let _ = write!(
            out,
            "- {}: {}",
            Text::new(format!("課題表 {table}"), format!("table {table}")).get(lang),
            Text::new(format!("{} 件", who.len()), format!("{}", who.len())).get(lang),
        );
        if Some(*table) != most {
            let _ = write!(out, ": {}", who.join(", "));
        }
        out.push('\n');
    }
    let _ = writeln!(
        out,
        "\n{}",
        t(
            "各提出物はその student.toml の課題表の版で採点しました。クラスで使う版と違う学生は記録し直せます（版 2 なら cargo run --release -- assignment --table 2 --save。docs/instructor-guide.md）。",
            "Each submission was graded on the table its student.toml names. A student on another table than the class's can record it again (for table 2: cargo run --release -- assignment --table 2 --save), as docs/instructor-guide.md says.",
        )
        .get(lang)
    );
    out
}

/// The assignments whose maximum differs between the graded results, each as `- a2: 14–16`
/// (the number of checks depends on the variant; `[totals]` evens it out).
fn uneven_maxima(results: &[Value]) -> Vec<String> {
    let mut range: BTreeMap<String, (f64, f64)> = BTreeMap::new();
    for r in results {
        let Some(per) = r["cg"]["assignments"].as_object() else { continue };
        for (m, a) in per {
            let Some(max) = a["max_score"].as_f64() else { continue };
            let e = range.entry(m.clone()).or_insert((max, max));
            e.0 = e.0.min(max);
            e.1 = e.1.max(max);
        }
    }
    range
        .into_iter()
        .filter(|(_, (lo, hi))| hi > lo)
        .map(|(m, (lo, hi))| format!("- {m}: {lo}–{hi}"))
        .collect()
}

/// The roster's findings: entries not on it, entries whose `student.toml` claims another
/// number than the roster's, and students on it with no entry (empty without a roster).
fn roster_section(results: &[Value], absent: &[(String, String)], lang: Lang) -> String {
    let mut unlisted = Vec::new();
    let mut claims = Vec::new();
    for r in results {
        let cg = &r["cg"];
        let entry = md_code(cg["submission"].as_str().unwrap_or(""), lang);
        if cg["roster"]["listed"] == false {
            let student = md_code(cg["student"].as_str().unwrap_or("?"), lang);
            unlisted.push(format!("- {entry} ({student})"));
        }
        if let Some(claimed) = cg["roster"]["claimed"].as_str() {
            let claimed = md_code(claimed, lang);
            claims.push(format!(
                "- {entry}: {} {claimed}{} {} {} ({})",
                t("student.toml は", "student.toml claims").get(lang),
                t("、", ",").get(lang),
                t("名簿では", "the roster says").get(lang),
                cg["student"].as_str().unwrap_or("?"),
                cg["roster"]["name"].as_str().unwrap_or("")
            ));
        }
    }
    let mut out = String::new();
    for (title, lines) in [
        (
            t(
                "名簿にない提出物（student.toml の番号で採点）",
                "Entries not on the roster (graded as their student.toml's number)",
            )
            .get(lang),
            unlisted,
        ),
        (
            t(
                "名簿と違う番号を名乗る提出物（名簿の番号で採点）",
                "Entries whose student.toml claims another number (graded as the roster's)",
            )
            .get(lang),
            claims,
        ),
        (
            t("提出物のない学生", "Students on the roster with no entry").get(lang),
            absent.iter().map(|(n, name)| format!("- {n} {name}")).collect(),
        ),
    ] {
        if !lines.is_empty() {
            let _ = write!(out, "{title}:\n\n{}\n\n", lines.join("\n"));
        }
    }
    out
}

/// A Markdown code block of `text` (its trailing blank lines dropped), fenced with more
/// backticks than it holds in a row, so nothing in it (a student's panic message) is read as
/// Markdown or HTML.
#[must_use]
pub fn code_block(text: &str) -> String {
    let text = text.trim_end();
    let mut longest = 0;
    let mut run = 0;
    for c in text.chars() {
        run = if c == '`' { run + 1 } else { 0 };
        longest = longest.max(run);
    }
    let fence = "`".repeat(longest.max(2) + 1);
    format!("{fence}text\n{text}\n{fence}")
}
