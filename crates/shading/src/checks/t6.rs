//! s.t6: flat, Gouraud and Phong shading — the student's `shade_pixel` against the renderer's
//! own rule, pixel by pixel (unit checks), and as whole images of the student's sphere against
//! the CPU rasterizer's images rendered now with the kit's lighting.
//!
//! Tolerances: unit checks 1e-4 per channel (the renderer interpolates the normal in f64, a
//! student in f32). Images: at least [`IMAGE_FRACTION`] of the sphere's pixels within
//! [`IMAGE_TOLERANCE`]/255 per channel in 8 bits — a correct `shade_pixel` gives every pixel
//! within 1/255 (the same weights, the same lighting; only float rounding differs).

use std::sync::{Arc, Mutex};

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::image::{Image, to_unorm8};
use cg_core::normals::interpolate_normal;
use cg_core::scene::Scene;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::inputs::{case_at, max_diff, num, vec};
use crate::render::{GBuffer, KitLight, compose, gbuffer, kit_image};
use crate::scenes::{CHECK_SIZE, check_scene, material};
use crate::{Impl, Pixel, Shading, Spec};

/// The fraction of the sphere's pixels that must be within [`IMAGE_TOLERANCE`].
pub const IMAGE_FRACTION: f64 = 0.995;
/// Per-channel tolerance in 8-bit steps.
pub const IMAGE_TOLERANCE: u8 = 2;
/// A pixel belongs to "the highlight Gouraud loses" when the kit's Phong image is brighter than
/// its Gouraud image there by more than this, in some channel.
pub const HIGHLIGHT_MARGIN: f32 = 0.1;
/// In the highlight, the student's Phong must be brighter than their Gouraud by more than this…
pub const KEEP_MARGIN: f32 = 0.05;
/// … in at least this fraction of its pixels.
pub const KEEP_FRACTION: f64 = 0.9;

/// The stub's colour: magenta, "not written yet".
const PLACEHOLDER: Rgb = Rgb::new(1.0, 0.0, 1.0);

const MODES: [Shading; 3] = [Shading::Flat, Shading::Gouraud, Shading::Phong];

fn mode_index(mode: Shading) -> usize {
    match mode {
        Shading::Flat => 0,
        Shading::Gouraud => 1,
        Shading::Phong => 2,
    }
}

fn mode_name(mode: Shading) -> (&'static str, &'static str) {
    match mode {
        Shading::Flat => ("フラットシェーディング", "flat shading"),
        Shading::Gouraud => ("グローシェーディング", "Gouraud shading"),
        Shading::Phong => ("フォンシェーディング", "Phong shading"),
    }
}

/// What the image checks compare with, made once per student variant: the sphere scene, its
/// G-buffer, the renderer's own flat, Gouraud and Phong images, and where the highlight is that
/// Gouraud loses.
pub(crate) struct Fixture {
    /// The checks' scene ([`check_scene`]).
    pub scene: Scene,
    /// Which face and weights every pixel sees.
    pub g: GBuffer,
    /// The renderer's images, flat, Gouraud, Phong.
    pub reference: [Image; 3],
    /// Per pixel: part of the highlight that Gouraud loses.
    pub highlight: Vec<bool>,
}

/// The fixtures made so far (the checks of one variant run many times in the kit's tests).
static FIXTURES: Mutex<Vec<(Spec, Arc<Fixture>)>> = Mutex::new(Vec::new());
/// How many fixtures are kept.
const KEEP: usize = 8;

fn kit_failure(e: &cg_raster::RenderError) -> Failure {
    Failure::new(t("kit があなたの球を描けること", "the kit draws your sphere"), e.text())
        .at(t("kit の描画", "the kit's rendering"))
        .cause(t(
            &format!(
                "kit の描画が失敗しました（kit の不具合です。先生に知らせてください）: {}",
                e.text().ja
            ),
            "the kit could not draw the sphere (a bug in the kit: please tell your teacher).",
        ))
}

