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
    let count = write_handout(&root, &args.dir)?;
    println!(
        "{} {} ({count} {})",
        t("学生用のコピーを書きました:", "wrote the student's copy to").get(lang),
        args.dir.display(),
        t("ファイル", "files").get(lang)
    );
    // The folder as the command names it, quoted for a shell when it has spaces.
    let dir = args.dir.display().to_string();
    let dir = if dir.contains([' ', '\'', '"']) {
        format!("'{}'", dir.replace('\'', "'\\''"))
    } else {
        dir
    };
    println!(
        "{} cd {dir} && cargo run --release -- check --student 12345678",
        t("solutions/ は含まれていません。確かめるには:", "It has no solutions/. To try it:")
            .get(lang)
    );
    Ok(())
}
