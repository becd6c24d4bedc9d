//! Why a scene could not be rendered, in words a student can read (Japanese and English).

use cg_core::lang::Lang;
use cg_core::scene::PrepareError;
use cg_core::transform::TransformError;

use crate::output::MAX_SIZE;

/// Why [`crate::render`] could not draw a scene. Nothing in the scene makes the renderer panic;
/// every problem it finds is one of these, naming what and where.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RenderError {
    /// The image has no pixels.
    #[error("the image size {width}×{height} has no pixels: width and height must be at least 1")]
    ZeroSize {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// The image is larger than the rasterizer's fixed-point window coordinates allow.
    #[error("the image size {width}×{height} is too large: each side can be at most {MAX_SIZE}")]
    TooLarge {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
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
        /// The vertex (V-number of the prepared mesh).
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

impl RenderError {
    /// The message for a student in `lang` (the English one is also the `Display`).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        if lang == Lang::En {
            return self.to_string();
        }
        match self {
            RenderError::ZeroSize { width, height } => format!(
                "画像の大きさ {width}×{height} には画素がありません。幅と高さは 1 以上にしてください"
            ),
            RenderError::TooLarge { width, height } => format!(
                "画像の大きさ {width}×{height} は大きすぎます。幅と高さは {MAX_SIZE} 以下にしてください"
            ),
            // The transform errors carry both languages in their own message.
            RenderError::Camera(e) => format!("カメラの設定が正しくありません: {e}"),
            RenderError::Projection(e) => format!("投影の設定が正しくありません: {e}"),
            RenderError::Prepare(e) => e.message(lang),
            RenderError::MissingTexture { object, texture, count } => format!(
                "オブジェクト \"{object}\" はテクスチャ {texture} を使いますが、シーンのテクスチャは {count} 個です (番号 0..{count})"
            ),
            RenderError::NonFinite { object, vertex, position } => format!(
                "オブジェクト \"{object}\": 頂点 V{vertex} のクリップ座標 {position:?} が有限の値ではありません (座標や拡大率が大きすぎませんか)"
            ),
            RenderError::Threads { threads, message } => {
                format!("描画用のスレッドを {threads} 個起動できません: {message}")
            }
        }
    }
}
