//! `a4.t2`, `tex_coords`: the corners of the ground, each block's range, shared vertices, a linear
//! formula, the orientation and the cell every square shows, against the f64 oracle
//! ([`SpecOracle`]).

use cg_core::glam::{DVec2, Vec2};
use cg_core::notation::decimal;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::prepared::{CELLS, cell_name};
use crate::spec::{
    CORNER_STEPS, Corner, GroundCorner, RegionExt, RegionOracle, Spec, SpecExt, SpecOracle,
};
use crate::view::{Coordinates, coordinates};
use crate::{Impl, SQUARES};

/// `a4.t2`'s tolerance on each coordinate.
const TOL: f64 = 1e-5;

// ---------------------------------------------------------------------------------------------
// Words and numbers

/// `(0.25, 0.375)`.
fn uv(v: Vec2) -> String {
    format!("({}, {})", decimal(v.x, 4), decimal(v.y, 4))
}

/// `(0.25, 0.375)` from the f64 oracle.
fn uv64(v: DVec2) -> String {
    uv(v.as_vec2())
}

/// Whether `a` and `b` agree within `tol` in both coordinates (false for NaN).
fn near(a: DVec2, b: DVec2, tol: f64) -> bool {
    (a - b).abs().max_element() <= tol
}

/// The cell a texture coordinate falls in, or why there is none: `cell E3` / `outside the
/// image`. A coordinate on the line between cells (within [`TOL`]) names the cells on both sides
/// (`the line between G2 and H2`, `the corner where G1, H1, G2 and H2 meet`): naming only the
/// cell the rounding falls into would call one corner of a square `G2` here and `H2` there.
fn cell_at(v: DVec2) -> Text {
    if !v.is_finite() {
        return t("数ではない（NaN か無限大）", "not a number (NaN or infinite)");
    }
    let n = f64::from(CELLS);
    let on_line = |c: f64| ((c * n).round() - c * n).abs() <= TOL * n;
    let inside =
        |c: f64| (0.0..1.0).contains(&c) || (on_line(c) && (-TOL..=1.0 + TOL).contains(&c));
    if !inside(v.x) || !inside(v.y) {
        return t("画像の外（s, t は 0〜1 の外）", "outside the image (s or t outside 0…1)");
    }
    // The columns (left to right) and rows (image top to bottom) the point touches.
    let columns = |x: f64| -> Vec<u32> {
        if on_line(x) {
            let k = (x * n).round() as i64;
            [k - 1, k]
                .into_iter()
                .filter(|c| (0..i64::from(CELLS)).contains(c))
                .map(|c| c as u32)
                .collect()
        } else {
            vec![(x * n).floor() as u32]
        }
    };
    let rows: Vec<u32> = columns(v.y).into_iter().rev().map(|r| CELLS - 1 - r).collect();
    let names: Vec<String> =
        rows.iter().flat_map(|&r| columns(v.x).into_iter().map(move |c| cell_name(c, r))).collect();
    match names.as_slice() {
        [one] => Text::new(format!("マス {one}"), format!("cell {one}")),
        [a, b] => {
            Text::new(format!("マス {a} と {b} の境目"), format!("the line between {a} and {b}"))
        }
        more => {
            let (last, rest) = more.split_last().unwrap_or((&more[0], &[]));
            let list = rest.join(", ");
            Text::new(
                format!("マス {}・{last} が接する角", rest.join("・")),
                format!("the corner where {list} and {last} meet"),
            )
        }
    }
}

/// What a coordinate is: one of the region's corners (`the region's top-left corner (cell C4)`),
/// or the cell it falls in.
fn what_is(spec: &Spec, v: Vec2) -> Text {
    for corner in Corner::ALL {
        if near(v.as_dvec2(), spec.corner_coord(corner).as_dvec2(), TOL) {
            let (name, cell) = (corner.name(), spec.region.corner_cell(corner));
            return Text::new(
                format!("範囲の{}の角（マス {cell}）", name.ja),
                format!("the region's {} corner (cell {cell})", name.en),
            );
        }
    }
    cell_at(v.as_dvec2())
}

