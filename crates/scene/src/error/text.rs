//! The messages: one [`Text`] per error, its Japanese and English sentence built side by side.

use cg_core::lang::{Lang, Text, t};
use cg_core::quote::shown;

use super::{ErrorKind, Expected, Found, Rule, SceneError};

/// `a, b, c` with each name in backquotes.
fn list(names: &[&str]) -> String {
    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}

impl SceneError {
    /// The message in both languages: `file:line:column: key: what is wrong`, with the parts
    /// that are known.
    #[must_use]
    pub fn text(&self) -> Text {
        let mut place = self.file.display().to_string();
        if let Some(p) = self.position {
            place = format!("{place}:{p}");
        }
        place.push_str(": ");
        // The key path as written, cut short and with invisible characters named.
        let key =
            |lang| self.key.as_ref().map_or_else(String::new, |k| format!("{}: ", shown(k, lang)));
        let Text { ja, en } = self.kind.text();
        Text::new(format!("{place}{}{ja}", key(Lang::Ja)), format!("{place}{}{en}", key(Lang::En)))
    }
}

impl ErrorKind {
    /// What is wrong, in both languages (without the file, place and key).
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            ErrorKind::Write { reason } => Text::new(
                format!("ファイルに書き込めません: {}", reason.ja),
                format!("cannot write the file: {}", reason.en),
            ),
            ErrorKind::Read { reason } => Text::new(
                format!("ファイルを読めません: {}", reason.ja),
                format!("cannot read the file: {}", reason.en),
            ),
            ErrorKind::Encoding { why } => Text::new(
                format!("ファイルの文字コードを読み取れません: {}", why.ja),
                format!("cannot read the file's text: {}", why.en),
            ),
            ErrorKind::Syntax { message } => {
                // The parser's English, said in Japanese too.
                let said = cg_core::toml_syntax::message(message);
                Text::new(
                    format!("TOML の書き方の誤りです（構文エラー）: {}", said.ja),
                    format!("TOML syntax error: {}", said.en),
                )
            }
            ErrorKind::DuplicateKey { key, first_line: Some(line) } => Text::new(
                format!(
                    "`{key}` が 2 回書かれています（1 回目は {line} 行目）。どちらかを消してください"
                ),
                format!("`{key}` is given twice (first on line {line}); remove one of them"),
            ),
            ErrorKind::DuplicateKey { key, first_line: None } => Text::new(
                format!("`{key}` が 2 回書かれています。どちらかを消してください"),
                format!("`{key}` is given twice; remove one of them"),
            ),
            ErrorKind::UnsupportedFormat { found } => Text::new(
                format!("format = {found} は読めません。このキットが読めるのは format = 1 です"),
                format!("format = {found} is not a version this kit reads; use format = 1"),
            ),
            ErrorKind::UnknownKey { key, suggestion: Some(s), .. } => Text::new(
                format!(
                    "`{key}` というキーはありません（`{s}` の間違いでは？）",
                    key = shown(key, Lang::Ja)
                ),
                format!("unknown key `{key}` (did you mean `{s}`?)", key = shown(key, Lang::En)),
            ),
            ErrorKind::UnknownKey { key, suggestion: None, allowed } => Text::new(
                format!(
                    "`{key}` というキーはありません。ここで使えるキー: {}",
                    list(allowed),
                    key = shown(key, Lang::Ja)
                ),
                format!(
                    "unknown key `{key}`; the keys here are {}",
                    list(allowed),
                    key = shown(key, Lang::En)
                ),
            ),
            ErrorKind::MissingKey { key } => Text::new(
                format!("必要なキー `{key}` がありません"),
                format!("missing key `{key}`"),
            ),
            ErrorKind::WrongType { expected, found } => {
                let (expected, found) = (expected.text(), found.text());
                Text::new(
                    format!("{}が必要ですが、{}が書かれています", expected.ja, found.ja),
                    format!("expected {}, found {}", expected.en, found.en),
                )
            }
            ErrorKind::UnknownChoice { value, suggestion: Some(s), .. } => Text::new(
                format!("\"{value}\" は使えません（\"{s}\" の間違いでは？）"),
                format!("unknown value \"{value}\" (did you mean \"{s}\"?)"),
            ),
            ErrorKind::UnknownChoice { value, suggestion: None, allowed } => {
                let choices = allowed.iter().map(|c| format!("\"{c}\"")).collect::<Vec<_>>();
                let choices = choices.join(", ");
                Text::new(
                    format!("\"{value}\" は使えません。使える値: {choices}"),
                    format!("unknown value \"{value}\"; use one of {choices}"),
                )
            }
            ErrorKind::BadValue { rule, got } => {
                let rule = rule.text();
                Text::new(
                    format!("{}（書かれている値: {got}）", rule.ja),
                    format!("{}, got {got}", rule.en),
                )
            }
            ErrorKind::ReflectanceSum { channel, kr, kt } => {
                let sum = kr + kt;
                let c = ["r", "g", "b"].get(*channel).copied().unwrap_or("?");
                Text::new(
                    format!(
                        "kr + kt が {c} 成分で {kr} + {kt} = {sum} です。1 以下にしてください\
                         （エネルギー保存: 面が反射・透過する光は届いた光を超えられません。\
                         超えるとレイトレーシングの反射・屈折レイが際限なく増えます）"
                    ),
                    format!(
                        "kr + kt is {kr} + {kt} = {sum} in channel {c}: it must be at most 1 \
                         (energy conservation: a surface cannot reflect and transmit more light \
                         than reaches it, and the ray tracer's reflected and refracted rays would \
                         multiply without bound)"
                    ),
                )
            }
            ErrorKind::TooManyPixels { width, height } => {
                let e = cg_core::image::SizeError::TooManyPixels { width: *width, height: *height };
                e.text()
            }
            ErrorKind::ColorWithReflectance { other } => Text::new(
                format!(
                    "`color` は ka と kd の両方を決めます（GL_COLOR_MATERIAL での glColor と同じ）。\
                     `color` か `ka`/`kd` のどちらか一方だけを書いてください（`{other}` も書かれています）"
                ),
                format!(
                    "`color` sets both ka and kd (as glColor does under GL_COLOR_MATERIAL); \
                     give either `color` or `ka`/`kd`, not both (`{other}` is also given)"
                ),
            ),
            ErrorKind::ShapeAndMesh => t(
                "物体には `shape` か `mesh` のどちらか一方だけを書いてください",
                "an object has either `shape` or `mesh`, not both",
            ),
            ErrorKind::NoGeometry => t(
                "物体の形がありません: `shape = { kind = \"...\" }` か `mesh = \"ファイル.obj\"` を書いてください",
                "the object has no geometry: give `shape = { kind = \"...\" }` or `mesh = \"file.obj\"`",
            ),
            ErrorKind::SpecularNeedsLectureModel => t(
                "`specular` は light_model = \"lecture\" でだけ選べます（OpenGL のモデルは常に Blinn の N·H）",
                "`specular` applies only to light_model = \"lecture\" (OpenGL's model always uses Blinn's N·H)",
            ),
            ErrorKind::WeldRemovesEveryFace { tolerance, faces } => Text::new(
                format!(
                    "weld = {tolerance} で頂点をまとめると、{faces} 個の面がすべてつぶれて消えます（この距離は面の辺と同じくらい長い）。座標が等しい頂点だけをまとめるなら weld = true、ずれを許すなら辺よりずっと短い距離（例: 1e-4）にしてください"
                ),
                format!(
                    "weld = {tolerance} merges the vertices so far that all {faces} faces collapse and nothing is left (the distance is as long as the edges); use weld = true for bit-equal positions, or a distance much shorter than the edges (e.g. 1e-4)"
                ),
            ),
            ErrorKind::WeldMergesSeam { uvs, kept, merged } => {
                let (ja, en) = if *uvs {
                    ("テクスチャ座標", "texture coordinates")
                } else {
                    ("法線（normals = \"given\"）", "normals (normals = \"given\")")
                };
                Text::new(
                    format!(
                        "weld で頂点 V{merged} を V{kept} にまとめると、{ja}が違うのに 1 つになります（テクスチャの継ぎ目や稜線は 1 つの頂点では保てません）。weld を外すか、テクスチャ・与えた法線なしで使ってください"
                    ),
                    format!(
                        "weld merges V{merged} into V{kept}, though their {en} differ (a texture seam or a hard edge, which one vertex cannot keep); leave weld out, or use it without the texture or the given normals"
                    ),
                )
            }
            ErrorKind::InnerConeNeedsLectureModel => t(
                "`inner_deg`（スポットライトの内側の円錐）は light_model = \"lecture\" でだけ使えます（OpenGL のモデルには内側の円錐がなく、境目は exponent だけで決まります）。[render] に light_model = \"lecture\" を書くか、inner_deg を消してください",
                "`inner_deg` (a spot light's inner cone) applies only to light_model = \"lecture\" (OpenGL's model has no inner cone: only the exponent softens the edge); set light_model = \"lecture\" in [render] or remove inner_deg",
            ),
            ErrorKind::TransformStep { found } => {
                let ops = "`translate`, `rotate_deg` (+ `axis`), `rotate_x_deg`, `rotate_y_deg`, `rotate_z_deg`, `scale`";
                let found: Vec<&str> = found.iter().map(String::as_str).collect();
                let found =
                    if found.is_empty() { t("なし", "none") } else { list(&found).into() };
                Text::new(
                    format!(
                        "変換の各ステップには操作を 1 つだけ書きます（{ops} のどれか）。書かれているキー: {}",
                        found.ja
                    ),
                    format!(
                        "each transform step has exactly one operation ({ops}); found {}",
                        found.en
                    ),
                )
            }
            ErrorKind::UnknownMaterial { name, suggestion: Some(s) } => Text::new(
                format!(
                    "[materials] に \"{name}\" という材質はありません（\"{s}\" の間違いでは？）",
                    name = shown(name, Lang::Ja)
                ),
                format!(
                    "no material named \"{name}\" in [materials] (did you mean \"{s}\"?)",
                    name = shown(name, Lang::En)
                ),
            ),
            ErrorKind::UnknownMaterial { name, suggestion: None } => Text::new(
                format!(
                    "\"{name}\" という材質はありません。[materials.{name}] を作るか、材質をその場に書いてください",
                    name = shown(name, Lang::Ja)
                ),
                format!(
                    "no material named \"{name}\"; define it as [materials.{name}] or write the material inline",
                    name = shown(name, Lang::En)
                ),
            ),
            ErrorKind::DuplicateName { name, first_line } => Text::new(
                format!(
                    "物体の名前 \"{name}\" は {first_line} 行目ですでに使われています",
                    name = shown(name, Lang::Ja)
                ),
                format!(
                    "another object (line {first_line}) is already named \"{name}\"",
                    name = shown(name, Lang::En)
                ),
            ),
            ErrorKind::NeedsNormals => t(
                "normals = \"given\" ですが、このメッシュには法線がありません（OBJ なら vn 行が必要）。\"face\" か \"smooth\" を使ってください",
                "normals = \"given\" but this mesh has no normals (an OBJ needs `vn` lines); use \"face\" or \"smooth\"",
            ),
            ErrorKind::NeedsUvs => t(
                "テクスチャにはテクスチャ座標が必要ですが、このメッシュにはありません（grid にはあります。OBJ なら vt 行が必要）",
                "a texture needs texture coordinates and this mesh has none (grid has them; an OBJ needs `vt` lines)",
            ),
            ErrorKind::Shape(e) => e.text(),
            ErrorKind::TooManyFaces { shape, faces, max } => Text::new(
                format!(
                    "この {shape} は面（三角形）が {faces} 個になります。1 つの形の面は {max} 個までです。分割数を減らしてください"
                ),
                format!(
                    "this {shape} would have {faces} faces (triangles), more than the {max} one shape may have: use fewer segments"
                ),
            ),
            ErrorKind::Limit(e) => e.text(),
            ErrorKind::Transform(e) => e.text(),
            ErrorKind::File(inner) => inner.text(),
            ErrorKind::Obj(e) => Text::new(
                format!("OBJ ファイルとして読めません（{}）", obj_error_ja(*e)),
                format!("not a valid OBJ file: {e}"),
            ),
            ErrorKind::ObjIndex { element, index, count } => Text::new(
                format!(
                    "面が {element} の {index} 番を参照していますが、この行より前の {element} 行は {count} 個です（番号は 1 から、負の数はこの行から後ろ向きに数えます）"
                ),
                format!(
                    "a face refers to {element} number {index}, but the lines before it define {count} `{element}` (indices count from 1; negative ones count back from this line)"
                ),
            ),
            ErrorKind::ObjNumber { element: element @ ("f" | "l"), word } => Text::new(
                format!(
                    "`{word}` は {element} 行の頂点番号として使えません（1 から数える整数か、後ろから数える負の整数を書きます）",
                    word = shown(word, Lang::Ja)
                ),
                format!(
                    "`{word}` is not a usable index on an `{element}` line (a whole number counted from 1, or a negative one counting back)",
                    word = shown(word, Lang::En)
                ),
            ),
            ErrorKind::ObjNumber { element, word } => Text::new(
                format!(
                    "{element} 行の `{word}` は有限の数ではありません",
                    word = shown(word, Lang::Ja)
                ),
                format!(
                    "`{word}` on a `{element}` line is not a finite number",
                    word = shown(word, Lang::En)
                ),
            ),
            ErrorKind::ObjValues { element: element @ ("f" | "l"), .. } => Text::new(
                format!("{element} 行に頂点番号がありません"),
                format!("an `{element}` line without vertex numbers"),
            ),
            ErrorKind::ObjValues { element, found } => {
                let needs = match *element {
                    "v" => t(
                        "3 つの座標 x y z（その後に w、または色 r g b を続けてもかまいません）",
                        "3 coordinates x y z, optionally followed by w or by a colour r g b",
                    ),
                    "vt" => t("少なくとも 2 つの座標 u v", "at least 2 coordinates u v"),
                    _ => t("3 つの成分 x y z", "3 components x y z"),
                };
                Text::new(
                    format!(
                        "{element} 行には{}が必要ですが、{found} 個の値が書かれています",
                        needs.ja
                    ),
                    format!("a `{element}` line needs {}; this one has {found} values", needs.en),
                )
            }
            ErrorKind::ObjCorner { corner } => Text::new(
                format!(
                    "面の頂点 `{corner}` の書き方が違います（v、v/vt、v//vn、v/vt/vn のどれかで書きます）",
                    corner = shown(corner, Lang::Ja)
                ),
                format!(
                    "face corner `{corner}` is not one of v, v/vt, v//vn, v/vt/vn",
                    corner = shown(corner, Lang::En)
                ),
            ),
            ErrorKind::ObjFaceForm { element, has, first_line } => {
                let (ja, en) = if *has {
                    (
                        format!(
                            "この面の頂点には {element} がありますが、{first_line} 行目の（最初の）面にはありません"
                        ),
                        format!(
                            "this face's corners have a `{element}`, but the first face (line {first_line}) has none"
                        ),
                    )
                } else {
                    (
                        format!(
                            "この面の頂点には {element} がありませんが、{first_line} 行目の（最初の）面にはあります"
                        ),
                        format!(
                            "this face's corners have no `{element}`, but the first face (line {first_line}) has one"
                        ),
                    )
                };
                Text::new(
                    format!("{ja}。{element} はすべての面に付けるか、すべて外してください"),
                    format!("{en}: give `{element}` on every face or on none"),
                )
            }
            ErrorKind::ObjCornerForm { corner, first, element, has } => {
                let (corner_ja, first_ja) = (shown(corner, Lang::Ja), shown(first, Lang::Ja));
                let (corner_en, first_en) = (shown(corner, Lang::En), shown(first, Lang::En));
                let (ja, en) = if *has {
                    (
                        format!(
                            "面の頂点 `{corner_ja}` には {element} がありますが、この面の最初の頂点 `{first_ja}` にはありません"
                        ),
                        format!(
                            "face corner `{corner_en}` has a `{element}`, but the face's first corner `{first_en}` has none"
                        ),
                    )
                } else {
                    (
                        format!(
                            "面の頂点 `{corner_ja}` には {element} がありませんが、この面の最初の頂点 `{first_ja}` にはあります"
                        ),
                        format!(
                            "face corner `{corner_en}` has no `{element}`, but the face's first corner `{first_en}` has one"
                        ),
                    )
                };
                Text::new(
                    format!(
                        "{ja}。1 つの面の頂点は同じ書き方（v、v/vt、v//vn、v/vt/vn のどれか）にそろえてください"
                    ),
                    format!(
                        "{en}: write every corner of a face alike (one of v, v/vt, v//vn, v/vt/vn)"
                    ),
                )
            }
            ErrorKind::ObjRepeatedVertex { corner, vertex, first } => Text::new(
                format!(
                    "面の頂点 `{corner}` が使う v の {vertex} 番は、この面の {first} 番目の頂点ですでに使われています。1 つの面の頂点はすべて違う v にしてください（自分自身に接する面は 2 つの面に分けて書きます）",
                    corner = shown(corner, Lang::Ja)
                ),
                format!(
                    "face corner `{corner}` uses v number {vertex}, which corner {first} of this face already uses: every corner of a face is a different `v` (write a face that touches itself as two faces)",
                    corner = shown(corner, Lang::En)
                ),
            ),
            ErrorKind::ObjPosition { w, .. } if *w == 0.0 => t(
                "同次座標 w が 0 です（頂点が無限遠になります）",
                "the homogeneous coordinate w is 0: the vertex would be at infinity",
            ),
            ErrorKind::ObjPosition { position: [x, y, z], .. } => Text::new(
                format!("頂点の座標 ({x}, {y}, {z}) が有限ではありません（無限大または NaN）"),
                format!("the vertex position ({x}, {y}, {z}) is not finite (infinite or NaN)"),
            ),
            ErrorKind::ObjPolygon { corners, problem } => match problem {
                crate::PolygonProblem::Crosses => Text::new(
                    format!(
                        "この面（角 {corners} 個）は辺どうしが交わるか接していて、内側が決まらないため三角形に分割できません。交わらない多角形か三角形に分けて書いてください"
                    ),
                    format!(
                        "this face of {corners} corners crosses or touches itself, so it has no inside to split into triangles: write it as polygons that do not cross, or as triangles"
                    ),
                ),
                crate::PolygonProblem::TooManyCorners { max } => Text::new(
                    format!(
                        "この面は角が {corners} 個の凹多角形です。凹多角形の面の角は {max} 個までです。小さな面に分けて書いてください"
                    ),
                    format!(
                        "this face is concave with {corners} corners; a concave face may have at most {max}: split it into smaller faces"
                    ),
                ),
                crate::PolygonProblem::NotCovered => Text::new(
                    format!(
                        "この面（角 {corners} 個）は、ぴったり覆う三角形に分割できませんでした（角や辺がほとんど重なっています）。三角形に分けて書いてください"
                    ),
                    format!(
                        "this face of {corners} corners could not be split into triangles that cover it exactly (corners or edges almost on top of each other): write it as triangles"
                    ),
                ),
            },
            ErrorKind::NameControl { code, place } => Text::new(
                format!(
                    "名前の {place} 文字目に制御文字 U+{code:04X} があります。名前には見える文字だけを書いてください"
                ),
                format!(
                    "the name has a control character, U+{code:04X}, at character {place}: a name holds visible characters only"
                ),
            ),
            ErrorKind::NameTooLong { chars, max } => Text::new(
                format!("名前が長すぎます（{chars} 文字）。名前は {max} 文字までです"),
                format!("a name of {chars} characters is too long: a name has at most {max}"),
            ),
            ErrorKind::ObjNoFaces => {
                t("OBJ ファイルに面（f 行）がありません", "the OBJ file has no faces (`f` lines)")
            }
            ErrorKind::ObjPartial { element } => Text::new(
                format!(
                    "{element} のある面の頂点とない面の頂点が混ざっています。すべての面に付けるか、すべて外してください"
                ),
                format!(
                    "some face corners have `{element}` and others do not; give it on every face or on none"
                ),
            ),
            ErrorKind::ObjZeroNormal => t(
                "vn の法線が長さ 0 で、向きがありません",
                "this vn normal has length 0: it has no direction",
            ),
            ErrorKind::ObjBadNormal { vertex } => Text::new(
                format!("頂点 V{vertex} の法線が 0 か有限でないベクトルです"),
                format!("vertex V{vertex} has a zero or non-finite normal"),
            ),
            ErrorKind::ObjBadUv { vertex } => Text::new(
                format!("頂点 V{vertex} のテクスチャ座標が有限ではありません"),
                format!("vertex V{vertex} has a non-finite texture coordinate"),
            ),
            ErrorKind::Mesh(e) => {
                let e = e.text();
                Text::new(
                    format!("メッシュとして使えません: {}", e.ja),
                    format!("unusable mesh: {}", e.en),
                )
            }
            ErrorKind::NotPng => t(
                "PNG 画像ではありません（PNG の先頭 8 バイトがありません）",
                "not a PNG image (the file does not start with the PNG signature)",
            ),
            ErrorKind::PngTooLarge { width, height } => {
                let side = crate::MAX_TEXTURE_SIDE;
                Text::new(
                    format!(
                        "PNG 画像が大きすぎます（{width}×{height}。テクスチャは縦横とも {side} ピクセルまで）"
                    ),
                    format!(
                        "PNG image too large ({width}×{height}; a texture is at most {side} pixels each way)"
                    ),
                )
            }
            ErrorKind::FileTooLarge { size, limit_mib } => {
                let (ja, en) = size.map_or_else(
                    || (String::new(), String::new()),
                    |n| (format!("（{n} バイト）"), format!(" ({n} bytes)")),
                );
                Text::new(
                    format!(
                        "ファイルが {limit_mib} MiB を超えています{ja}。指定したファイルが正しいか確かめてください"
                    ),
                    format!(
                        "the file is larger than {limit_mib} MiB{en}: check that you named the right file"
                    ),
                )
            }
            ErrorKind::Png { reason } => Text::new(
                format!(
                    "PNG 画像が壊れているか途中で切れています（画像デコーダの英語の説明: {reason}）"
                ),
                format!("corrupt or truncated PNG image: {reason}"),
            ),
            ErrorKind::Texture(e) => e.text(),
        }
    }
}

