//! [`LimitError`]: what is beyond a limit, and why the limit is there, in Japanese and English.

use cg_core::image::MAX_SIDE;
use cg_core::lang::{Text, t};

use super::{
    MAX_COORDINATE, MAX_DEPTH_RATIO, MAX_FOVY_DEG, MAX_POINT_LIGHTS, MAX_SCENE_FACES, MIN_FOVY_DEG,
    MIN_NEAR,
};

/// A scene beyond one of the limits that keep every scene that loads drawable, and drawn alike
/// by the three renderers (see `docs/scene-format.md`, "Limits"). Each variant's message says
/// which limit, and why it is there.
#[derive(Clone, Debug, PartialEq)]
pub enum LimitError {
    /// The transform's steps up to this one multiply out of f32's range (the error's key is the
    /// step's operation: `objects[1].transform[1].scale`).
    StepOverflow {
        /// The matrix that overflows.
        matrix: Matrix,
    },
    /// A point beyond [`MAX_COORDINATE`] on some axis (the error's key is the transform step,
    /// the shape or the model that puts a vertex there, or the camera's key).
    Coordinate {
        /// Which point.
        point: WorldPoint,
        /// Where it is, in world space (rounded to f32; `inf` where even that overflows).
        position: [f32; 3],
    },
    /// `fovy_deg` outside [[`MIN_FOVY_DEG`], [`MAX_FOVY_DEG`]].
    FieldOfView {
        /// The value.
        fovy_deg: f32,
    },
    /// `near` below [`MIN_NEAR`].
    Near {
        /// The value.
        near: f32,
    },
    /// `far / near` above [`MAX_DEPTH_RATIO`].
    DepthRatio {
        /// The near plane.
        near: f32,
        /// The far plane.
        far: f32,
    },
    /// The projection times the view, or its inverse (with which the ray tracer turns pixels
    /// into rays), is not finite in f32.
    ViewProjection,
    /// The objects have more than [`MAX_SCENE_FACES`] faces in all (the error's key is the
    /// parameter or the model that goes over).
    SceneFaces {
        /// The faces counted up to and with this object.
        faces: u64,
    },
    /// The lights are more than [`MAX_POINT_LIGHTS`] point lights in all, an area light counting
    /// its samples (the error's key is the `samples` or the light that goes over).
    PointLights {
        /// The point lights counted up to and with this light.
        lights: u64,
    },
}

/// Which product of a transform overflows, for [`LimitError::StepOverflow`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Matrix {
    /// The model matrix (モデル座標系→ワールド座標系).
    Model,
    /// The model-view matrix: the camera's view times the model matrix.
    ModelView,
    /// The normal matrix: the cofactor matrix of the model matrix's upper 3×3.
    Normal,
}

/// Which point, for [`LimitError::Coordinate`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WorldPoint {
    /// A vertex of the object's mesh (`V`-number, as its file or shape numbers it).
    Vertex(usize),
    /// The camera's eye.
    Eye,
    /// The camera's target.
    Target,
}

