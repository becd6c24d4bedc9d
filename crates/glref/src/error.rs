//! Why the OpenGL reference could not draw a scene, in Japanese and English.

use cg_core::lang::Lang;
use cg_core::scene::PrepareError;
use cg_core::texture::TextureError;
use cg_core::transform::TransformError;

/// What to install, and how, for the OpenGL reference to run (one sentence in `lang`).
#[must_use]
pub fn install_hint(lang: Lang) -> &'static str {
    match lang {
        Lang::En => {
            "It needs a C compiler and Mesa's off-screen renderer OSMesa: run `bash scripts/setup.sh` \
             (on Debian/Ubuntu it installs gcc, libc6-dev and libosmesa6-dev), or set CC to your C \
             compiler"
        }
        Lang::Ja => {
            "C コンパイラーと Mesa のオフスクリーンレンダラー OSMesa が必要です: \
             `bash scripts/setup.sh` を実行してください（Debian/Ubuntu では gcc, libc6-dev, \
             libosmesa6-dev を入れます）。C コンパイラーは環境変数 CC でも指定できます"
        }
    }
}

/// Why the OpenGL reference could not draw a scene. `Display` is the English message;
/// [`GlRefError::message`] gives it in either language.
#[derive(Debug, thiserror::Error)]
pub enum GlRefError {
    /// The reference cannot run on this machine: no C compiler, no OSMesa, or the program did
    /// not build or start.
    #[error("the OpenGL reference is not available: {detail}. {}", install_hint(Lang::En))]
    NotAvailable {
        /// What went wrong, with the compiler's or the program's own words.
        detail: String,
    },
    /// The scene uses the lecture's light model, which OpenGL does not have.
    #[error(
        "the scene uses the lecture's light model (light_model = \"lecture\"), which OpenGL 1.x \
         does not have: the OpenGL reference draws only light_model = \"opengl\""
    )]
    LectureLightModel,
    /// The scene asks for Phong shading, which OpenGL's fixed-function pipeline does not have.
    #[error(
        "the scene asks for Phong shading (shading = \"phong\"), which OpenGL's fixed-function \
         pipeline does not have: the OpenGL reference draws only \"flat\" (GL_FLAT) and \
         \"gouraud\" (GL_SMOOTH)"
    )]
    PhongShading,
    /// More point lights than OpenGL's eight (GL_LIGHT0 … GL_LIGHT7); area lights count as
    /// their samples.
    #[error(
        "the scene has {count} point lights (area lights count as their samples), but OpenGL \
         has only 8 (GL_LIGHT0 … GL_LIGHT7)"
    )]
    TooManyLights {
        /// How many point lights the scene's lights stand for.
        count: usize,
    },
    /// An image side of zero pixels, or larger than OSMesa draws.
    #[error("the image must be 1×1 to {max}×{max} pixels, got {width}×{height}")]
    Size {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
        /// The largest side OSMesa draws.
        max: u32,
    },
    /// The projection cannot be built.
    #[error("the projection: {0}")]
    Projection(TransformError),
    /// The view cannot be built.
    #[error("the camera: {0}")]
    View(TransformError),
    /// An object cannot be made ready to draw.
    #[error("{0}")]
    Prepare(PrepareError),
    /// A number the reference must pass to OpenGL is NaN or infinite.
    #[error("{what} is not finite ({value}): OpenGL cannot draw it")]
    NotFinite {
        /// Which number (`object "pyramid": vertex 3 position`).
        what: String,
        /// The value found.
        value: f32,
    },
    /// A value outside the range OpenGL accepts (GL_INVALID_VALUE).
    #[error("{what} is {value}, but OpenGL accepts only {range}")]
    OutsideGlRange {
        /// Which value (`material "shiny": shininess`).
        what: String,
        /// The value found.
        value: f32,
        /// The range OpenGL accepts, as text (`0 to 128`).
        range: &'static str,
    },
    /// A directional light whose direction is zero.
    #[error("light {light}: a directional light needs a non-zero direction")]
    ZeroDirection {
        /// The light's index in the scene (from 0).
        light: usize,
    },
    /// An object refers to a texture the scene does not have.
    #[error("object \"{object}\": texture {texture} does not exist (the scene has {count})")]
    MissingTexture {
        /// The object's name.
        object: String,
        /// The texture index asked for.
        texture: usize,
        /// How many textures the scene has.
        count: usize,
    },
    /// A texture whose size and texels do not agree.
    #[error("texture {texture}: {source}")]
    BadTexture {
        /// The texture's index in the scene.
        texture: usize,
        /// What is wrong with it.
        source: TextureError,
    },
    /// A textured object whose mesh has no texture coordinates.
    #[error("object \"{object}\" has a texture but its mesh has no texture coordinates")]
    MissingTextureCoordinates {
        /// The object's name.
        object: String,
    },
    /// The program ran and reported an error (a GL error or an OSMesa failure).
    #[error("the OpenGL reference program failed ({status}): {stderr}")]
    Program {
        /// How it ended (`exit status: 1`).
        status: String,
        /// What it wrote on standard error.
        stderr: String,
    },
    /// The program's image could not be read.
    #[error("the OpenGL reference program wrote an unreadable image: {detail}")]
    BadOutput {
        /// What is wrong with it.
        detail: String,
    },
}

