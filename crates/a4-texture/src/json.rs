//! The variant as `cg assignment --json` shows it: the plain data of [`Spec`] and, worked out on
//! the kit's side, the region's cell names and pixels and the table of where each corner of the
//! region lands. The students' crate ([`cg_student::a4`]) holds the plain data only, so the
//! worked-out fields are added here.

use serde::{Serialize, Serializer};

use crate::spec::{Corner, GroundCorner, RegionExt, Spec, SpecExt};

/// A [`Spec`] presented for `cg assignment --json` (table version 1, frozen):
///
/// ```json
/// { "region": { "first": "C4", "last": "D5", "column": 2, "row": 3, "columns": 2, "rows": 2,
///               "pixels": [128, 192, 256, 320] },
///   "rotation_deg": 0, "mirrored": false, "repeat": 1,
///   "corners": [ { "corner": "bottom_left", "cell": "C5", "ground": "near_left",
///                  "vertex": [0, 10] }, … ] }
/// ```
///
/// `corners` lists, for each corner of the region ([`Corner::ALL`]), where it lands — the table
/// the assignment text prints.
#[derive(Clone, Copy, Debug)]
pub struct Presented<'a>(pub &'a Spec);

impl Serialize for Presented<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct RegionJson {
            first: String,
            last: String,
            column: u32,
            row: u32,
            columns: u32,
            rows: u32,
            pixels: [u32; 4],
        }
        #[derive(Serialize)]
        struct CornerJson {
            corner: Corner,
            cell: String,
            ground: GroundCorner,
            vertex: (u32, u32),
        }
        #[derive(Serialize)]
        struct Json {
            region: RegionJson,
            rotation_deg: u32,
            mirrored: bool,
            repeat: u32,
            corners: Vec<CornerJson>,
        }
        let spec = self.0;
        let r = &spec.region;
        Json {
            region: RegionJson {
                first: r.first(),
                last: r.last(),
                column: r.column,
                row: r.row,
                columns: r.columns,
                rows: r.rows,
                pixels: r.pixels(),
            },
            rotation_deg: spec.rotation_deg,
            mirrored: spec.mirrored,
            repeat: spec.repeat,
            corners: Corner::ALL
                .into_iter()
                .map(|corner| {
                    let ground = spec.ground_corner_of(corner);
                    CornerJson {
                        corner,
                        cell: r.corner_cell(corner),
                        ground,
                        vertex: ground.vertex(),
                    }
                })
                .collect(),
        }
        .serialize(serializer)
    }
}

/// Serialises `spec` as [`Presented`] does, for a field of type [`Spec`]:
/// `#[serde(serialize_with = "cg_a4::serialize_spec")]`.
///
/// # Errors
/// The serializer's own.
pub fn serialize_spec<S: Serializer>(spec: &Spec, serializer: S) -> Result<S::Ok, S::Error> {
    Presented(spec).serialize(serializer)
}