/// `(i, j) = (3, 7)`.
fn ij(i: u32, j: u32) -> String {
    format!("({i}, {j})")
}

/// The corner `(i+1, j)` of square `(i, j)` as the location text `四角形 (9, 3) の頂点 (i+1, j)` /
/// `corner (i+1, j) of square (9, 3)`.
fn corner_of_square(i: u32, j: u32, c: usize) -> Text {
    let names = ["(i, j)", "(i, j+1)", "(i+1, j+1)", "(i+1, j)"];
    let (square, corner) = (ij(i, j), names[c]);
    Text::new(
        format!("四角形 {square} の頂点 {corner}"),
        format!("corner {corner} of square {square}"),
    )
}

/// `{uv} {words}` in each language (`words` one of [`cell_at`], [`what_is`]), with `sep`
/// between.
fn with_words(value: &str, sep: &str, words: &Text) -> Text {
    Text::new(format!("{value}{sep}{}", words.ja), format!("{value}{sep}{}", words.en))
}

/// The student's coordinates, refusing NaN and infinities with their place.
fn finite_coordinates(spec: &Spec, imp: &Impl) -> Result<Coordinates, Failure> {
    let table = coordinates(spec, imp);
    for j in 0..SQUARES {
        for i in 0..SQUARES {
            for (c, v) in table[i as usize][j as usize].iter().enumerate() {
                if !v.is_finite() {
                    return Err(Failure::new(
                        t("有限のテクスチャ座標", "finite texture coordinates"),
                        uv(*v),
                    )
                        .at(corner_of_square(i, j, c))
                        .cause(t(
                            "0 で割った（まとまりの大きさや範囲の幅が 0）か、まだ計算していない値",
                            "a division by zero (a block size or a range width of 0), or a value never computed",
                        ))
                        .hint(t(
                            "i と j を f32 にしてから割り、割る数が 0 にならないか確かめる",
                            "convert i and j to f32 before dividing, and make sure you never divide by 0",
                        )));
                }
            }
        }
    }
    Ok(table)
}

/// The coordinate of ground vertex `(vi, vj)` as square `(i, j)` gives it.
fn corner_index(i: u32, j: u32, vi: u32, vj: u32) -> usize {
    CORNER_STEPS.iter().position(|&(di, dj)| (i + di, j + dj) == (vi, vj)).unwrap_or(0)
}

// ---------------------------------------------------------------------------------------------
// The checks

pub(super) fn corners(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let table = finite_coordinates(spec, imp)?;
    let last = SQUARES - 1;
    let mut wrong = Vec::new();
    for g in GroundCorner::ALL {
        let (vi, vj) = g.vertex();
        let (i, j) = (vi.min(last), vj.min(last));
        let c = corner_index(i, j, vi, vj);
        let got = table[i as usize][j as usize][c];
        let corner = spec.corner_at(g);
        let want = spec.corner_coord(corner);
        if !near(got.as_dvec2(), want.as_dvec2(), TOL) {
            wrong.push((g, i, j, c, got, corner, want));
        }
    }
    let Some(&(g, i, j, c, got, _, want)) = wrong.first() else {
        return Ok(());
    };
    let found = what_is(spec, got);
    let another_corner =
        Corner::ALL.into_iter().any(|k| near(got.as_dvec2(), spec.corner_coord(k).as_dvec2(), TOL));
    let cause = if another_corner {
        t(
            "範囲の別の角が来ている: 向き（回転・左右反転・上下）が違う（a4.t2.orientation も見る）か、頂点ごとに (i + 1) % k を取って地面の端で座標が始まりに戻っている",
            "another corner of the region lands here: the orientation (turn, mirror, top and bottom) is wrong (see a4.t2.orientation), or (i + 1) % k taken per vertex sends the ground's far edge back to the start",
        )
    } else {
        t(
            "式のずらし方か大きさが違う（i・j が 0 と 10 のとき範囲の端になるか）、範囲でなく画像全体を使っている、または 1 つずれている（i*0.1 + 0.1 など）",
            "the formula's offset or scale is off (at i, j = 0 and 10 it must give the region's edges), it uses the whole image instead of the region, or it is off by one (i*0.1 + 0.1)",
        )
    };
    let (n, square) = (wrong.len(), corner_of_square(i, j, c));
    Err(Failure::new(
        with_words(&uv(want), " = ", &what_is(spec, want)),
        Text::new(
            format!("{} = {}（4 隅のうち {n} 個が違う）", uv(got), found.ja),
            format!("{} = {} — {n} of 4 corners wrong", uv(got), found.en),
        ),
    )
    .at(Text::new(
        format!("{}、{}", g.text().ja, square.ja),
        format!("{}; {}", g.text().en, square.en),
    ))
    .cause(cause)
    .hint(t(
        "まず範囲の 4 つの角の (s, t) と、それぞれが地面のどの隅に来るか（課題の表）を書き出し、i, j = 0 と 10 で式がその値になるか確かめる",
        "write down the (s, t) of the region's 4 corners and which ground corner each goes to (the table in your assignment), then check that your formula gives exactly those at i, j = 0 and 10",
    )))
}

