//! Why a scene could not be rendered, in words a student can read (Japanese and English).

use cg_core::image::SizeError;
use cg_core::lang::{Lang, Text};
use cg_core::scene::PrepareError;
use cg_core::transform::TransformError;

use crate::pipeline::GUARD_BAND_PIXELS;

/// Why [`crate::render`] could not draw a scene. Nothing in the scene makes the renderer panic;
/// every problem it finds is one of these, naming what and where.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RenderError {
    /// The image has no pixels ([`SizeError::ZeroSize`]).
    #[error("{}", SizeError::ZeroSize { width: *width, height: *height })]
    ZeroSize {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// A side is longer than [`cg_core::image::MAX_SIDE`] (the rasterizer's fixed-point window
    /// coordinates stop there; [`SizeError::TooLarge`]).
    #[error("{}", SizeError::TooLarge { width: *width, height: *height })]
    TooLarge {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// More than [`cg_core::image::MAX_PIXELS`] pixels in all ([`SizeError::TooManyPixels`]).
    #[error("{}", SizeError::TooManyPixels { width: *width, height: *height })]
    TooManyPixels {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// A corner given to [`crate::coverage`] is not finite or lies beyond the guard band
    /// (±[`GUARD_BAND_PIXELS`]), where the fixed-point coordinates and edge functions would
    /// overflow.
    #[error(
        "coverage: triangle {triangle}, corner {corner} is at {position:?}: window coordinates must be finite and within ±{GUARD_BAND_PIXELS} pixels"
    )]
    OutsideGuardBand {
        /// The triangle (index into the slice given).
        triangle: usize,
        /// The corner (0, 1 or 2).
        corner: usize,
        /// Its window coordinates `(x, y)`.
        position: [f32; 2],
    },
    /// The camera gives no view transform.
    #[error("the camera is invalid: {0}")]
    Camera(TransformError),
    /// The projection is invalid (near ≤ 0, far ≤ near, a field of view outside (0°, 180°), …).
    #[error("the projection is invalid: {0}")]
    Projection(TransformError),
    /// An object cannot be made ready to draw (its transform or its normals).
    #[error("{0}")]
    Prepare(#[from] PrepareError),
    /// An object's texture index points past the scene's textures.
    #[error(
        "object \"{object}\" uses texture {texture}, but the scene has {count} texture(s) (indices 0..{count})"
    )]
    MissingTexture {
        /// The object's name.
        object: String,
        /// The index it uses.
        texture: usize,
        /// How many textures the scene has.
        count: usize,
    },
    /// A vertex lands at an infinite or NaN position after the model, view or projection
    /// transform (a huge coordinate or scale).
    #[error(
        "object \"{object}\": vertex V{vertex} is at {position:?} in clip space, which is not finite (a coordinate or scale too large?)"
    )]
    NonFinite {
        /// The object's name.
        object: String,
        /// The vertex: its V-number in the object's mesh, as the scene's shape or OBJ file
        /// numbers it (the first one whose clip position is not finite).
        vertex: usize,
        /// Its clip-space position `(x, y, z, w)`.
        position: [f32; 4],
    },
    /// The worker threads could not be started.
    #[error("cannot start {threads} rendering threads: {message}")]
    Threads {
        /// How many were asked for.
        threads: usize,
        /// What the thread pool said.
        message: String,
    },
}

impl From<SizeError> for RenderError {
    fn from(e: SizeError) -> RenderError {
        match e {
            SizeError::ZeroSize { width, height } => RenderError::ZeroSize { width, height },
            SizeError::TooLarge { width, height } => RenderError::TooLarge { width, height },
            SizeError::TooManyPixels { width, height } => {
                RenderError::TooManyPixels { width, height }
            }
        }
    }
}

impl RenderError {
    /// The message for a student in `lang` (the English one is also the `Display`).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let ja = match self {
            // The size messages are core's, shared with the ray tracer.
            &RenderError::ZeroSize { width, height } => {
                return SizeError::ZeroSize { width, height }.text();
            }
            &RenderError::TooLarge { width, height } => {
                return SizeError::TooLarge { width, height }.text();
            }
            &RenderError::TooManyPixels { width, height } => {
                return SizeError::TooManyPixels { width, height }.text();
            }
            RenderError::Prepare(e) => return e.text(),
            RenderError::OutsideGuardBand { triangle, corner, position } => format!(
                "coverage: 三角形 {triangle} の頂点 {corner} が {position:?} にあります。ウィンドウ座標は有限で ±{GUARD_BAND_PIXELS} ピクセル以内でなければなりません"
            ),
            // The transform errors carry both languages in their own message.
            RenderError::Camera(e) => format!("カメラの設定が正しくありません: {e}"),
            RenderError::Projection(e) => format!("投影の設定が正しくありません: {e}"),
            RenderError::MissingTexture { object, texture, count } => format!(
                "オブジェクト \"{object}\" はテクスチャ {texture} を使いますが、シーンのテクスチャは {count} 個です (番号 0..{count})"
            ),
            RenderError::NonFinite { object, vertex, position } => format!(
                "オブジェクト \"{object}\": 頂点 V{vertex} のクリップ座標 {position:?} が有限の値ではありません (座標や拡大率が大きすぎませんか)"
            ),
            RenderError::Threads { threads, message } => {
                format!("描画用のスレッドを {threads} 個起動できません: {message}")
            }
        };
        Text::new(ja, self.to_string())
    }
}
