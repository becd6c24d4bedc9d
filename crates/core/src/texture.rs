//! Textures (テクスチャ) and their sampling: nearest and bilinear filtering, repeat and clamp.

/// An RGBA8 image used as a texture. Row 0 is the image's *bottom* row, so texture coordinate
/// `(0, 0)` is the bottom-left corner as in OpenGL (loaders flip images stored top row first).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Texture {
    /// Width in texels (≥ 1).
    pub width: u32,
    /// Height in texels (≥ 1).
    pub height: u32,
    /// `width × height` texels, row by row from the bottom row up.
    pub texels: Vec<[u8; 4]>,
}

/// How a texture is filtered.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Filter {
    /// GL_NEAREST
    Nearest,
    /// GL_LINEAR
    #[default]
    Bilinear,
}

/// What happens to texture coordinates outside `[0, 1]`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Wrap {
    /// GL_REPEAT
    #[default]
    Repeat,
    /// GL_CLAMP_TO_EDGE
    Clamp,
}

/// How the texture colour combines with the lit colour.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TexEnv {
    /// GL_MODULATE: lit colour × texture colour.
    #[default]
    Modulate,
    /// GL_REPLACE: the texture colour, unlit.
    Replace,
}

/// Filter and wrap modes of one texture use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sampler {
    /// Filtering.
    pub filter: Filter,
    /// Wrap mode along u (s).
    pub wrap_u: Wrap,
    /// Wrap mode along v (t).
    pub wrap_v: Wrap,
}
