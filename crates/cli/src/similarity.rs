//! `cg similarity <SUBMISSIONS> --out DIR`: copies found (instructors); see `cg_similarity` and
//! docs/instructor-guide.md ("Copies found").

use std::path::PathBuf;

use cg_core::lang::{Lang, Text, t};
// The names printed are the students' (zips, folders, Moodle full names): a control character
// in one (an escape sequence for the instructor's terminal) is shown as its code.
use cg_core::quote::visible;
use cg_harness::exit::Ending;
use cg_similarity::{Settings, read};

/// Options of `cg similarity`.
#[derive(clap::Args)]
pub struct Args {
    /// This year's submissions, as `cg grade` reads them (a folder of folders and .zip files, or Moodle's "Download all submissions", the .zip or its folder) / 今年の提出物（cg grade と同じ: フォルダ、または Moodle の一括ダウンロードの .zip かそのフォルダ）
    submissions: PathBuf,
    /// Where similarity.html and similarity.csv go / similarity.html と similarity.csv の出力先
    #[arg(long, default_value = "similarity")]
    out: PathBuf,
    /// An earlier year's submissions, compared with this year's but not with one another (repeatable) / 過去の年度の提出物（今年の提出物とだけ比べます。複数指定可）
    #[arg(long, value_name = "SUBMISSIONS")]
    reference: Vec<PathBuf>,
    /// A folder of reports, each file named with its student number (20260001.md, report-20260001.txt), used instead of the report inside that student's submission. For a student without one here, the submission's own report/report.md or report/report.tex (where `cg report fill` writes it; UTF-8, UTF-16 or Shift_JIS; at most 4 MiB) is read. Reports' numbers are checked against the variants / レポートのフォルダ（ファイル名に学生番号を含める）。その学生の提出物の中のレポートの代わりに使います。ここにない学生は、提出物の中の report/report.md か report/report.tex（cg report fill が書く場所。UTF-8・UTF-16・Shift_JIS、4 MiB まで）を読みます。レポートの数値を課題と照らし合わせます
    #[arg(long, value_name = "DIR")]
    reports: Option<PathBuf>,
    /// The class roster, as `cg grade --roster` reads it (CSV: student, name, entry): an entry on it is that student, and one without exercises/student.toml is compared too / 名簿（cg grade --roster と同じ CSV: student, name, entry）。名簿の学生番号を使い、exercises/student.toml のない提出物も比べます
    #[arg(long, value_name = "FILE")]
    roster: Option<PathBuf>,
    /// The least share of the smaller submission's fingerprints two submissions must share to be listed (0 to 1) / 一覧に載せる類似度の下限（小さいほうの提出物の指紋のうち共有する割合、0〜1）
    #[arg(long, value_name = "SCORE", default_value_t = Settings::default().threshold)]
    threshold: f64,
    /// The fewest shared fingerprints of a listed pair, at least 1 / 一覧に載せる組が共有する指紋の最小数（1 以上）
    #[arg(long, value_name = "N", default_value_t = Settings::default().min_shared as u64, value_parser = clap::value_parser!(u64).range(1..))]
    min_shared: u64,
    /// A fingerprint found in more submissions than this is common code, not a copy (MOSS's -m), at least 2 / これを超える数の提出物にある指紋は共通のコードとみなす（2 以上）
    #[arg(long, value_name = "N", default_value_t = Settings::default().max_share as u64, value_parser = clap::value_parser!(u64).range(2..))]
    max_share: u64,
}

