//! Why a scene cannot be traced, in words a student can act on (Japanese and English).

use std::fmt;

use cg_core::image::SizeError;
use cg_core::lang::{Lang, Text};
use cg_core::scene::PrepareError;
use cg_core::transform::TransformError;

use crate::options::MAX_DEPTH_LIMIT;

/// Why [`crate::render`] (or [`crate::Tracer::new`]) refused a scene or its options.
#[derive(Clone, Debug, PartialEq)]
pub enum TraceError {
    /// The image has no pixels ([`SizeError::ZeroSize`]).
    ZeroSize {
        /// Width asked for.
        width: u32,
        /// Height asked for.
        height: u32,
    },
    /// A side longer than [`crate::MAX_SIZE`] ([`SizeError::TooLarge`]).
    TooLarge {
        /// Width asked for.
        width: u32,
        /// Height asked for.
        height: u32,
    },
    /// More than [`cg_core::image::MAX_PIXELS`] pixels in all ([`SizeError::TooManyPixels`]).
    TooManyPixels {
        /// Width asked for.
        width: u32,
        /// Height asked for.
        height: u32,
    },
    /// [`crate::Options::max_depth`] above [`MAX_DEPTH_LIMIT`].
    MaxDepth {
        /// The depth asked for.
        max_depth: u32,
    },
    /// [`crate::Options::min_weight`] negative, infinite or NaN.
    MinWeight {
        /// The value given.
        value: f32,
    },
    /// An object cannot be made ready to draw (its transform or its normals).
    Prepare(PrepareError),
    /// The camera (view transform) is invalid.
    Camera(TransformError),
    /// The projection is invalid.
    Projection(TransformError),
    /// An object's model transform takes a vertex to infinity or NaN.
    Geometry {
        /// The object's name.
        object: String,
    },
    /// An object refers to a texture the scene does not have.
    Texture {
        /// The object's name.
        object: String,
        /// The texture index it gives.
        index: usize,
    },
    /// The worker threads could not be started.
    Threads {
        /// What rayon said.
        message: String,
    },
}

impl From<SizeError> for TraceError {
    fn from(e: SizeError) -> TraceError {
        match e {
            SizeError::ZeroSize { width, height } => TraceError::ZeroSize { width, height },
            SizeError::TooLarge { width, height } => TraceError::TooLarge { width, height },
            SizeError::TooManyPixels { width, height } => {
                TraceError::TooManyPixels { width, height }
            }
        }
    }
}

impl TraceError {
    /// The message for a student in `lang`. (`Display` gives the English one.)
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message for a student in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        // The size messages are core's, shared with the rasterizer.
        let size = |e: SizeError| Text::new(e.message(Lang::Ja), e.message(Lang::En));
        match self {
            &TraceError::ZeroSize { width, height } => size(SizeError::ZeroSize { width, height }),
            &TraceError::TooLarge { width, height } => size(SizeError::TooLarge { width, height }),
            &TraceError::TooManyPixels { width, height } => {
                size(SizeError::TooManyPixels { width, height })
            }
            TraceError::MaxDepth { max_depth } => Text::new(
                format!(
                    "反射・屈折の深さ max_depth = {max_depth} が大きすぎます（{MAX_DEPTH_LIMIT} まで）"
                ),
                format!("max_depth = {max_depth} is too deep (at most {MAX_DEPTH_LIMIT})"),
            ),
            TraceError::MinWeight { value } => Text::new(
                format!("min_weight = {value} は 0 以上の有限の値でなければなりません"),
                format!("min_weight = {value} must be finite and ≥ 0"),
            ),
            TraceError::Prepare(e) => Text::new(e.message(Lang::Ja), e.message(Lang::En)),
            TraceError::Camera(e) => {
                let e = e.text();
                Text::new(
                    format!("カメラ（視野変換）: {}", e.ja),
                    format!("camera (view transform): {}", e.en),
                )
            }
            TraceError::Projection(e) => {
                let e = e.text();
                Text::new(format!("投影変換: {}", e.ja), format!("projection: {}", e.en))
            }
            TraceError::Geometry { object } => Text::new(
                format!(
                    "オブジェクト \"{object}\": モデル変換で頂点が無限大か NaN になります（変換の値が大きすぎます）"
                ),
                format!(
                    "object \"{object}\": its model transform takes a vertex to infinity or NaN (the transform is too large)"
                ),
            ),
            TraceError::Texture { object, index } => Text::new(
                format!("オブジェクト \"{object}\": テクスチャ {index} がシーンにありません"),
                format!("object \"{object}\": the scene has no texture {index}"),
            ),
            TraceError::Threads { message } => Text::new(
                format!("スレッドを起動できません: {message}"),
                format!("cannot start the worker threads: {message}"),
            ),
        }
    }
}

