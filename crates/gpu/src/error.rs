//! Why the GPU renderer could not start or draw, in Japanese and English.

use cg_core::image::SizeError;
use cg_core::lang::{Lang, Text, t};
use cg_core::scene::PrepareError;
use cg_core::transform::TransformError;

/// Why [`crate::Gpu::new`] or [`crate::Gpu::render`] failed. `Display` gives English and
/// Japanese; [`GpuError::message`] one language.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum GpuError {
    /// No GPU adapter (no Vulkan driver, not even Mesa's lavapipe).
    #[error(
        "no GPU adapter found: install a Vulkan driver (on Linux without a GPU: Mesa's lavapipe, package mesa-vulkan-drivers) or use the CPU rasterizer / GPU アダプタが見つかりません: Vulkan ドライバ（GPU のない Linux では Mesa の lavapipe、パッケージ mesa-vulkan-drivers）を入れるか、CPU ラスタライザを使ってください"
    )]
    NoAdapter,
    /// The adapter refused to open a device.
    #[error("the GPU adapter refused a device: {0} / GPU デバイスを開けません: {0}")]
    Device(String),
    /// The image size is zero or too large.
    #[error("{0}")]
    Size(SizeError),
    /// The camera is invalid (eye at the target, up parallel to the view direction…).
    #[error("the camera is invalid: {0}")]
    Camera(TransformError),
    /// The projection is invalid.
    #[error("the projection is invalid: {0}")]
    Projection(TransformError),
    /// An object cannot be prepared (its transform or its normals).
    #[error("{0}")]
    Prepare(PrepareError),
    /// An object refers to a texture the scene does not have.
    #[error("object \"{object}\" uses texture {texture}, but the scene has {count}")]
    MissingTexture {
        /// The object's name.
        object: String,
        /// The index it refers to.
        texture: usize,
        /// How many textures the scene has.
        count: usize,
    },
    /// A vertex's world position is not finite.
    #[error("object \"{object}\": vertex {vertex} is at {position:?}, not a finite point")]
    NonFinite {
        /// The object's name.
        object: String,
        /// The vertex index in the prepared mesh.
        vertex: usize,
        /// Where it ended up.
        position: [f32; 3],
    },
    /// An object's vertex buffer is larger than the device allows (`max_buffer_size`).
    #[error(
        "object \"{object}\" has {triangles} triangles: its vertices take {bytes} bytes, more than this GPU's largest buffer ({limit} bytes); draw it with the CPU rasterizer (--renderer raster) or with fewer triangles"
    )]
    TooLarge {
        /// The object's name.
        object: String,
        /// Its triangles.
        triangles: usize,
        /// Its vertex buffer's size in bytes.
        bytes: u64,
        /// The device's `max_buffer_size`.
        limit: u64,
    },
    /// wgpu reported an error (a shader or pipeline the device rejected, a lost device).
    #[error("wgpu: {0}")]
    Wgpu(String),
}

impl GpuError {
    /// The message for a student in `lang`.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let ja = match self {
            GpuError::NoAdapter => {
                return t(
                    "GPU アダプタが見つかりません: Vulkan ドライバ（GPU のない Linux では Mesa の lavapipe、パッケージ mesa-vulkan-drivers）を入れるか、CPU ラスタライザを使ってください",
                    "no GPU adapter found: install a Vulkan driver (on Linux without a GPU: Mesa's lavapipe, package mesa-vulkan-drivers) or use the CPU rasterizer",
                );
            }
            GpuError::Device(e) => {
                return Text::new(
                    format!("GPU デバイスを開けません: {e}"),
                    format!("the GPU adapter refused a device: {e}"),
                );
            }
            GpuError::Size(e) => return e.text(),
            GpuError::Prepare(e) => return e.text(),
            GpuError::Camera(e) => format!("カメラが不正です: {e}"),
            GpuError::Projection(e) => format!("投影が不正です: {e}"),
            GpuError::MissingTexture { object, texture, count } => format!(
                "オブジェクト \"{object}\" はテクスチャ {texture} を使いますが、シーンには {count} 枚しかありません"
            ),
            GpuError::TooLarge { object, triangles, bytes, limit } => format!(
                "オブジェクト \"{object}\" は三角形 {triangles} 個で、頂点が {bytes} バイトになり、この GPU のバッファの上限（{limit} バイト）を超えます。CPU ラスタライザ（--renderer raster）で描くか、三角形を減らしてください"
            ),
            GpuError::NonFinite { object, vertex, position } => format!(
                "オブジェクト \"{object}\": 頂点 {vertex} の位置 {position:?} が有限の点ではありません"
            ),
            _ => self.to_string(),
        };
        Text::new(ja, self.to_string())
    }
}

impl From<SizeError> for GpuError {
    fn from(e: SizeError) -> GpuError {
        GpuError::Size(e)
    }
}

impl From<PrepareError> for GpuError {
    fn from(e: PrepareError) -> GpuError {
        GpuError::Prepare(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_adapter_says_what_to_do_in_both_languages() {
        let e = GpuError::NoAdapter;
        let both = e.to_string();
        assert!(both.contains("no GPU adapter") && both.contains("GPU アダプタが見つかりません"));
        assert!(e.message(Lang::En).contains("mesa-vulkan-drivers"));
        assert!(!e.message(Lang::En).contains("アダプタ"));
        assert!(e.message(Lang::Ja).contains("lavapipe") && !e.message(Lang::Ja).contains("found"));
    }
}