impl Fixture {
    fn make(spec: &Spec) -> Result<Fixture, cg_raster::RenderError> {
        let scene = check_scene(spec);
        let g = gbuffer(&scene, CHECK_SIZE, CHECK_SIZE)?;
        let render = |mode| kit_image(&scene, Some(mode));
        let reference = [render(MODES[0])?, render(MODES[1])?, render(MODES[2])?];
        let highlight = reference[2]
            .pixels
            .iter()
            .zip(&reference[1].pixels)
            .zip(&g.texels)
            .map(|((p, q), seen)| seen.is_some() && (*p - *q).max_element() > HIGHLIGHT_MARGIN)
            .collect();
        Ok(Fixture { scene, g, reference, highlight })
    }

    /// The fixture of `spec`, made now or earlier.
    pub(crate) fn of(spec: &Spec) -> Result<Arc<Fixture>, Failure> {
        let mut cache = FIXTURES.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some((_, f)) = cache.iter().find(|(s, _)| s == spec) {
            return Ok(Arc::clone(f));
        }
        let f = Arc::new(Fixture::make(spec).map_err(|e| kit_failure(&e))?);
        if cache.len() >= KEEP {
            cache.remove(0);
        }
        cache.push((*spec, Arc::clone(&f)));
        Ok(f)
    }
}

/// The renderer's rule for one pixel (what `shade_pixel` must reproduce): flat lights the face
/// at its centroid with the face normal, Gouraud interpolates the three lit corners, Phong lights
/// the interpolated point with the renormalised interpolated normal (the face normal when it
/// vanishes). A test checks that composing an image with it reproduces the rasterizer's own.
pub fn kit_rule(mode: Shading, px: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    let w = px.weights;
    let mix = |v: [Vec3; 3]| w[0] * v[0] + w[1] * v[1] + w[2] * v[2];
    match mode {
        Shading::Flat => {
            light((px.positions[0] + px.positions[1] + px.positions[2]) / 3.0, px.face_normal)
        }
        Shading::Gouraud => mix([0, 1, 2].map(|k| light(px.positions[k], px.normals[k]))),
        Shading::Phong => {
            light(mix(px.positions), interpolate_normal(px.normals, Vec3::from(w), px.face_normal))
        }
    }
}

