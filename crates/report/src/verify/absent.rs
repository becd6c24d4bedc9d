//! Notes for what a report writes that the data does not have, one note per kind however many
//! rows it is: vertices and faces past the data's count (`V8–V15 (lines 54–61)`), factors past a
//! product's, and matrix tags that name no derived matrix — a product and its factors said once,
//! and every tag of a part that could not be derived said in one note that says so. A report
//! copied from another student's model or filled from unwritten functions named each row in a
//! note of its own (dozens of notes, the same one twice).

use std::collections::BTreeMap;

use cg_harness::Text;

use super::{Checker, Known};
use crate::model::Derived;
use crate::parse::{FACTORS, ParsedMatrix};

/// How many runs a list names; the rest are counted.
const RUNS: usize = 10;

/// `8–15, 17` for 8, 9, …, 15, 17 (each number written with `prefix`: `V8–V15, V17`): the
/// numbers sorted, each run of consecutive ones as its ends, the first [`RUNS`] runs named and
/// the rest counted.
pub(super) fn runs(prefix: &str, numbers: impl IntoIterator<Item = u64>) -> Text {
    let mut sorted: Vec<u64> = numbers.into_iter().collect();
    sorted.sort_unstable();
    sorted.dedup();
    let mut spans: Vec<(u64, u64)> = Vec::new();
    for n in sorted {
        match spans.last_mut() {
            Some((_, end)) if *end + 1 == n => *end = n,
            _ => spans.push((n, n)),
        }
    }
    let say = |dash: &str| {
        spans
            .iter()
            .take(RUNS)
            .map(|&(a, b)| match b - a {
                0 => format!("{prefix}{a}"),
                1 => format!("{prefix}{a}, {prefix}{b}"),
                _ => format!("{prefix}{a}{dash}{prefix}{b}"),
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    match spans.len().saturating_sub(RUNS) {
        0 => Text::new(say("〜"), say("–")),
        more => Text::new(
            format!("{} ほか {more} か所", say("〜")),
            format!("{} and {more} more runs", say("–")),
        ),
    }
}

/// `line 54` or `lines 54–61`, in both languages (`54 行目`, `54〜61 行目`).
fn lines(numbers: &[usize]) -> Text {
    let list = runs("", numbers.iter().map(|&n| n as u64));
    let one = numbers.iter().min() == numbers.iter().max();
    Text::new(
        format!("{} 行目", list.ja),
        format!("{} {}", if one { "line" } else { "lines" }, list.en),
    )
}

/// Rows `(number, line)` of the vertex (`kind` `'V'`) or face (`'F'`) table that the data, with
/// `count` of them, does not have: one note.
pub(super) fn rows(c: &mut Checker, kind: char, absent: &[(u32, usize)], count: usize) {
    let Some(&(first, _)) = absent.first() else { return };
    let (ja_kind, en_kind, en_kinds) =
        if kind == 'V' { ("頂点", "vertex", "vertices") } else { ("面", "face", "faces") };
    let at = lines(&absent.iter().map(|&(_, l)| l).collect::<Vec<_>>());
    let named = runs(&kind.to_string(), absent.iter().map(|&(k, _)| u64::from(k)));
    if absent.iter().all(|&(k, _)| k == first) {
        c.note(
            format!("{kind}{first}（{}）: データに {kind}{first} はありません（{ja_kind}は {count} 個）", at.ja),
            format!("{kind}{first} ({}): the data has no {kind}{first} (it has {count} {en_kinds})", at.en),
        );
        return;
    }
    let (ja_have, en_have) = match count {
        0 => (String::new(), String::new()),
        1 => (format!(": {kind}0"), format!(": {kind}0")),
        n => (format!(": {kind}0〜{kind}{}", n - 1), format!(": {kind}0–{kind}{}", n - 1)),
    };
    c.note(
        format!(
            "{}（{}）: データにこれらの{ja_kind}はありません（{ja_kind}は {count} 個{ja_have}。別のモデルの表ではありませんか）",
            named.ja, at.ja
        ),
        format!(
            "{} ({}): the data has no such {en_kind} (it has {count} {en_kinds}{en_have}; is the table from another model?)",
            named.en, at.en
        ),
    );
}

/// The product a tag names: `a2.view.start` for itself and for `a2.view.start.factors.3`.
fn product_of(tag: &str) -> &str {
    match tag.rsplit_once('.') {
        Some((head, k)) if k.bytes().all(|b| b.is_ascii_digit()) && !k.is_empty() => {
            head.strip_suffix(FACTORS).unwrap_or(tag)
        }
        _ => tag,
    }
}

/// Whether the part a tag belongs to (`a2` of `a2.view.start`) was derived: `false` only for a
/// part that makes matrices and could not be derived from the student's program.
fn part_derived(tag: &str, derived: &Derived) -> bool {
    match tag.split('.').next() {
        Some("a1") => derived.a1.is_some(),
        Some("a2") => derived.a2.is_some(),
        Some("a3") => derived.a3.is_some(),
        _ => true,
    }
}

/// `` `a2.view.start`, `a2.view.rotate` `` and whether any factor was among the tags: the products
/// of `tags`, each once, in the order written.
fn products<'a>(tags: &[&'a ParsedMatrix]) -> (Vec<&'a str>, bool) {
    let mut out: Vec<&str> = Vec::new();
    for m in tags {
        let p = product_of(&m.id);
        if !out.contains(&p) {
            out.push(p);
        }
    }
    let factors = tags.iter().any(|m| product_of(&m.id) != m.id);
    (out, factors)
}

/// How a note names `tags`: their products in backticks (`` `a2.view.start`, `a2.view.pan` ``),
/// how many products, whether a factor was among the tags, and their lines.
fn said(tags: &[&ParsedMatrix]) -> (String, usize, bool, Text) {
    let (names, factors) = products(tags);
    let list = names.iter().map(|p| format!("`{p}`")).collect::<Vec<_>>().join(", ");
    (list, names.len(), factors, lines(&tags.iter().map(|m| m.line).collect::<Vec<_>>()))
}

/// The tags written past a product's factors (`a3.object3.t0.factors.4` where the product has
/// three): one note per product.
pub(super) fn extra_factors(c: &mut Checker, extra: &[&ParsedMatrix], known: &[Known]) {
    let mut by_product: BTreeMap<&str, Vec<&ParsedMatrix>> = BTreeMap::new();
    for m in extra {
        by_product.entry(product_of(&m.id)).or_default().push(m);
    }
    for (product, tags) in by_product {
        let have = known.iter().find(|k| k.id == product).map_or(0, |k| k.factors.len());
        let mut names: Vec<String> = tags.iter().map(|m| format!("`{}`", m.id)).collect();
        names.dedup();
        let names = names.join(", ");
        let at = lines(&tags.iter().map(|m| m.line).collect::<Vec<_>>());
        c.note(
            format!(
                "{names}（{}）: 積 `{product}` の因子は {have} 個なので、それより後の因子は確かめていません",
                at.ja
            ),
            format!(
                "{names} ({}): the product `{product}` has {have} factors, so the ones after them are not checked",
                at.en
            ),
        );
    }
}

/// Tags that name no derived matrix: those of a part that could not be derived in one note per
/// note (the parts' own account says why), the others in one note with the tags the kit knows.
pub(super) fn unknown_tags(
    c: &mut Checker,
    unknown: &[&ParsedMatrix],
    known: &[Known],
    derived: &Derived,
) {
    let (underived, unknown): (Vec<&ParsedMatrix>, Vec<&ParsedMatrix>) =
        unknown.iter().partition(|m| !part_derived(&m.id, derived));
    if !underived.is_empty() {
        let mut parts: Vec<&str> =
            underived.iter().map(|m| m.id.split('.').next().unwrap_or_default()).collect();
        parts.sort_unstable();
        parts.dedup();
        let (list, names, factors, at) = said(&underived);
        let (ja_factors, en_factors) = match (factors, names) {
            (false, _) => ("", ""),
            (true, 1) => (" とその因子", " and its factors"),
            (true, _) => (" とその因子", " and their factors"),
        };
        let en_parts = match parts.split_last() {
            Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
            _ => parts.join(""),
        };
        let ja_parts = parts.join("・");
        c.note(
            format!(
                "{list}{ja_factors}（{}）: {ja_parts} をプログラムから導出できなかったので、これらの行列は確かめていません",
                at.ja
            ),
            format!(
                "{list}{en_factors} ({}): {en_parts} could not be derived from your program, so these matrices were not checked",
                at.en
            ),
        );
    }
    if unknown.is_empty() {
        return;
    }
    let ids: Vec<&str> = known.iter().map(|k| k.id.as_str()).collect();
    let known_list = if ids.is_empty() { "—".to_owned() } else { ids.join(", ") };
    let (tags, names, factors, at) = said(&unknown);
    let (ja_factors, en_factors) = match (factors, names) {
        (false, _) => ("", ""),
        (true, 1) => ("（とその因子）", " (or its factors)"),
        (true, _) => ("（とその因子）", " (or their factors)"),
    };
    c.note(
        format!(
            "タグ {tags}{ja_factors}（{}）に対応する導出済みの行列がないので確かめていません（あるのは {known_list}）",
            at.ja
        ),
        format!(
            "no derived matrix has the tag {tags}{en_factors} ({}), so it was not checked; known: {known_list}",
            at.en
        ),
    );
}
