//! Why the OpenGL reference could not draw a scene, in Japanese and English.

use cg_core::lang::{Lang, Text, t};
use cg_core::scene::PrepareError;
use cg_core::texture::TextureError;
use cg_core::transform::TransformError;

/// What to install, and how, for the OpenGL reference to run (one sentence).
#[must_use]
pub fn install_hint() -> Text {
    t(
        "C コンパイラーと Mesa のオフスクリーンレンダラ OSMesa が必要です: \
         `bash scripts/setup.sh` を実行してください（Debian/Ubuntu では gcc, libc6-dev, \
         libosmesa6-dev を入れます）。C コンパイラーは環境変数 CC でも指定できます",
        "It needs a C compiler and Mesa's off-screen renderer OSMesa: run `bash scripts/setup.sh` \
         (on Debian/Ubuntu it installs gcc, libc6-dev and libosmesa6-dev), or set CC to your C \
         compiler",
    )
}

/// Why the OpenGL reference could not draw a scene. `Display` is the English message;
/// [`GlRefError::message`] gives it in either language, [`GlRefError::text`] in both.
#[derive(Debug)]
pub enum GlRefError {
    /// The reference cannot run on this machine: no C compiler, no OSMesa, or the program did
    /// not build or start.
    NotAvailable {
        /// What went wrong, with the compiler's or the program's own words.
        detail: String,
    },
    /// The scene uses the lecture's light model, which OpenGL does not have.
    LectureLightModel,
    /// The scene asks for Phong shading, which OpenGL's fixed-function pipeline does not have.
    PhongShading,
    /// More point lights than OpenGL's eight (GL_LIGHT0 … GL_LIGHT7); area lights count as
    /// their samples.
    TooManyLights {
        /// How many point lights the scene's lights stand for.
        count: usize,
    },
    /// An image side of zero pixels, or larger than OSMesa draws.
    Size {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
        /// The largest side OSMesa draws.
        max: u32,
    },
    /// The projection cannot be built.
    Projection(TransformError),
    /// The view cannot be built.
    View(TransformError),
    /// An object cannot be made ready to draw.
    Prepare(PrepareError),
    /// A number the reference must pass to OpenGL is NaN or infinite.
    NotFinite {
        /// Which number (`object "pyramid": vertex 3 position`).
        what: String,
        /// The value found.
        value: f32,
    },
    /// A value outside the range OpenGL accepts (GL_INVALID_VALUE).
    OutsideGlRange {
        /// Which value (`material "shiny": shininess`).
        what: String,
        /// The value found.
        value: f32,
        /// The range OpenGL accepts, as text (`0 to 128`).
        range: &'static str,
    },
    /// A directional light whose direction is zero.
    ZeroDirection {
        /// The light's index in the scene (from 0).
        light: usize,
    },
    /// An object refers to a texture the scene does not have.
    MissingTexture {
        /// The object's name.
        object: String,
        /// The texture index asked for.
        texture: usize,
        /// How many textures the scene has.
        count: usize,
    },
    /// A texture whose size and texels do not agree.
    BadTexture {
        /// The texture's index in the scene.
        texture: usize,
        /// What is wrong with it.
        source: TextureError,
    },
    /// A textured object whose mesh has no texture coordinates.
    MissingTextureCoordinates {
        /// The object's name.
        object: String,
    },
    /// The program ran and reported an error (a GL error or an OSMesa failure).
    Program {
        /// How it ended (`exit status: 1`).
        status: String,
        /// What it wrote on standard error.
        stderr: String,
    },
    /// The program's image could not be read.
    BadOutput {
        /// What is wrong with it.
        detail: String,
    },
}

