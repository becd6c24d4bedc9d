//! `cg handout <DIR>`: the student's copy of the kit — everything but `solutions/`, with the
//! stubs freshly generated, the manifests' solution-only lines dropped and the lock file without
//! the solutions crate — which builds, runs and checks on its own.

use std::path::PathBuf;

use cg_core::lang::{Lang, t};
use cg_grade::handout::write_handout;

/// Options of `cg handout`.
#[derive(clap::Args)]
pub struct Args {
    /// The folder to write the student's copy into (must not exist, or be empty) / 出力先のフォルダ
    dir: PathBuf,
}

/// `cg handout <DIR>`.
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    let root = crate::kit_path(None, ".");
    if !root.join("solutions/Cargo.toml").exists() {
        return Err(t(
            "solutions/ がありません（配布用のコピーは、キット本体のリポジトリから作ります）",
            "there is no solutions/ here: a handout is made from the kit's own repository",
        )
        .get(lang)
        .to_owned());
    }
    if args.dir.exists()
        && std::fs::read_dir(&args.dir).map(|mut d| d.next().is_some()).unwrap_or(true)
    {
        return Err(format!(
            "{} {}",
            args.dir.display(),
            t(
                "は空ではありません（新しいフォルダを指定してください）",
                "is not empty (give a new folder)"
            )
            .get(lang)
        ));
    }
    let count = write_handout(&root, &args.dir).map_err(|e| e.get(lang).to_owned())?;
    println!(
        "{} {} ({count} {})",
        t("学生用のコピーを書きました:", "wrote the student's copy to").get(lang),
        args.dir.display(),
        t("ファイル", "files").get(lang)
    );
    print!("{}", try_it(&args.dir, lang));
    Ok(())
}

/// How to try the copy in `dir`: two commands on lines of their own, the folder quoted for a
/// shell where it needs it (`shell_word`: POSIX shells and PowerShell). Not joined by `&&`,
/// which Windows PowerShell 5.1 (the one Windows opens) cannot parse.
fn try_it(dir: &std::path::Path, lang: Lang) -> String {
    format!(
        "{}\n  cd {}\n  cargo run --release -- check --student 12345678\n",
        t("solutions/ は含まれていません。確かめるには:", "It has no solutions/. To try it:")
            .get(lang),
        cg_harness::args::shell_word(&dir.display().to_string())
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
        assert!(odd.contains("\n  cd '/tmp/Tom'\\''s copy'\n"), "{odd}");
        assert!(odd.contains("確かめるには"), "{odd}");
        for text in [plain, odd] {
            assert!(!text.contains("&&"), "{text}");
            assert!(text.ends_with("\n  cargo run --release -- check --student 12345678\n"));
        }
    }
}
