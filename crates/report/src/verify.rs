//! Checking the numbers of a report against the data they must follow from: every vertex,
//! normal, matrix entry and texture coordinate that does not follow is a [`Finding`] that names
//! the item, what was written, the derived value and the tolerance used; a face whose vertex
//! order points its normal inward is named with the outward order.
//!
//! A written number with `d` decimals is accepted when it is correct to its last written digit,
//! rounded or cut off: `|written − derived| < 10^-max(d, 2)` (plus `1e-6·max(1, |derived|)` for
//! float noise) — see [`tolerance`]. So `0.49` and `0.48` pass for 0.4856, `0.53` does not, and
//! `1` passes for 0.9995 but not for 0.53.
//!
//! [`verify`] checks a report against what the kit derived from the student's own program
//! ([`verify_with`]: and against the student's assignment, for the periods of `a3`);
//! [`verify_data`] against a vertex and face list alone (see [`crate::parse::polygon_from_text`]),
//! where "outward" comes from the geometry of the closed model ([`face_outwardness`]).

use cg_core::glam::{DVec3, Mat4, Vec2, Vec3};
use cg_core::lang::Lang;
use cg_core::product::MatrixProduct;
use cg_harness::Text;

use crate::model::{Derived, TexRow, TextureData, Written};
use crate::parse::{FACTORS, ParsedFace, ParsedMatrix, ParsedReport, ParsedTex, ParsedVertex};

/// What a written number must be, said once under the findings that compare numbers (it ended
/// every one of them).
#[must_use]
pub fn accepted() -> Text {
    Text::new(
        "数値は、書いた最後の桁まで正しければ（四捨五入でも切り捨てでも）受け付けます",
        "a number is accepted when it is correct to its last written digit (rounded or cut off)",
    )
}

/// A number in a report that does not follow from the data (or a face wound the wrong way).
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    /// The 1-based line of the report.
    pub line: usize,
    /// What it is: `V3`, `F2 normal`, `F4 order`, `F4 vertices`,
    /// `a2.view.start (row 1, column 4)`, `tex (3, 5)`, `tex (3, 5) position`,
    /// `s.spot α = 15° (column 3)` (a shading table's row by its label, and the column).
    pub item: String,
    /// What the report says, as written (`{ 0.0, 0.53, 0.85 }`).
    pub written: String,
    /// What follows from the data (`{ 0.0, 0.4856, 0.8742 }`, `{ V1, V3, V2 }`).
    pub derived: String,
    /// The tolerance the numbers were compared with (the largest among the wrong ones); `None`
    /// for a vertex order.
    pub tolerance: Option<f64>,
    /// Which numbers are off and by how much, or why the order is wrong.
    pub why: Text,
}

/// `0.01` for 0.010001: the tolerance with its float-noise part cut off.
fn show_tolerance(tol: f64) -> String {
    let digits = ((-tol.log10()).ceil() + 1.0).clamp(1.0, 12.0) as usize;
    trim(format!("{tol:.digits$}"))
}

/// A written number as a message quotes it: at most 24 characters (a 400-digit number is not
/// printed whole).
fn short(text: &str) -> String {
    if text.chars().count() > 24 {
        format!("{}…", text.chars().take(23).collect::<String>())
    } else {
        text.to_owned()
    }
}

/// Trailing zeros (and a bare point) removed: `0.0100` → `0.01`.
fn trim(s: String) -> String {
    if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_owned() } else { s }
}

impl Finding {
    /// `line 14: F0 normal: written { 0.0, 0.53, 0.85 }, derived { 0.0, 0.4856, 0.8742 }
    /// (tolerance ±0.01) — y is 0.53 but …`, or in Japanese.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let (line, written, derived) = (self.line, &self.written, &self.derived);
        let tolerance = self.tolerance.map_or_else(Text::default, |t| {
            let t = show_tolerance(t);
            Text::new(format!("（許容誤差 ±{t}）"), format!(" (tolerance ±{t})"))
        });
        Text::new(
            format!(
                "{line} 行目: {}: 記入 `{written}`、導出値 `{derived}`{} — {}",
                item_ja(&self.item),
                tolerance.ja,
                self.why.ja
            ),
            format!(
                "line {line}: {}: written `{written}`, derived `{derived}`{} — {}",
                self.item, tolerance.en, self.why.en
            ),
        )
    }
}