/// A number as a message shows it: the shortest digits, with an exponent when very large or
/// small (`8e6`, `3.4e38`, `1e-20`, not 39 digits).
pub(crate) fn number(x: f32) -> String {
    if x.is_finite() && x != 0.0 && !(1e-3..1e6).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// `[x, y, z]` with [`number`].
fn point(p: [f32; 3]) -> String {
    format!("[{}]", p.map(number).join(", "))
}

impl LimitError {
    /// What is beyond which limit, and why the limit is there, in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            LimitError::StepOverflow { matrix } => {
                let what = match matrix {
                    Matrix::Model => t(
                        "このステップまでの積であるモデル変換行列",
                        "the model matrix, the product of the steps up to this one,",
                    ),
                    Matrix::ModelView => t(
                        "モデルビュー行列（視点の変換とこのステップまでの積）",
                        "the model-view matrix (the camera's view times the steps up to this one)",
                    ),
                    Matrix::Normal => t(
                        "法線を変換する行列（このステップまでの積の余因子行列）",
                        "the normal matrix (the cofactor matrix of the steps up to this one, which turns the normals)",
                    ),
                };
                Text::new(
                    format!(
                        "{}が f32 の範囲（±3.4e38）を超えます。拡大縮小や平行移動を小さくしてください",
                        what.ja
                    ),
                    format!(
                        "{} overflows f32 (a number beyond ±3.4e38): use smaller scales or translations",
                        what.en
                    ),
                )
            }
            LimitError::Coordinate { point: which, position } => {
                let at = point(*position);
                let max = MAX_COORDINATE;
                let why = Text::new(
                    format!(
                        "シーンのどの点も各座標が ±{max} 以内になければなりません。\
                         f32 の有効桁は 24 ビットなので、その外では隣り合う座標の間隔が 0.001 を超え、\
                         小さな三角形の形が崩れて、描画の方法ごとに違う絵になります"
                    ),
                    format!(
                        "every point of a scene must lie within ±{max} on each axis: \
                         f32 keeps 24 significant bits, so beyond that neighbouring positions are more \
                         than 0.001 apart, small triangles lose their shape, and each renderer draws them differently"
                    ),
                );
                match which {
                    WorldPoint::Vertex(v) => Text::new(
                        format!(
                            "この物体の頂点 V{v} がワールド座標で {at} にあります。{}。モデルを小さくするか、原点の近くに移してください",
                            why.ja
                        ),
                        format!(
                            "vertex V{v} of this object is at {at} in world space; {}. Scale the model down or move it nearer the origin",
                            why.en
                        ),
                    ),
                    WorldPoint::Eye => Text::new(
                        format!(
                            "視点の位置が {at} になります。{}。カメラを原点に近づけてください",
                            why.ja
                        ),
                        format!(
                            "the eye would be at {at}; {}. Bring the camera nearer the origin",
                            why.en
                        ),
                    ),
                    WorldPoint::Target => Text::new(
                        format!("注視点 {at} が原点から遠すぎます。{}", why.ja),
                        format!("the target {at} is too far from the origin; {}", why.en),
                    ),
                }
            }
            LimitError::FieldOfView { fovy_deg } => {
                let (fovy, min, max) = (number(*fovy_deg), MIN_FOVY_DEG, MAX_FOVY_DEG);
                Text::new(
                    format!(
                        "視野角 fovy_deg = {fovy} は {min} 以上 {max} 以下でなければなりません\
                         。{min}° より狭いと、最大のウィンドウ\
                         （{MAX_SIDE} ピクセル）の 1 ピクセルが f32 の座標の丸め誤差（6e-8）の 18 倍ほどに\
                         なり、描画の方法ごとに違う絵になります。{max}° より広いと、シーンが画像の中央に\
                         押し縮められます"
                    ),
                    format!(
                        "fovy_deg = {fovy} must be in [{min}, {max}]: \
                         below {min}° a pixel of the largest window ({MAX_SIDE} pixels) spans only about \
                         18 times f32's rounding of a position (6e-8), and the renderers draw different \
                         pictures; above {max}° the scene is squeezed into the middle of the image"
                    ),
                )
            }
            LimitError::Near { near } => {
                let (near, min, max) = (number(*near), number(MIN_NEAR), MAX_COORDINATE);
                Text::new(
                    format!(
                        "near = {near} は {min} 以上でなければなりません。\
                         それより近い前方クリップ面は、f32 の座標で表せる細かさ（±{max} で 0.001）より\
                         細かく、奥行きの精度もなくなります。near を大きくしてください"
                    ),
                    format!(
                        "near = {near} must be at least {min}: a nearer plane is \
                         finer than the scene's f32 positions can say (0.001 apart at ±{max}) and \
                         leaves no precision for depth; use a larger near"
                    ),
                )
            }
            LimitError::DepthRatio { near, far } => {
                let ratio = number(far / near);
                let (near, far, max) = (number(*near), number(*far), number(MAX_DEPTH_RATIO));
                Text::new(
                    format!(
                        "far / near = {far} / {near} = {ratio} が {max} を超えます。\
                         奥行きは near から far までを f32 で表すので、比がこれより大きいと視点から遠い面\
                         どうしが同じ奥行きになって前後が決まらず（Z ファイティング）、描画の方法ごとに\
                         違う絵になります。near を大きくするか、far を小さくしてください"
                    ),
                    format!(
                        "far / near = {far} / {near} = {ratio} is more than {max}: \
                         depth from near to far is stored in f32, and with a larger ratio surfaces far \
                         from the eye get the same depth (z-fighting), so the renderers disagree; \
                         raise near or lower far"
                    ),
                )
            }
            LimitError::ViewProjection => t(
                "透視投影と視点の変換の積、またはその逆行列が f32 の範囲に収まりません\
                 （レイトレーシングは逆行列でピクセルをレイに変えます）。カメラを原点に近づけるか、\
                 ふつうの透視投影にしてください",
                "the projection times the camera's view, or its inverse, does not fit f32 (the ray \
                 tracer turns pixels into rays with the inverse): bring the camera nearer the \
                 origin or use a more usual projection",
            ),
            LimitError::SceneFaces { faces } => {
                let max = MAX_SCENE_FACES;
                Text::new(
                    format!(
                        "この物体までで、シーンの面（三角形）が合わせて {faces} 個になります。1 つのシーンの\
                         面は {max} 個までです（それより多いと何 GB もの\
                         メモリと長い時間がかかります）。分割数を減らすか、小さいモデルを使ってください"
                    ),
                    format!(
                        "with this object the scene would have {faces} faces (triangles) in all, more \
                         than the {max} a scene may have (more take \
                         gigabytes of memory and long to draw): use fewer segments or smaller models"
                    ),
                )
            }
            LimitError::PointLights { lights } => {
                let max = MAX_POINT_LIGHTS;
                Text::new(
                    format!(
                        "この光源までで、点光源が合わせて {lights} 個になります（面光源は標本の数だけ\
                         数えます）。1 つのシーンでは {max} 個までです。1 つ 1 つが、\
                         すべてのピクセルで光源処理 1 回と影のレイ 1 本になります（{max} 個で、640 × 640 の\
                         レイトレーシングに 2 コアで約 10 秒）。光源か samples を減らしてください"
                    ),
                    format!(
                        "with this light the scene has {lights} point lights in all (an area light \
                         counts its samples), more than the {max} a scene may have: every \
                         one is one more light to evaluate and shadow ray to trace at every pixel \
                         ({max} take about 10 s to ray-trace at 640 × 640 on two cores); use fewer \
                         lights or samples"
                    ),
                )
            }
        }
    }
}
