//! docs/numerics.md row 22, the fill rule: pixels on an edge shared by two triangles are drawn
//! exactly once, none are missed. Pixel-exact on small rasters, through the renderer's own
//! snapping, setup, tiling and rasterizer ([`cg_raster::coverage`]); and once through the whole
//! pipeline of a scene.
//!
//! The oracle is geometric: triangles that tile a region cover every pixel centre inside it
//! exactly once, whatever the fill rule's details; and on a region's own border the rule is
//! OpenGL's (the top-left rule in its y-up window coordinates): as the image is seen, "left and
//! bottom edges belong to the region, right and top edges do not".

mod common;

use cg_core::Rgb;
use cg_core::glam::{Vec2, Vec3};
use cg_core::shapes::grid;
use cg_raster::{GUARD_BAND_PIXELS, Options, RenderError, coverage, render};
use cg_testkit::Inputs;
use common::{looking_down_z, masks_side_by_side, object, tri, unlit};

/// Tile sides to draw every case with: one tile, odd tiles that cut triangles anywhere, tiny tiles.
const TILES: [u32; 3] = [64, 5, 2];

/// Asserts that `triangles` cover pixel `(x, y)` of a `width × height` raster `expected(x, y)`
/// times, for every tile size in [`TILES`] and for both windings; on failure prints both masks.
fn assert_coverage(
    name: &str,
    width: u32,
    height: u32,
    triangles: &[[Vec2; 3]],
    expected: impl Fn(u32, u32) -> u32,
) {
    let expected: Vec<u32> = (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| expected(x, y))
        .collect();
    let reversed: Vec<[Vec2; 3]> = triangles.iter().map(|&[a, b, c]| [a, c, b]).collect();
    for (winding, set) in [("as given", triangles), ("reversed", &reversed[..])] {
        for tile in TILES {
            let actual = coverage(width, height, tile, set).unwrap();
            if actual != expected {
                let wrong: Vec<String> = actual
                    .iter()
                    .zip(&expected)
                    .enumerate()
                    .filter(|(_, (a, e))| a != e)
                    .take(8)
                    .map(|(i, (a, e))| {
                        format!("({}, {}): {a} instead of {e}", i as u32 % width, i as u32 / width)
                    })
                    .collect();
                panic!(
                    "{name} (winding {winding}, tiles of {tile} px): pixels covered the wrong number of times: {}\n{}",
                    wrong.join(", "),
                    masks_side_by_side(&expected, &actual, width, height)
                );
            }
        }
    }
}

/// The two triangles of the rectangle `[x0, x1] × [y0, y1]`, split along the diagonal from the
/// top-left to the bottom-right corner (or the other one).
fn rectangle(x0: f32, y0: f32, x1: f32, y1: f32, main_diagonal: bool) -> [[Vec2; 3]; 2] {
    if main_diagonal {
        [tri((x0, y0), (x1, y0), (x1, y1)), tri((x0, y0), (x1, y1), (x0, y1))]
    } else {
        [tri((x0, y0), (x1, y0), (x0, y1)), tri((x1, y0), (x1, y1), (x0, y1))]
    }
}

#[test]
fn row22_a_diagonal_shared_edge_through_pixel_centres_is_drawn_once() {
    // The whole 16 × 16 raster in two triangles; y = x and x + y = 16 run through the centres
    // (k + ½, k + ½) and (k + ½, 15 − k + ½).
    for main_diagonal in [true, false] {
        assert_coverage(
            &format!(
                "square split along the {} diagonal",
                if main_diagonal { "main" } else { "other" }
            ),
            16,
            16,
            &rectangle(0.0, 0.0, 16.0, 16.0, main_diagonal),
            |_, _| 1,
        );
    }
}

#[test]
fn row22_horizontal_and_vertical_shared_edges_through_pixel_centres_are_drawn_once() {
    // Four rectangles meeting at x = 8.5 and y = 7.5, lines of pixel centres.
    let mut triangles = Vec::new();
    for (x0, x1) in [(0.0, 8.5), (8.5, 16.0)] {
        for (y0, y1) in [(0.0, 7.5), (7.5, 16.0)] {
            triangles.extend(rectangle(x0, y0, x1, y1, (x0 + y0) == 0.0));
        }
    }
    assert_coverage("four rectangles", 16, 16, &triangles, |_, _| 1);

    // Horizontal and vertical edges shared between two triangles directly: a diamond split along
    // both of its diagonals, which run through pixel centres.
    let c = (8.5, 7.5);
    let (left, top, right, bottom) = ((-8.0, 7.5), (8.5, -9.0), (25.0, 7.5), (8.5, 24.0));
    let diamond =
        [tri(c, left, top), tri(c, top, right), tri(c, right, bottom), tri(c, bottom, left)];
    // The diamond |x − 8.5| + |y − 7.5| ≤ 16.5 holds every pixel centre of the raster (at most
    // 16 away) inside it.
    assert_coverage("diamond in four", 16, 16, &diamond, |_, _| 1);
}