/// A finding's item in Japanese: `F2 normal` → `F2 の法線`, `tex (3, 5)` → `テクスチャ (3, 5)`,
/// `a2.view.start (row 1, column 4)` → `a2.view.start（1 行 4 列）`.
fn item_ja(item: &str) -> String {
    let mut out = item.to_owned();
    if let Some(rest) = out.strip_prefix("tex ") {
        out = format!("テクスチャ座標 {rest}");
    }
    for (en, ja) in [
        (" normal", " の法線"),
        (" order", " の頂点の順序"),
        (" vertices", " の頂点"),
        (" position", " の位置"),
    ] {
        if let Some(head) = out.strip_suffix(en) {
            out = format!("{head}{ja}");
        }
    }
    if let Some(k) = out.find(" at (") {
        out = format!("{}（格子点 {}）", &out[..k], &out[k + 4..]);
    }
    if let Some(k) = out.find(" (column ") {
        let column = out[k + 9..].trim_end_matches(')').to_owned();
        out = format!("{}（{column} 列目）", &out[..k]);
    }
    if let Some(k) = out.find(" (row ") {
        let cell = out[k + 6..].trim_end_matches(')').replace(", column ", " 行 ");
        out = format!("{}（{cell} 列）", &out[..k]);
    }
    out
}

impl std::fmt::Display for Finding {
    /// The English [`Finding::message`].
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message(Lang::En))
    }
}

/// The result of checking a report.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Verification {
    /// Every number that does not follow, by line.
    pub findings: Vec<Finding>,
    /// How many written numbers were compared.
    pub checked: usize,
    /// What could not be checked and why: derived tables the report does not have at all, rows
    /// for items the data does not have, matrix tags with unknown IDs, degenerate faces.
    pub notes: Vec<Text>,
}

impl Verification {
    /// No finding (notes do not count).
    #[must_use]
    pub fn is_clean(&self) -> bool {
        self.findings.is_empty()
    }
}

/// The tolerance for a written number with `d` decimals (notation item 6):
/// `10^-max(d, 2) + 1e-6·max(1, |derived|)` — correct to the last written digit, rounded or cut
/// off; numbers with fewer than two decimals count as exact to 0.01; the second term absorbs the
/// float noise of the derived value.
#[must_use]
pub fn tolerance(w: &Written, derived: f64) -> f64 {
    let d = i32::try_from(w.decimals.clamp(2, 300)).unwrap_or(300);
    10f64.powi(-d) + 1e-6 * derived.abs().max(1.0)
}

/// Whether the written number follows from `derived` within [`tolerance`] (never for a
/// non-finite derived value).
#[must_use]
pub fn accepts(w: &Written, derived: f64) -> bool {
    derived.is_finite() && (w.value - derived).abs() < tolerance(w, derived)
}

/// A derived number with a digit more than was written (at least 4 decimals), trailing zeros
/// trimmed to one decimal: `0.4856`, `-1.0`, `0.0`.
fn show(x: f64, written_decimals: u32) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    let k = (written_decimals.saturating_add(1)).clamp(4, 12) as usize;
    let mut s = format!("{x:.k$}");
    while s.ends_with('0') && !s.ends_with(".0") {
        s.pop();
    }
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s.remove(0);
    }
    s
}

fn bracket(open: &str, parts: &[String], close: &str) -> String {
    if parts.len() == 1 {
        parts[0].clone()
    } else if open == "{" {
        format!("{{ {} }}", parts.join(", "))
    } else {
        format!("{open}{}{close}", parts.join(", "))
    }
}

fn face_text(v: [u32; 3]) -> String {
    format!("{{ V{}, V{}, V{} }}", v[0], v[1], v[2])
}

/// Collects findings, notes and the count of compared numbers.
#[derive(Default)]
pub(crate) struct Checker {
    pub(crate) out: Verification,
}

impl Checker {
    pub(crate) fn note(&mut self, ja: impl Into<String>, en: impl Into<String>) {
        self.out.notes.push(Text::new(ja, en));
    }