/// The squares `from..from + k` of block `b` along one side, as `5…9`.
fn squares_text(b: u32, k: u32) -> String {
    format!("{}…{}", b * k, b * k + k - 1)
}

pub(super) fn block_range(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let table = finite_coordinates(spec, imp)?;
    let (n, k) = (spec.repeat, spec.block());
    let want = spec.region.range();
    for bj in 0..n {
        for bi in 0..n {
            let mut lo = DVec2::splat(f64::INFINITY);
            let mut hi = DVec2::splat(f64::NEG_INFINITY);
            for i in bi * k..(bi + 1) * k {
                for j in bj * k..(bj + 1) * k {
                    for v in table[i as usize][j as usize] {
                        lo = lo.min(v.as_dvec2());
                        hi = hi.max(v.as_dvec2());
                    }
                }
            }
            let (wlo, whi) = (
                DVec2::new(want.s_min.into(), want.t_min.into()),
                DVec2::new(want.s_max.into(), want.t_max.into()),
            );
            if near(lo, wlo, TOL) && near(hi, whi, TOL) {
                continue;
            }
            let (size, wsize) = (hi - lo, whi - wlo);
            let ratio = size / wsize;
            let cause = if near(lo, DVec2::ZERO, TOL) && near(hi, DVec2::ONE, TOL) {
                t("範囲でなく画像全体を貼っている", "the whole image is mapped, not the region")
            } else if n > 1 && near(ratio, DVec2::splat(1.0 / f64::from(n)), 1e-3) {
                t(
                    "まとまりが範囲の一部しか覆っていない: 繰り返しの数を使っていない（地面全体に範囲を 1 回）",
                    "each block covers only part of the region: the repeat count is not used (the region once over the whole ground)",
                )
            } else if near(size, wsize, TOL) && {
                // Shifted by one square's step along s or t.
                let (shift, step) = ((lo - wlo).abs(), wsize / f64::from(k));
                (shift.x - step.x).abs() < TOL || (shift.y - step.y).abs() < TOL
            } {
                t(
                    "四角形 1 つ分ずれている（i*0.1 + 0.1 のように、頂点 i の座標に 1 つ先の値を使っている）",
                    "off by one square (like i*0.1 + 0.1: vertex i gets the coordinate of vertex i + 1)",
                )
            } else if (n > 1 && near(ratio, DVec2::splat(f64::from(n)), 1e-3))
                || (near(size, wsize, TOL) && {
                    // The next copy of the region over: lo moved by whole region sizes.
                    let copies = (lo - wlo) / wsize;
                    let whole = |c: f64| c.abs() > 0.5 && (c - c.round()).abs() < 1e-3;
                    whole(copies.x) || whole(copies.y)
                })
                || hi.max_element() > 1.0 + TOL
                || lo.min_element() < -TOL
            {
                t(
                    "座標が範囲の先まで続いている（範囲の何倍にも広がるか、0〜1 をはみ出す）: GL_REPEAT が繰り返すのは画像全体で、画像の一部は繰り返せない。まとまりごとに座標を範囲の中で計算し直す（i をまとまりの大きさで割った余りを使う）",
                    "the coordinates run on past the region (over several copies of it, or out of 0…1): GL_REPEAT repeats the whole image, never a part of it; give each block its own coordinates inside the region (use the remainder of i divided by the block size)",
                )
            } else {
                t(
                    "範囲の大きさ・位置か、繰り返しの数が違う",
                    "the region's size or place, or the repeat count, is off",
                )
            };
            let place = if n == 1 {
                let last = SQUARES - 1;
                Text::new(
                    format!("地面全体（四角形 i, j = 0…{last}）"),
                    format!("the whole ground, squares i, j = 0…{last}"),
                )
            } else {
                let (si, sj) = (squares_text(bi, k), squares_text(bj, k));
                Text::new(
                    format!("まとまり ({bi}, {bj}): 四角形 i = {si}, j = {sj}"),
                    format!("block ({bi}, {bj}): squares i = {si}, j = {sj}"),
                )
            };
            let range = format!(
                "s = {}…{}, t = {}…{}",
                decimal(want.s_min, 4),
                decimal(want.s_max, 4),
                decimal(want.t_min, 4),
                decimal(want.t_max, 4)
            );
            let name = spec.region.name();
            return Err(Failure::new(
                Text::new(format!("{range}（範囲 {name}）"), format!("{range} ({name} region)")),
                format!(
                    "s = {}…{}, t = {}…{}",
                    decimal(lo.x as f32, 4),
                    decimal(hi.x as f32, 4),
                    decimal(lo.y as f32, 4),
                    decimal(hi.y as f32, 4)
                ),
            )
            .at(place)
            .cause(cause)
            .hint(if n == 1 {
                t(
                    "頂点 i = 0 と i = 10（j も）で範囲の端になる式にする",
                    "make the formula reach the region's edges exactly at i = 0 and i = 10 (and j)",
                )
            } else {
                Text::new(
                    format!(
                        "{n} × {n} 回の繰り返し: {k} 個の四角形ごとに範囲全体。まとまりの中の位置は i % {k} と j % {k}（四角形の右・奥の頂点は +1 して {k} まで）"
                    ),
                    format!(
                        "a {n} × {n} repeat: the whole region every {k} squares. The place inside a block is i % {k}, j % {k} (a square's far corners add 1, up to {k})"
                    ),
                )
            }));
        }
    }
    Ok(())
}

