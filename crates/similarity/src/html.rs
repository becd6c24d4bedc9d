//! `similarity.html`: one self-contained page (no script, no link outside it; every text from a
//! submission escaped). The listed pairs and their clusters, the cross-variant findings, the
//! closest pairs below the threshold, and for each listed pair its files side by side with the
//! matching regions highlighted, region by region in the same colour on both sides.

use std::collections::BTreeSet;
use std::fmt::Write as _;

use cg_core::lang::{Lang, Text, t};

use crate::{Analysis, Pair, Submission, output, winnow};

/// `s` with `& < > " '` escaped for HTML text and attributes.
#[must_use]
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

const STYLE: &str = "body{font-family:sans-serif;margin:1.5em;color:#222}\
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #bbb;padding:.2em .5em;text-align:left;vertical-align:top}\
th{background:#eee}.num{text-align:right}.side{display:flex;gap:1em;align-items:flex-start}\
.side>div{flex:1;min-width:0;overflow-x:auto}pre{margin:0;font-size:12px;line-height:1.35}\
.l{display:block;white-space:pre}.n{color:#888;display:inline-block;width:3.5em;text-align:right;margin-right:.8em;user-select:none}\
.r0{background:#ffe08a}.r1{background:#a8e6a1}.r2{background:#a9d1ff}.r3{background:#f8b4d9}.r4{background:#d3c4ff}.r5{background:#ffc49b}\
.flag{color:#b00;font-weight:bold}.note{color:#555}h3{margin-top:2em}";

fn who(s: &Submission, lang: Lang) -> String {
    let reference = if s.reference {
        format!(" <span class=\"note\">({})</span>", t("参照", "reference").get(lang))
    } else {
        String::new()
    };
    format!("{} <span class=\"note\">{}</span>{reference}", escape(&s.name), escape(&s.number()))
}

