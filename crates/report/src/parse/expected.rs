//! What a problem says was expected: the notation's example for each kind of row, and the
//! detail of why a group did not read (not closed, the wrong count, a decimal comma, exponent
//! notation, not a number).

use cg_harness::Text;

use super::{GroupError, MAX_GROUP, clip};

pub(super) fn detail(e: &GroupError, what_ja: &str, what_en: &str) -> Text {
    match e {
        GroupError::Unclosed => {
            // Not looked for further on (a face of 300 vertices was said to be not closed).
            Text::new(
                format!("（括弧が閉じていないか、{MAX_GROUP} 文字より先で閉じています）"),
                format!(" (the bracket is not closed within {MAX_GROUP} characters)"),
            )
        }
        GroupError::Count(k, true) => Text::new(
            format!(
                "（{what_ja}が {k} 個あります。小数点にコンマを使っていませんか。0.5 のようにピリオドで書きます）"
            ),
            format!(
                " (found {k} {what_en}: is a comma used as the decimal point? Write decimals with a point, such as 0.5)"
            ),
        ),
        GroupError::Count(k, false) => {
            Text::new(format!("（{what_ja}が {k} 個あります）"), format!(" (found {k} {what_en})"))
        }
        GroupError::NotNumber(s) if is_exponent_notation(s) => Text::new(
            format!(
                "（`{}` は指数表記です。指数表記は読めないので、0.49 のようにふつうの小数で書きます）",
                clip(s)
            ),
            format!(
                " (`{}` is in exponent notation, which is not read: write a plain decimal such as 0.49)",
                clip(s)
            ),
        ),
        GroupError::NotNumber(s) => Text::new(
            format!("（`{}` は{what_ja}ではありません）", clip(s)),
            format!(" (`{}` is not {what_en})", clip(s)),
        ),
    }
}

/// Whether `s` is a number in exponent notation (`4.9e-1`, `1E+3`, `-2e5`), which the notation
/// does not read ([`super::parse_number`] takes plain decimals only).
pub(super) fn is_exponent_notation(s: &str) -> bool {
    let Some((mantissa, exponent)) = s.trim().split_once(['e', 'E']) else { return false };
    let mantissa = mantissa.strip_prefix(['-', '+', '−']).unwrap_or(mantissa);
    let exponent = exponent.strip_prefix(['-', '+', '−']).unwrap_or(exponent);
    !exponent.is_empty()
        && exponent.chars().all(|c| c.is_ascii_digit())
        && mantissa.chars().any(|c| c.is_ascii_digit())
        && mantissa.chars().all(|c| c.is_ascii_digit() || c == '.')
        && mantissa.matches('.').count() <= 1
}

pub(super) fn join(a: Text, b: Text) -> Text {
    Text::new(a.ja + &b.ja, a.en + &b.en)
}

pub(super) fn expected_vertex(e: &GroupError) -> Text {
    join(
        Text::new(
            "`V0 (0.0, 1.0, 0.0)` のように、頂点番号のあとに括弧で囲んだ 3 つの数（cos 30° ではなく 0.866 のような値）",
            "three numbers in parentheses after the vertex number, like `V0 (0.0, 1.0, 0.0)` (values such as 0.866, not cos 30°)",
        ),
        match e {
            GroupError::NotNumber(_) => detail(e, "数", "a plain number"),
            _ => detail(e, "数", "numbers"),
        },
    )
}

pub(super) fn expected_face(e: &GroupError) -> Text {
    join(
        Text::new(
            "`F0 { V0, V3, V1 }` のように、面番号のあとに波括弧で囲んだ 3 つの頂点番号",
            "three vertex numbers in braces after the face number, like `F0 { V0, V3, V1 }`",
        ),
        match e {
            GroupError::NotNumber(_) => detail(e, "頂点番号", "a vertex number like V3"),
            _ => detail(e, "頂点番号", "vertex numbers"),
        },
    )
}

pub(super) fn expected_normal(e: &GroupError) -> Text {
    join(
        Text::new(
            "面の頂点のあとに、法線を `{ 0.0, 0.49, 0.87 }` のように 3 つの数で",
            "the face's normal after its vertices as three numbers, like `{ 0.0, 0.49, 0.87 }`",
        ),
        match e {
            GroupError::NotNumber(_) => detail(e, "数", "a plain number"),
            _ => detail(e, "数", "numbers"),
        },
    )
}

pub(super) fn expected_number_size() -> Text {
    Text::new(
        "有限で単精度（f32）の範囲に収まる数",
        "a finite number within single precision (f32) range",
    )
}
