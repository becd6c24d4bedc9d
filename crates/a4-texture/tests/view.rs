//! What the view shows, rendered: an answer written by hand for one region (not the reference
//! solution) passes every check, and the rasterizer draws, at the ground points the picture says,
//! the cells the assignment asks for; a flipped answer visibly puts other cells there.

use cg_a4::{
    CELL_PIXELS, Corner, Filter, IMAGE_PIXELS, Impl, Region, RegionExt, Sampler, Spec, SpecExt,
    TexRange, Wrap, cell_color,
};
use cg_core::glam::{Vec2, Vec3, Vec4};
use cg_core::scene::Scene;
use cg_core::texture::TexEnv;

/// Cells C4–D5, upright, once over the ground: s = 2/8 … 4/8, t = 3/8 … 5/8.
fn spec() -> Spec {
    Spec {
        region: Region { column: 2, row: 3, columns: 2, rows: 2 },
        rotation_deg: 0,
        mirrored: false,
        repeat: 1,
    }
}

fn range(_: &Spec) -> TexRange {
    TexRange { s_min: 0.25, s_max: 0.5, t_min: 0.375, t_max: 0.625 }
}

/// By hand: s goes with i from 0.25 to 0.5; t goes *against* j (the camera looks from +z, so
/// the image's top is at j = 0) from 0.625 down to 0.375: 0.025 per square either way.
fn vertex(i: u32, j: u32) -> Vec2 {
    Vec2::new(0.25 + 0.025 * i as f32, 0.625 - 0.025 * j as f32)
}

fn upright(_: &Spec, i: u32, j: u32) -> [Vec2; 4] {
    [vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1), vertex(i + 1, j)]
}

/// The classic mistake: t grows with j.
fn flipped(_: &Spec, i: u32, j: u32) -> [Vec2; 4] {
    let v = |i: u32, j: u32| Vec2::new(0.25 + 0.025 * i as f32, 0.375 + 0.025 * j as f32);
    [v(i, j), v(i, j + 1), v(i + 1, j + 1), v(i + 1, j)]
}

fn sampler() -> Sampler {
    Sampler { filter: Filter::Nearest, wrap_u: Wrap::Clamp, wrap_v: Wrap::Clamp }
}

const SIZE: u32 = 320;

/// The view drawn with GL_REPLACE (the texel's own colour, unlit) at `SIZE × SIZE`.
fn render(imp: &Impl) -> (Scene, cg_core::image::Image) {
    let mut scene = cg_a4::view(&spec(), imp, 0.0).expect("a scene");
    for object in &mut scene.objects {
        if let Some(t) = object.texture.as_mut() {
            t.env = TexEnv::Replace;
        }
    }
    let options = cg_raster::Options { size: Some((SIZE, SIZE)), ..Default::default() };
    let image = cg_raster::render(&scene, &options).expect("renders").image;
    (scene, image)
}

/// The pixel where the world point `p` appears.
fn pixel_of(scene: &Scene, p: Vec3) -> (u32, u32) {
    let view = scene.view_product().unwrap().matrix().unwrap();
    let projection = scene.projection_matrix_for(SIZE, SIZE).unwrap();
    let clip = projection * view * Vec4::new(p.x, p.y, p.z, 1.0);
    let ndc = clip.truncate() / clip.w;
    let x = (ndc.x + 1.0) / 2.0 * SIZE as f32;
    let y = (1.0 - ndc.y) / 2.0 * SIZE as f32;
    (x as u32, y as u32)
}

/// A plain background point of the cell in `column`, `row` (right of its name, below its arrow),
/// as a pixel of the image from its top-left corner, and as a point on the ground under the
/// hand-written upright answer (i = (s − 0.25)/0.025, j = (0.625 − t)/0.025).
fn background_point(column: u32, row: u32) -> Vec3 {
    let (x_px, y_px) = (column * CELL_PIXELS + 58, row * CELL_PIXELS + 40);
    let s = (x_px as f32 + 0.5) / IMAGE_PIXELS as f32;
    let t = 1.0 - (y_px as f32 + 0.5) / IMAGE_PIXELS as f32;
    let (i, j) = ((s - 0.25) / 0.025, (0.625 - t) / 0.025);
    Vec3::new(i - 5.0, 0.0, j - 5.0)
}

#[test]
fn an_answer_written_by_hand_passes_every_check() {
    let imp = Impl { tex_range: range, tex_coords: upright, sampler };
    for c in cg_a4::checks(&spec(), &imp) {
        assert!(c.passed(), "{}: {:?}", c.id, c.outcome);
    }
    // The corners the assignment text names: the region's bottom-left (cell C5) near left.
    let text = spec().describe(cg_core::lang::Lang::En);
    assert!(text.contains("bottom-left (cell C5) → vertex (i, j) = (0, 10)"), "{text}");
    assert_eq!(spec().region.corner_cell(Corner::BottomLeft), "C5");
}

#[test]
fn the_rendered_ground_shows_the_assigned_cells_where_the_picture_says() {
    let (scene, image) = render(&Impl { tex_range: range, tex_coords: upright, sampler });
    // C4 far left, D4 far right, C5 near left, D5 near right, as the camera sees the ground.
    for (column, row, name) in [(2, 3, "C4"), (3, 3, "D4"), (2, 4, "C5"), (3, 4, "D5")] {
        let (x, y) = pixel_of(&scene, background_point(column, row));
        let got = image.get(x, y).expect("on screen");
        let want =
            Vec3::from_array(cell_color(column, row).map(f32::from)[..3].try_into().unwrap())
                / 255.0;
        assert!(
            (got - want).abs().max_element() <= 1.0 / 255.0,
            "{name} at pixel ({x}, {y}): {got} ≠ {want}"
        );
    }
    // The flipped answer puts row 4 where row 5 should be: a mistake the viewer sees.
    let (_, wrong) = render(&Impl { tex_range: range, tex_coords: flipped, sampler });
    let (x, y) = pixel_of(&scene, background_point(2, 4));
    let got = wrong.get(x, y).unwrap();
    let c4 = Vec3::from_array(cell_color(2, 3).map(f32::from)[..3].try_into().unwrap()) / 255.0;
    assert!(
        (got - c4).abs().max_element() <= 1.0 / 255.0,
        "the flipped answer shows C4 near left: {got}"
    );
}
