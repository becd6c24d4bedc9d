//! The kit writes two languages one way (docs/conventions.md, "Two languages"): a `Text` built
//! side by side and read with `.get(lang)`. This test reads every Rust file of the kit and fails
//! on the ways that were removed: `Lang::pick` / `lang.pick(…)`, `if ja { … }` and
//! `if lang == Lang::Ja { … }`, and a `match` that writes the same sentence twice, once per
//! language (`Lang::Ja => format!(…)`).

mod sources;

/// The forbidden forms found in `source`, as `line: text`.
fn findings(source: &str) -> Vec<String> {
    let forbidden = [
        ".pick(\"",
        "lang.pick(",
        "Lang::pick",
        "if ja {",
        "if lang == Lang::Ja {",
        "if lang == Lang::En {",
        "Lang::Ja => format!",
        "Lang::En => format!",
        "Lang::Ja => writeln!",
        "Lang::En => writeln!",
    ];
    source
        .lines()
        .enumerate()
        .filter(|(_, line)| !line.trim_start().starts_with("//"))
        .filter(|(_, line)| forbidden.iter().any(|f| line.contains(f)))
        .map(|(i, line)| format!("{}: {}", i + 1, line.trim()))
        .collect()
}

#[test]
fn one_way_to_write_two_languages() {
    let found = sources::scan(file!(), |_, source| findings(source));
    assert!(
        found.is_empty(),
        "write both languages as one Text (docs/conventions.md, \"Two languages\"):\n{}",
        found.join("\n")
    );
}

#[test]
fn the_scan_finds_each_removed_form() {
    for bad in [
        "let s = lang.pick(\"面\", \"face\");",
        "let w = if ja { \"面\" } else { \"face\" };",
        "if lang == Lang::Ja { a } else { b }",
        "    if lang == Lang::En { \"face\" } else { \"面\" }",
        "        Lang::Ja => format!(\"{n} 行目\"),",
        "            Lang::En => writeln!(out, \"x\"),",
    ] {
        assert_eq!(findings(bad).len(), 1, "{bad}");
    }
    assert!(findings("let s = t(\"面\", \"face\").get(lang);").is_empty());
    assert!(findings("// lang.pick(\"a\", \"b\") in a comment").is_empty());
    assert!(findings("let x = *rng.pick(&SIZES);").is_empty());
}
