//! # 第11回 シェーディング / Lecture 11: shading (assignment `s`)
//!
//! The lecture's light model (光のモデル), term by term, the light types, vertex normals, the
//! three shading methods, and the directions of the global terms:
//!
//! ```text
//! I = Ia·ka + Σᵢ Iᵢ·[kd (N·L) + ks (R·V)ⁿ] + kr·Ir + kt·It
//!     環境光      拡散反射光   鏡面反射光(局所)   鏡面反射光・透過光(大域)
//! ```
//!
//! Conventions: every vector is in world space; `n` (N) is the unit surface normal, `l` (L) the
//! unit vector from the surface *towards* the light, `v` (V) the unit vector from the surface
//! towards the eye. Colours and reflectances are RGB (`Rgb` is a `Vec3`: `a * b` multiplies
//! channel by channel). Angles are in degrees where a name ends in `_deg`; Rust's `cos` and
//! `sin` take radians (`x.to_radians()`).
//!
//! 約束: ベクトルはすべてワールド座標系。`n` (N) は面の単位法線、`l` (L) は面から光源へ向かう単位
//! ベクトル、`v` (V) は面から視点へ向かう単位ベクトル。色と反射係数は RGB（`Rgb` は `Vec3`。
//! `a * b` はチャンネルごとの積）。名前が `_deg` で終わる角度は度、Rust の `cos`・`sin` は
//! ラジアンを受け取ります（`x.to_radians()`）。
//!
//! Check your work with `cargo run --release -- check s`; look at it with
//! `cargo run --release -- view s`. / 確認は `cargo run --release -- check s`、
//! 画像は `cargo run --release -- view s`。

use cg_student::Rgb;
use cg_student::glam::Vec3;
use cg_student::mesh::Mesh;
use cg_student::s::{Pixel, Shading};

/// **s.t1 環境光 (ambient light)**: `Ia·ka`.
///
/// - `ia`: the ambient light Ia (環境光の明るさ), RGB.
/// - `ka`: the ambient reflectance ka of the surface (環境光の反射係数), RGB.
/// - Returns `Ia·ka`, channel by channel (R·R, G·G, B·B). Not clamped.
///
/// Hint: `*` between two `Vec3` multiplies channel by channel.
///
/// 環境光 Ia·ka を返します（チャンネルごとの積、0〜1 に切り詰めない）。
/// ヒント: `Vec3` 同士の `*` はチャンネルごとの積です。
pub fn ambient(ia: Rgb, ka: Rgb) -> Rgb {
    todo!("s.t1: 環境光 Ia·ka を返す / return the ambient term Ia·ka")
}

/// **s.t2 拡散反射光 (diffuse reflection, Lambert's cosine law)**: `Ii·kd·max(N·L, 0)`.
///
/// - `ii`: the light's intensity Ii (光源の明るさ), RGB; `kd`: the diffuse reflectance, RGB.
/// - `n`, `l`: unit vectors; `l` points from the surface towards the light.
/// - Returns `Ii·kd·(N·L)` where `N·L > 0`, and **0** where `N·L ≤ 0` (the light is behind the
///   surface: no negative light). Not clamped above.
///
/// Hint: `n.dot(l)`, then `.max(0.0)`.
///
/// ランバートの余弦則 Id = kd·Ii·cos θ = kd·Ii·(N·L)。光が面の裏から当たる (N·L ≤ 0) ときは 0
/// （負の光はありません）。ヒント: `n.dot(l).max(0.0)`。
pub fn diffuse(ii: Rgb, kd: Rgb, n: Vec3, l: Vec3) -> Rgb {
    todo!("s.t2: 拡散反射光 Ii·kd·max(N·L, 0) を返す / return the diffuse term Ii·kd·max(N·L, 0)")
}

