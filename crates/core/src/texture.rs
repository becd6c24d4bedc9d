//! Textures (テクスチャ) and their sampling: nearest and bilinear filtering, repeat and clamp.
//!
//! Texture coordinates follow OpenGL: `(s, t) = (0, 0)` is the image's bottom-left corner and
//! `(1, 1)` its top-right corner; texel `(i, j)` covers `[i/w, (i+1)/w) × [j/h, (j+1)/h)` and its
//! centre is at `((i + ½)/w, (j + ½)/h)`.
//!
//! | coordinate | [`Wrap::Repeat`] (GL_REPEAT) | [`Wrap::Clamp`] (GL_CLAMP_TO_EDGE) |
//! |---|---|---|
//! | `0.0` | the first texel (nearest); the seam between the last and the first texel (bilinear) | the first texel, exactly |
//! | `1.0` | the same point as `0.0` | the last texel, exactly |
//! | `-0.25` | the same point as `0.75` | the first texel |
//! | `1e6 + 0.25` | the same point as `0.25` (reduced before scaling to texels) | the last texel |
//! | NaN, ±∞ | transparent black `(0, 0, 0, 0)` | transparent black |
//!
//! See also [`Texture::sample`] and [`wrap_coordinate`].

use glam::{Vec2, Vec4};

use crate::Rgb;
use crate::lang::{Lang, Text};

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

impl TexEnv {
    /// The texture environment (GL_TEXTURE_ENV_MODE) applied to a fragment: GL_MODULATE gives
    /// `lit × texel` per channel (specular included, as OpenGL's GL_SINGLE_COLOR), GL_REPLACE the
    /// texel's colour alone. Alpha is dropped (the kit draws opaque surfaces). Not clamped.
    #[must_use]
    #[inline]
    pub fn apply(self, lit: Rgb, texel: Vec4) -> Rgb {
        match self {
            TexEnv::Modulate => lit * texel.truncate(),
            TexEnv::Replace => texel.truncate(),
        }
    }
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

impl Sampler {
    /// The integer shift to take off a triangle's texture coordinates before they are
    /// interpolated (docs/numerics.md row 23): `⌊uv⌋` of one of its corners along each [`Wrap::Repeat`]
    /// axis, 0 along a [`Wrap::Clamp`] axis (where a shift would change what is sampled).
    ///
    /// Under repeat an integer shift is invisible, and it keeps the interpolated values small:
    /// coordinates near 1e6 interpolated as they are lose everything below 1e6·2⁻²⁴ ≈ 0.06 to
    /// the rounding of the weights; shifted, they keep f32's precision near 1. Non-finite
    /// coordinates give no shift.
    #[must_use]
    #[inline]
    pub fn repeat_origin(self, uv: Vec2) -> Vec2 {
        let shift = |s: f32, wrap: Wrap| match wrap {
            Wrap::Repeat if s.is_finite() => s.floor(),
            _ => 0.0,
        };
        Vec2::new(shift(uv.x, self.wrap_u), shift(uv.y, self.wrap_v))
    }
}

/// Why a [`Texture`] could not be made.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TextureError {
    /// A side of zero texels.
    #[error("a texture needs at least 1×1 texels, got {width}×{height}")]
    ZeroSize {
        /// The width given.
        width: u32,
        /// The height given.
        height: u32,
    },
    /// The texel list does not have `width × height` entries.
    #[error("a {width}×{height} texture needs {expected} texels, got {got}")]
    TexelCount {
        /// The width given.
        width: u32,
        /// The height given.
        height: u32,
        /// `width × height`.
        expected: u64,
        /// How many texels were given.
        got: usize,
    },
}

impl TextureError {
    /// The message in `lang` (the English one is also the `Display`).
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let ja = match self {
            TextureError::ZeroSize { width, height } => format!(
                "テクスチャは 1×1 テクセル以上が必要です（{width}×{height} が指定されました）"
            ),
            TextureError::TexelCount { width, height, expected, got } => format!(
                "{width}×{height} のテクスチャには {expected} 個のテクセルが必要ですが、{got} 個でした"
            ),
        };
        Text::new(ja, self.to_string())
    }
}