/// tobj's error in Japanese (its `Display` is English).
fn obj_error_ja(e: tobj::LoadError) -> &'static str {
    use tobj::LoadError as E;
    match e {
        E::OpenFileFailed => "ファイルを開けません",
        E::ReadError => "読み込みに失敗しました",
        E::UnrecognizedCharacter => "読めない文字があります",
        E::PositionParseError => "頂点の座標（v 行）が読めません",
        E::ScalingByZeroError => "同次座標 w が 0 です",
        E::ColorParseError => "頂点の色（v 行の r g b）の数が合いません",
        E::NormalParseError => "法線（vn 行）が読めません",
        E::TexcoordParseError => "テクスチャ座標（vt 行）が読めません",
        E::FaceParseError => "面（f 行）が読めません",
        E::MaterialParseError => "材質（usemtl 行）が読めません",
        E::InvalidObjectName => "物体の名前（o 行）が正しくありません",
        E::InvalidPolygon => "多角形が正しくありません",
        E::FaceVertexOutOfBounds => "面が存在しない頂点を参照しています",
        E::FaceTexCoordOutOfBounds => "面が存在しないテクスチャ座標を参照しています",
        E::FaceNormalOutOfBounds => "面が存在しない法線を参照しています",
        E::FaceColorOutOfBounds => {
            "色のない頂点があります（v 行の色は全部に付けるか、全部外します）"
        }
        E::InvalidLoadOptionConfig => "読み込みの設定が矛盾しています",
        E::GenericFailure => "原因不明の失敗です",
    }
}

