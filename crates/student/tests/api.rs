//! A reviewed snapshot of the students' API: every public item of `cg-student`, listed from the
//! source, must equal `crates/student/api.txt`. A change to what students can reach (a new
//! function, a re-export, a public method) then shows in review as a change of that file, and
//! happens only on purpose.
//!
//! To accept a change: run this test, read `target/student-api.txt` (the list it found) against
//! `api.txt`, and copy it over when every new line is a type, a spec or a recorder — never
//! something that computes an answer.

use std::path::Path;

use quote::ToTokens;
use syn::{ImplItem, Item, Visibility};

fn is_pub(vis: &Visibility) -> bool {
    matches!(vis, Visibility::Public(_))
}

fn tokens(t: &impl ToTokens) -> String {
    t.to_token_stream().to_string()
}

/// The public items of one module file, as sorted lines `kind path: signature`.
fn items(module: &str, items: &[Item], out: &mut Vec<String>) {
    for item in items {
        match item {
            Item::Fn(f) if is_pub(&f.vis) => out.push(format!("{module}: {}", tokens(&f.sig))),
            Item::Struct(s) if is_pub(&s.vis) => {
                out.push(format!("struct {module}::{}", s.ident));
                for field in &s.fields {
                    if is_pub(&field.vis) {
                        let name =
                            field.ident.as_ref().map(ToString::to_string).unwrap_or_default();
                        out.push(format!(
                            "field {module}::{}.{name}: {}",
                            s.ident,
                            tokens(&field.ty)
                        ));
                    }
                }
            }
            Item::Enum(e) if is_pub(&e.vis) => {
                out.push(format!("enum {module}::{}", e.ident));
                for v in &e.variants {
                    out.push(format!(
                        "variant {module}::{}::{} {}",
                        e.ident,
                        v.ident,
                        tokens(&v.fields)
                    ));
                }
            }
            Item::Const(c) if is_pub(&c.vis) => {
                out.push(format!("const {module}::{}: {}", c.ident, tokens(&c.ty)));
            }
            Item::Type(t) if is_pub(&t.vis) => {
                out.push(format!("type {module}::{} = {}", t.ident, tokens(&t.ty)));
            }
            Item::Use(u) if is_pub(&u.vis) => {
                out.push(format!("use {module}: {}", tokens(&u.tree)))
            }
            Item::Mod(m) if is_pub(&m.vis) => out.push(format!("mod {module}::{}", m.ident)),
            Item::Trait(t) if is_pub(&t.vis) => out.push(format!("trait {module}::{}", t.ident)),
            Item::Macro(m) if m.mac.path.is_ident("macro_rules") => {
                out.push(format!("macro {module}: {}", tokens(&m.ident)));
            }
            Item::Impl(i) => {
                let ty = tokens(&i.self_ty);
                if let Some((_, path, _)) = &i.trait_ {
                    out.push(format!("impl {module}: {} for {ty}", tokens(path)));
                    continue;
                }
                for member in &i.items {
                    match member {
                        ImplItem::Fn(f) if is_pub(&f.vis) => {
                            out.push(format!("{module}::{ty}: {}", tokens(&f.sig)));
                        }
                        ImplItem::Const(c) if is_pub(&c.vis) => {
                            out.push(format!("const {module}::{ty}::{}", c.ident));
                        }
                        _ => {}
                    }
                }
            }
            _ => {}
        }
    }
}

fn derives(items: &[Item], module: &str, out: &mut Vec<String>) {
    // Derived traits are part of the API too (a derived `Default` hands out a value).
    for item in items {
        let (attrs, name) = match item {
            Item::Struct(s) if is_pub(&s.vis) => (&s.attrs, s.ident.to_string()),
            Item::Enum(e) if is_pub(&e.vis) => (&e.attrs, e.ident.to_string()),
            _ => continue,
        };
        for attr in attrs.iter().filter(|a| a.path().is_ident("derive")) {
            out.push(format!("derive {module}::{name}: {}", tokens(&attr.meta)));
        }
    }
}

#[test]
fn the_students_api_is_the_reviewed_snapshot() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut lines = Vec::new();
    let mut files: Vec<_> = std::fs::read_dir(dir.join("src"))
        .expect("src")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .collect();
    files.sort();
    for file in files {
        let stem = file.file_stem().and_then(|s| s.to_str()).unwrap_or_default().to_owned();
        let module =
            if stem == "lib" { "cg_student".to_owned() } else { format!("cg_student::{stem}") };
        let text = std::fs::read_to_string(&file).expect("source");
        let parsed = syn::parse_file(&text).expect("the source parses");
        items(&module, &parsed.items, &mut lines);
        derives(&parsed.items, &module, &mut lines);
    }
    lines.sort();
    let found = lines.join("\n") + "\n";
    let target = dir.join("../../target/student-api.txt");
    let _ = std::fs::write(&target, &found);
    let reviewed = std::fs::read_to_string(dir.join("api.txt")).unwrap_or_default();
    assert!(
        found == reviewed,
        "the students' API changed: compare target/student-api.txt with crates/student/api.txt \
         (diff target/student-api.txt crates/student/api.txt); copy it over once every new item \
         is a type, a spec or a recorder, never something that computes an answer"
    );
}