impl Texture {
    /// A `width × height` texture from its texels, row by row from the *bottom* row up.
    ///
    /// # Errors
    /// [`TextureError::ZeroSize`] when a side is 0; [`TextureError::TexelCount`] when `texels`
    /// does not have `width × height` entries.
    ///
    /// See also [`Texture::from_fn`].
    pub fn new(width: u32, height: u32, texels: Vec<[u8; 4]>) -> Result<Texture, TextureError> {
        if width == 0 || height == 0 {
            return Err(TextureError::ZeroSize { width, height });
        }
        let expected = u64::from(width) * u64::from(height);
        if texels.len() as u64 != expected {
            return Err(TextureError::TexelCount { width, height, expected, got: texels.len() });
        }
        Ok(Texture { width, height, texels })
    }

    /// A `width × height` texture whose texel `(x, y)` is `f(x, y)`; `y = 0` is the bottom row.
    ///
    /// # Errors
    /// [`TextureError::ZeroSize`] when a side is 0.
    pub fn from_fn(
        width: u32,
        height: u32,
        mut f: impl FnMut(u32, u32) -> [u8; 4],
    ) -> Result<Texture, TextureError> {
        if width == 0 || height == 0 {
            return Err(TextureError::ZeroSize { width, height });
        }
        let texels =
            (0..height).flat_map(|y| (0..width).map(move |x| (x, y))).map(|(x, y)| f(x, y));
        Texture::new(width, height, texels.collect())
    }

    /// Texel `(x, y)` as stored (RGBA8); `y = 0` is the bottom row.
    ///
    /// # Panics
    /// When `x ≥ width` or `y ≥ height`.
    ///
    /// See also [`Texture::sample`], which never panics.
    #[must_use]
    pub fn texel(&self, x: u32, y: u32) -> [u8; 4] {
        assert!(
            x < self.width && y < self.height,
            "texel ({x}, {y}) is outside the {}×{} texture",
            self.width,
            self.height
        );
        self.texels[y as usize * self.width as usize + x as usize]
    }

    /// The texture's colour at texture coordinate `uv = (s, t)` as RGBA in `[0, 1]`, with OpenGL's
    /// conventions: texel `i` covers `[i/w, (i+1)/w)`; [`Filter::Nearest`] takes the texel that
    /// covers the point, [`Filter::Bilinear`] blends the four texels whose centres surround it.
    /// Each coordinate is first reduced by [`wrap_coordinate`], so huge coordinates (`1e6 + 0.25`)
    /// sample like their fractional part as far as f32 holds it.
    ///
    /// At the edges: under [`Wrap::Clamp`], `0.0` gives the first texel and `1.0` the last one,
    /// exactly (bilinear included). Under [`Wrap::Repeat`], `1.0` is the same point as `0.0`: the
    /// seam between the last and the first texel (nearest: the first texel; bilinear: their
    /// average).
    ///
    /// Non-finite coordinates (NaN, ±∞) give transparent black `(0, 0, 0, 0)`, never NaN; so does a
    /// texture built by hand with a zero side or missing texels (use [`Texture::new`]).
    ///
    /// See also [`Texture::texel`].
    #[must_use]
    pub fn sample(&self, uv: Vec2, sampler: Sampler) -> Vec4 {
        if !uv.is_finite() || self.width == 0 || self.height == 0 {
            return Vec4::ZERO;
        }
        let s = wrap_coordinate(uv.x, sampler.wrap_u);
        let t = wrap_coordinate(uv.y, sampler.wrap_v);
        match sampler.filter {
            Filter::Nearest => {
                self.fetch(nearest_index(s, self.width), nearest_index(t, self.height))
            }
            Filter::Bilinear => {
                let (x0, x1, a) = linear_indices(s, self.width, sampler.wrap_u);
                let (y0, y1, b) = linear_indices(t, self.height, sampler.wrap_v);
                let bottom = self.fetch(x0, y0).lerp(self.fetch(x1, y0), a);
                let top = self.fetch(x0, y1).lerp(self.fetch(x1, y1), a);
                // The blend of values in [0, 1] can round a hair outside; keep the promise.
                bottom.lerp(top, b).clamp(Vec4::ZERO, Vec4::ONE)
            }
        }
    }

    /// Texel `(x, y)` as RGBA in `[0, 1]`; transparent black if the texel list is too short.
    fn fetch(&self, x: u32, y: u32) -> Vec4 {
        let i = y as usize * self.width as usize + x as usize;
        let [r, g, b, a] = self.texels.get(i).copied().unwrap_or([0; 4]);
        Vec4::new(r.into(), g.into(), b.into(), a.into()) / 255.0
    }
}