#[test]
fn row22_a_fan_around_a_vertex_at_a_pixel_centre_covers_every_pixel_once() {
    // A fan about the pixel centre (7.5, 8.5) out to the raster's border, with spokes through
    // pixel centres: horizontal, vertical, and both diagonals (slope ±1 from a centre).
    let c = (7.5, 8.5);
    let border = [
        (0.0, 0.0),   // a corner
        (0.0, 1.0),   // slope 1: through the centres (7.5 − k, 8.5 − k)
        (0.0, 8.5),   // horizontal
        (0.0, 16.0),  // a corner, and slope −1: through (7.5 − k, 8.5 + k)
        (7.5, 16.0),  // vertical
        (15.0, 16.0), // slope 1
        (16.0, 16.0), // a corner
        (16.0, 8.5),  // horizontal
        (16.0, 0.0),  // a corner, and slope −1
        (7.5, 0.0),   // vertical
        (3.0, 0.0),   // a spoke through no centre
    ];
    // Order the border points around the centre so the fan closes without overlaps.
    let mut spokes: Vec<(f32, f32)> = border.to_vec();
    spokes.sort_by(|a, b| {
        let angle = |p: &(f32, f32)| f64::from(p.1 - c.1).atan2(f64::from(p.0 - c.0));
        angle(a).total_cmp(&angle(b))
    });
    spokes.dedup();
    let fan: Vec<[Vec2; 3]> =
        (0..spokes.len()).map(|i| tri(c, spokes[i], spokes[(i + 1) % spokes.len()])).collect();
    assert_coverage("fan about a pixel centre", 16, 16, &fan, |_, _| 1);
}

#[test]
fn row22_the_border_of_a_region_follows_opengls_fill_rule() {
    // The rectangle [2.5, 12.5] × [3.5, 9.5]: all four sides run through pixel centres. Its left
    // and bottom sides belong to it, its right and top sides do not: pixel x is covered for
    // 2.5 ≤ x + ½ < 12.5, pixel y (row 0 at the top) for 3.5 < y + ½ ≤ 9.5.
    for main_diagonal in [true, false] {
        assert_coverage(
            "rectangle on pixel centres",
            16,
            12,
            &rectangle(2.5, 3.5, 12.5, 9.5, main_diagonal),
            |x, y| u32::from((2..12).contains(&x) && (4..10).contains(&y)),
        );
    }
    // A triangle with a top side and a left side on pixel centres, and a diagonal right side
    // through centres: (2.5, 2.5), (10.5, 2.5), (2.5, 10.5). Centre (x + ½, y + ½) is covered for
    // x ≥ 2 (left: kept), y ≥ 3 (top: left out) and (x + ½) + (y + ½) < 13 (right: left out).
    assert_coverage(
        "right triangle, top-left corner",
        14,
        14,
        &[tri((2.5, 2.5), (10.5, 2.5), (2.5, 10.5))],
        |x, y| u32::from(x >= 2 && y >= 3 && x + y + 1 < 13),
    );
    // Its mirror image with the right angle at the bottom right: (11.5, 11.5), (3.5, 11.5),
    // (11.5, 3.5). Bottom side kept (y + ½ ≤ 11.5), right side left out (x + ½ < 11.5), the
    // diagonal is a left edge here: kept ((x + ½) + (y + ½) ≥ 15).
    assert_coverage(
        "right triangle, bottom-right corner",
        14,
        14,
        &[tri((11.5, 11.5), (3.5, 11.5), (11.5, 3.5))],
        |x, y| u32::from(x <= 10 && y <= 11 && x + y + 1 >= 15),
    );
}

#[test]
fn row22_a_jittered_mesh_covers_every_pixel_exactly_once() {
    // A 6 × 6 grid of quads over a 24 × 20 raster, the inner grid points moved by up to a
    // quarter cell and snapped to 1/16 pixel (so many edges pass exactly through pixel centres),
    // each quad split along a random diagonal. When every triangle turns the same way, the mesh
    // covers each point of the rectangle exactly once (its winding number), and every pixel
    // centre lies strictly inside the rectangle.
    let (w, h, n) = (24u32, 20u32, 6usize);
    let cell = Vec2::new(w as f32 / n as f32, h as f32 / n as f32);
    let mut inputs = Inputs::seeded(22);
    let turn = |[a, b, c]: [Vec2; 3]| (b - a).as_dvec2().perp_dot((c - a).as_dvec2());
    for _ in 0..if cfg!(debug_assertions) { 8 } else { 64 } {
        let mut points = vec![vec![Vec2::ZERO; n + 1]; n + 1];
        for (j, row) in points.iter_mut().enumerate() {
            for (i, p) in row.iter_mut().enumerate() {
                *p = Vec2::new(i as f32, j as f32) * cell;
                if (1..n).contains(&i) && (1..n).contains(&j) {
                    let jitter =
                        Vec2::new(inputs.uniform_f32(-0.25, 0.25), inputs.uniform_f32(-0.25, 0.25));
                    *p = ((*p + jitter * cell) * 16.0).round() / 16.0;
                }
            }
        }
        let mut triangles = Vec::new();
        for j in 0..n {
            for i in 0..n {
                let (a, b, c, d) =
                    (points[j][i], points[j][i + 1], points[j + 1][i + 1], points[j + 1][i]);
                let one = [[a, b, c], [a, c, d]];
                let other = [[a, b, d], [b, c, d]];
                let positive = |pair: &[[Vec2; 3]; 2]| pair.iter().all(|&t| turn(t) > 0.0);
                // A concave quad has one good diagonal; take a random one where both are.
                let pick = if positive(&one) && (inputs.coin() || !positive(&other)) {
                    one
                } else {
                    other
                };
                assert!(
                    positive(&pick),
                    "premise: quad ({i}, {j}) splits into two triangles that turn alike"
                );
                triangles.extend(pick);
            }
        }
        assert_coverage(
            &format!("jittered mesh, seed {}", inputs.seed()),
            w,
            h,
            &triangles,
            |_, _| 1,
        );
    }
}

