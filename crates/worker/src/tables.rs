//! The student's functions as the worker offers them: one [`Handler`] per field of each
//! assignment's `Impl` table, named `"<id>.<field>"`, and the batch operations the checks need
//! so that a check costs one round trip, not one per frame or per pixel.
//!
//! Arguments are a JSON tuple (one argument: the value itself, none: `null`); a `&mut` argument
//! goes in with the others and comes back as the result, as it was after the call. Every entry,
//! `name: arguments → result`:
//!
//! | entry | arguments → result |
//! |---|---|
//! | `a1.vertices` | `Spec` → `Vec<Vec3>` |
//! | `a1.faces` | `Spec` → `Vec<[u32; 3]>` |
//! | `a1.face_normals` | `Spec` → `Vec<Vec3>` |
//! | `a1.model_transform` | `Spec` → `MatrixProduct` |
//! | `a2.motion` | `(Spec, CameraState, Drag)` → `CameraState` after the call |
//! | `a2.camera` | `(Gl, CameraState)` → `Gl` after the call |
//! | `a2.display` | `(Gl, CameraState)` → `Gl` after the call |
//! | `a3.warmup_display` | `(Gl, f64)` → `Gl` after the call |
//! | `a3.idle` | `(A3Spec, State)` → `State` after the call |
//! | `a3.display` | `(A3Spec, State, Gl)` → `Gl` after the call |
//! | `a3.frames` | `(A3Spec, Vec<u64>)` → `Vec<(State, Gl)>`: per frame, idle up to it, then `display` (each call announced with `serve::running`) |
//! | `a4.tex_range` | `Spec` → `TexRange` |
//! | `a4.tex_coords` | `(Spec, u32, u32)` → `[Vec2; 4]` |
//! | `a4.sampler` | `()` → `Sampler` |
//! | `s.ambient` | `(Rgb, Rgb)` → `Rgb` |
//! | `s.diffuse` | `(Rgb, Rgb, Vec3, Vec3)` → `Rgb` |
//! | `s.specular` | `(Rgb, Rgb, Vec3, Vec3, Vec3, f32)` → `Rgb` |
//! | `s.attenuation` | `(f32, f32, f32, f32)` → `f32` |
//! | `s.spot_factor` | `(Vec3, Vec3, f32, f32)` → `f32` |
//! | `s.vertex_normals` | `Mesh` → `Vec<Vec3>` |
//! | `s.vertex_normals_area` | `Mesh` → `Vec<Vec3>` |
//! | `s.shade_pixel` | `(Shading, Pixel, Queries, Vec<Rgb>)` → `Result<Rgb, Reason>`: one pixel of `s.shade_pixels` |
//! | `s.reflect` | `(Vec3, Vec3)` → `Vec3` |
//! | `s.refract` | `(Vec3, Vec3, f32, f32)` → `Option<Vec3>` |
//! | `s.shade_pixels_queries` | `(Shading, Vec<Pixel>)` → `Vec<Queries>`: what each pixel asked `light` |
//! | `s.shade_pixels` | `(Shading, Vec<Pixel>, Vec<Queries>, Vec<Vec<Rgb>>)` → `Result<Vec<Rgb>, Reason>` |
//!
//! **`shade_pixel`'s light.** `light(p, n)` is the kit's lighting stage, evaluated on the trusted
//! side, so a pixel takes two calls for any number of pixels: `s.shade_pixels_queries` runs the
//! function with a light that returns [`QUERY_COLOUR`] and records each `(p, n)` it is asked
//! ([`Queries`]); the trusted side lights those points and sends the colours back with
//! `s.shade_pixels`, which runs the function again with a light that answers the `k`-th query of
//! pixel `i` with `answers[i][k]`. That is the same function's answer only if it asks the same
//! questions in the same order: the phase-1 queries go back with the answers, and a query that
//! differs from the `k`-th one of phase 1 (bit for bit), or one more than phase 1 asked, is
//! answered with NaN and the reply is `Err` naming the pixel and the query (asking only the first
//! few of phase 1's queries is no error: each of them was answered for what it asked).
//!
//! **a3's meshes.** `a3::Object::mesh` is `#[serde(skip)]` (`--json` leaves it out), so a3's spec
//! crosses the pipe as an [`A3Spec`]: the spec as `--json` writes it, and the meshes beside it.
//!
//! Nothing here computes an answer: each handler only calls the student's function.

