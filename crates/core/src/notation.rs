//! The lecture's table notation, so every table the kit prints reads like the slides:
//!
//! ```text
//! V0 (0.0, 1.0, 0.0)
//! F0 { V0, V3, V1 }   { 0.0, 0.4856, 0.8742 }
//! ```
//!
//! Numbers keep at least one decimal (`1.0`, `-0.8`) and at most the requested number of decimals,
//! trailing zeros trimmed; `-0` prints as `0.0`.

use glam::Vec3;

/// `x` with at least one and at most `max_decimals` decimals, trailing zeros trimmed:
/// `1 → "1.0"`, `-0.8 → "-0.8"`, `0.48564293 → "0.4856"` (4 decimals), rounded as [`fixed`]
/// rounds. Negative zero and values that round to zero print without a sign. Non-finite values
/// print as `NaN`, `inf`, `-inf`.
#[must_use]
pub fn decimal(x: f32, max_decimals: usize) -> String {
    let mut s = fixed(x, max_decimals.max(1));
    if !x.is_finite() {
        return s;
    }
    while s.ends_with('0') && !s.ends_with(".0") {
        s.pop();
    }
    s
}

/// `x` with exactly `places` decimals, rounded as one rounds by hand (四捨五入: a 5 rounds away
/// from zero), from the shortest decimal that reads back as the same `f32`: `0.3125 → "0.313"`
/// (Rust's `{:.3}` gives `0.312`, the even one), `0.1625 → "0.163"` (the `f32` is
/// 0.162499994…, and stands for 0.1625), `-0.0625 → "-0.063"`. Negative zero and values that
/// round to zero print without a sign (`0.000`). Non-finite values print as `NaN`, `inf`,
/// `-inf`. At most 45 places (every place an `f32` can have).
#[must_use]
pub fn fixed(x: f32, places: usize) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    rounded(&x.abs().to_string(), x.is_sign_negative(), places.min(45))
}

/// [`fixed`] for an `f64`, from the shortest decimal that reads back as the same `f64`. At most
/// 400 places.
#[must_use]
pub fn fixed64(x: f64, places: usize) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    rounded(&x.abs().to_string(), x.is_sign_negative(), places.min(400))
}

/// `digits` (a non-negative decimal as Rust's `Display` writes a float: `15`, `0.1625`, never
/// an exponent) rounded half up to `places` decimals, with `-` in front when `negative` and the
/// result is not zero.
fn rounded(digits: &str, negative: bool, places: usize) -> String {
    let (int, frac) = digits.split_once('.').unwrap_or((digits, ""));
    let frac = frac.as_bytes();
    let mut kept: Vec<u8> = int.bytes().collect();
    kept.extend((0..places).map(|k| frac.get(k).copied().unwrap_or(b'0')));
    if frac.get(places).is_some_and(|&d| d >= b'5') {
        // Add one in the last place, carrying.
        let mut k = kept.len();
        loop {
            if k == 0 {
                kept.insert(0, b'1');
                break;
            }
            k -= 1;
            if kept[k] == b'9' {
                kept[k] = b'0';
            } else {
                kept[k] += 1;
                break;
            }
        }
    }
    let point = kept.len() - places;
    let zero = kept.iter().all(|&d| d == b'0');
    let mut out = String::with_capacity(kept.len() + 2);
    if negative && !zero {
        out.push('-');
    }
    out.push_str(std::str::from_utf8(&kept[..point]).unwrap_or("0"));
    if places > 0 {
        out.push('.');
        out.push_str(std::str::from_utf8(&kept[point..]).unwrap_or(""));
    }
    out
}

/// `(x, y, z)` with [`decimal`] components: the lecture's vertex notation.
#[must_use]
pub fn tuple(v: Vec3, max_decimals: usize) -> String {
    format!(
        "({}, {}, {})",
        decimal(v.x, max_decimals),
        decimal(v.y, max_decimals),
        decimal(v.z, max_decimals)
    )
}