/// What a mismatch most likely is: the value another rule gives, with its explanation.
fn explain(
    mode: Shading,
    px: &Pixel,
    light: &dyn Fn(Vec3, Vec3) -> Rgb,
    actual: Rgb,
) -> (cg_harness::Text, cg_harness::Text) {
    let w = px.weights;
    let mix = |v: [Vec3; 3]| w[0] * v[0] + w[1] * v[1] + w[2] * v[2];
    let same = |a: Rgb, b: Rgb| max_diff(a, b) <= 1e-4;
    let expected = kit_rule(mode, px, light);
    let flat = kit_rule(Shading::Flat, px, light);
    let gouraud = kit_rule(Shading::Gouraud, px, light);
    let phong = kit_rule(Shading::Phong, px, light);
    let unnormalised = light(mix(px.positions), mix(px.normals));
    let face_normal_per_pixel = light(mix(px.positions), px.face_normal);
    if actual == PLACEHOLDER {
        return (
            t(
                "shade_pixel はまだ仮の色（マゼンタ (1, 0, 1)）を返しています。",
                "shade_pixel still returns the placeholder magenta (1, 0, 1).",
            ),
            t(
                "s.t6 を書きます: mode ごとに、面の法線・頂点の色・補間して正規化した法線のどれで光源処理するかを決めます。",
                "write s.t6: for each mode, decide what to light — the face normal, the vertex colours, or the interpolated and renormalised normal.",
            ),
        );
    }
    if !actual.is_finite() {
        return (
            t("色が NaN（または無限大）です。", "the colour is NaN (or infinite)."),
            t(
                "補間した法線が長さ 0 になると normalize() は NaN を返します。そのときは面の法線を使います（normalize_or(pixel.face_normal)）。",
                "normalize() of an interpolated normal of length 0 is NaN: fall back to the face normal (normalize_or(pixel.face_normal)).",
            ),
        );
    }
    let cancelled = mix(px.normals).length() <= 1e-6;
    let centroid = (px.positions[0] + px.positions[1] + px.positions[2]) / 3.0;
    // Flat shading lit with a vertex normal, at a corner or at the centroid.
    let vertex_normal_used = (0..3).any(|k| {
        let lit = [light(px.positions[k], px.normals[k]), light(centroid, px.normals[k])];
        lit.iter().any(|&c| same(actual, c) && !same(c, expected))
    });
    // Flat shading with the face normal, lit at a corner (OpenGL's GL_FLAT takes the last one).
    let corner_used = (0..3).any(|k| {
        let c = light(px.positions[k], px.face_normal);
        same(actual, c) && !same(c, expected)
    });
    match mode {
        Shading::Phong if cancelled => (
            t(
                "ここでは頂点の法線が打ち消し合い、補間した法線 N = Σ wᵢ·Nᵢ の長さが 0 です。normalize() は NaN を返し、その法線では光が当たりません。",
                "the vertex normals cancel here: the interpolated N = Σ wᵢ·Nᵢ has length 0, normalize() gives NaN, and no light reaches such a normal.",
            ),
            t(
                "長さ 0 のときは面の法線を使います: normalize_or(pixel.face_normal)。",
                "fall back to the face normal when the length is 0: normalize_or(pixel.face_normal).",
            ),
        ),
        Shading::Flat if same(actual, gouraud) && !same(gouraud, expected) => (
            t(
                "頂点の色を補間しています（グローシェーディング）。",
                "the vertex colours are interpolated (that is Gouraud shading).",
            ),
            t(
                "フラットでは面の法線で面全体を 1 色にします: light(重心, face_normal)。",
                "flat shading gives the whole face one colour from its face normal: light(centroid, face_normal).",
            ),
        ),
        Shading::Flat if same(actual, phong) && !same(phong, expected) => (
            t(
                "ピクセルごとに補間した法線で計算しています（フォンシェーディング）。",
                "each pixel is lit with an interpolated normal (that is Phong shading).",
            ),
            t(
                "フラットでは面の法線を使います: light(重心, face_normal)。",
                "flat shading uses the face normal: light(centroid, face_normal).",
            ),
        ),
        Shading::Flat if vertex_normal_used => (
            t("頂点の法線を使っています。", "a vertex normal is used."),
            t(
                "フラットでは面の法線 (pixel.face_normal) で面の色を決めます: light(重心, face_normal)。",
                "flat shading takes the face normal (pixel.face_normal): light(centroid, face_normal).",
            ),
        ),
        Shading::Flat if corner_used => (
            t(
                "面の法線は正しいですが、頂点の位置で光源処理をしています（OpenGL の GL_FLAT は最後の頂点を使います）。",
                "the face normal is right, but it is lit at a corner (OpenGL's GL_FLAT takes the last vertex).",
            ),
            t(
                "この kit では面の重心 (P₀ + P₁ + P₂)/3 で 1 回だけ計算します。",
                "the kit lights the face once, at its centroid (P₀ + P₁ + P₂)/3.",
            ),
        ),
        Shading::Flat
            if same(actual, face_normal_per_pixel) && !same(face_normal_per_pixel, expected) =>
        {
            (
                t(
                    "面の法線は正しいですが、光を当てる位置がピクセルごとに変わっています。",
                    "the face normal is right, but the lit point moves with the pixel.",
                ),
                t(
                    "面の色は 1 色: 面の重心 (P₀ + P₁ + P₂)/3 で 1 回だけ計算します。",
                    "one colour per face: light it once, at its centroid (P₀ + P₁ + P₂)/3.",
                ),
            )
        }
        Shading::Gouraud if same(actual, phong) && !same(phong, expected) => (
            t(
                "ピクセルごとに光源処理をしています。それはフォンシェーディングです。",
                "every pixel is lit: that is Phong shading.",
            ),
            t(
                "グローでは頂点の法線で 3 つの頂点の色を求め (light(Pᵢ, Nᵢ))、その色を重み wᵢ で補間します。",
                "Gouraud lights the three vertices with their normals (light(Pᵢ, Nᵢ)) and interpolates those colours with the weights wᵢ.",
            ),
        ),
        Shading::Gouraud if same(actual, flat) && !same(flat, expected) => (
            t(
                "面の法線で 1 色にしています（フラットシェーディング）。",
                "the face gets one colour from its face normal (that is flat shading).",
            ),
            t(
                "頂点の法線で頂点の色を求め、補間します。",
                "light the vertices with their vertex normals and interpolate the colours.",
            ),
        ),
        Shading::Phong if same(actual, unnormalised) && !same(unnormalised, expected) => (
            t(
                "補間した法線を正規化していません。補間した法線は長さが 1 より短くなります。",
                "the interpolated normal is not renormalised: interpolation makes it shorter than 1.",
            ),
            t("N = Σ wᵢ·Nᵢ の後で N' = N/|N| とします。", "after N = Σ wᵢ·Nᵢ, take N' = N/|N|."),
        ),
        Shading::Phong if same(actual, gouraud) && !same(gouraud, expected) => (
            t(
                "頂点の色を補間しています（グローシェーディング）。フォンでは法線を補間します。",
                "the vertex colours are interpolated (that is Gouraud shading); Phong interpolates the normals.",
            ),
            t(
                "N = Σ wᵢ·Nᵢ を正規化し、P = Σ wᵢ·Pᵢ で light(P, N) を計算します。",
                "normalise N = Σ wᵢ·Nᵢ and light P = Σ wᵢ·Pᵢ with it: light(P, N).",
            ),
        ),
        Shading::Phong if same(actual, flat) && !same(flat, expected) => (
            t(
                "面の法線を使っています（フラットシェーディング）。",
                "the face normal is used (that is flat shading).",
            ),
            t(
                "頂点の法線を重み wᵢ で補間して正規化します。",
                "interpolate the vertex normals with the weights wᵢ and normalise.",
            ),
        ),
        _ => {
            let (ja, en) = mode_name(mode);
            (
                t(
                    &format!("{ja}の規則どおりの色ではありません。"),
                    &format!("this is not the colour {en} gives."),
                ),
                t(
                    "フラット: light(重心, 面の法線)。グロー: Σ wᵢ·light(Pᵢ, Nᵢ)。フォン: light(Σ wᵢ·Pᵢ, 正規化した Σ wᵢ·Nᵢ)。",
                    "flat: light(centroid, face normal). Gouraud: Σ wᵢ·light(Pᵢ, Nᵢ). Phong: light(Σ wᵢ·Pᵢ, normalised Σ wᵢ·Nᵢ).",
                ),
            )
        }
    }
}