use std::cell::{Cell, RefCell};

use cg_student::gl::Gl;
use cg_student::glam::Vec3;
use cg_student::mesh::Mesh;
use cg_student::s::{Pixel, Shading};
use cg_student::{Rgb, a1, a2, a3, a4, s};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::Reason;
use crate::serve::{Handler, handler, running};

/// The fields of `a1::Impl`, by hand: [`a1()`] has one handler `a1.<field>` for each.
pub const A1_FIELDS: &[&str] = &["vertices", "faces", "face_normals", "model_transform"];
/// The fields of `a2::Impl`.
pub const A2_FIELDS: &[&str] = &["motion", "camera", "display"];
/// The fields of `a3::Impl`.
pub const A3_FIELDS: &[&str] = &["warmup_display", "idle", "display"];
/// a3's batch operations.
pub const A3_BATCH: &[&str] = &["frames"];
/// The fields of `a4::Impl`.
pub const A4_FIELDS: &[&str] = &["tex_range", "tex_coords", "sampler"];
/// The fields of `s::Impl`.
pub const S_FIELDS: &[&str] = &[
    "ambient",
    "diffuse",
    "specular",
    "attenuation",
    "spot_factor",
    "vertex_normals",
    "vertex_normals_area",
    "shade_pixel",
    "reflect",
    "refract",
];
/// s's batch operations.
pub const S_BATCH: &[&str] = &["shade_pixels_queries", "shade_pixels"];

/// a1's table.
pub fn a1(imp: a1::Impl) -> Vec<(&'static str, Handler)> {
    // No `..`: a field added to the Impl fails to compile here (and, once named, warns as unused
    // until it has its handler).
    let a1::Impl { vertices, faces, face_normals, model_transform } = imp;
    vec![
        ("a1.vertices", handler(move |spec: a1::Spec| vertices(&spec))),
        ("a1.faces", handler(move |spec: a1::Spec| faces(&spec))),
        ("a1.face_normals", handler(move |spec: a1::Spec| face_normals(&spec))),
        ("a1.model_transform", handler(move |spec: a1::Spec| model_transform(&spec))),
    ]
}

/// a2's table.
pub fn a2(imp: a2::Impl) -> Vec<(&'static str, Handler)> {
    let a2::Impl { motion, camera, display } = imp;
    vec![
        (
            "a2.motion",
            handler(move |(spec, mut state, drag): (a2::Spec, a2::CameraState, a2::Drag)| {
                motion(&spec, &mut state, &drag);
                state
            }),
        ),
        (
            "a2.camera",
            handler(move |(mut gl, state): (Gl, a2::CameraState)| {
                camera(&mut gl, &state);
                gl
            }),
        ),
        (
            "a2.display",
            handler(move |(mut gl, state): (Gl, a2::CameraState)| {
                display(&mut gl, &state);
                gl
            }),
        ),
    ]
}

/// a3's table, with the batch operation `a3.frames`.
pub fn a3(imp: a3::Impl) -> Vec<(&'static str, Handler)> {
    let a3::Impl { warmup_display, idle, display } = imp;
    vec![
        (
            "a3.warmup_display",
            handler(move |(mut gl, t): (Gl, f64)| {
                warmup_display(&mut gl, t);
                gl
            }),
        ),
        (
            "a3.idle",
            handler(move |(A3Spec(spec), mut state): (A3Spec, a3::State)| {
                idle(&spec, &mut state);
                state
            }),
        ),
        (
            "a3.display",
            handler(move |(A3Spec(spec), state, mut gl): (A3Spec, a3::State, Gl)| {
                display(&spec, &state, &mut gl);
                gl
            }),
        ),
        // The checks' `each_frame` (a3-animation/src/checks/mod.rs) and the view's
        // `record_frame`: one state from the start, idle until each frame count in turn, then
        // display recorded on a fresh recorder (a frame count not above the last one reached is
        // recorded at the state reached, as `each_frame` does). Before each call it says which
        // function runs at which frame (`running`): a timeout then names `idle` or `display`
        // and the frame, not the batch.
        (
            "a3.frames",
            handler(move |(A3Spec(spec), frames): (A3Spec, Vec<u64>)| {
                let mut state = a3::State::new();
                let mut done = 0;
                let mut out = Vec::with_capacity(frames.len());
                for frame in frames {
                    while done < frame {
                        running("a3.idle", Some(done + 1));
                        idle(&spec, &mut state);
                        done += 1;
                    }
                    let mut gl = Gl::new();
                    running("a3.display", Some(done));
                    display(&spec, &state, &mut gl);
                    out.push((state.clone(), gl));
                }
                out
            }),
        ),
    ]
}