pub(super) fn shared(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let table = finite_coordinates(spec, imp)?;
    let k = spec.block();
    for vj in 0..=SQUARES {
        for vi in 0..=SQUARES {
            // The squares around vertex (vi, vj), grouped by block (a block's edge is a seam).
            let mut around: Vec<(u32, u32, Vec2)> = Vec::new();
            for i in vi.saturating_sub(1)..=vi.min(SQUARES - 1) {
                for j in vj.saturating_sub(1)..=vj.min(SQUARES - 1) {
                    let v = table[i as usize][j as usize][corner_index(i, j, vi, vj)];
                    around.push((i, j, v));
                }
            }
            for (a, &(i1, j1, v1)) in around.iter().enumerate() {
                for &(i2, j2, v2) in &around[a + 1..] {
                    let same_block = (i1 / k, j1 / k) == (i2 / k, j2 / k);
                    if same_block && !near(v1.as_dvec2(), v2.as_dvec2(), TOL) {
                        let (vertex, a, b) = (ij(vi, vj), ij(i1, j1), ij(i2, j2));
                        let (u1, u2) = (uv(v1), uv(v2));
                        return Err(Failure::new(
                            Text::new(
                                format!("頂点 {vertex} で、同じまとまりのどの四角形からも同じ座標"),
                                format!(
                                    "the same coordinate from every square of a block at vertex {vertex}"
                                ),
                            ),
                            Text::new(
                                format!("四角形 {a} では {u1}、四角形 {b} では {u2}"),
                                format!("square {a} gives {u1}, square {b} gives {u2}"),
                            ),
                        )
                        .at(Text::new(
                            format!("頂点 (i, j) = {vertex}"),
                            format!("vertex (i, j) = {vertex}"),
                        ))
                        .cause(t(
                            "四角形ごとに別々に 0〜1（範囲全体）を割り当てている、または隣の四角形と別の式: 画像が四角形ごとに繰り返されたり、四角形の境目でずれたりする",
                            "each square gets its own 0…1 (the whole region), or neighbouring squares use different formulas: the image repeats in every square, or jumps at the squares' edges",
                        ))
                        .hint(t(
                            "4 つの頂点をそれぞれ自分の i, j（右・奥は i+1, j+1）から同じ式で計算する",
                            "compute each of the 4 corners from its own vertex's i and j (i+1, j+1 for the far ones) with one formula",
                        )));
                    }
                }
            }
        }
    }
    Ok(())
}

