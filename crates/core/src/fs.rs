//! Writing a file so that a failure never leaves it half written: the student's record, a
//! rendered picture, a grade sheet.

use std::path::Path;

/// Writes `bytes` to `path` atomically: to a temporary file beside it, then renamed over it, so
/// the file is either as it was or wholly new (a full disk, a quota, a killed process leave the
/// old file). The temporary file is removed when the write fails. A path that is not a regular
/// file (`/dev/stdout`, `/dev/null`, a pipe) is written directly: it cannot be replaced.
///
/// # Errors
/// The file could not be written or renamed.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    if std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
        return std::fs::write(path, bytes);
    }
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let temp = path.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    let written = std::fs::write(&temp, bytes).and_then(|()| std::fs::rename(&temp, path));
    if written.is_err() {
        let _ = std::fs::remove_file(&temp);
    }
    written
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A write that fails leaves the old file whole and no temporary file beside it; one that
    /// works replaces it; a device is written, not replaced.
    #[test]
    fn a_failed_write_keeps_the_old_file() {
        let dir = std::env::temp_dir().join(format!("cg-core-fs-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("student.toml");
        write_atomic(&path, b"old").unwrap();
        write_atomic(&path, b"new").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"new");
        // A folder where the file is: the rename fails, the folder stays, nothing is left over.
        let folder = dir.join("folder");
        std::fs::create_dir_all(folder.join("inside")).unwrap();
        assert!(write_atomic(&folder, b"x").is_err());
        assert!(folder.join("inside").is_dir());
        let left: Vec<_> =
            std::fs::read_dir(&dir).unwrap().flatten().map(|e| e.file_name()).collect();
        assert_eq!(left.len(), 2, "{left:?}");
        #[cfg(unix)]
        write_atomic(Path::new("/dev/null"), b"to a device").unwrap();
        let _ = std::fs::remove_dir_all(&dir);
    }
}