impl fmt::Display for TraceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message(Lang::En))
    }
}

impl std::error::Error for TraceError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            TraceError::Prepare(e) => Some(e),
            TraceError::Camera(e) | TraceError::Projection(e) => Some(e),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use cg_core::glam::Vec3;
    use cg_core::normals::NormalsError;

    use super::*;

    /// Every variant (the match in the loop is exhaustive: a new one does not compile until it
    /// has a sample here).
    fn samples() -> Vec<TraceError> {
        let all = vec![
            TraceError::ZeroSize { width: 0, height: 4 },
            TraceError::TooLarge { width: 100_000, height: 4 },
            TraceError::TooManyPixels { width: 10_000, height: 10_000 },
            TraceError::MaxDepth { max_depth: 1000 },
            TraceError::MinWeight { value: -1.0 },
            TraceError::Prepare(PrepareError::Normals {
                object: "ball".into(),
                source: NormalsError::Missing,
            }),
            TraceError::Camera(TransformError::EyeAtTarget { eye: Vec3::ONE }),
            TraceError::Projection(TransformError::FieldOfView { fovy_deg: 180.0 }),
            TraceError::Geometry { object: "ball".into() },
            TraceError::Texture { object: "ball".into(), index: 3 },
            TraceError::Threads { message: "EAGAIN".into() },
        ];
        for e in &all {
            match e {
                TraceError::ZeroSize { .. }
                | TraceError::TooLarge { .. }
                | TraceError::TooManyPixels { .. }
                | TraceError::MaxDepth { .. }
                | TraceError::MinWeight { .. }
                | TraceError::Prepare(_)
                | TraceError::Camera(_)
                | TraceError::Projection(_)
                | TraceError::Geometry { .. }
                | TraceError::Texture { .. }
                | TraceError::Threads { .. } => {}
            }
        }
        all
    }

    /// Runs of two or more ASCII words with only spaces between them (`is not finite`): English
    /// inside a Japanese sentence. Names and formulas (`max_depth = 1000`, `NaN`) stand alone.
    fn english_fragments(text: &str) -> Vec<String> {
        let is_word = |w: &&str| w.chars().filter(char::is_ascii_alphabetic).count() >= 2;
        text.split(|c: char| !(c == ' ' || c == '_' || c.is_ascii_alphanumeric()))
            .flat_map(|segment| {
                let words: Vec<&str> = segment.split_whitespace().collect();
                let pairs: Vec<String> = words
                    .windows(2)
                    .filter(|w| is_word(&w[0]) && is_word(&w[1]))
                    .map(|w| w.join(" "))
                    .collect();
                pairs
            })
            .collect()
    }

    #[test]
    fn every_message_is_one_clean_line_in_each_language() {
        let kana_or_kanji =
            |c: char| matches!(c, '\u{3040}'..='\u{30ff}' | '\u{4e00}'..='\u{9fff}');
        let mut found = Vec::new();
        for e in samples() {
            let text = e.text();
            assert_eq!([e.message(Lang::Ja), e.message(Lang::En)], [&*text.ja, &*text.en]);
            assert_eq!(e.to_string(), text.en);
            for (lang, s) in [(Lang::Ja, &text.ja), (Lang::En, &text.en)] {
                let mut complain = |why: &str| found.push(format!("{e:?} ({lang}): {why}: {s:?}"));
                if s.is_empty() || s.trim() != s.as_str() {
                    complain("empty, or whitespace at an end");
                }
                if s.contains("  ") || s.contains(['\n', '\r', '\t']) {
                    complain("a run of spaces or a line break");
                }
                match lang {
                    Lang::Ja if !s.chars().any(kana_or_kanji) => complain("no Japanese"),
                    Lang::Ja if !english_fragments(s).is_empty() => {
                        complain("English words in the Japanese text");
                    }
                    Lang::En if s.chars().any(kana_or_kanji) => {
                        complain("Japanese in the English text");
                    }
                    _ => {}
                }
            }
        }
        assert!(found.is_empty(), "{} problems:\n{}", found.len(), found.join("\n"));
    }
}