impl Expected {
    /// What a key takes, in both languages (`an array of 3 numbers [x, y, z]`).
    #[must_use]
    pub fn text(self) -> Text {
        match self {
            Expected::Number => t("数", "a number"),
            Expected::Integer => t("整数", "an integer"),
            Expected::String => t("文字列", "a string"),
            Expected::Boolean => t("true か false", "true or false"),
            Expected::Table => t("テーブル", "a table"),
            Expected::ArrayOfTables => t("テーブルの配列", "an array of tables"),
            Expected::Vec3 => t("3 つの数の配列 [x, y, z]", "an array of 3 numbers [x, y, z]"),
            Expected::Color => t("RGB の色 [r, g, b]", "an RGB colour [r, g, b]"),
            Expected::Attenuation => "[kc, kl, kq]".into(),
            Expected::Samples => t("2 つの整数 [nu, nv]", "two integers [nu, nv]"),
            Expected::Wrap => t(
                "\"repeat\" か \"clamp\"、またはその [u, v]",
                "\"repeat\", \"clamp\" or [u, v] of those",
            ),
            Expected::Choice => t("引用符で囲んだ語", "a word in quotes"),
            Expected::Normals => t(
                "\"face\", \"given\", \"smooth\" または { weighting = ..., crease_deg = ... }",
                "\"face\", \"given\", \"smooth\" or { weighting = ..., crease_deg = ... }",
            ),
            Expected::Material => t(
                "引用符で囲んだ材質名かインラインテーブル { ... }",
                "a material name in quotes or an inline table { ... }",
            ),
            Expected::Weld => t(
                "true、false、または 0 以上の距離の許容値",
                "true, false or a distance tolerance ≥ 0",
            ),
        }
    }
}

