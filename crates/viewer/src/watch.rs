//! A file whose change ends the window (`ViewerOptions::reload_on_change`): `cg view` watches its
//! own program, which `cg watch` (or any `cargo run`) rebuilds when the student saves, and starts
//! the new one with the same view.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant, SystemTime};

/// How often the file is looked at.
pub(crate) const POLL: Duration = Duration::from_millis(400);

/// How long a changed file must stay the same before it counts (the linker writes it in parts).
const SETTLE: Duration = Duration::from_millis(600);

/// What is compared: the time of the last change and the length.
type Stamp = (SystemTime, u64);

fn stamp(path: &Path) -> Option<Stamp> {
    let meta = std::fs::metadata(path).ok()?;
    Some((meta.modified().ok()?, meta.len()))
}

/// A watched file.
#[derive(Debug)]
pub(crate) struct Watch {
    path: PathBuf,
    first: Option<Stamp>,
    /// The last different stamp seen, and since when.
    seen: Option<(Stamp, Instant)>,
    /// When the file was last looked at.
    looked: Option<Instant>,
}

impl Watch {
    pub(crate) fn new(path: PathBuf) -> Watch {
        let first = stamp(&path);
        Watch { path, first, seen: None, looked: None }
    }

    /// Whether it is time to look again (at most every [`POLL`], also while an animation
    /// redraws frame after frame).
    pub(crate) fn due(&mut self, now: Instant) -> bool {
        if self.looked.is_some_and(|t| now.duration_since(t) < POLL) {
            return false;
        }
        self.looked = Some(now);
        true
    }

    /// Whether the file has changed since the start (or appeared) and has stayed the same for a
    /// while since. A file that is gone (being replaced) has not changed yet.
    pub(crate) fn changed(&mut self, now: Instant) -> bool {
        let Some(current) = stamp(&self.path) else {
            self.seen = None;
            return false;
        };
        if Some(current) == self.first {
            self.seen = None;
            return false;
        }
        match self.seen {
            Some((previous, since)) if previous == current => now.duration_since(since) >= SETTLE,
            _ => {
                self.seen = Some((current, now));
                false
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_change_counts_once_it_has_settled_and_not_before() {
        let dir = std::env::temp_dir().join(format!("cg-viewer-watch-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("cg");
        std::fs::write(&file, b"old program").unwrap();
        let mut watch = Watch::new(file.clone());
        let start = Instant::now();
        assert!(!watch.changed(start), "unchanged");
        assert!(!watch.changed(start + SETTLE * 2), "still unchanged");
        // Replaced (a new length, so the test does not depend on the clock's resolution).
        std::fs::write(&file, b"the new, rebuilt program").unwrap();
        let seen = Instant::now();
        assert!(!watch.changed(seen), "just changed: not settled");
        assert!(!watch.changed(seen + SETTLE / 2), "not settled yet");
        assert!(watch.changed(seen + SETTLE), "settled");
        // Gone (being replaced) is not a change.
        std::fs::remove_file(&file).unwrap();
        let mut gone = Watch::new(file.clone());
        assert!(!gone.changed(seen + SETTLE * 4));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