/// **s.t3 鏡面反射光 (specular reflection, Phong's model)**: `Ii·ks·max(R·V, 0)ⁿ`.
///
/// - `ii`: the light's intensity Ii, RGB; `ks`: the specular reflectance, RGB.
/// - `n`, `l`, `v`: unit vectors (normal, towards the light, towards the eye).
/// - `shininess`: the exponent n ≥ 0 (ハイライトの鋭さ).
/// - `R` is the mirror direction of the light, `R = 2(N·L)N − L` (= `reflect(−L, N)`, s.t7).
/// - Returns `Ii·ks·(R·V)ⁿ`, and **0** when `N·L ≤ 0` (light from behind) or when `R·V ≤ 0` —
///   also for n = 0, where `0.0.powf(0.0)` would be 1. Never NaN: `(-0.5f32).powf(2.5)` is NaN,
///   so the cosine must be checked *before* `powf`.
///
/// Hint: compute `R·V`; if it is ≤ 0 return `Rgb::ZERO`, else `ii * ks * rv.powf(shininess)`.
///
/// フォンのモデル: R は L の正反射方向 R = 2(N·L)N − L。N·L ≤ 0（裏からの光）や R·V ≤ 0 のときは 0
/// （n = 0 でも）。powf の前に R·V を調べること（負の数の非整数乗は NaN）。
pub fn specular(ii: Rgb, ks: Rgb, n: Vec3, l: Vec3, v: Vec3, shininess: f32) -> Rgb {
    todo!(
        "s.t3: 鏡面反射光 Ii·ks·max(R·V, 0)ⁿ を返す / return the specular term Ii·ks·max(R·V, 0)ⁿ"
    )
}

/// **s.t4 点光源の減衰 (attenuation of point and spot lights)**: `1 / (kc + kl·d + kq·d²)`.
///
/// - `kc`, `kl`, `kq`: the constant, linear and quadratic coefficients, ≥ 0.
/// - `d`: the distance from the light to the point, ≥ 0.
/// - Returns the factor the light is multiplied by. When the denominator is below `1e-6`
///   (a light sitting on the point with `kc = 0`), use `1e-6`: the result is at most `1e6`,
///   never infinite.
///
/// Hint: `d * d`, and `f32::max`.
///
/// 距離 d による減衰。分母が 1e-6 より小さいときは 1e-6 を使います（d = 0 で kc = 0 でも無限大に
/// しない）。ヒント: `d * d` と `f32::max`。
pub fn attenuation(kc: f32, kl: f32, kq: f32, d: f32) -> f32 {
    todo!("s.t4: 減衰 1/(kc + kl·d + kq·d²) を返す / return the attenuation 1/(kc + kl·d + kq·d²)")
}

/// **s.t4 スポットライト光源 (spot light)**: the factor of a spot light for a point that sees it
/// in direction `l`.
///
/// - `l`: unit vector from the point towards the light (the light shines along `−l`).
/// - `spot_direction`: unit vector, the direction the spot points to (S).
/// - `cutoff_deg`: half-angle of the cone in **degrees**, in `[0, 90]`, or `180` for no cone.
/// - `exponent`: ≥ 0; the light fades towards the rim.
/// - With `cos α = −L·S` (α the angle between the spot's axis and the ray to the point), returns
///   `1` when `cutoff_deg = 180`; `0` outside the cone (`cos α < cos(cutoff)`); otherwise
///   `max(cos α, 0)^exponent` (OpenGL's GL_SPOT_CUTOFF and GL_SPOT_EXPONENT).
///
/// Hint: `cutoff_deg.to_radians().cos()`.
///
/// スポットライト: 指定した方向・角度にのみ有効な点光源。cos α = −L·S が cos(cutoff) より小さい
/// （円錐の外）なら 0、内側なら max(cos α, 0)^exponent、cutoff = 180° なら 1。
/// cutoff_deg は度なので、cos の前に `to_radians()`。
pub fn spot_factor(l: Vec3, spot_direction: Vec3, cutoff_deg: f32, exponent: f32) -> f32 {
    todo!("s.t4: スポットライトの係数を返す / return the spot light's factor")
}

