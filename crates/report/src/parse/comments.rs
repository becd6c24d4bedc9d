//! What the reader does not read: HTML comments (other than tags) and code fences, blanked
//! line by line so line numbers stay those of the text.

/// The lines of `text` as the reader sees them: what is inside an HTML comment `<!-- … -->`
/// (other than a tag `<!-- cg: ID -->`, or one mistyped) or a code fence (```` ``` ```` or `~~~`, the fence lines
/// too) is blanked, so an old table kept in a comment or an example in a fence is not read;
/// every line stays, so line numbers stay right. Also the line and text of a `<!--` that is
/// never closed (everything after it is blanked).
pub(super) fn without_comments(text: &str) -> (Vec<String>, Option<(usize, String)>) {
    let mut out = Vec::new();
    let mut open_comment: Option<(usize, String)> = None;
    let mut fence: Option<(char, usize)> = None;
    for (k, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        if open_comment.is_none() {
            if let Some((c, n)) = fence {
                let run = trimmed.len() - trimmed.trim_start_matches(c).len();
                if run >= n && trimmed[run..].trim().is_empty() {
                    fence = None;
                }
                out.push(String::new());
                continue;
            }
            if let Some(c) = ['`', '~'].into_iter().find(|&c| trimmed.starts_with([c; 3])) {
                let run = trimmed.len() - trimmed.trim_start_matches(c).len();
                fence = Some((c, run));
                out.push(String::new());
                continue;
            }
        }
        let mut kept = String::new();
        let mut rest = line;
        loop {
            if open_comment.is_some() {
                match rest.find("-->") {
                    Some(end) => {
                        open_comment = None;
                        rest = &rest[end + 3..];
                    }
                    None => break,
                }
            }
            let Some(start) = rest.find("<!--") else {
                kept.push_str(rest);
                break;
            };
            kept.push_str(&rest[..start]);
            // A tag, or a tag mistyped (`<!-- CG: … -->`, `<!-- cg s.spot`), stays for the
            // tag readers, which name a mistyped one.
            let tag = rest[start + 4..]
                .trim_start()
                .get(..2)
                .is_some_and(|s| s.eq_ignore_ascii_case("cg"));
            match rest[start + 4..].find("-->") {
                Some(len) => {
                    let end = start + 4 + len + 3;
                    if tag {
                        kept.push_str(&rest[start..end]);
                    } else {
                        kept.push(' ');
                    }
                    rest = &rest[end..];
                }
                None if tag => {
                    kept.push_str(&rest[start..]);
                    break;
                }
                None => {
                    open_comment = Some((k + 1, rest[start..].to_owned()));
                    rest = "";
                }
            }
        }
        out.push(kept);
    }
    (out, open_comment)
}