fn weights_text(w: [f32; 3]) -> String {
    format!("({}, {}, {})", num(w[0]), num(w[1]), num(w[2]))
}

/// The unit checks: every face of the student's sphere at a few weights, and the Phong hard case
/// of docs/numerics.md row 18 (vertex normals that cancel at the pixel: the face normal is used).
pub(super) fn unit(spec: &Spec, imp: &Impl, mode: Shading) -> Result<(), Failure> {
    let fx = Fixture::of(spec)?;
    let kit = KitLight::new(&fx.scene, &material(spec)).map_err(|e| kit_failure(&e))?;
    let light = |p: Vec3, n: Vec3| kit.light(p, n);
    let weights = [
        [1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0],
        [0.6, 0.3, 0.1],
        [0.1, 0.15, 0.75],
        [0.5, 0.0, 0.5],
        [0.2, 0.7, 0.1],
    ];
    let mut cases: Vec<(Text, Pixel)> = Vec::new();
    for f in fx.g.faces.iter().filter(|f| f.face_normal != Vec3::ZERO) {
        for w in weights {
            let px = Pixel {
                positions: f.positions,
                normals: f.normals,
                face_normal: f.face_normal,
                weights: w,
            };
            let (face, w) = (f.face, weights_text(w));
            cases.push((
                Text::new(
                    format!("あなたの球の面 F{face}、重み {w}"),
                    format!("face F{face} of your sphere, weights {w}"),
                ),
                px,
            ));
        }
    }
    // The hard case on the face the light shows best (so the fallback is seen).
    let brightness = |f: &&crate::render::FaceData| {
        let centroid = (f.positions[0] + f.positions[1] + f.positions[2]) / 3.0;
        light(centroid, f.face_normal).element_sum()
    };
    let lit =
        fx.g.faces
            .iter()
            .filter(|f| f.face_normal != Vec3::ZERO)
            .max_by(|a, b| brightness(a).total_cmp(&brightness(b)));
    if let Some(f) = lit {
        let n = f.normals[0];
        let px = Pixel {
            positions: f.positions,
            normals: [n, -n, f.normals[2]],
            face_normal: f.face_normal,
            weights: [0.5, 0.5, 0.0],
        };
        cases.push((
            Text::new(
                format!(
                    "頂点の法線 N₀ = {} と N₁ = −N₀ が重み (0.5, 0.5, 0) で打ち消し合う",
                    vec(n)
                ),
                format!(
                    "vertex normals N₀ = {} and N₁ = −N₀ cancel at weights (0.5, 0.5, 0)",
                    vec(n)
                ),
            ),
            px,
        ));
    }
    for (name, px) in cases {
        let expected = kit_rule(mode, &px, &light);
        let actual = (imp.shade_pixel)(mode, &px, &light);
        if max_diff(actual, expected) <= 1e-4 {
            continue;
        }
        let (cause, hint) = explain(mode, &px, &light, actual);
        let values = format!(
            "P = {}, {}, {}; N = {}, {}, {}",
            vec(px.positions[0]),
            vec(px.positions[1]),
            vec(px.positions[2]),
            vec(px.normals[0]),
            vec(px.normals[1]),
            vec(px.normals[2])
        );
        let face_normal = vec(px.face_normal);
        return Err(Failure::new(vec(expected), vec(actual))
            .at(Text::new(
                format!("{}; 面の法線 {face_normal}", case_at(&name, &values).ja),
                format!("{}; face normal {face_normal}", case_at(&name, &values).en),
            ))
            .cause(cause)
            .hint(hint));
    }
    Ok(())
}