/// One texture coordinate reduced by the wrap mode, *before* it is scaled to texels:
///
/// - [`Wrap::Repeat`]: the fractional part `s − ⌊s⌋` in `[0, 1)`. It is exact for every finite
///   `s ≥ 0` and every `s ≤ −1`; for `−1 < s < 0` the one rounding of `s + 1` may reach 1, and
///   then the result is the largest f32 below 1 (the point still lies in the last texel). Integers
///   (`0`, `1`, `−3`, `1e6`) give 0; `1e6 + 0.25` gives `0.25` exactly.
/// - [`Wrap::Clamp`]: `s` clamped to `[0, 1]` (exact).
///
/// Non-finite input is returned unchanged (NaN stays NaN); [`Texture::sample`] checks for it first.
#[must_use]
pub fn wrap_coordinate(s: f32, wrap: Wrap) -> f32 {
    match wrap {
        Wrap::Repeat => {
            if !s.is_finite() {
                return s;
            }
            // `%` is exact; only the `+ 1` that makes a negative remainder positive rounds.
            let r = s.rem_euclid(1.0);
            if r < 1.0 { r } else { 1.0 - f32::EPSILON / 2.0 }
        }
        Wrap::Clamp => s.clamp(0.0, 1.0),
    }
}

/// The texel that covers `s ∈ [0, 1]` along a side of `n` texels; `1.0` (clamp) is the last one.
fn nearest_index(s: f32, n: u32) -> u32 {
    // `as u32` saturates; s·n ≥ 0 here.
    ((s * n as f32).floor() as u32).min(n - 1)
}

/// The two texels whose centres surround `s ∈ [0, 1]` along a side of `n` texels, wrapped or
/// clamped, and the weight of the second one.
fn linear_indices(s: f32, n: u32, wrap: Wrap) -> (u32, u32, f32) {
    let u = s * n as f32 - 0.5;
    let i0 = u.floor();
    let weight = u - i0;
    let i0 = i0 as i64;
    let n = i64::from(n);
    let place = |i: i64| match wrap {
        Wrap::Repeat => i.rem_euclid(n),
        Wrap::Clamp => i.clamp(0, n - 1),
    };
    // Both results lie in 0..n, so they fit u32.
    (place(i0) as u32, place(i0 + 1) as u32, weight)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tex_env_modulates_or_replaces() {
        let lit = Rgb::new(0.5, 2.0, 0.0);
        let texel = Vec4::new(0.5, 0.25, 1.0, 0.0);
        assert_eq!(TexEnv::Modulate.apply(lit, texel), Rgb::new(0.25, 0.5, 0.0));
        assert_eq!(TexEnv::Replace.apply(lit, texel), Rgb::new(0.5, 0.25, 1.0));
    }

    #[test]
    fn the_repeat_origin_is_an_integer_shift_on_repeat_axes_only() {
        let s = Sampler { filter: Filter::Nearest, wrap_u: Wrap::Repeat, wrap_v: Wrap::Clamp };
        assert_eq!(s.repeat_origin(Vec2::new(1.0e6 + 0.25, 7.5)), Vec2::new(1.0e6, 0.0));
        assert_eq!(s.repeat_origin(Vec2::new(-1.0e6 + 0.25, 0.0)), Vec2::new(-1.0e6, 0.0));
        assert_eq!(s.repeat_origin(Vec2::new(-0.5, 0.0)), Vec2::new(-1.0, 0.0));
        assert_eq!(s.repeat_origin(Vec2::new(f32::NAN, 0.0)), Vec2::ZERO);
        // Sampling after the shift is the same as before it, for every coordinate a texel
        // centre away from the edges (both exact here).
        let t = Texture::from_fn(4, 1, |x, _| [x as u8 * 60, 0, 0, 255]).unwrap();
        for u in [1.0e3 + 0.375, 1.0e5 + 0.625, 1.0e6 + 0.125, -1.0e6 + 0.875] {
            let uv = Vec2::new(u, 0.5);
            assert_eq!(t.sample(uv - s.repeat_origin(uv), s), t.sample(uv, s), "u = {u}");
        }
    }
}