impl GlRefError {
    /// The message for a student in `lang` (English is also the `Display`).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message for a student in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            GlRefError::NotAvailable { detail } => Text::new(
                format!("OpenGL の参照レンダラが使えません: {detail}。{}", install_hint().ja),
                format!("the OpenGL reference is not available: {detail}. {}", install_hint().en),
            ),
            GlRefError::LectureLightModel => t(
                "シーンが講義の光のモデル (light_model = \"lecture\") \
                 を使っていますが、OpenGL 1.x にはありません。OpenGL の参照レンダラが描けるのは \
                 light_model = \"opengl\" だけです",
                "the scene uses the lecture's light model (light_model = \"lecture\"), which OpenGL 1.x \
                 does not have: the OpenGL reference draws only light_model = \"opengl\"",
            ),
            GlRefError::PhongShading => t(
                "シーンがフォンシェーディング (shading = \"phong\") を\
                 指定していますが、OpenGL の固定機能パイプラインにはありません。描けるのは \"flat\" \
                 (GL_FLAT) と \"gouraud\" (GL_SMOOTH) だけです",
                "the scene asks for Phong shading (shading = \"phong\"), which OpenGL's fixed-function \
                 pipeline does not have: the OpenGL reference draws only \"flat\" (GL_FLAT) and \
                 \"gouraud\" (GL_SMOOTH)",
            ),
            GlRefError::TooManyLights { count } => Text::new(
                format!(
                    "シーンの点光源は {count} 個です（面光源はサンプル数で数えます）が、OpenGL の光源は \
                     8 個 (GL_LIGHT0 … GL_LIGHT7) までです"
                ),
                format!(
                    "the scene has {count} point lights (area lights count as their samples), but OpenGL \
                     has only 8 (GL_LIGHT0 … GL_LIGHT7)"
                ),
            ),
            GlRefError::Size { width, height, max } => Text::new(
                format!(
                    "画像の大きさは 1×1 から {max}×{max} ピクセルまでです（{width}×{height} が指定されました）"
                ),
                format!("the image must be 1×1 to {max}×{max} pixels, got {width}×{height}"),
            ),
            GlRefError::Projection(e) => {
                let e = e.text();
                Text::new(format!("投影変換: {}", e.ja), format!("the projection: {}", e.en))
            }
            GlRefError::View(e) => {
                let e = e.text();
                Text::new(format!("カメラ: {}", e.ja), format!("the camera: {}", e.en))
            }
            GlRefError::Prepare(e) => e.text(),
            GlRefError::NotFinite { what, value } => Text::new(
                format!("{what} が有限の値ではありません ({value})。OpenGL では描けません"),
                format!("{what} is not finite ({value}): OpenGL cannot draw it"),
            ),
            GlRefError::OutsideGlRange { what, value, range } => Text::new(
                format!("{what} が {value} ですが、OpenGL が受け付けるのは {range} だけです"),
                format!("{what} is {value}, but OpenGL accepts only {range}"),
            ),
            GlRefError::ZeroDirection { light } => Text::new(
                format!("光源 {light}: 平行光源の方向がゼロです"),
                format!("light {light}: a directional light needs a non-zero direction"),
            ),
            GlRefError::MissingTexture { object, texture, count } => Text::new(
                format!(
                    "オブジェクト \"{object}\": テクスチャ {texture} がありません（シーンのテクスチャは {count} 個）"
                ),
                format!(
                    "object \"{object}\": texture {texture} does not exist (the scene has {count})"
                ),
            ),
            GlRefError::BadTexture { texture, source } => Text::new(
                format!("テクスチャ {texture}: {}", source.describe(Lang::Ja)),
                format!("texture {texture}: {}", source.describe(Lang::En)),
            ),
            GlRefError::MissingTextureCoordinates { object } => Text::new(
                format!(
                    "オブジェクト \"{object}\" にはテクスチャがありますが、メッシュにテクスチャ座標がありません"
                ),
                format!(
                    "object \"{object}\" has a texture but its mesh has no texture coordinates"
                ),
            ),
            GlRefError::Program { status, stderr } => Text::new(
                format!("OpenGL の参照プログラムがエラーで終了しました ({status}): {stderr}"),
                format!("the OpenGL reference program failed ({status}): {stderr}"),
            ),
            GlRefError::BadOutput { detail } => Text::new(
                format!("OpenGL の参照プログラムの出力画像が読めません: {detail}"),
                format!("the OpenGL reference program wrote an unreadable image: {detail}"),
            ),
        }
    }
}

impl std::fmt::Display for GlRefError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text().en)
    }
}

impl std::error::Error for GlRefError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            GlRefError::BadTexture { source, .. } => Some(source),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every variant (the match in the loop is exhaustive: a new one does not compile until it
    /// has a sample here).
    fn samples() -> Vec<GlRefError> {
        let all = vec![
            GlRefError::NotAvailable { detail: "ENOENT".into() },
            GlRefError::LectureLightModel,
            GlRefError::PhongShading,
            GlRefError::TooManyLights { count: 12 },
            GlRefError::Size { width: 0, height: 4, max: 4096 },
            GlRefError::Projection(TransformError::FieldOfView { fovy_deg: 180.0 }),
            GlRefError::View(TransformError::EyeAtTarget { eye: cg_core::glam::Vec3::ONE }),
            GlRefError::Prepare(PrepareError::Normals {
                object: "ball".into(),
                source: cg_core::normals::NormalsError::Missing,
            }),
            GlRefError::NotFinite { what: "V3".into(), value: f32::NAN },
            GlRefError::OutsideGlRange { what: "shininess".into(), value: 200.0, range: "0..=128" },
            GlRefError::ZeroDirection { light: 1 },
            GlRefError::MissingTexture { object: "ball".into(), texture: 2, count: 1 },
            GlRefError::BadTexture {
                texture: 0,
                source: TextureError::ZeroSize { width: 0, height: 4 },
            },
            GlRefError::MissingTextureCoordinates { object: "ball".into() },
            GlRefError::Program { status: "SIGSEGV".into(), stderr: "GL_ERROR".into() },
            GlRefError::BadOutput { detail: "EOF".into() },
        ];
        for e in &all {
            match e {
                GlRefError::NotAvailable { .. }
                | GlRefError::LectureLightModel
                | GlRefError::PhongShading
                | GlRefError::TooManyLights { .. }
                | GlRefError::Size { .. }
                | GlRefError::Projection(_)
                | GlRefError::View(_)
                | GlRefError::Prepare(_)
                | GlRefError::NotFinite { .. }
                | GlRefError::OutsideGlRange { .. }
                | GlRefError::ZeroDirection { .. }
                | GlRefError::MissingTexture { .. }
                | GlRefError::BadTexture { .. }
                | GlRefError::MissingTextureCoordinates { .. }
                | GlRefError::Program { .. }
                | GlRefError::BadOutput { .. } => {}
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

    #[test]
    fn only_a_bad_texture_has_a_source() {
        use std::error::Error as _;
        for e in samples() {
            assert_eq!(e.source().is_some(), matches!(e, GlRefError::BadTexture { .. }), "{e:?}");
        }
    }
}