fn rgb8(c: Rgb) -> [u8; 3] {
    [to_unorm8(c.x), to_unorm8(c.y), to_unorm8(c.z)]
}

fn diff8(a: Rgb, b: Rgb) -> u8 {
    let (a, b) = (rgb8(a), rgb8(b));
    (0..3).map(|k| a[k].abs_diff(b[k])).max().unwrap_or(0)
}

/// The student's image in `mode`.
fn student_image(fx: &Fixture, spec: &Spec, imp: &Impl, mode: Shading) -> Result<Image, Failure> {
    let kit = KitLight::new(&fx.scene, &material(spec)).map_err(|e| kit_failure(&e))?;
    let light = |p: Vec3, n: Vec3| kit.light(p, n);
    let base = &fx.reference[mode_index(mode)];
    // The student's functions in a worker: every pixel in two round trips (the worker's
    // `s.shade_pixels`), in the order `compose` visits them, not two per pixel.
    if cg_worker::proxy::active() {
        let (w, h) = (fx.g.width, fx.g.height);
        let pixels: Vec<Pixel> = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .filter_map(|(x, y)| fx.g.pixel(x, y).map(|(_, px)| px))
            .collect();
        let mut colours = cg_worker::proxy::shade_pixels(mode, &pixels, &light).into_iter();
        return Ok(compose(
            base,
            &fx.g,
            |_| Some(mode),
            |_, _, _| colours.next().unwrap_or(Vec3::NAN),
        ));
    }
    Ok(compose(base, &fx.g, |_| Some(mode), |m, _, px| (imp.shade_pixel)(m, px, &light)))
}