/// `{ x, y, z }` with [`decimal`] components: the lecture's normal notation.
#[must_use]
pub fn braces(v: Vec3, max_decimals: usize) -> String {
    format!(
        "{{ {}, {}, {} }}",
        decimal(v.x, max_decimals),
        decimal(v.y, max_decimals),
        decimal(v.z, max_decimals)
    )
}

/// `V3 (-1.0, -0.8, 1.0)`.
#[must_use]
pub fn vertex_line(index: usize, position: Vec3, max_decimals: usize) -> String {
    format!("V{index} {}", tuple(position, max_decimals))
}

/// `F0 { V0, V3, V1 }`.
#[must_use]
pub fn face(index: usize, vertices: [u32; 3]) -> String {
    format!("F{index} {{ V{}, V{}, V{} }}", vertices[0], vertices[1], vertices[2])
}

/// `V3–V5`: the edge from vertex `a` to vertex `b` (an en dash between them).
#[must_use]
pub fn edge(a: u32, b: u32) -> String {
    format!("V{a}–V{b}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_follow_the_slides() {
        assert_eq!(decimal(1.0, 4), "1.0");
        assert_eq!(decimal(-0.8, 4), "-0.8");
        assert_eq!(decimal(0.485_642_93, 4), "0.4856");
        assert_eq!(decimal(0.874_157_3, 2), "0.87");
        assert_eq!(decimal(-0.0, 4), "0.0");
        assert_eq!(decimal(-0.000_01, 4), "0.0");
        assert_eq!(decimal(15.0, 0), "15.0");
        assert_eq!(decimal(f32::NAN, 4), "NaN");
        // Any number of decimals is accepted (formatting precision is capped, never a panic).
        assert_eq!(decimal(0.5, 100_000), "0.5");
    }

    /// Ties round away from zero as by hand, from the decimal the float stands for; carries run
    /// through; zero has no sign; more places than the float has are zeros.
    #[test]
    fn numbers_round_as_by_hand() {
        assert_eq!(fixed(0.3125, 3), "0.313");
        assert_eq!(fixed(0.6875, 3), "0.688");
        assert_eq!(fixed(0.1625, 3), "0.163");
        assert_eq!(fixed(0.85625, 4), "0.8563");
        assert_eq!(fixed(-0.0625, 3), "-0.063");
        assert_eq!(fixed(0.4999, 3), "0.500");
        assert_eq!(fixed(9.9996, 3), "10.000");
        assert_eq!(fixed(-0.0004, 3), "0.000");
        assert_eq!(fixed(-0.0, 2), "0.00");
        assert_eq!(fixed(0.485_642_93, 3), "0.486");
        assert_eq!(fixed(2.5, 0), "3");
        assert_eq!(fixed(0.5, 6), "0.500000");
        assert_eq!(fixed(1.0e-7, 3), "0.000");
        assert_eq!(fixed(1.0e20, 1), "100000000000000000000.0");
        assert_eq!(fixed(f32::NEG_INFINITY, 3), "-inf");
        assert_eq!(fixed(0.5, 100_000).len(), 47);
        assert_eq!(fixed64(0.3125, 3), "0.313");
        assert_eq!(fixed64(0.1625, 3), "0.163");
        assert_eq!(fixed64(-1.999_95, 4), "-2.0000");
        assert_eq!(fixed64(f64::NAN, 3), "NaN");
        assert_eq!(decimal(0.3125, 3), "0.313");
        assert_eq!(decimal(0.999_96, 4), "1.0");
    }

    #[test]
    fn lines_use_the_lecture_notation() {
        assert_eq!(vertex_line(3, Vec3::new(-1.0, -0.8, 1.0), 4), "V3 (-1.0, -0.8, 1.0)");
        assert_eq!(face(0, [0, 3, 1]), "F0 { V0, V3, V1 }");
        assert_eq!(edge(3, 5), "V3–V5");
        assert_eq!(braces(Vec3::new(0.0, 0.485_642_93, 0.874_157_3), 4), "{ 0.0, 0.4856, 0.8742 }");
    }
}