    /// Compares written numbers with derived ones component by component; one finding naming
    /// every component that is off.
    pub(crate) fn tuple(
        &mut self,
        line: usize,
        item: String,
        written: &[Written],
        derived: &[f64],
        names: &[&str],
        curly: bool,
    ) {
        let mut wrong = Vec::new();
        for (k, (w, &d)) in written.iter().zip(derived).enumerate() {
            if !d.is_finite() {
                continue;
            }
            self.out.checked += 1;
            if !accepts(w, d) {
                wrong.push(k);
            }
        }
        if wrong.is_empty() {
            return;
        }
        let (open, close) = if curly { ("{", "}") } else { ("(", ")") };
        let written_s: Vec<String> = written.iter().map(|w| short(&w.text)).collect();
        let derived_s: Vec<String> =
            written.iter().zip(derived).map(|(w, &d)| show(d, w.decimals)).collect();
        let tol = wrong.iter().map(|&k| tolerance(&written[k], derived[k])).fold(0.0, f64::max);
        let (mut ja, mut en) = (Vec::new(), Vec::new());
        for &k in &wrong {
            let name = names.get(k).copied().unwrap_or("");
            // Names of a whole value in Japanese (no space before は); `x`, `r`, … are the same
            // in both.
            let name_ja = match name {
                "value" => "値".to_owned(),
                "the entry" => "この成分".to_owned(),
                other => format!("{other} "),
            };
            // As many decimals as the derived value shows, so a difference is never "0".
            let digits = (written[k].decimals.saturating_add(1)).clamp(4, 12) as usize;
            let off = trim(format!("{:.digits$}", (written[k].value - derived[k]).abs()));
            let shown = short(&written[k].text);
            ja.push(format!("{name_ja}は {shown} ですが導出値は {}（差 {off}）", derived_s[k]));
            en.push(format!("{name} is {shown} but follows as {} (off by {off})", derived_s[k]));
        }
        // What is accepted is said once under the findings ([`accepted`]), not on each.
        let why = Text::new(ja.join("、"), en.join(", "));
        self.out.findings.push(Finding {
            line,
            item,
            written: bracket(open, &written_s, close),
            derived: bracket(open, &derived_s, close),
            tolerance: Some(tol),
            why,
        });
    }

    fn vertices(&mut self, rows: &[ParsedVertex], data: &[Vec3]) {
        let mut absent = Vec::new();
        for v in rows {
            match data.get(v.index as usize) {
                Some(p) => {
                    let d = p.as_dvec3().to_array();
                    self.tuple(
                        v.line,
                        format!("V{}", v.index),
                        &v.coords,
                        &d,
                        &["x", "y", "z"],
                        false,
                    );
                }
                None => absent.push((v.index, v.line)),
            }
        }
        absent::rows(self, 'V', &absent, data.len());
    }

    fn normal(&mut self, f: &ParsedFace, derived: Option<DVec3>) {
        match (derived, &f.normal) {
            (Some(_), None) => {}
            (Some(n), Some(w)) => {
                self.tuple(
                    f.line,
                    format!("F{} normal", f.index),
                    w,
                    &n.to_array(),
                    &["x", "y", "z"],
                    true,
                );
            }
            // A face with no area (a vertex twice, or three in a line) is no face of a
            // polyhedron, and its normal is no number: a mistake, not a note, whether or not a
            // normal is written.
            (None, written) => {
                let written = written.as_ref().map_or_else(
                    || face_text(f.vertices),
                    |w| bracket("{", &w.iter().map(|x| short(&x.text)).collect::<Vec<_>>(), "}"),
                );
                self.out.checked += 1;
                self.out.findings.push(Finding {
                    line: f.line,
                    item: format!("F{} normal", f.index),
                    written,
                    derived: "—".to_owned(),
                    tolerance: None,
                    why: Text::new(
                        "面積 0 の面です（同じ頂点が 2 回あるか、3 つの頂点が一直線上にあります）。法線は導出できません。多面体の面は面積のある三角形にしてください",
                        "the face has no area (a vertex twice, or three vertices in a line), so it has no normal: a face of a polyhedron is a triangle with an area",
                    ),
                });
            }
        }
    }

    fn order(&mut self, f: &ParsedFace) {
        let [a, b, c] = f.vertices;
        let outward = face_text([a, c, b]);
        self.out.findings.push(Finding {
            line: f.line,
            item: format!("F{} order", f.index),
            written: face_text(f.vertices),
            derived: outward.clone(),
            tolerance: None,
            why: Text::new(
                format!(
                    "外側から見て時計回りなので、法線 (V_b − V_a) × (V_c − V_a) が内側を向きます。外向きの順番は {outward}（またはその巡回）です"
                ),
                format!(
                    "the vertices run clockwise seen from outside, so the normal (V_b − V_a) × (V_c − V_a) points inward; the outward order is {outward} (or a rotation of it)"
                ),
            ),
        });
    }