/// The student's image of the sphere in `mode` against the renderer's.
pub(super) fn image(spec: &Spec, imp: &Impl, mode: Shading) -> Result<(), Failure> {
    let fx = Fixture::of(spec)?;
    let mine = student_image(&fx, spec, imp, mode)?;
    let reference = &fx.reference[mode_index(mode)];
    let (w, h) = (fx.g.width, fx.g.height);
    let mut seen = 0usize;
    let mut off = 0usize;
    let mut off_in_highlight = 0usize;
    let mut worst: Option<(u8, usize)> = None;
    let mut bounds = [u32::MAX, u32::MAX, 0, 0];
    for (i, texel) in fx.g.texels.iter().enumerate() {
        if texel.is_none() {
            continue;
        }
        seen += 1;
        let d = diff8(mine.pixels[i], reference.pixels[i]);
        if d > IMAGE_TOLERANCE {
            off += 1;
            off_in_highlight += usize::from(fx.highlight[i]);
            let (x, y) = (i as u32 % w, i as u32 / w);
            bounds = [bounds[0].min(x), bounds[1].min(y), bounds[2].max(x), bounds[3].max(y)];
            if worst.is_none_or(|(wd, _)| d > wd) {
                worst = Some((d, i));
            }
        }
    }
    let within = seen - off;
    if seen == 0 || within as f64 >= IMAGE_FRACTION * seen as f64 {
        return Ok(());
    }
    let (d, i) = worst.unwrap_or((0, 0));
    let (x, y) = (i as u32 % w, i as u32 / w);
    let (ja, en) = mode_name(mode);
    let (face, px) = fx.g.pixel(x, y).map_or((u32::MAX, None), |(f, p)| (f.face, Some(p)));
    let kit = KitLight::new(&fx.scene, &material(spec)).map_err(|e| kit_failure(&e))?;
    let light = |p: Vec3, n: Vec3| kit.light(p, n);
    let (cause, hint) = px.map_or_else(
        || (t("", ""), t("", "")),
        |px| explain(mode, &px, &light, (imp.shade_pixel)(mode, &px, &light)),
    );
    let [er, eg, eb] = rgb8(reference.pixels[i]);
    let [ar, ag, ab] = rgb8(mine.pixels[i]);
    let pct = IMAGE_FRACTION * 100.0;
    let share = 100.0 * within as f64 / seen as f64;
    let [x0, y0, x1, y1] = bounds;
    let weights = px.map(|p| weights_text(p.weights));
    Err(Failure::new(
        Text::new(
            format!(
                "球の {seen} ピクセルの ≥ {pct:.1} % が kit の{ja}の画像と {IMAGE_TOLERANCE}/255 以内"
            ),
            format!(
                "≥ {pct:.1} % of the sphere's {seen} pixels within {IMAGE_TOLERANCE}/255 of the kit's {en} image"
            ),
        ),
        Text::new(
            format!(
                "{IMAGE_TOLERANCE}/255 以内は {within} ピクセル（{share:.1} %）、超えるのは {off} ピクセル（うちハイライト内 {off_in_highlight}）、x {x0}–{x1}、y {y0}–{y1}; 最大の差 {d}/255（ピクセル ({x}, {y})）: kit ({er}, {eg}, {eb})、あなた ({ar}, {ag}, {ab})"
            ),
            format!(
                "{within} ({share:.1} %) within; {off} differ ({off_in_highlight} in the highlight), x {x0}–{x1}, y {y0}–{y1}; the largest difference {d}/255 at pixel ({x}, {y}): kit ({er}, {eg}, {eb}), yours ({ar}, {ag}, {ab})"
            ),
        ),
    )
    .at(Text::new(
        format!(
            "{w}×{h} の画像（{ja}）のピクセル ({x}, {y})、面 F{face}{}",
            weights.as_ref().map_or_else(String::new, |w| format!("、重み {w}"))
        ),
        format!(
            "pixel ({x}, {y}) of the {w}×{h} image ({en}), face F{face}{}",
            weights.as_ref().map_or_else(String::new, |w| format!(", weights {w}"))
        ),
    ))
    .cause(cause)
    .hint(hint))
}

