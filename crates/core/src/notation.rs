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
/// `1 → "1.0"`, `-0.8 → "-0.8"`, `0.48564293 → "0.4856"` (4 decimals). Negative zero and values
/// that round to zero print without a sign. Non-finite values print as `NaN`, `inf`, `-inf`.
#[must_use]
pub fn decimal(x: f32, max_decimals: usize) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    // f32 has at most 9 significant decimal digits, but small values need more places: 45 covers
    // every decimal place an f32 can have (the smallest subnormal is 1.4e-45).
    let max_decimals = max_decimals.clamp(1, 45);
    let mut s = format!("{:.*}", max_decimals, f64::from(x));
    while s.ends_with('0') && !s.ends_with(".0") {
        s.pop();
    }
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s.remove(0);
    }
    s
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

    #[test]
    fn lines_use_the_lecture_notation() {
        assert_eq!(vertex_line(3, Vec3::new(-1.0, -0.8, 1.0), 4), "V3 (-1.0, -0.8, 1.0)");
        assert_eq!(face(0, [0, 3, 1]), "F0 { V0, V3, V1 }");
        assert_eq!(edge(3, 5), "V3–V5");
        assert_eq!(braces(Vec3::new(0.0, 0.485_642_93, 0.874_157_3), 4), "{ 0.0, 0.4856, 0.8742 }");
    }
}
