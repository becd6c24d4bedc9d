//! `cg handout <DIR>`: the student's copy of the kit — everything but `solutions/`, with the
//! stubs freshly generated, the manifests' solution-only lines dropped and the lock file without
//! the solutions crate — which builds, runs and checks on its own. With `--table 2`, the copy's
//! `exercises/course.toml` makes version 2 of the variant tables what its students get.

use std::path::{Path, PathBuf};

use cg_core::lang::{Lang, Text, t};
use cg_grade::handout::write_handout;

/// Options of `cg handout`.
#[derive(clap::Args)]
pub struct Args {
    /// The folder to write the student's copy into (must not exist, or be empty) / 出力先のフォルダ
    dir: PathBuf,
    /// The variant table the class uses: what the copy's students get without naming one (default: 1) / 授業で使う課題表の版
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    table: Option<cg_harness::TableVersion>,
}

/// `cg handout <DIR>`.
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    let root =
        crate::instructor::kit_root(&t("配布用のコピーは、", "a handout is made from"), lang)?;
    let dir = &args.dir;
    let shown = dir.display();
    let said = |ja: &str, en: &str| format!("{shown} {}", t(ja, en).get(lang));
    if dir.to_str().is_none() {
        return Err(said(
            "の名前が UTF-8 ではありません（次に実行するコマンドで名前を示せません）",
            "is not a UTF-8 name (the commands to run next could not name it)",
        ));
    }
    if let Ok(meta) = std::fs::symlink_metadata(dir) {
        if !dir.is_dir() {
            let (ja, en) = if meta.file_type().is_symlink() {
                (
                    "は行き先のないリンクです。新しいフォルダを指定してください",
                    "is a link to nothing: give a new folder",
                )
            } else {
                (
                    "はフォルダではなくファイルです。新しいフォルダを指定してください",
                    "is a file, not a folder: give a new folder",
                )
            };
            return Err(said(ja, en));
        }
        if std::fs::read_dir(dir).map(|mut d| d.next().is_some()).unwrap_or(true) {
            return Err(said(
                "は空ではありません（新しいフォルダを指定してください）",
                "is not empty (give a new folder)",
            ));
        }
    }
    // Inside the kit, the next handout or autograder would take this copy along.
    if inside(dir, &root) {
        return Err(format!(
            "{} {}",
            said("はキットのフォルダの中です", "is inside the kit's folder"),
            t(
                "（キットの外のフォルダ、例えば ../cg-kit-2026 を指定してください）",
                "(give a folder outside it, ../cg-kit-2026 say)"
            )
            .get(lang)
        ));
    }
    let count = write_handout(&root, dir).map_err(|e| e.get(lang).to_owned())?;
    println!(
        "{} {shown} ({count} {})",
        t("学生用のコピーを書きました:", "wrote the student's copy to").get(lang),
        t("ファイル", "files").get(lang)
    );
    if let Some(table) = args.table {
        let course = dir.join("exercises").join(cg_assign::COURSE_FILE);
        let text = format!(
            "# The variant table this class uses (cg handout --table {table}): what a student gets\n\
             # when they record their number. 授業で使う課題表の版（学生番号を記録するときに使われます）。\n\
             table = {table}\n"
        );
        cg_core::fs::write_atomic(&course, text.as_bytes())
            .map_err(|e| Text::io_at(&course, &e).get(lang).to_owned())?;
        println!(
            "{}",
            Text::new(
                format!("課題表の版 {table} を、このコピーの学生の既定にしました（exercises/course.toml）"),
                format!("table {table} is what this copy's students get (exercises/course.toml)"),
            )
            .get(lang)
        );
    }
    if let Some(note) = cg_grade::handout::untracked_note(&root) {
        eprintln!("{}", note.get(lang));
    }
    print!("{}", try_it(dir, lang));
    Ok(())
}

/// Whether `path` (which may not exist yet) is `root` or inside it, but not in its build
/// folders (`target/`, `out/`, which nothing copies): its nearest existing ancestor, made
/// canonical, with the rest of its name after it.
fn inside(path: &Path, root: &Path) -> bool {
    let absolute = std::env::current_dir().unwrap_or_default().join(path);
    let mut rest = Vec::new();
    let mut at = absolute.as_path();
    loop {
        if let Ok(real) = at.canonicalize() {
            let whole: PathBuf = rest.iter().rev().fold(real, |p, name| p.join(name));
            let root = root.canonicalize().unwrap_or_else(|_| root.to_path_buf());
            return whole.strip_prefix(&root).is_ok_and(|relative| {
                let first = relative.components().next().map(|c| c.as_os_str().to_owned());
                !matches!(first.as_ref().and_then(|f| f.to_str()), Some("target" | "out"))
            });
        }
        match (at.parent(), at.file_name()) {
            (Some(parent), Some(name)) => {
                rest.push(name.to_os_string());
                at = parent;
            }
            _ => return false,
        }
    }
}

/// How to try the copy in `dir`: two commands on lines of their own, the folder quoted for a
/// shell where it needs it (`shell_word`: POSIX shells and PowerShell), a relative name that
/// begins with `-` as `./-name` (so that `cd` does not take it for an option). Not joined by
/// `&&`, which Windows PowerShell 5.1 (the one Windows opens) cannot parse.
fn try_it(dir: &Path, lang: Lang) -> String {
    let name = dir.display().to_string();
    let name = if dir.is_relative() && name.starts_with('-') { format!("./{name}") } else { name };
    format!(
        "{}\n  cd {}\n  cargo run --release -- check --student 12345678\n",
        t("solutions/ は含まれていません。確かめるには:", "It has no solutions/. To try it:")
            .get(lang),
        cg_harness::args::shell_word(&name)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The folder comes back whole through a shell: as it is when plain, in single quotes (a
    /// quote inside closed, escaped and reopened) when it has spaces or quotes; and no `&&`.
    #[test]
    fn the_next_commands_name_the_folder_as_a_shell_reads_it() {
        let plain = try_it(std::path::Path::new("/tmp/hand-out_1"), Lang::En);
        assert!(plain.contains("\n  cd /tmp/hand-out_1\n"), "{plain}");
        let odd = try_it(std::path::Path::new("/tmp/Tom's copy"), Lang::Ja);
        // Double quotes: both a POSIX shell and PowerShell read them back.
        assert!(odd.contains("\n  cd \"/tmp/Tom's copy\"\n"), "{odd}");
        let dash = try_it(std::path::Path::new("-copy 2026"), Lang::En);
        assert!(dash.contains("\n  cd './-copy 2026'\n"), "{dash}");
        assert!(odd.contains("確かめるには"), "{odd}");
        for text in [plain, odd] {
            assert!(!text.contains("&&"), "{text}");
            assert!(text.ends_with("\n  cargo run --release -- check --student 12345678\n"));
        }
    }
}