    fn other_vertices(&mut self, f: &ParsedFace, data: [u32; 3]) {
        self.out.findings.push(Finding {
            line: f.line,
            item: format!("F{} vertices", f.index),
            written: face_text(f.vertices),
            derived: face_text(data),
            tolerance: None,
            why: Text::new(
                format!("データの F{} の頂点ではありません", f.index),
                format!("these are not the vertices of the data's F{}", f.index),
            ),
        });
    }

    fn matrices(&mut self, written: &[ParsedMatrix], unread: &[String], derived: &Derived) {
        let known = known_matrices(derived);
        // ID → the derived matrix, for the products and (`ID.factors.k`) their factors.
        let mut by_id: Vec<(String, Option<Mat4>)> = Vec::new();
        for k in &known {
            by_id.push((k.id.clone(), k.matrix));
            let ids = (1..=k.factors.len()).map(|i| format!("{}{FACTORS}.{i}", k.id));
            by_id.extend(ids.zip(k.factors.iter().map(|&f| Some(f))));
        }
        let mut unknown = Vec::new();
        for m in written {
            let Some((_, result)) = by_id.iter().find(|(id, _)| *id == m.id) else {
                unknown.push(m);
                continue;
            };
            let Some(mat) = result else {
                self.note(
                    format!("`{}`（{} 行目）: 行列を計算できませんでした", m.id, m.line),
                    format!("`{}` (line {}): the matrix could not be computed", m.id, m.line),
                );
                continue;
            };
            self.entries(m, mat);
        }
        // Factors written beyond the product's, and tags that name no derived matrix.
        let (extra, unknown): (Vec<&ParsedMatrix>, Vec<&ParsedMatrix>) = unknown
            .into_iter()
            .partition(|m| known.iter().any(|k| m.id.starts_with(&format!("{}{FACTORS}.", k.id))));
        absent::extra_factors(self, &extra, &known);
        absent::unknown_tags(self, &unknown, &known, derived);
        let missing: Vec<&str> = known
            .iter()
            // A matrix written but not read is a problem at its line already.
            .filter(|k| !written.iter().any(|m| m.id == k.id) && !unread.contains(&k.id))
            .map(|k| k.id.as_str())
            .collect();
        if !missing.is_empty() {
            let list = missing.join(", ");
            self.note(
                format!("レポートにタグ付きの行列がありません: {list}"),
                format!("no tagged matrix found in the report for: {list}"),
            );
        }
    }

    /// Each entry of a written matrix against the derived one.
    fn entries(&mut self, m: &ParsedMatrix, mat: &Mat4) {
        for (r, row) in m.rows.iter().enumerate().take(4) {
            for (c, w) in row.iter().enumerate().take(4) {
                let d = f64::from(mat.col(c)[r]);
                let line = m.entry_lines.get(r).and_then(|l| l.get(c)).copied().unwrap_or(m.line);
                self.tuple(
                    line,
                    format!("{} (row {}, column {})", m.id, r + 1, c + 1),
                    std::slice::from_ref(w),
                    &[d],
                    &["the entry"],
                    false,
                );
            }
        }
    }

    fn texture(&mut self, rows: &[ParsedTex], data: &TextureData) {
        for t in rows {
            let Some(row) = data.rows.iter().find(|r| r.i == t.i && r.j == t.j) else {
                self.note(
                    format!(
                        "格子点 ({}, {})（{} 行目）は導出したデータにありません",
                        t.i, t.j, t.line
                    ),
                    format!(
                        "grid vertex ({}, {}) (line {}) is not in the derived data",
                        t.i, t.j, t.line
                    ),
                );
                continue;
            };
            self.tuple(
                t.line,
                format!("tex ({}, {}) position", t.i, t.j),
                &t.position,
                &row.position.as_dvec3().to_array(),
                &["x", "y", "z"],
                false,
            );
            self.coordinates(t, row);
        }
    }