impl Found {
    /// What was written, in both languages (`an array of 2 values`).
    #[must_use]
    pub fn text(self) -> Text {
        match self {
            Found::String => t("文字列", "a string"),
            Found::Integer => t("整数", "an integer"),
            Found::Float => t("小数", "a float"),
            Found::Boolean => t("真偽値", "a boolean"),
            Found::Datetime => t("日時", "a date-time"),
            Found::Array { len } => Text::new(
                format!("{len} 個の値の配列"),
                if len == 1 {
                    "an array of 1 value".to_owned()
                } else {
                    format!("an array of {len} values")
                },
            ),
            Found::Table => t("テーブル", "a table"),
        }
    }
}

impl Rule {
    /// The rule, in both languages (`must be finite and > 0`).
    #[must_use]
    pub fn text(self) -> Text {
        match self {
            // Numbers are f32 in the renderers: 1e300 is finite, but not there.
            Rule::Finite => t(
                "有限の数（絶対値 3.4e38 まで）でなければなりません",
                "must be finite (at most 3.4e38 in absolute value)",
            ),
            Rule::NonNegative => {
                t("0 以上の有限の数でなければなりません", "must be finite and ≥ 0")
            }
            Rule::Positive => {
                t("0 より大きい有限の数でなければなりません", "must be finite and > 0")
            }
            Rule::Between { min, max } => Text::new(
                format!("{min} 以上 {max} 以下でなければなりません"),
                format!("must be in [{min}, {max}]"),
            ),
            Rule::Inside { min, max } => Text::new(
                format!("{min} より大きく {max} より小さくなければなりません"),
                format!("must be strictly between {min} and {max}"),
            ),
            Rule::InnerNeedsCone => t(
                "cutoff_deg = 180（円錐なし）のスポットには内側の円錐がありません。cutoff_deg を 90 以下にするか、inner_deg を消してください",
                "a spot with cutoff_deg = 180 (no cone) has no inner cone: make cutoff_deg at most 90, or remove inner_deg",
            ),
            Rule::SpotCutoff => t(
                "0 より大きく 90 以下、または 180（円錐なし）でなければなりません",
                "must be in (0, 90] or exactly 180 (no cone)",
            ),
            Rule::Integer { min, max } => Text::new(
                format!("{min} 以上 {max} 以下の整数でなければなりません"),
                format!("must be an integer in {min}..={max}"),
            ),
            Rule::NonZeroVector => t(
                "有限で長さが 0 でないベクトルでなければなりません",
                "must be a finite, non-zero vector",
            ),
            Rule::GreaterThan { key, value } => Text::new(
                format!("{key}（= {value}）より大きくなければなりません"),
                format!("must be greater than {key} (= {value})"),
            ),
            Rule::NotAbove { key, value } => Text::new(
                format!("{key}（= {value}）以下でなければなりません"),
                format!("must not exceed {key} (= {value})"),
            ),
            Rule::NonZeroArea => t(
                "edge_u × edge_v が 0 で、面光源に面積がありません",
                "edge_u × edge_v is zero: the light has no area",
            ),
            Rule::SomeAttenuation => t(
                "kc, kl, kq のどれかは 0 より大きくなければなりません",
                "at least one of kc, kl, kq must be > 0",
            ),
            Rule::AtMost { max } => Text::new(
                format!("{max:e} 以下でなければなりません"),
                format!("must be at most {max:e}"),
            ),
        }
    }
}