/// **s.t5 頂点の法線 (vertex normals)**: at every vertex, the average of the normals of the faces
/// around it (頂点に隣接する全ての面の法線を平均), normalised.
///
/// - `mesh`: positions and faces `[a, b, c]`, counter-clockwise seen from outside.
/// - Returns one unit normal per vertex (V0, V1, …): the sum of the *unit* face normals of the
///   faces that use the vertex, normalised. Every face counts the same.
/// - A zero-area face (a repeated corner, collinear corners) has no normal and adds nothing; a
///   vertex that no usable face touches gets the zero vector. Never NaN.
///
/// Hint: the face normal of `F { a, b, c }` is the cross product `(b − a).cross(c − a)`,
/// normalised. `try_normalize()` gives the unit vector, or `None` when the cross product has
/// length 0 (a zero-area face: skip it); add it to the three corners, then `normalize_or_zero()`
/// each sum.
///
/// 面の法線は外積 (b−a)×(c−a) を正規化したもの（単位ベクトル）。それをその面の 3 つの頂点に足して
/// いき、最後に正規化します。面積 0 の面は外積がゼロベクトルなので足しません（`try_normalize()` が
/// `None`）。どの面にも使われない頂点はゼロベクトル。NaN にしないこと。
///
/// The stub runs (the view needs normals) and starts with `cg_student::not_started("s.t5");`:
/// the checks say s.t5 is "not done yet" until you delete that line, which you do when you start.
/// スタブの最初の行 `cg_student::not_started("s.t5");` は書き始めたら消します。
pub fn vertex_normals(mesh: &Mesh) -> Vec<Vec3> {
    cg_student::not_started("s.t5"); // 書き始めたらこの行を消す / delete it when you start
    // TODO s.t5: every vertex points straight up for now, so the view still draws.
    vec![Vec3::Y; mesh.positions.len()]
}

/// **s.t5 頂点の法線・面積で重み付け (area-weighted vertex normals)**: like [`vertex_normals`],
/// but each face counts in proportion to its area (面の面積に応じて加重平均).
///
/// - Returns one unit normal per vertex; zero for a vertex no face with area touches. Never NaN.
///
/// Hint: the cross product `(b − a).cross(c − a)` *before* normalising points along the face
/// normal and is twice the face's area long: add it as it is, and normalise only the sums.
///
/// 外積 (b−a)×(c−a) は正規化する前、長さが面の面積の 2 倍です。それをそのまま頂点に足し、
/// 最後に和を正規化すると、面積に応じた加重平均になります。
pub fn vertex_normals_area(mesh: &Mesh) -> Vec<Vec3> {
    todo!("s.t5: 面積に応じた加重平均の頂点の法線 / the area-weighted vertex normals")
}

/// **s.t6 フラット／グロー／フォンシェーディング (flat, Gouraud and Phong shading)**: the colour of
/// one pixel of a triangle.
///
/// - `mode`: `Shading::Flat`, `Shading::Gouraud` or `Shading::Phong`.
/// - `pixel`: the triangle's corners `positions` P₀, P₁, P₂, its vertex normals `normals`
///   N₀, N₁, N₂ (unit), its `face_normal` (unit), and the `weights` w₀, w₁, w₂ of the corners at
///   this pixel (each in [0, 1], summing to 1).
/// - `light(p, n)`: the lighting stage (光源処理) — the colour the light gives a point `p` with
///   unit normal `n` (already clamped to [0, 1]).
/// - Returns:
///   - flat: the face's one colour, lit at its centroid `(P₀ + P₁ + P₂)/3` with the **face
///     normal** (面の法線をもとに面の色を決定);
///   - Gouraud: the three **vertex colours** `light(Pᵢ, Nᵢ)` interpolated with the weights,
///     `w₀·C₀ + w₁·C₁ + w₂·C₂` (頂点の色をなめらかに補間);
///   - Phong: the **normal** interpolated, `N = Σ wᵢ·Nᵢ`, **renormalised** `N' = N/|N|`, and the
///     point `P = Σ wᵢ·Pᵢ` lit with it: `light(P, N')` (各ピクセルごとに光源処理). When `N` is
///     (nearly) zero — vertex normals that cancel — use the face normal instead.
///
/// Hint: `w[0] * v[0] + w[1] * v[1] + w[2] * v[2]` interpolates anything; `normalize_or(…)`
/// falls back when the length is zero.
///
/// フラット: 面の法線で面の色を 1 回計算。グロー: 頂点の法線で頂点の色を計算し、重みで補間。
/// フォン: 頂点の法線を重みで補間して正規化 (N' = N/|N|) し、ピクセルごとに光源処理。補間した法線の長さが
/// 0 なら面の法線を使います。
pub fn shade_pixel(mode: Shading, pixel: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    cg_student::not_started("s.t6"); // 書き始めたらこの行を消す / delete it when you start
    // TODO s.t6: magenta marks the pixels your shading does not colour yet (the view still
    // draws).
    Rgb::new(1.0, 0.0, 1.0)
}