impl GlRefError {
    /// The message for a student in `lang` (English is also the `Display`).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        if lang == Lang::En {
            return self.to_string();
        }
        match self {
            GlRefError::NotAvailable { detail } => {
                format!("OpenGL の参照レンダラーが使えません: {detail}。{}", install_hint(lang))
            }
            GlRefError::LectureLightModel => "シーンが講義の光のモデル (light_model = \"lecture\") \
                 を使っていますが、OpenGL 1.x にはありません。OpenGL の参照レンダラーが描けるのは \
                 light_model = \"opengl\" だけです"
                .to_owned(),
            GlRefError::PhongShading => "シーンがフォンシェーディング (shading = \"phong\") を\
                 指定していますが、OpenGL の固定機能パイプラインにはありません。描けるのは \"flat\" \
                 (GL_FLAT) と \"gouraud\" (GL_SMOOTH) だけです"
                .to_owned(),
            GlRefError::TooManyLights { count } => format!(
                "シーンの点光源は {count} 個です（面光源はサンプル数で数えます）が、OpenGL の光源は \
                 8 個 (GL_LIGHT0 … GL_LIGHT7) までです"
            ),
            GlRefError::Size { width, height, max } => format!(
                "画像の大きさは 1×1 から {max}×{max} ピクセルまでです（{width}×{height} が指定されました）"
            ),
            GlRefError::Projection(e) => format!("投影変換: {e}"),
            GlRefError::View(e) => format!("カメラ: {e}"),
            GlRefError::Prepare(e) => e.message(lang),
            GlRefError::NotFinite { what, value } => {
                format!("{what} が有限の値ではありません ({value})。OpenGL では描けません")
            }
            GlRefError::OutsideGlRange { what, value, range } => {
                format!("{what} が {value} ですが、OpenGL が受け付けるのは {range} だけです")
            }
            GlRefError::ZeroDirection { light } => {
                format!("光源 {light}: 平行光源の方向がゼロです")
            }
            GlRefError::MissingTexture { object, texture, count } => format!(
                "オブジェクト \"{object}\": テクスチャ {texture} がありません（シーンのテクスチャは {count} 個）"
            ),
            GlRefError::BadTexture { texture, source } => {
                format!("テクスチャ {texture}: {}", source.describe(lang))
            }
            GlRefError::MissingTextureCoordinates { object } => format!(
                "オブジェクト \"{object}\" にはテクスチャがありますが、メッシュにテクスチャ座標がありません"
            ),
            GlRefError::Program { status, stderr } => {
                format!("OpenGL の参照プログラムがエラーで終了しました ({status}): {stderr}")
            }
            GlRefError::BadOutput { detail } => {
                format!("OpenGL の参照プログラムの出力画像が読めません: {detail}")
            }
        }
    }
}