/// `cg similarity`: 0 when nothing is found, 1 when a pair or a cross-variant copy is (the
/// kit's "mistakes found"), 2 for input that cannot be read.
pub fn run(args: &Args, lang: Lang) -> Result<Ending, String> {
    if !(0.0..=1.0).contains(&args.threshold) {
        return Err(t(
            "--threshold は 0 から 1 の数にしてください",
            "--threshold must be a number from 0 to 1",
        )
        .get(lang)
        .to_owned());
    }
    let settings = Settings {
        threshold: args.threshold,
        min_shared: usize::try_from(args.min_shared).unwrap_or(usize::MAX),
        max_share: usize::try_from(args.max_share).unwrap_or(usize::MAX),
    };
    // The stubs as handed out: the kit's exercises/ (here, or the kit this binary was built in).
    let src = crate::kit_path(None, "exercises/src");
    let kit = src.ancestors().nth(2).unwrap_or(&src).to_path_buf();
    let stubs = read::stubs(&kit).map_err(|e| e.get(lang).to_owned())?;
    let mut class = read::class(&args.submissions, false).map_err(|e| e.get(lang).to_owned())?;
    // --out inside the submissions folder: last run's output is no submission.
    if let (Ok(out), Ok(subs)) = (args.out.canonicalize(), args.submissions.canonicalize())
        && out.parent() == Some(subs.as_path())
        && let Some(name) = out.file_name().map(|n| n.to_string_lossy().into_owned())
    {
        class.retain(|s| s.name != name);
    }
    // This year's submissions given again as an earlier year's would pair each with itself.
    let this_year = args.submissions.canonicalize().ok();
    if let Some(same) =
        args.reference.iter().find(|r| r.canonicalize().ok().is_some_and(|r| Some(r) == this_year))
    {
        return Err(Text::new(
            format!(
                "--reference {} は今年の提出物と同じフォルダです（過去の年度の提出物を指定してください）",
                same.display()
            ),
            format!(
                "--reference {} is this year's submissions again (give an earlier year's)",
                same.display()
            ),
        )
        .get(lang)
        .to_owned());
    }
    for reference in &args.reference {
        class.extend(read::class(reference, true).map_err(|e| e.get(lang).to_owned())?);
    }
    if let Some(path) = &args.roster {
        let roster = cg_grade::roster::Roster::read(path).map_err(|e| e.get(lang).to_owned())?;
        for note in read::bind(&mut class, &roster) {
            eprintln!("{}", visible(note.get(lang)));
        }
    }
    if let Some(dir) = &args.reports {
        let unmatched = read::reports(dir, &mut class).map_err(|e| e.get(lang).to_owned())?;
        for name in unmatched {
            let name = visible(&name);
            eprintln!(
                "{}: {name}",
                t(
                    "学生番号で提出物に結びつかないレポート（飛ばします）",
                    "a report that names no submission's student number (skipped)"
                )
                .get(lang)
            );
        }
    }
    for s in class.iter().filter(|s| s.refused.is_some()) {
        let why = s.refused.as_ref().map(|w| w.get(lang).to_owned()).unwrap_or_default();
        // The reason and the notes quote names from inside the submission (a zip entry's): no
        // escape of theirs reaches the terminal.
        eprintln!("{}: {}", visible(&s.name), visible(&why));
    }
    for s in &class {
        for note in &s.notes {
            eprintln!("{}: {}", visible(&s.name), visible(note.get(lang)));
        }
    }
    // Nothing of this year's to compare (an empty folder, a wrong one, every entry refused) is
    // input that cannot be read, not "nothing found".
    let readable = class.iter().filter(|s| !s.reference && s.refused.is_none()).count();
    if readable == 0 {
        let entries = class.iter().filter(|s| !s.reference).count();
        let shown = args.submissions.display();
        return Err(Text::new(
            format!(
                "{shown}: 比べられる提出物がありません（{entries} 件のうち読めたものは 0 件。理由は上に）。提出物のフォルダか Moodle のダウンロードを指定してください"
            ),
            format!(
                "{shown}: no submission to compare ({entries} entries, none readable; the reasons are above): give the folder of submissions or Moodle's download"
            ),
        )
        .get(lang)
        .to_owned());
    }
    let analysis = cg_similarity::analyse(&class, &stubs, settings);
    cg_similarity::output::write(&args.out, &class, &analysis, lang)?;
    let this_year = class.iter().filter(|s| !s.reference).count();
    let (references, pairs, clusters, cross) = (
        class.len() - this_year,
        analysis.pairs.len(),
        analysis.clusters.len(),
        analysis.cross.len(),
    );
    let summary = Text::new(
        format!(
            "提出物 {this_year} 件、参照 {references} 件: しきい値以上の組 {pairs}、クラスタ {clusters}、ほかの学生の課題の数値 {cross} 件"
        ),
        format!(
            "{this_year} submissions, {references} references: {pairs} pairs at or above the threshold, {clusters} clusters, {cross} parts with another student's numbers"
        ),
    );
    println!("{}", summary.get(lang));
    let inside = class.iter().filter(|s| s.report_inside.is_some()).count();
    let given = class.iter().filter(|s| s.report.is_some()).count() - inside;
    let reports = Text::new(
        format!("レポート: 提出物の中から {inside} 件、--reports から {given} 件"),
        format!("reports: {inside} from inside the submissions, {given} from --reports"),
    );
    println!("{}", reports.get(lang));
    if let Some(note) = read::set_aside(&class) {
        println!("{}", note.get(lang));
    }
    if !analysis.mostly_common.is_empty() {
        let names: Vec<&str> =
            analysis.mostly_common.iter().map(|&i| class[i].name.as_str()).collect();
        let (n, share) = (names.len(), args.max_share);
        println!(
            "{}: {}",
            Text::new(
                format!(
                    "注意: {n} 件の提出物は、コードの指紋の半分以上が {share} 件を超える提出物と共通なので、共通のコードとして比べていません（{share} 件を超えるコピーの輪かもしれません。--max-share を大きくして確かめてください）"
                ),
                format!(
                    "note: {n} submissions share most of their code's fingerprints with more than {share} submissions, so it was taken as common code and not compared (a ring of more than {share} copies would look so: check with a larger --max-share)"
                ),
            )
            .get(lang),
            visible(&names.join(", "))
        );
    }
    for p in &analysis.pairs {
        let same = if cg_similarity::output::same_number(&class[p.a], &class[p.b]) {
            t(
                "（同じ学生番号: 再提出か、本人の過去の提出物）",
                " (the same student number: a resubmission, or the student's own earlier work)",
            )
        } else {
            Text::default()
        };
        let line = format!(
            "  {:>3.0}%  {} ({}) — {} ({}){}",
            p.score * 100.0,
            class[p.a].name,
            class[p.a].number(),
            class[p.b].name,
            class[p.b].number(),
            same.get(lang)
        );
        println!("{}", visible(&line));
    }
    for c in &analysis.cross {
        let s = &class[c.submission];
        let line = format!("  {}: {}", s.name, cg_similarity::output::cross_note(c, s, lang));
        println!("{}", visible(&line));
    }
    println!(
        "{}: {}",
        t("書き出し", "written").get(lang),
        args.out.join("similarity.html").display()
    );
    Ok(Ending::passed(!analysis.found()))
}