/// a4's table.
pub fn a4(imp: a4::Impl) -> Vec<(&'static str, Handler)> {
    let a4::Impl { tex_range, tex_coords, sampler } = imp;
    vec![
        ("a4.tex_range", handler(move |spec: a4::Spec| tex_range(&spec))),
        (
            "a4.tex_coords",
            handler(move |(spec, i, j): (a4::Spec, u32, u32)| tex_coords(&spec, i, j)),
        ),
        ("a4.sampler", handler(move |(): ()| sampler())),
    ]
}

/// s's table, with the two phases of `shade_pixel` for many pixels (`s.shade_pixels_queries`,
/// `s.shade_pixels`).
pub fn s(imp: s::Impl) -> Vec<(&'static str, Handler)> {
    let s::Impl {
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
    } = imp;
    vec![
        ("s.ambient", handler(move |(ia, ka): (Rgb, Rgb)| ambient(ia, ka))),
        ("s.diffuse", handler(move |(ii, kd, n, l): (Rgb, Rgb, Vec3, Vec3)| diffuse(ii, kd, n, l))),
        (
            "s.specular",
            handler(move |(ii, ks, n, l, v, shininess): (Rgb, Rgb, Vec3, Vec3, Vec3, f32)| {
                specular(ii, ks, n, l, v, shininess)
            }),
        ),
        (
            "s.attenuation",
            handler(move |(kc, kl, kq, d): (f32, f32, f32, f32)| attenuation(kc, kl, kq, d)),
        ),
        (
            "s.spot_factor",
            handler(move |(l, axis, cutoff_deg, exponent): (Vec3, Vec3, f32, f32)| {
                spot_factor(l, axis, cutoff_deg, exponent)
            }),
        ),
        ("s.vertex_normals", handler(move |mesh: Mesh| vertex_normals(&mesh))),
        ("s.vertex_normals_area", handler(move |mesh: Mesh| vertex_normals_area(&mesh))),
        (
            "s.shade_pixel",
            handler(move |(mode, pixel, queries, answers): (Shading, Pixel, Queries, Vec<Rgb>)| {
                answered(shade_pixel, mode, &pixel, &queries, &answers)
            }),
        ),
        ("s.reflect", handler(move |(i, n): (Vec3, Vec3)| reflect(i, n))),
        ("s.refract", handler(move |(i, n, n1, n2): (Vec3, Vec3, f32, f32)| refract(i, n, n1, n2))),
        (
            "s.shade_pixels_queries",
            handler(move |(mode, pixels): (Shading, Vec<Pixel>)| {
                pixels.iter().map(|p| asked(shade_pixel, mode, p)).collect::<Vec<_>>()
            }),
        ),
        (
            "s.shade_pixels",
            handler(
                move |(mode, pixels, queries, answers): (
                    Shading,
                    Vec<Pixel>,
                    Vec<Queries>,
                    Vec<Vec<Rgb>>,
                )| {
                    let (p, q, a) = (pixels.len(), queries.len(), answers.len());
                    if q != p || a != p {
                        return Err(Reason::new(
                            format!(
                                "ピクセル {p} 個に、問い合わせの列が {q} 個、答えの列が {a} 個"
                            ),
                            format!("{p} pixels, {q} lists of queries and {a} lists of answers"),
                        ));
                    }
                    pixels
                        .iter()
                        .zip(queries.iter().zip(&answers))
                        .enumerate()
                        .map(|(i, (p, (q, a)))| {
                            answered(shade_pixel, mode, p, q, a).map_err(|why| {
                                Reason::new(
                                    format!("ピクセル {i}: {}", why.ja),
                                    format!("pixel {i}: {}", why.en),
                                )
                            })
                        })
                        .collect::<Result<Vec<_>, _>>()
                },
            ),
        ),
    ]
}