/// **s.t7 鏡面反射 (the mirror direction, global illumination)**: the direction of `i` reflected
/// about the unit normal `n`: `i − 2(i·n)n`.
///
/// - `i`: the incoming direction, travelling *towards* the surface (any length).
/// - `n`: the unit normal (either side gives the same result).
/// - Returns the reflected direction, travelling away from the surface, as long as `i`.
///
/// Hint: `i - 2.0 * i.dot(n) * n`.
///
/// i は面へ向かう向き、結果は面から離れる向き（長さは i と同じ）。レイトレーシングで反射先の色 Ir
/// を求めるときの方向です。
pub fn reflect(i: Vec3, n: Vec3) -> Vec3 {
    todo!("s.t7: 正反射方向 i − 2(i·n)n を返す / return the mirror direction i − 2(i·n)n")
}

/// **s.t8 透過光・屈折 (refraction by Snell's law, n₁ sin θ₁ = n₂ sin θ₂)**: the direction of
/// the transmitted ray, or `None` under total internal reflection (全反射).
///
/// - `i`: unit direction of the incoming ray, travelling towards the surface.
/// - `n`: the surface's unit **outward** normal.
/// - `n1`: the refractive index outside (where `n` points); `n2`: inside the object.
/// - A ray from outside has `i·n < 0`. A ray from **inside** has `i·n > 0`: then flip the normal
///   (`−n`) and swap the indices (it goes from `n2` into `n1`).
/// - With the normal on the incident side, `η = n_incident / n_transmitted`,
///   `cos θ₁ = −i·n`, `k = 1 − η²(1 − cos²θ₁)`: `k < 0` is total internal reflection → `None`;
///   otherwise `t = η·i + (η cos θ₁ − √k)·n`, normalised.
/// - Normal incidence and `n1 = n2` go straight through (`t = i`). Never NaN.
///
/// Hint: test `k < 0.0` *before* `k.sqrt()` (the square root of a negative number is NaN).
///
/// スネルの法則。n は外向きの法線、n1 が外側、n2 が内側の屈折率。内側からの光 (i·n > 0) では法線を
/// 反転し屈折率を入れ替えます。k < 0 なら全反射で `None`（平方根の前に調べること）。
pub fn refract(i: Vec3, n: Vec3, n1: f32, n2: f32) -> Option<Vec3> {
    todo!(
        "s.t8: 屈折方向（全反射なら None）を返す / the refracted direction, or None under total internal reflection"
    )
}

/// The functions of this module, for the checks and the view.
#[must_use]
pub fn implementation() -> cg_student::s::Impl {
    cg_student::s::Impl {
        ambient,
        diffuse,
        specular,
        attenuation,
        spot_factor,
        vertex_normals,
        vertex_normals_area,
        shade_pixel,
        reflect,
        refract,
    }
}