    /// The written coordinates as a set against the row's: the count must match and each
    /// written pair must match a different derived pair.
    fn coordinates(&mut self, t: &ParsedTex, row: &TexRow) {
        self.out.checked += 2 * t.tex.len();
        let unmatched = unmatched(&t.tex, &row.tex);
        if unmatched.is_empty() && t.tex.len() == row.tex.len() {
            return;
        }
        let pair = |w: &[Written; 2]| format!("({}, {})", w[0].text, w[1].text);
        let decimals = t.tex.iter().flatten().map(|w| w.decimals).max().unwrap_or(3);
        let dpair = |v: &Vec2| {
            format!("({}, {})", show(f64::from(v.x), decimals), show(f64::from(v.y), decimals))
        };
        let written: Vec<String> = t.tex.iter().map(pair).collect();
        let derived: Vec<String> = row.tex.iter().map(dpair).collect();
        let (mut ja, mut en) = (Vec::new(), Vec::new());
        if t.tex.len() != row.tex.len() {
            ja.push(format!(
                "{} 組書かれていますが、この格子点のテクスチャ座標は {} 組です（使う四角形ごとに座標が異なる格子点は、その組をすべて書きます）",
                t.tex.len(),
                row.tex.len()
            ));
            en.push(format!(
                "{} pairs are written but this grid vertex has {} (where the squares that use it give it different coordinates, write each of them)",
                t.tex.len(),
                row.tex.len()
            ));
        }
        if !unmatched.is_empty() {
            let list: Vec<String> = unmatched.iter().map(|&k| pair(&t.tex[k])).collect();
            let list = list.join(", ");
            ja.push(format!("{list} はどの導出値とも一致しません"));
            en.push(format!("{list} matches none of the derived coordinates"));
        }
        let tol = unmatched
            .iter()
            .flat_map(|&k| t.tex[k].iter())
            .map(|w| tolerance(w, 1.0))
            .fold(None, |acc: Option<f64>, x| Some(acc.map_or(x, |a| a.max(x))));
        self.out.findings.push(Finding {
            line: t.line,
            item: format!("tex ({}, {})", t.i, t.j),
            written: written.join(" / "),
            derived: derived.join(" / "),
            tolerance: tol,
            why: Text::new(ja.join("。"), en.join("; ")),
        });
    }

    fn finish(mut self) -> Verification {
        self.out.findings.sort_by(|a, b| a.line.cmp(&b.line).then_with(|| a.item.cmp(&b.item)));
        self.out
    }
}

/// The written pairs that match no derived pair, under the best one-to-one assignment (small
/// sets: exhaustive; larger ones: greedy).
fn unmatched(written: &[[Written; 2]], derived: &[Vec2]) -> Vec<usize> {
    let fits = |w: &[Written; 2], d: &Vec2| {
        accepts(&w[0], f64::from(d.x)) && accepts(&w[1], f64::from(d.y))
    };
    fn best(
        k: usize,
        used: &mut Vec<bool>,
        written: &[[Written; 2]],
        derived: &[Vec2],
        fits: &dyn Fn(&[Written; 2], &Vec2) -> bool,
    ) -> Vec<usize> {
        let Some(w) = written.get(k) else { return Vec::new() };
        // Leave this one unmatched…
        let mut best_rest = best(k + 1, used, written, derived, fits);
        best_rest.insert(0, k);
        // …or match it with each free derived pair that fits.
        for (m, d) in derived.iter().enumerate() {
            if !used[m] && fits(w, d) {
                used[m] = true;
                let rest = best(k + 1, used, written, derived, fits);
                used[m] = false;
                if rest.len() < best_rest.len() {
                    best_rest = rest;
                }
            }
        }
        best_rest
    }
    if written.len() <= 6 && derived.len() <= 8 {
        let mut used = vec![false; derived.len()];
        return best(0, &mut used, written, derived, &fits);
    }
    let mut used = vec![false; derived.len()];
    let mut out = Vec::new();
    for (k, w) in written.iter().enumerate() {
        match derived.iter().enumerate().find(|(m, d)| !used[*m] && fits(w, d)) {
            Some((m, _)) => used[m] = true,
            None => out.push(k),
        }
    }
    out
}

/// Every matrix the data derives, by ID: `a1.transform` (the polygon's model transform), the
/// camera's and the animation's, each with its factors ([`crate::tables::factor_matrices`]).
fn known_matrices(derived: &Derived) -> Vec<Known> {
    let mut products: Vec<(String, &MatrixProduct)> = Vec::new();
    if let Some(t) = derived.a1.as_ref().and_then(|p| p.transform.as_ref()) {
        products.push(("a1.transform".to_owned(), t));
    }
    if let Some(c) = &derived.a2 {
        products.extend(c.matrices.iter().map(|m| (m.id.clone(), &m.numeric)));
    }
    if let Some(a) = &derived.a3 {
        for (_, ms) in &a.objects {
            products.extend(ms.iter().map(|m| (m.id.clone(), &m.numeric)));
        }
    }
    products
        .into_iter()
        .map(|(id, p)| Known {
            matrix: p.matrix().ok(),
            factors: crate::tables::factor_matrices(p),
            id,
        })
        .collect()
}