/// The whole page in `lang`.
#[must_use]
pub fn page(class: &[Submission], analysis: &Analysis, lang: Lang) -> String {
    let tr = |ja: &str, en: &str| t(ja, en).get(lang).to_owned();
    let mut h = String::new();
    let lang_attr = lang.to_string();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"{lang_attr}\"><head><meta charset=\"utf-8\"><title>{}</title><style>{STYLE}</style></head><body>\n<h1>{}</h1>\n",
        tr("類似度", "Similarity"),
        tr("コピーの検出", "Copies found")
    );
    let settings = analysis.settings.unwrap_or_default();
    let this_year = class.iter().filter(|s| !s.reference).count();
    let (k, w, references) = (winnow::K, winnow::W, class.len() - this_year);
    let run = k + w - 1;
    let (threshold, min_shared, max_share) =
        (settings.threshold, settings.min_shared, settings.max_share);
    let summary = Text::new(
        format!(
            "今年の提出物 {this_year} 件、参照（過去の年度）{references} 件。Rust のトークン（識別子とリテラルは正規化）を k = {k}、w = {w} で winnowing（共通する {run} トークン以上の連続は必ず見つかります）。しきい値 {threshold}、共有する指紋は {min_shared} 個以上、{max_share} 件を超える提出物にある指紋は共通のコードとして数えません。スタブとそのヒントのコードは配布したコードとして除きます。"
        ),
        format!(
            "This year's submissions: {this_year}; references (earlier years): {references}. Winnowing over Rust tokens (identifiers and literals normalised) with k = {k}, w = {w}: every shared run of {run} tokens or more is found. Threshold {threshold}, at least {min_shared} shared fingerprints; a fingerprint in more than {max_share} submissions is common code. The stubs and the code of their hints are base code."
        ),
    );
    let _ = writeln!(h, "<p>{}</p>", escape(summary.get(lang)));
    let refused: Vec<&Submission> = class.iter().filter(|s| s.refused.is_some()).collect();
    if !refused.is_empty() {
        let _ = writeln!(
            h,
            "<h2>{}</h2><ul>",
            tr("読めなかった提出物", "Submissions that could not be read")
        );
        for s in refused {
            let why = s.refused.as_ref().map(|w| w.get(lang).to_owned()).unwrap_or_default();
            let _ = writeln!(h, "<li>{}: {}</li>", escape(&s.name), escape(&why));
        }
        h.push_str("</ul>\n");
    }

    let _ = writeln!(h, "<h2>{}</h2>", tr("しきい値以上の組", "Pairs at or above the threshold"));
    if analysis.pairs.is_empty() {
        let _ = writeln!(h, "<p>{}</p>", tr("ありません。", "None."));
    } else {
        pair_table(&mut h, class, &analysis.pairs, true, lang);
    }
    if !analysis.clusters.is_empty() {
        let _ = writeln!(h, "<h2>{}</h2><ol>", tr("クラスタ", "Clusters"));
        for c in &analysis.clusters {
            let names: Vec<String> = c.iter().map(|i| who(&class[*i], lang)).collect();
            let _ = writeln!(h, "<li>{}</li>", names.join(", "));
        }
        h.push_str("</ol>\n");
    }

    let _ = writeln!(
        h,
        "<h2>{}</h2><p class=\"note\">{}</p>",
        tr("ほかの学生の課題から出た数値", "Numbers from another student's variant"),
        tr(
            "提出物のコード（ファイルごと）やレポートの数値が、本人の課題ではなくほかの学生の課題から出ているもの。多くの課題に共通する数値は根拠にしません。",
            "Files or reports whose numbers follow from another student's variant rather than the student's own. Numbers common to many variants are no evidence."
        )
    );
    if analysis.cross.is_empty() {
        let _ = writeln!(h, "<p>{}</p>", tr("ありません。", "None."));
    } else {
        let _ = writeln!(
            h,
            "<table><tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>",
            tr("提出物", "Submission"),
            tr("部分", "Part"),
            tr("一致する課題の学生（提出物）", "Variant of (submissions)"),
            tr("根拠", "Evidence"),
        );
        for c in &analysis.cross {
            let sources: Vec<String> = c.sources.iter().map(|i| escape(&class[*i].name)).collect();
            let _ = writeln!(
                h,
                "<tr><td>{}</td><td>{}</td><td class=\"flag\">{} <span class=\"note\">{}</span></td><td>{}</td></tr>",
                who(&class[c.submission], lang),
                escape(&c.finding.part),
                escape(c.finding.matches.as_str()),
                sources.join(", "),
                escape(&output::cross_note(c, &class[c.submission], lang)),
            );
        }
        h.push_str("</table>\n");
    }

    if !analysis.near.is_empty() {
        let _ = writeln!(
            h,
            "<h2>{}</h2>",
            tr(
                "しきい値未満で最も近い組（参考）",
                "The closest pairs below the threshold (for scale)"
            )
        );
        pair_table(&mut h, class, &analysis.near, false, lang);
    }
    for (n, p) in analysis.pairs.iter().enumerate().take(MAX_DETAILED) {
        detail(&mut h, class, p, n + 1, lang);
    }
    if analysis.pairs.len() > MAX_DETAILED {
        let more = analysis.pairs.len() - MAX_DETAILED;
        let _ = writeln!(
            h,
            "<p class=\"note\">{}</p>",
            Text::new(
                format!(
                    "ほかの {more} 組は、ファイルを並べた表示を省きました（上の表と similarity.csv にすべてあります）"
                ),
                format!(
                    "the other {more} pairs are not shown side by side (the table above and similarity.csv list them all)"
                ),
            )
            .get(lang)
        );
    }
    h.push_str("</body></html>\n");
    h
}

/// The most pairs shown side by side, file by file: 200 copies of one submission list 19 900
/// pairs, whose files side by side made a page of 5 GB.
pub const MAX_DETAILED: usize = 200;

