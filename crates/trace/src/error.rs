//! Why a scene cannot be traced, in words a student can act on (Japanese and English).

use std::fmt;

use cg_core::image::SizeError;
use cg_core::lang::Lang;
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
        let ja = lang == Lang::Ja;
        match self {
            // The size messages are core's, shared with the rasterizer.
            &TraceError::ZeroSize { width, height } => {
                SizeError::ZeroSize { width, height }.message(lang)
            }
            &TraceError::TooLarge { width, height } => {
                SizeError::TooLarge { width, height }.message(lang)
            }
            &TraceError::TooManyPixels { width, height } => {
                SizeError::TooManyPixels { width, height }.message(lang)
            }
            TraceError::MaxDepth { max_depth } => {
                if ja {
                    format!(
                        "反射・屈折の深さ max_depth = {max_depth} が大きすぎます（{MAX_DEPTH_LIMIT} まで）"
                    )
                } else {
                    format!("max_depth = {max_depth} is too deep (at most {MAX_DEPTH_LIMIT})")
                }
            }
            TraceError::MinWeight { value } => {
                if ja {
                    format!("min_weight = {value} は 0 以上の有限の値でなければなりません")
                } else {
                    format!("min_weight = {value} must be finite and ≥ 0")
                }
            }
            TraceError::Prepare(e) => e.message(lang),
            TraceError::Camera(e) => {
                format!("{}: {e}", lang.pick("カメラ（視野変換）", "camera (view transform)"))
            }
            TraceError::Projection(e) => {
                format!("{}: {e}", lang.pick("投影変換", "projection"))
            }
            TraceError::Geometry { object } => {
                if ja {
                    format!(
                        "オブジェクト \"{object}\": モデル変換で頂点が無限大か NaN になります（変換の値が大きすぎます）"
                    )
                } else {
                    format!(
                        "object \"{object}\": its model transform takes a vertex to infinity or NaN (the transform is too large)"
                    )
                }
            }
            TraceError::Texture { object, index } => {
                if ja {
                    format!("オブジェクト \"{object}\": テクスチャ {index} がシーンにありません")
                } else {
                    format!("object \"{object}\": the scene has no texture {index}")
                }
            }
            TraceError::Threads { message } => {
                format!(
                    "{}: {message}",
                    lang.pick("スレッドを起動できません", "cannot start the worker threads")
                )
            }
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