pub(super) fn linear(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let table = finite_coordinates(spec, imp)?;
    let (n, k) = (spec.repeat, spec.block());
    for bj in 0..n {
        for bi in 0..n {
            let (i0, j0) = (bi * k, bj * k);
            let first = table[i0 as usize][j0 as usize].map(|v| v.as_dvec2());
            let origin = first[0];
            let (du, dv) = (first[3] - origin, first[1] - origin);
            let det = du.perp_dot(dv);
            if det.abs() <= 1e-9 {
                let (along, other) =
                    if du.abs().max_element() <= 1e-9 { ("i", "j") } else { ("j", "i") };
                let (su, sv, square) = (uv64(du), uv64(dv), ij(i0, j0));
                return Err(Failure::new(
                    t("i にも j にも沿って変わる座標", "coordinates that change along i and along j"),
                    Text::new(
                        format!("四角形 1 つ分の変化: i 方向 {su}、j 方向 {sv}"),
                        format!("steps per square: along i {su}, along j {sv}"),
                    ),
                )
                .at(Text::new(format!("四角形 {square}"), format!("square {square}")))
                .cause(Text::new(
                    format!(
                        "{along} を変えても座標が変わらない（または {other} と同じ向きにしか変わらない）: 整数の割り算（i / 10 は i < 10 で 0）や、i か j の入れ忘れ"
                    ),
                    format!(
                        "the coordinates do not change along {along} (or only the way they change along {other}): an integer division (i / 10 is 0 for i < 10), or i or j left out"
                    ),
                ))
                .hint(t(
                    "i as f32 / 10.0 のように f32 にしてから割る",
                    "convert to f32 before dividing: i as f32 / 10.0",
                )));
            }
            for i in i0..i0 + k {
                for j in j0..j0 + k {
                    for (c, &(di, dj)) in CORNER_STEPS.iter().enumerate() {
                        let (a, b) = (f64::from(i - i0 + di), f64::from(j - j0 + dj));
                        let predicted = origin + du * a + dv * b;
                        let got = table[i as usize][j as usize][c].as_dvec2();
                        if !near(got, predicted, TOL) {
                            let (vi, vj) = (i + di, j + dj);
                            let (p, a, b, d) =
                                (uv64(predicted), ij(i0, j0), ij(i0 + 1, j0), ij(i0, j0 + 1));
                            let (vertex, square) = (ij(vi, vj), corner_of_square(i, j, c));
                            return Err(Failure::new(
                                Text::new(
                                    format!("{p} — 頂点 {a}, {b}, {d} を通る式の続き"),
                                    format!("{p} — the formula through vertices {a}, {b}, {d} continued"),
                                ),
                                uv64(got),
                            )
                            .at(Text::new(
                                format!("頂点 (i, j) = {vertex}; {}", square.ja),
                                format!("vertex (i, j) = {vertex}; {}", square.en),
                            ))
                            .cause(t(
                                "i と j の 1 つの式になっていない: 整数の割り算、特別な場合の表、頂点ごとに i % k を取ってまとまりの最後の頂点が 0 に戻る、四角形ごとに 0〜1 を割り当てる、など",
                                "not one formula in i and j: an integer division, a table of special cases, i % k taken per vertex (a block's last vertex wraps back to 0), or 0…1 given to every square",
                            ))
                            .hint(t(
                                "座標 = 始まり + (i の位置) × (1 つ分の変化) の形にする。頂点 i+1 は i % k + 1 で（(i+1) % k ではなく）",
                                "write coordinate = start + (place along i) × (step per square); the far corner is i % k + 1, not (i + 1) % k",
                            )));
                        }
                    }
                }
            }
        }
    }
    Ok(())
}