fn pair_table(h: &mut String, class: &[Submission], pairs: &[Pair], linked: bool, lang: Lang) {
    let tr = |ja: &str, en: &str| t(ja, en).get(lang).to_owned();
    let _ = writeln!(
        h,
        "<table><tr><th>#</th><th>A</th><th>B</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>",
        tr("類似度", "Score"),
        tr("共有する指紋", "Shared fingerprints"),
        tr("共有する行 A / B", "Shared lines A / B"),
        tr("クラスタ", "Cluster"),
    );
    for (n, p) in pairs.iter().enumerate() {
        let number = if linked && n < MAX_DETAILED {
            format!("<a href=\"#pair-{}\">{}</a>", n + 1, n + 1)
        } else {
            (n + 1).to_string()
        };
        let _ = writeln!(
            h,
            "<tr><td>{number}</td><td>{}</td><td>{}</td><td class=\"num\">{:.0}%</td><td class=\"num\">{}</td><td class=\"num\">{} / {}</td><td class=\"num\">{}</td></tr>",
            who(&class[p.a], lang),
            who(&class[p.b], lang),
            p.score * 100.0,
            p.shared,
            p.lines_a,
            p.lines_b,
            p.cluster.map(|c| c.to_string()).unwrap_or_default(),
        );
    }
    h.push_str("</table>\n");
}

/// A pair's regions, then each pair of files with regions side by side.
fn detail(h: &mut String, class: &[Submission], p: &Pair, n: usize, lang: Lang) {
    let tr = |ja: &str, en: &str| t(ja, en).get(lang).to_owned();
    let (a, b) = (&class[p.a], &class[p.b]);
    let _ = writeln!(
        h,
        "<h3 id=\"pair-{n}\">{} {n}: {} — {} ({:.0}%)</h3><ol>",
        tr("組", "Pair"),
        who(a, lang),
        who(b, lang),
        p.score * 100.0
    );
    for (i, r) in p.regions.iter().enumerate() {
        let _ = writeln!(
            h,
            "<li><span class=\"r{}\">A {}.rs {}–{} ↔ B {}.rs {}–{}</span> <span class=\"note\">({} {})</span></li>",
            i % 6,
            escape(&r.module_a),
            r.lines_a.0,
            r.lines_a.1,
            escape(&r.module_b),
            r.lines_b.0,
            r.lines_b.1,
            r.fingerprints,
            tr("個の指紋", "fingerprints"),
        );
    }
    h.push_str("</ol>\n");
    let files: BTreeSet<(&str, &str)> =
        p.regions.iter().map(|r| (r.module_a.as_str(), r.module_b.as_str())).collect();
    for (ma, mb) in files {
        let _ = writeln!(h, "<div class=\"side\"><div><b>A: {}.rs</b>", escape(ma));
        let here =
            || p.regions.iter().enumerate().filter(|(_, r)| r.module_a == ma && r.module_b == mb);
        let spans_a: Vec<(usize, &BTreeSet<usize>)> =
            here().map(|(i, r)| (i, &r.marked_a)).collect();
        let spans_b: Vec<(usize, &BTreeSet<usize>)> =
            here().map(|(i, r)| (i, &r.marked_b)).collect();
        code(h, a.modules.get(ma).map_or("", String::as_str), &spans_a);
        let _ = writeln!(h, "</div><div><b>B: {}.rs</b>", escape(mb));
        code(h, b.modules.get(mb).map_or("", String::as_str), &spans_b);
        h.push_str("</div></div>\n");
    }
}

/// A file's lines, numbered, each line of a region's tokens coloured as its region.
fn code(h: &mut String, text: &str, spans: &[(usize, &BTreeSet<usize>)]) {
    h.push_str("<pre>");
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let class = spans
            .iter()
            .find(|(_, lines)| lines.contains(&n))
            .map(|(r, _)| format!(" r{}", r % 6))
            .unwrap_or_default();
        let _ = write!(
            h,
            "<span class=\"l{class}\"><span class=\"n\">{n}</span>{}</span>",
            escape(line)
        );
    }
    h.push_str("</pre>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_from_a_submission_is_escaped() {
        assert_eq!(escape("<script>&\"'"), "&lt;script&gt;&amp;&quot;&#39;");
        let class = vec![Submission {
            name: "<b>x</b>".to_owned(),
            refused: Some(cg_core::lang::Text::new("<i>", "<i>")),
            ..Submission::default()
        }];
        let page = page(&class, &Analysis::default(), Lang::En);
        assert!(!page.contains("<b>x</b>") && !page.contains("<i>"), "{page}");
        assert!(page.contains("&lt;b&gt;x&lt;/b&gt;"));
    }
}
