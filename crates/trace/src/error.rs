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
        let size = |e: SizeError| e.text();
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
            TraceError::Prepare(e) => e.text(),
            TraceError::Camera(e) => {
                let e = e.text();
                Text::new(
                    format!("カメラ（視点の変換）: {}", e.ja),
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

    #[test]
    fn every_message_is_one_clean_line_in_each_language() {
        let messages = samples().into_iter().map(|e| {
            let text = e.text();
            assert_eq!([e.message(Lang::Ja), e.message(Lang::En)], [&*text.ja, &*text.en]);
            assert_eq!(e.to_string(), text.en);
            (format!("{e:?}"), text.ja, text.en)
        });
        cg_testkit::text::assert_clean_lines(messages, true, false);
    }
}