/// The `(p, n)` a pixel asked `light` for, in the order it asked.
pub type Queries = Vec<(Vec3, Vec3)>;

/// What the recording light of `s.shade_pixels_queries` answers every query with.
pub const QUERY_COLOUR: Rgb = Vec3::new(0.5, 0.5, 0.5);

/// `shade_pixel`'s type in `s::Impl`.
type ShadePixel = fn(Shading, &Pixel, &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb;

/// Phase 1: the queries of one pixel, with a light that answers [`QUERY_COLOUR`].
fn asked(shade_pixel: ShadePixel, mode: Shading, pixel: &Pixel) -> Queries {
    let queries = RefCell::new(Vec::new());
    let light = |p: Vec3, n: Vec3| {
        queries.borrow_mut().push((p, n));
        QUERY_COLOUR
    };
    shade_pixel(mode, pixel, &light);
    queries.into_inner()
}

/// What a `shade_pixel` that asked other questions the second time is told: it ran twice on the
/// same pixel (once to list what it asks `light`, once with the answers), so it must ask the same.
const SAME_QUESTIONS_JA: &str = "（shade_pixel は同じピクセルで 2 回実行されます。乱数や呼び出しをまたいで残る状態を使わず、同じ順に同じ light を呼んでください）";
const SAME_QUESTIONS_EN: &str = " (shade_pixel runs twice on the same pixel: ask light the same questions in the same order, with no randomness and no state kept between calls)";

/// Phase 2: the pixel's colour with a light that answers the `k`-th query with `answers[k]`,
/// provided it is phase 1's `k`-th query bit for bit; any other query gets NaN and makes the
/// result `Err`.
fn answered(
    shade_pixel: ShadePixel,
    mode: Shading,
    pixel: &Pixel,
    queries: &[(Vec3, Vec3)],
    answers: &[Rgb],
) -> Result<Rgb, Reason> {
    let (q, a) = (queries.len(), answers.len());
    if q != a {
        return Err(Reason::new(
            format!("問い合わせ {q} 個に答え {a} 個"),
            format!("{q} queries but {a} answers"),
        ));
    }
    let bits = |v: Vec3| v.to_array().map(f32::to_bits);
    let k = Cell::new(0);
    let wrong = RefCell::new(None);
    let light = |p: Vec3, n: Vec3| {
        let at = k.get();
        k.set(at + 1);
        match queries.get(at) {
            Some(&(qp, qn)) if bits(qp) == bits(p) && bits(qn) == bits(n) => answers[at],
            asked_before => {
                if wrong.borrow().is_none() {
                    *wrong.borrow_mut() = Some(match asked_before {
                        Some(&(qp, qn)) => Reason::new(
                            format!(
                                "light の {at} 番目の呼び出しが light({p:?}, {n:?}) でした。\
                                 1 回目は light({qp:?}, {qn:?}) でした{SAME_QUESTIONS_JA}"
                            ),
                            format!(
                                "light query {at} was light({p:?}, {n:?}), not light({qp:?}, \
                                 {qn:?}) as the first time{SAME_QUESTIONS_EN}"
                            ),
                        ),
                        None => Reason::new(
                            format!(
                                "light が {} 回以上呼ばれました。1 回目は {} 回でした\
                                 {SAME_QUESTIONS_JA}",
                                at + 1,
                                queries.len()
                            ),
                            format!(
                                "light was asked {} times or more, {} times the first time\
                                 {SAME_QUESTIONS_EN}",
                                at + 1,
                                queries.len()
                            ),
                        ),
                    });
                }
                Vec3::NAN
            }
        }
    };
    let colour = shade_pixel(mode, pixel, &light);
    match wrong.into_inner() {
        None => Ok(colour),
        Some(why) => Err(why),
    }
}

/// a3's [`Spec`](a3::Spec) on the wire. `a3::Object::mesh` is `#[serde(skip)]` so that `--json`
/// (frozen by `crates/assign/tests/table-v1.json`) leaves it out; the wire form is the spec as
/// `--json` writes it with the meshes beside it, `{"spec": …, "meshes": [mesh of object 1, …]}`.
#[derive(Clone, Debug, PartialEq)]
pub struct A3Spec(pub a3::Spec);

impl Serialize for A3Spec {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct Wire<'a> {
            spec: &'a a3::Spec,
            meshes: Vec<&'a Mesh>,
        }
        let meshes = self.0.objects.iter().map(|o| &o.mesh).collect();
        Wire { spec: &self.0, meshes }.serialize(s)
    }
}