/// A direction on the screen along an axis, as the camera sees the ground: `(1, 0)` right (+x),
/// `(0, 1)` away from the camera (−z).
type Axis = (i32, i32);

/// The [`Axis`] of the direction in which a coordinate grows by `along_i` per step in i and
/// `along_j` per step in j; `None` when it is not along an axis.
fn screen_axis(along_i: f64, along_j: f64) -> Option<Axis> {
    // On the screen, i grows to the right and j grows towards the camera (down).
    let v = DVec2::new(along_i, -along_j);
    let len = v.length();
    if len <= 1e-9 || !len.is_finite() {
        return None;
    }
    let u = v / len;
    [(1, 0), (-1, 0), (0, 1), (0, -1)]
        .into_iter()
        .find(|&(x, y)| (u - DVec2::new(f64::from(x), f64::from(y))).length() < 1e-4)
}

/// `right (+x)`, … for an axis from [`screen_axis`].
fn axis_name(a: Axis) -> Text {
    match a {
        (1, 0) => t("右（+x）", "right (+x)"),
        (-1, 0) => t("左（−x）", "left (−x)"),
        (0, 1) => t("奥（−z、カメラから遠ざかる）", "away from the camera (−z)"),
        _ => t("手前（+z、カメラへ）", "towards the camera (+z)"),
    }
}

/// `the image's right (+s) points right (+x), its top (+t) away from the camera (−z)`.
fn orientation_words(right: Axis, up: Axis) -> Text {
    let (r, u) = (axis_name(right), axis_name(up));
    Text::new(
        format!("画像の右（+s）が{}、上（+t）が{}", r.ja, u.ja),
        format!("the image's right (+s) points {}, its top (+t) {}", r.en, u.en),
    )
}

/// A 2 × 2 integer matrix, rows first.
type M2 = [[i32; 2]; 2];

fn mul(a: M2, b: M2) -> M2 {
    let at = |r: usize, c: usize| a[r][0] * b[0][c] + a[r][1] * b[1][c];
    [[at(0, 0), at(0, 1)], [at(1, 0), at(1, 1)]]
}

fn transpose(a: M2) -> M2 {
    [[a[0][0], a[1][0]], [a[0][1], a[1][1]]]
}