/// Phong keeps the highlight Gouraud loses: in the pixels where the kit's Phong image is brighter
/// than its Gouraud image by more than [`HIGHLIGHT_MARGIN`], the student's Phong must be brighter
/// than the student's Gouraud by more than [`KEEP_MARGIN`] in at least [`KEEP_FRACTION`] of them.
pub(super) fn highlight(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let fx = Fixture::of(spec)?;
    let kit = KitLight::new(&fx.scene, &material(spec)).map_err(|e| kit_failure(&e))?;
    let light = |p: Vec3, n: Vec3| kit.light(p, n);
    let w = fx.g.width;
    let region: Vec<usize> = (0..fx.highlight.len()).filter(|&i| fx.highlight[i]).collect();
    if region.is_empty() {
        return Ok(());
    }
    let mut kept = 0usize;
    let mut gouraud_shows = 0usize;
    let mut phong_loses = 0usize;
    let mut brightest = (f32::MIN, 0usize);
    for &i in &region {
        let (x, y) = (i as u32 % w, i as u32 / w);
        let Some((_, px)) = fx.g.pixel(x, y) else { continue };
        let g = crate::render::saturate((imp.shade_pixel)(Shading::Gouraud, &px, &light));
        let p = crate::render::saturate((imp.shade_pixel)(Shading::Phong, &px, &light));
        if (p - g).max_element() > KEEP_MARGIN {
            kept += 1;
        }
        if diff8(g, fx.reference[2].pixels[i]) <= 4 {
            gouraud_shows += 1;
        }
        if diff8(p, fx.reference[1].pixels[i]) <= 4 {
            phong_loses += 1;
        }
        let bright = fx.reference[2].pixels[i].element_sum();
        if bright > brightest.0 {
            brightest = (bright, i);
        }
    }
    let n = region.len();
    if kept as f64 >= KEEP_FRACTION * n as f64 {
        return Ok(());
    }
    let mut placeholder = 0usize;
    for &i in &region {
        let (x, y) = (i as u32 % w, i as u32 / w);
        if let Some((_, px)) = fx.g.pixel(x, y)
            && (imp.shade_pixel)(Shading::Phong, &px, &light) == PLACEHOLDER
        {
            placeholder += 1;
        }
    }
    let (cause, hint) = if placeholder * 2 > n {
        (
            t(
                "shade_pixel はまだ仮の色（マゼンタ (1, 0, 1)）を返しています。",
                "shade_pixel still returns the placeholder magenta (1, 0, 1).",
            ),
            t(
                "s.t6 を書くと、フォンでだけハイライトが見えるはずです。",
                "write s.t6: the highlight should then show in your Phong image only.",
            ),
        )
    } else if gouraud_shows * 2 > n {
        (
            t(
                "グローシェーディングの画像にもハイライトがあります: ピクセルごとに光源処理をしていませんか（それはフォンです）。",
                "your Gouraud image shows the highlight too: is every pixel lit? (That is Phong.)",
            ),
            t(
                "グローは頂点の色を補間するだけなので、頂点から離れた面の内側のハイライトは消えます。頂点で light(Pᵢ, Nᵢ) を求めて補間します。",
                "Gouraud only interpolates vertex colours, so a highlight inside a face, away from the vertices, is lost: light the vertices, light(Pᵢ, Nᵢ), and interpolate.",
            ),
        )
    } else if phong_loses * 2 > n {
        (
            t(
                "フォンシェーディングの画像でハイライトが消えています: 色を補間していませんか。",
                "your Phong image loses the highlight: are colours interpolated?",
            ),
            t(
                "フォンでは法線 N = Σ wᵢ·Nᵢ を補間して正規化し、ピクセルごとに light(P, N) を計算します。",
                "Phong interpolates the normal N = Σ wᵢ·Nᵢ, renormalises it and lights every pixel: light(P, N).",
            ),
        )
    } else {
        (
            t(
                "ハイライトの明るさがフォンとグローで期待どおりに違いません。",
                "your Phong and Gouraud images do not differ at the highlight as they should.",
            ),
            t(
                "s.t6.gouraud と s.t6.phong の結果も見てください。",
                "see what s.t6.gouraud and s.t6.phong say.",
            ),
        )
    };
    let (x, y) = (brightest.1 as u32 % w, brightest.1 as u32 / w);
    let pct = KEEP_FRACTION * 100.0;
    let share = 100.0 * kept as f64 / n as f64;
    Err(Failure::new(
        Text::new(
            format!(
                "ハイライトの {n} ピクセルの ≥ {pct:.0} % で、あなたのフォンがグローより {KEEP_MARGIN} 以上明るい"
            ),
            format!(
                "your Phong brighter than your Gouraud by > {KEEP_MARGIN} in ≥ {pct:.0} % of the {n} highlight pixels"
            ),
        ),
        Text::new(
            format!(
                "{kept} / {n}（{share:.0} %）; kit のフォンのハイライトがあなたのグローに出たピクセル: {gouraud_shows}、あなたのフォンが kit のグローのようになったピクセル: {phong_loses}"
            ),
            format!(
                "{kept} / {n} ({share:.0} %); your Gouraud shows the kit's Phong highlight: {gouraud_shows}, your Phong looks like the kit's Gouraud: {phong_loses}"
            ),
        ),
    )
    .at(Text::new(
        format!("ハイライト: {w}×{w} の画像のピクセル ({x}, {y}) のまわりの {n} ピクセル"),
        format!("the highlight: {n} pixels around pixel ({x}, {y}) of the {w}×{w} image"),
    ))
    .cause(cause)
    .hint(hint))
}