impl<'de> Deserialize<'de> for A3Spec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        #[derive(Deserialize)]
        struct Wire {
            spec: a3::Spec,
            meshes: Vec<Mesh>,
        }
        let Wire { mut spec, meshes } = Wire::deserialize(d)?;
        if meshes.len() != spec.objects.len() {
            return Err(serde::de::Error::custom(format!(
                "{} meshes for {} objects",
                meshes.len(),
                spec.objects.len()
            )));
        }
        for (object, mesh) in spec.objects.iter_mut().zip(meshes) {
            object.mesh = mesh;
        }
        Ok(A3Spec(spec))
    }
}

/// Every assignment's table from a crate laid out like `exercises/` (`cg_exercises` or
/// `cg_solutions`): `tables!(cg_exercises)` is the handlers of `cg_exercises::<id>::
/// implementation()` for each assignment, in one list.
#[macro_export]
macro_rules! tables {
    ($krate:ident) => {
        [
            $crate::tables::a1($krate::a1::implementation()),
            $crate::tables::a2($krate::a2::implementation()),
            $crate::tables::a3($krate::a3::implementation()),
            $crate::tables::a4($krate::a4::implementation()),
            $crate::tables::s($krate::s::implementation()),
        ]
        .into_iter()
        .flatten()
        .collect::<::std::vec::Vec<_>>()
    };
}

#[cfg(test)]
mod tests {
    use std::sync::atomic::{AtomicU32, Ordering};

    use super::*;

    /// A `shade_pixel` that asks `light` somewhere else on each run (a counter kept between
    /// calls): its second run is refused, said in both languages with what to do.
    #[test]
    fn a_shade_pixel_that_asks_other_questions_the_second_time_is_told_why() {
        static RUNS: AtomicU32 = AtomicU32::new(0);
        fn moving(_: Shading, p: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
            let k = RUNS.fetch_add(1, Ordering::Relaxed) as f32;
            light(p.positions[0] + Vec3::X * k, p.face_normal)
        }
        fn steady(_: Shading, p: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
            light(p.positions[0], p.face_normal)
        }
        let pixel = Pixel {
            positions: [Vec3::ZERO, Vec3::X, Vec3::Y],
            normals: [Vec3::Z; 3],
            face_normal: Vec3::Z,
            weights: [1.0, 0.0, 0.0],
        };
        let answer = vec![Vec3::splat(0.25)];
        let queries = asked(steady, Shading::Phong, &pixel);
        assert_eq!(answered(steady, Shading::Phong, &pixel, &queries, &answer), Ok(answer[0]));
        let queries = asked(moving, Shading::Phong, &pixel);
        let why = answered(moving, Shading::Phong, &pixel, &queries, &answer).unwrap_err();
        assert!(why.ja.contains("light の 0 番目の呼び出し"), "{why:?}");
        assert!(why.ja.contains("同じピクセルで 2 回実行されます"), "{why:?}");
        assert!(
            why.en.contains("light query 0 was") && why.en.contains("no randomness"),
            "{why:?}"
        );
    }
}