/// A derived matrix: its ID, the product (`None` when it cannot be computed) and its factors.
struct Known {
    id: String,
    matrix: Option<Mat4>,
    factors: Vec<Mat4>,
}

/// How a written face's vertex numbers relate to the data's face.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Relation {
    /// The same cyclic order (a rotation is fine).
    Same,
    /// The same three vertices in the reverse order.
    Reversed,
    /// Other vertices.
    Different,
}

fn relation(written: [u32; 3], data: [u32; 3]) -> Relation {
    let [a, b, c] = data;
    if [[a, b, c], [b, c, a], [c, a, b]].contains(&written) {
        Relation::Same
    } else if [[a, c, b], [c, b, a], [b, a, c]].contains(&written) {
        Relation::Reversed
    } else {
        Relation::Different
    }
}

/// Checks a report against the data derived from the student's program: vertices by number
/// against `polygon.vertices`; each face's vertex order against the data's face of that number
/// (a rotation is fine, the reverse order is one `F4 order` finding, other vertices one
/// `F4 vertices` finding) and its written normal against the data's derived (outward) normal;
/// tagged matrices entry by entry against the derived matrix with that ID (`a1.transform` is the
/// polygon's transform); texture rows by (i, j): the position, and the coordinates as a set; the
/// tagged shading tables ([`crate::shading`]); the texture formula of `a4`, evaluated at every
/// ground vertex ([`crate::formula`]).
/// Items the report leaves out are not findings; derived tables the report lacks altogether,
/// the model's vertices and faces a table leaves out (the first ten named, the rest counted),
/// rows for items the data does not have and unknown tags are `notes`.
#[must_use]
pub fn verify(report: &ParsedReport, derived: &Derived) -> Verification {
    verify_with(report, derived, None)
}

/// [`verify`], and what follows from the student's `assignment` alone: the periods table of
/// `a3` ([`crate::periods`]). Without the assignment a written periods table is a note.
#[must_use]
pub fn verify_with(
    report: &ParsedReport,
    derived: &Derived,
    assignment: Option<&cg_assign::Variants>,
) -> Verification {
    let mut c = Checker::default();
    match &derived.a1 {
        Some(p) => {
            c.vertices(&report.vertices, &p.vertices);
            let mut absent = Vec::new();
            for f in &report.faces {
                let Some(&data) = p.faces.get(f.index as usize) else {
                    absent.push((f.index, f.line));
                    continue;
                };
                match relation(f.vertices, data) {
                    Relation::Different => {
                        c.other_vertices(f, data);
                        continue;
                    }
                    Relation::Reversed => c.order(f),
                    Relation::Same => {}
                }
                let n = p.derived_normals.get(f.index as usize).copied().flatten();
                c.normal(f, n.map(Vec3::as_dvec3));
            }
            absent::rows(&mut c, 'F', &absent, p.faces.len());
            missing::tables_missing(&mut c, report);
            missing::rows_missing(&mut c, report, p);
        }
        None => {
            if !report.vertices.is_empty() || !report.faces.is_empty() {
                c.note(
                    "ポリゴンモデルのデータがないので、頂点と面の表は確かめていません",
                    "there is no polygon data, so the vertex and face tables were not checked",
                );
            }
        }
    }
    c.matrices(&report.matrices, &report.unread_matrices, derived);
    crate::shading::verify(&mut c, &report.tables, derived.s.as_ref());
    crate::periods::verify(&mut c, &report.tables, assignment);
    crate::formula::verify(&mut c, &report.formulas, derived.a4.as_ref());
    match &derived.a4 {
        Some(t) => {
            c.texture(&report.tex, t);
            if report.tex.is_empty() {
                c.note(
                    "レポートにテクスチャ座標の表がありません",
                    "no texture-coordinate table found in the report",
                );
            }
        }
        None => {
            if !report.tex.is_empty() {
                c.note(
                    "テクスチャのデータがないので、テクスチャ座標の表は確かめていません",
                    "there is no texture data, so the texture-coordinate table was not checked",
                );
            }
        }
    }
    c.finish()
}

mod absent;
mod data;
mod missing;
mod outward;

pub use data::verify_data;
pub use outward::face_outwardness;

#[cfg(test)]
mod tests;
