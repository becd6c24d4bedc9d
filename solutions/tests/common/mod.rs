//! Whether a report reads in one language: the Japanese report has no English words, the
//! English one no Japanese characters. Shared by the assignments' tests (`mod common;`).

use std::collections::BTreeMap;

use cg_core::lang::Lang;
use cg_harness::check::Report;

/// Words every Japanese report may hold: `panic` in the report's own 「異常終了しました（panic）」,
/// and the names of the language and library the course uses (`Rust`, `GLUT`).
const SHARED: &[&str] = &["panic", "Rust", "GLUT"];

/// The words of `text` that look English.
///
/// `text` is cut into tokens of ASCII letters, digits, `_`, `.` and `:` (a trailing `.` or `:`
/// dropped: the end of a sentence). A token is a word when it is only letters, at least four,
/// lower case after the first (`drawn`, `Expected`) or all capitals (`NOTE`); it is English
/// unless `allowed` or [`SHARED`] has it. Tokens shaped like code are not words: with a digit,
/// `_`, `.` or `::` (`camera_pitch`, `GL_REPEAT`, `theta_2`, `n.normalize`, `Vec3::new`, a
/// method `.then`) or a capital inside (`glRotatef`, `OpenGL`, `MatrixProduct`), so the
/// allow-lists only need the identifiers that are plain words (`vertices`, `display`, `todo`).
/// The kit's command lines are skipped too (`cargo run --release -- check a1`, up to two
/// spaces or the next non-ASCII character).
pub fn english_words<'a>(text: &'a str, allowed: &[&str]) -> Vec<&'a str> {
    let mut rest = text;
    let mut words = Vec::new();
    while let Some(at) = rest.find("cargo ") {
        words.extend(words_of(&rest[..at], allowed));
        let command = &rest[at..];
        let end = command
            .find("  ")
            .into_iter()
            .chain(command.find(|c: char| !c.is_ascii()))
            .min()
            .unwrap_or(command.len());
        rest = &command[end..];
    }
    words.extend(words_of(rest, allowed));
    words
}

/// Whether `token` is a word: letters only, four or more, lower case after the first or all
/// capitals.
fn is_word(token: &str) -> bool {
    let mut chars = token.chars();
    let Some(first) = chars.next() else { return false };
    let rest: Vec<char> = chars.collect();
    first.is_ascii_alphabetic()
        && rest.len() >= 3
        && (rest.iter().all(char::is_ascii_lowercase)
            || (first.is_ascii_uppercase() && rest.iter().all(char::is_ascii_uppercase)))
}

fn words_of<'a>(text: &'a str, allowed: &[&str]) -> impl Iterator<Item = &'a str> {
    let is_token = |c: char| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | ':');
    text.split(move |c: char| !is_token(c))
        .map(|raw| raw.trim_end_matches(['.', ':']))
        .filter(move |token| is_word(token) && !allowed.contains(token) && !SHARED.contains(token))
}

/// Whether `c` is Japanese: kana, kanji, or the full-width punctuation that goes with them.
pub fn is_japanese(c: char) -> bool {
    matches!(c,
        '\u{3000}'..='\u{303f}' // 、。「」
        | '\u{3040}'..='\u{30ff}' // hiragana, katakana
        | '\u{3400}'..='\u{4dbf}' | '\u{4e00}'..='\u{9fff}' // kanji
        | '\u{ff00}'..='\u{ffef}') // full-width forms: （）：
}

/// `report` without what it quotes verbatim from the student's own code: the message of a stub's
/// `todo!("<task>: …")` after 「まだです: 」 / `not done yet: `, and a panic's message and
/// place. Those are the code's words, not the checks'.
pub fn without_quoted_code(report: &str) -> String {
    const QUOTES: [&str; 6] = [
        "まだです: ",
        "not done yet: ",
        "プログラムが異常終了しました（panic）: ",
        "your code panicked: ",
        "場所: ",
        "at: ",
    ];
    report
        .lines()
        .map(|line| {
            let body = line.trim_start();
            QUOTES
                .iter()
                .find(|q| body.starts_with(*q))
                .map_or(line, |q| &line[..line.len() - body.len() + q.len()])
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// `text` up to the panic message it quotes (after `（panic）: ` or `panicked: `), for the views'
/// explanations.
#[allow(dead_code)] // Not every assignment's test needs it.
pub fn without_panic_message(text: &str) -> &str {
    ["（panic）: ", "panicked: "]
        .iter()
        .find_map(|m| text.find(m).map(|at| &text[..at + m.len()]))
        .unwrap_or(text)
}

/// What is wrong with the languages of `ja` (no English word outside `allowed`) and `en` (no
/// Japanese character): one line per offending word or character, each with the line it is in.
pub fn language_problems(context: &str, ja: &str, en: &str, allowed: &[&str]) -> Vec<String> {
    let mut problems = Vec::new();
    for line in without_quoted_code(ja).lines() {
        for word in english_words(line, allowed) {
            problems.push(format!("{context}: ja: {word:?} in {:?}", line.trim()));
        }
    }
    for line in without_quoted_code(en).lines() {
        if let Some(c) = line.chars().find(|&c| is_japanese(c)) {
            problems.push(format!("{context}: en: {c:?} in {:?}", line.trim()));
        }
    }
    problems
}

/// The problems of each report rendered in each language (see [`language_problems`]).
pub fn report_problems(context: &str, report: &Report, allowed: &[&str]) -> Vec<String> {
    language_problems(context, &report.render(Lang::Ja), &report.render(Lang::En), allowed)
}

/// Fails listing every problem, each offending word once (with the first place it was seen).
pub fn assert_no_problems(problems: &[String]) {
    let mut first: BTreeMap<String, &String> = BTreeMap::new();
    for p in problems {
        let key = p.split_once(": ").map_or(p.as_str(), |(_, rest)| rest);
        let word = key.split(" in ").next().unwrap_or(key).to_owned();
        first.entry(word).or_insert(p);
    }
    assert!(
        problems.is_empty(),
        "{} problems, {} different words or characters:\n{}",
        problems.len(),
        first.len(),
        first.values().map(|p| p.as_str()).collect::<Vec<_>>().join("\n")
    );
}
