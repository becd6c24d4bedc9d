use super::*;

#[test]
fn text_drops_a_character_cut_at_the_end() {
    let bytes = "aé".as_bytes()[..2].to_vec();
    assert_eq!(text(bytes, true), ("a".to_owned(), true));
}

#[test]
fn text_never_grows_past_what_was_kept() {
    let (s, cut) = text(vec![b'a', 0xff, 0xff], false);
    assert!(s.len() <= 3, "{s:?}");
    assert!(s.starts_with('a'));
    assert!(cut);
}

#[test]
fn outer_folders_are_bound_before_inner_ones() {
    let args = bwrap_args(
        Path::new("/p/prog"),
        Path::new("/k/build/work"),
        &[
            (PathBuf::from("/k/build/work/exercises"), None),
            (PathBuf::from("/k/build/work/link"), Some(PathBuf::from("exercises"))),
        ],
        &[PathBuf::from("/k")],
        &[("HOME".into(), "/k/build/work".into())],
        &Limits { tmp_bytes: 1000, workdir_bytes: 0, ..Limits::default() },
        &[],
    );
    let args: Vec<String> = args.iter().map(|a| a.to_string_lossy().into_owned()).collect();
    let at = |x: &str| args.iter().position(|a| a == x).unwrap();
    assert!(at("/k") < at("/k/build/work"), "{args:?}");
    // Both writable places are sized tmpfs (bwrap refuses a size of 0); the work folder's
    // comes before what it held, bound read-only (a link recreated as a link).
    let has = |w: &[&str]| args.windows(w.len()).any(|x| x == w);
    assert!(has(&["--size", "1000", "--tmpfs", "/tmp"]), "{args:?}");
    assert!(has(&["--size", "1", "--tmpfs", "/k/build/work"]), "{args:?}");
    assert!(!args.iter().any(|a| a == "--bind"), "{args:?}");
    assert!(at("/k/build/work") < at("/k/build/work/exercises"), "{args:?}");
    assert!(has(&["--ro-bind", "/k/build/work/exercises", "/k/build/work/exercises"]));
    assert!(has(&["--symlink", "exercises", "/k/build/work/link"]), "{args:?}");
    assert!(has(&["--dev", "/dev", "--remount-ro", "/dev"]), "{args:?}");
    assert!(!args.iter().any(|a| a == "/usr/bin" || a == "/bin" || a == "/sbin"), "{args:?}");
    assert!(args.windows(2).any(|w| w[0] == "--chdir" && w[1] == "/k/build/work"));
    assert_eq!(args.last().map(String::as_str), Some("/"));
}

#[cfg(unix)]
#[test]
fn a_signal_reported_by_bwrap_reads_as_a_signal() {
    use std::os::unix::process::ExitStatusExt;
    let exited = |code: i32| ExitStatus::from_raw(code << 8);
    assert_eq!(ended(exited(134), Isolation::Bubblewrap), Ended::Signalled(6));
    assert_eq!(ended(exited(134), Isolation::Limits), Ended::Exited(134));
    assert_eq!(ended(exited(101), Isolation::Bubblewrap), Ended::Exited(101));
    assert_eq!(ended(ExitStatus::from_raw(9), Isolation::Limits), Ended::Signalled(9));
}