#[test]
fn zero_area_and_outside_triangles_cover_nothing() {
    let none = |_, _| 0;
    assert_coverage("collinear", 8, 8, &[tri((1.0, 1.0), (4.0, 4.0), (7.0, 7.0))], none);
    assert_coverage("repeated corner", 8, 8, &[tri((1.0, 1.0), (1.0, 1.0), (7.0, 2.0))], none);
    assert_coverage(
        "left of the raster",
        8,
        8,
        &[tri((-9.0, 1.0), (-1.0, 1.0), (-1.0, 7.0))],
        none,
    );
    // Thinner than a pixel, between two rows of centres.
    assert_coverage("sliver", 8, 8, &[tri((0.0, 3.6), (8.0, 3.6), (8.0, 3.9))], none);
}

#[test]
fn coverage_refuses_corners_beyond_the_guard_band_and_bad_sizes() {
    // Beyond ±2²⁰ pixels the fixed-point snap would saturate and the edge functions could
    // overflow i64: an error naming the corner, never a panic or a wrong mask.
    let far = GUARD_BAND_PIXELS * 4.0;
    for (bad, what) in [(far, "far"), (-far, "far left"), (f32::NAN, "NaN"), (f32::INFINITY, "∞")]
    {
        let triangles =
            [tri((0.0, 0.0), (4.0, 0.0), (0.0, 4.0)), tri((1.0, 1.0), (2.0, 1.0), (bad, 3.0))];
        let e = coverage(8, 8, 4, &triangles).unwrap_err();
        assert!(
            matches!(e, RenderError::OutsideGuardBand { triangle: 1, corner: 2, .. }),
            "{what}: {e}"
        );
        assert!(e.message(cg_core::lang::Lang::Ja).contains("三角形 1"), "{what}");
    }
    // On the band's edge itself: accepted (and it covers what it covers).
    let edge = GUARD_BAND_PIXELS;
    let counts = coverage(8, 8, 4, &[tri((-1.0, -1.0), (edge, -1.0), (-1.0, edge))]).unwrap();
    assert!(counts.iter().all(|&n| n == 1), "a huge triangle covers every pixel once");
    assert!(matches!(coverage(0, 8, 4, &[]), Err(RenderError::ZeroSize { .. })));
    assert!(matches!(coverage(20_000, 8, 4, &[]), Err(RenderError::TooLarge { .. })));
    assert!(matches!(coverage(16_384, 16_384, 4, &[]), Err(RenderError::TooManyPixels { .. })));
}

#[test]
fn row22_a_ground_grid_through_the_whole_pipeline_draws_each_pixel_once() {
    // A 48 × 48 ground grid (4608 triangles sharing edges) seen in perspective from above, large
    // enough to fill the whole image: the rasterizer must generate exactly one fragment per pixel
    // (none twice along the shared edges, none missed) and no pixel may keep the clear colour.
    let (w, h) = (40u32, 30u32);
    let mut scene = looking_down_z(w, h, 60.0);
    scene.clear_color = Rgb::new(0.0, 0.0, 1.0);
    let mut ground = object("ground", grid(48, 40.0).unwrap(), unlit(Rgb::new(1.0, 0.0, 0.0)));
    // Tilted towards the camera and pushed away: the plane fills the whole view.
    ground.transform = cg_core::product::MatrixProduct::identity()
        .then(cg_core::product::Factor::translate(Vec3::new(0.0, 0.0, -6.0)))
        .then(cg_core::product::Factor::rotate_x_deg(70.0));
    scene.objects.push(ground);
    let out = render(&scene, &Options::default()).unwrap();
    let clear = out.image.pixels.iter().filter(|&&c| c == scene.clear_color).count();
    assert_eq!(clear, 0, "{clear} pixels not covered by the ground");
    assert_eq!(
        out.stats.fragments,
        u64::from(w * h),
        "fragments generated vs pixels: each pixel must be covered exactly once ({})",
        out.stats
    );
    assert_eq!(out.stats.depth_rejects, 0, "no pixel drawn twice, so nothing to reject");
    assert!(
        out.stats.triangles_drawn > 100,
        "premise: many shared edges on screen ({})",
        out.stats
    );
}
