//! How many data items one CBOR value holds, counted from its heads alone, before anything is
//! decoded. A reply of one byte per item can decode to tens of bytes per item (a
//! `ciborium::Value` is 32 bytes; an empty list inside a list, one byte on the pipe, is a
//! 24-byte `Vec`), so a hostile worker's 256 MiB frame of one-byte items took the caller about
//! 8 GiB. The caller reads a reply straight into the function's result type, and refuses one of
//! more than [`MAX_ITEMS`] items first: at most about 512 MiB, whatever the worker writes.

/// The most data items a reply may hold (every number, string, list, map entry and tag counts
/// one). The largest honest reply is far below: a1's faces of the finest sphere a spec allows
/// (1.3 M triangles, four items each) is about 5 M; s.t6's pixels about 0.5 M.
pub const MAX_ITEMS: usize = 1 << 24;

/// The deepest nesting read (ciborium's own limit when it decodes).
pub const MAX_DEPTH: usize = 256;

/// The number of data items of the CBOR value at the start of `bytes`, when it is at most
/// `max`.
///
/// # Errors
/// More than `max` items, a malformed head, or a value cut short.
pub fn items(bytes: &[u8], max: usize) -> Result<usize, String> {
    // What each open list, map, tag or chunked string still holds: `None` until its break.
    let mut open: Vec<Option<u64>> = Vec::new();
    let mut at = 0usize;
    let mut count = 0usize;
    loop {
        let &head = bytes.get(at).ok_or("the value is cut short")?;
        at += 1;
        let (major, info) = (head >> 5, head & 0x1f);
        if head == 0xff {
            // A break ends the innermost chunked container.
            match open.pop() {
                Some(None) => {}
                _ => return Err(format!("a break at byte {} ends nothing", at - 1)),
            }
        } else {
            count += 1;
            if count > max {
                return Err(format!("more than {max} items"));
            }
            let argument = match info {
                0..=23 => Some(u64::from(info)),
                24..=27 => {
                    let width = 1usize << (info - 24);
                    let field = bytes.get(at..at + width).ok_or("the value is cut short")?;
                    at += width;
                    Some(field.iter().fold(0u64, |n, &b| (n << 8) | u64::from(b)))
                }
                31 if (2..=5).contains(&major) => None,
                _ => return Err(format!("a malformed head {head:#04x} at byte {}", at - 1)),
            };
            let opened = match (major, argument) {
                (2 | 3, Some(length)) => {
                    let length = usize::try_from(length).map_err(|_| "a string too long")?;
                    at = at
                        .checked_add(length)
                        .filter(|&end| end <= bytes.len())
                        .ok_or("the value is cut short")?;
                    None
                }
                (4, Some(n)) => Some(Some(n)),
                (5, Some(n)) => Some(Some(n.checked_mul(2).ok_or("a map too long")?)),
                (6, _) => Some(Some(1)),
                (2..=5, None) => Some(None),
                _ => None,
            };
            // A container with items to come: its items are read next. Anything else (a
            // number, a string, an empty list or map) is one item complete.
            if let Some(Some(1..) | None) = opened {
                if open.len() == MAX_DEPTH {
                    return Err(format!("nested deeper than {MAX_DEPTH}"));
                }
                open.push(opened.flatten());
                continue;
            }
        }
        // An item is complete: count it off its container, and close each container that it
        // completes in turn.
        loop {
            match open.last_mut() {
                None => return Ok(count),
                Some(Some(n)) => {
                    *n -= 1;
                    if *n > 0 {
                        break;
                    }
                    open.pop();
                }
                Some(None) => break,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cbor(value: &impl serde::Serialize) -> Vec<u8> {
        let mut bytes = Vec::new();
        ciborium::into_writer(value, &mut bytes).unwrap();
        bytes
    }

    #[test]
    fn every_item_is_counted_nested_or_not() {
        assert_eq!(items(&cbor(&7u32), 10), Ok(1));
        assert_eq!(items(&cbor(&"text"), 10), Ok(1));
        assert_eq!(items(&cbor(&Vec::<u8>::new()), 10), Ok(1));
        // A list of three lists of three floats: 1 + 3 × (1 + 3).
        let nested = vec![[1.5f32, 2.0, f32::NAN]; 3];
        assert_eq!(items(&cbor(&nested), 100), Ok(13));
        // A map of two entries, each a key and a value: 1 + 2 × 2.
        let map: std::collections::BTreeMap<&str, u64> = [("a", 1), ("b", 1 << 40)].into();
        assert_eq!(items(&cbor(&map), 100), Ok(5));
        // An empty list inside a list closes both.
        assert_eq!(items(&cbor(&vec![Vec::<u8>::new(), vec![1]]), 100), Ok(4));
        // Chunked (indefinite) forms: a list [1, 2] and a string of two chunks, then 3.
        assert_eq!(items(&[0x9f, 0x01, 0x02, 0xff], 10), Ok(3));
        assert_eq!(items(&[0x82, 0x7f, 0x61, b'a', 0x61, b'b', 0xff, 0x03], 10), Ok(5));
        // A tag counts and holds one item.
        assert_eq!(items(&[0xc1, 0x1a, 0, 0, 0, 1], 10), Ok(2));
    }

    #[test]
    fn too_many_items_and_malformed_values_are_refused() {
        // A million one-byte items: a few megabytes on the pipe, 32 MB as values.
        let flood = vec![0u8; 1_000_000];
        assert_eq!(items(&cbor(&flood), 999_999).unwrap_err(), "more than 999999 items");
        assert_eq!(items(&cbor(&flood), 1_000_001), Ok(1_000_001));
        // A list that says it holds 2⁶⁴ − 1 items and holds none.
        let liar = [0x9b, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff];
        assert!(items(&liar, MAX_ITEMS).is_err());
        // A map of 2⁶³ entries (twice that many items) overflows nothing.
        assert!(items(&[0xbb, 0x80, 0, 0, 0, 0, 0, 0, 0], MAX_ITEMS).is_err());
        assert!(items(&[0x5a, 0xff, 0xff, 0xff, 0xff], 10).is_err(), "a string past the end");
        assert!(items(&[0xff], 10).is_err(), "a break outside a chunked container");
        assert!(items(&[0x1c], 10).is_err(), "a reserved head");
        assert!(items(&[], 10).is_err());
        // 10 000 lists, each the only item of the one before: refused at the depth limit, not
        // a stack entry per list.
        assert_eq!(items(&[0x81; 10_000], MAX_ITEMS).unwrap_err(), "nested deeper than 256");
        assert_eq!(items(&[[0x81; 255].as_slice(), &[0x80]].concat(), 10_000), Ok(256));
    }
}
