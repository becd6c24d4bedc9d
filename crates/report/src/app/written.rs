//! What `report derive` and `report fill` wrote, and its summary for the terminal.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::PathBuf;

use cg_core::lang::{Lang, t};
use cg_core::text::Encoding;
use cg_harness::Text;

use super::read_notes;
use crate::derive::Missing;

/// What a command wrote.
#[derive(Clone, Debug, Default)]
pub struct Written {
    /// The output folder.
    pub folder: PathBuf,
    /// Files written, relative to the folder.
    pub files: Vec<String>,
    /// Files left alone (an existing report without `--force`).
    pub kept: Vec<String>,
    /// What could not be derived.
    pub missing: Vec<Missing>,
    /// The files read (the data file), each with the encoding it was read in.
    pub read: Vec<(PathBuf, Encoding)>,
}

impl Written {
    /// A summary for the terminal.
    #[must_use]
    pub fn summary(&self, lang: Lang) -> String {
        // What was read first (`table.md: read as Shift_JIS`), then what was written.
        let mut out = read_notes(&self.read, "", lang);
        let _ = writeln!(
            out,
            "{} {} ({} {})",
            t("書き出し先:", "written to").get(lang),
            self.folder.display(),
            self.files.len(),
            t("ファイル", "files").get(lang)
        );
        // The files at the top by name; a folder's (58 fragments) counted.
        let mut folders: BTreeMap<&str, usize> = BTreeMap::new();
        let mut top = Vec::new();
        for f in &self.files {
            match f.split_once('/') {
                Some((folder, _)) => *folders.entry(folder).or_default() += 1,
                None => top.push(f.as_str()),
            }
        }
        for line in top.chunks(4) {
            let _ = writeln!(out, "  {}", line.join(", "));
        }
        for (folder, n) in &folders {
            let what = if *folder == "fragments" {
                t(
                    "（表・行列・図を 1 つずつ Markdown と LaTeX で。自分の書式のレポートに貼れます）",
                    " (each table, matrix and figure in Markdown and LaTeX, to paste into a report of your own)",
                )
            } else {
                Text::default()
            };
            let _ = writeln!(
                out,
                "  {folder}/: {n} {}{}",
                t("ファイル", if *n == 1 { "file" } else { "files" }).get(lang),
                what.get(lang)
            );
        }
        for f in &self.kept {
            // What is new is in the fragments: the report keeps the student's writing.
            let fresh = if folders.contains_key("fragments") {
                t(
                    "。今のデータの表は fragments/ にあるので、変わったところを貼り替えてください",
                    "; the tables as the data now is are in fragments/: paste what changed",
                )
            } else {
                Text::default()
            };
            let _ = writeln!(
                out,
                "  {f}: {}{}",
                t(
                    "既にあるので上書きしません（--force で上書きすると書いた文章は消えます）",
                    "exists, left alone (--force overwrites it, and what you wrote in it)"
                )
                .get(lang),
                fresh.get(lang)
            );
        }
        if !self.missing.is_empty() {
            let _ = writeln!(
                out,
                "{}",
                t(
                    "まだ導出できない部分（レポートには「まだ導出できません」と書かれます）:",
                    "not derived yet (the report says so where they belong):"
                )
                .get(lang)
            );
            for m in &self.missing {
                let _ = writeln!(out, "  {}", m.message(lang));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `report fill`'s summary names the files at the top and counts a folder's (it listed 68
    /// files, one a line); a report kept says where the tables as they are now went.
    #[test]
    fn the_summary_counts_a_folders_files_and_says_where_fresh_tables_are() {
        let mut files: Vec<String> =
            ["report.tex", "a1-top.svg", "a1-side.svg", "a1-front.svg", "render-a1.png"]
                .map(str::to_owned)
                .to_vec();
        files.extend((0..58).map(|k| format!("fragments/f{k}.md")));
        let written = Written {
            folder: PathBuf::from("report"),
            files,
            kept: vec!["report.md".to_owned()],
            ..Written::default()
        };
        let en = written.summary(Lang::En);
        assert_eq!(
            en,
            "written to report (63 files)\n  report.tex, a1-top.svg, a1-side.svg, a1-front.svg\n  render-a1.png\n  fragments/: 58 files (each table, matrix and figure in Markdown and LaTeX, to paste into a report of your own)\n  report.md: exists, left alone (--force overwrites it, and what you wrote in it); the tables as the data now is are in fragments/: paste what changed\n"
        );
        let ja = written.summary(Lang::Ja);
        assert!(ja.contains("  fragments/: 58 ファイル（表・行列・図"), "{ja}");
        assert!(ja.contains("今のデータの表は fragments/ にある"), "{ja}");
        assert!(!ja.contains("fragments/f0.md"), "{ja}");
    }
}