pub(super) fn orientation(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let table = finite_coordinates(spec, imp)?;
    let k = f64::from(spec.block());
    // Steps per square along i and j, from vertex (0, 0) of the first block.
    let first = table[0][0].map(|v| v.as_dvec2());
    let (du, dv) = (first[3] - first[0], first[1] - first[0]);
    let e0 = spec.expected_at(0.0, 0.0);
    let (eu, ev) = (spec.expected_at(1.0 / k, 0.0) - e0, spec.expected_at(0.0, 1.0 / k) - e0);
    let want_right = screen_axis(eu.x, ev.x);
    let want_up = screen_axis(eu.y, ev.y);
    let (Some(want_right), Some(want_up)) = (want_right, want_up) else {
        // The oracle is always axis-aligned; this cannot happen for a valid spec.
        return Err(Failure::new(
            t("軸に沿った向き", "an axis-aligned orientation"),
            t("課題の向きそのものが軸に沿っていない", "the assignment's own orientation is not"),
        )
        .at("spec"));
    };
    let expected = orientation_words(want_right, want_up);
    let place = t(
        "頂点 (0, 0) から (1, 0)・(0, 1) への変化",
        "the steps from vertex (0, 0) to (1, 0) and to (0, 1)",
    );
    let (Some(right), Some(up)) = (screen_axis(du.x, dv.x), screen_axis(du.y, dv.y)) else {
        let (ds, dt) = (uv64(DVec2::new(du.x, dv.x)), uv64(DVec2::new(du.y, dv.y)));
        return Err(Failure::new(
            expected,
            Text::new(
                format!(
                    "四角形 1 つごとに i, j 方向へ s が {ds}、t が {dt} 変わる — 地面の辺に沿っていない"
                ),
                format!(
                    "s changes by {ds} and t by {dt} per square along i, j — not along the ground's edges"
                ),
            ),
        )
        .at(place)
        .cause(t(
            "s か t が i と j の両方で変わる（斜め）か、どちらでも変わらない",
            "s or t changes with both i and j (slanted), or with neither",
        ))
        .hint(t(
            "s と t のそれぞれが i か j の一方だけで決まるようにする",
            "make each of s and t depend on only one of i and j",
        )));
    };
    if (right, up) == (want_right, want_up) {
        return Ok(());
    }
    // Columns: where the image's right and top go on the screen.
    let m = |r: Axis, u: Axis| [[r.0, u.0], [r.1, u.1]];
    let (s, e) = (m(right, up), m(want_right, want_up));
    // Both are orthogonal, so e⁻¹ = eᵀ. On the screen the viewer sees the right picture under
    // g = s·e⁻¹; in the image's own frame, your s and t axes are the right ones under h = e⁻¹·s
    // (the two differ when the right orientation has a mirror in it).
    let g = mul(s, transpose(e));
    let h = mul(transpose(e), s);
    let seen = match g {
        [[0, -1], [1, 0]] => t(
            "正しい絵を反時計回りに 90° 回したもの",
            "the right picture turned 90° counter-clockwise",
        ),
        [[0, 1], [-1, 0]] => {
            t("正しい絵を時計回りに 90° 回したもの", "the right picture turned 90° clockwise")
        }
        [[-1, 0], [0, -1]] => {
            t("正しい絵を 180° 回したもの（逆さま）", "the right picture turned 180° (upside down)")
        }
        [[-1, 0], [0, 1]] => t(
            "正しい絵の左右反転（名前が鏡文字）",
            "the right picture mirrored left to right (the names in mirror writing)",
        ),
        [[1, 0], [0, -1]] => t(
            "正しい絵の上下反転（名前が鏡文字、矢印が逆）",
            "the right picture flipped top to bottom (the names in mirror writing, the arrows reversed)",
        ),
        _ => t(
            "正しい絵を対角線で裏返したもの（名前が鏡文字）",
            "the right picture mirrored across a diagonal (the names in mirror writing)",
        ),
    };
    let cause = match h {
        [[-1, 0], [0, 1]] => t(
            "s の向きが逆: 左右反転が抜けているか余計（x の代わりに 1 − x）",
            "s runs the wrong way: the mirror is missing or extra (1 − x where x was needed, or the other way round)",
        ),
        [[1, 0], [0, -1]] => t(
            "t の向きが逆: テクスチャ座標の t は画像の下から上へ増え、地面の j はカメラへ向かって増える。t を反転していない（1 − … が必要）か、反転が余計",
            "t runs the wrong way: texture t grows from the image's bottom to its top, ground j grows towards the camera; t was not inverted (1 − … was needed), or inverted once too often",
        ),
        [[-1, 0], [0, -1]] => t(
            "s と t の両方の向きが逆（180° 回し忘れか、回し過ぎ）",
            "both s and t run the wrong way (a half turn missing or extra)",
        ),
        [[0, -1], [1, 0]] | [[0, 1], [-1, 0]] => t(
            "回す向きが逆か、回す角度が違う（反時計回りはカメラから＝上から見て）",
            "the turn goes the wrong way or by the wrong angle (counter-clockwise as seen from the camera, from above)",
        ),
        _ => t("s と t、または i と j を取り違えている", "s and t, or i and j, are swapped"),
    };
    let yours = orientation_words(right, up);
    Err(Failure::new(
        expected,
        Text::new(format!("{} — {}", yours.ja, seen.ja), format!("{} — {}", yours.en, seen.en)),
    )
    .at(place)
    .cause(cause)
    .hint(t(
        "課題の表の 4 隅から、画像の右（s が増える向き）と上（t が増える向き）が地面のどちらを向くかを図に描いて確かめる。cargo run --release -- view a4 で名前と矢印を見る",
        "draw which way the image's right (s growing) and top (t growing) point on the ground, from the 4 corners in your assignment's table; look at the names and arrows with cargo run --release -- view a4",
    )))
}

pub(super) fn cells(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let table = finite_coordinates(spec, imp)?;
    // A point 3/8 of the way along each square's diagonal from corner (i, j) to (i+1, j+1): on
    // both of its triangles, so the renderer shows exactly this blend there; and never on a
    // cell's edge: (a + 3/8)/k of a region w cells wide is a cell edge only if w·(8a + 3) is a
    // multiple of 8, and 8a + 3 is odd while w ≤ 4 (the same for 1 − …), so the cell it falls in
    // is never a matter of rounding.
    const AT: f64 = 3.0 / 8.0;
    let k = spec.block();
    let mut first = None;
    let mut wrong = 0;
    for j in 0..SQUARES {
        for i in 0..SQUARES {
            let c = table[i as usize][j as usize];
            let got = c[0].as_dvec2() + (c[2].as_dvec2() - c[0].as_dvec2()) * AT;
            let p = (f64::from(i % k) + AT) / f64::from(k);
            let q = (f64::from(j % k) + AT) / f64::from(k);
            let want = spec.expected_at(p, q);
            if !near(got, want, 10.0 * TOL) {
                wrong += 1;
                first.get_or_insert((i, j, got, want));
            }
        }
    }
    let Some((i, j, got, want)) = first else {
        return Ok(());
    };
    let (shows, should) = (cell_at(got), cell_at(want));
    let square = ij(i, j);
    Err(Failure::new(
        with_words(&uv64(want), " ", &should),
        Text::new(
            format!("{} {}（100 個中 {wrong} 個が違う）", uv64(got), shows.ja),
            format!("{} {} — {wrong} of 100 squares wrong", uv64(got), shows.en),
        ),
    )
    .at(Text::new(
        format!(
            "四角形 (i, j) = {square}、頂点 {square} から対角線の 3/8（カメラから見て左から {} 列目、奥から {} 行目）",
            i + 1,
            j + 1
        ),
        format!(
            "square (i, j) = {square}, 3/8 along its diagonal from vertex {square}; column {} from the left, row {} from the far edge (seen from the camera)",
            i + 1,
            j + 1
        ),
    ))
    .cause(t(
        "a4.t2 の他のチェック（隅・範囲・共有・1 次式・向き）のどれかが原因のことが多い",
        "usually what another a4.t2 check reports (corners, range, shared, linear, orientation)",
    ))
    .hint(t(
        "cargo run --release -- view a4 で自分の結果と参考解答を並べ、マスの名前と矢印で何がどこに来たかを見る",
        "compare yours with the reference (cargo run --release -- view a4): the cell names and arrows show what went where",
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_on_a_line_between_cells_names_both_sides() {
        let en = |x: f64, y: f64| cell_at(DVec2::new(x, y)).en;
        assert_eq!(en(0.51, 0.51), "cell E4");
        // s = 7/8 is the line between columns G and H; t = 0.8 is inside row 2.
        assert_eq!(en(0.875, 0.8), "the line between G2 and H2");
        assert_eq!(en(0.875 + 1e-7, 0.8), "the line between G2 and H2", "within the tolerance");
        assert_eq!(en(0.875, 0.875), "the corner where G1, H1, G2 and H2 meet");
        // The image's own edges: one side only.
        assert_eq!(en(1.0, 0.5), "the line between H4 and H5");
        assert_eq!(en(0.0, 0.01), "cell A8");
        assert!(en(1.2, 0.5).starts_with("outside the image"));
        assert!(en(f64::NAN, 0.5).starts_with("not a number"));
        let ja = cell_at(DVec2::new(0.875, 0.8)).ja;
        assert_eq!(ja, "マス G2 と H2 の境目");
    }
}
