//! Image comparison for rendering tests (after wgpu's test harness): compare two RGBA8 images
//! with a stated tolerance and, on failure, write `<name>-actual.png`, `<name>-expected.png` and
//! `<name>-diff.png` under `target/test-images/` and say where they are.
//!
//! Reference images are committed. A missing reference fails the test unless `CG_BLESS=1` is
//! set, so a run on a student's machine never creates its own "golden" image.

use std::path::{Path, PathBuf};

/// How far two images may differ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// A pixel "differs" when one of its channels differs by more than this (0..=255).
    pub per_channel: u8,
    /// The largest fraction of differing pixels allowed, in `[0, 1]` (0: none may differ).
    pub max_fraction: f64,
}

impl Tolerance {
    /// Every pixel within `per_channel` of the reference.
    #[must_use]
    pub fn all_within(per_channel: u8) -> Tolerance {
        Tolerance { per_channel, max_fraction: 0.0 }
    }

    /// At least `percent` % of the pixels within `per_channel` of the reference.
    #[must_use]
    pub fn percent_within(percent: f64, per_channel: u8) -> Tolerance {
        Tolerance { per_channel, max_fraction: 1.0 - percent / 100.0 }
    }
}

/// What a comparison measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// The largest channel difference over all pixels.
    pub max_diff: u8,
    /// The mean channel difference (over RGB of all pixels).
    pub mean_diff: f64,
    /// Pixels with a channel difference above the tolerance's `per_channel`.
    pub pixels_over: usize,
    /// `pixels_over` as a fraction of all pixels.
    pub fraction_over: f64,
}

/// Compares two RGBA8 images of the same size channel by channel (RGB; alpha is ignored).
///
/// # Panics
/// When either buffer does not hold `width × height` pixels (a broken test, not a result).
#[must_use]
pub fn compare(
    actual: &[[u8; 4]],
    expected: &[[u8; 4]],
    width: u32,
    height: u32,
    per_channel: u8,
) -> Comparison {
    let n = width as usize * height as usize;
    assert_eq!(actual.len(), n, "actual image is not {width}×{height}");
    assert_eq!(expected.len(), n, "expected image is not {width}×{height}");
    let (mut max_diff, mut sum, mut over) = (0u8, 0u64, 0usize);
    for (a, e) in actual.iter().zip(expected) {
        let d = (0..3).map(|c| a[c].abs_diff(e[c])).max().unwrap_or(0);
        sum += (0..3).map(|c| u64::from(a[c].abs_diff(e[c]))).sum::<u64>();
        max_diff = max_diff.max(d);
        over += usize::from(d > per_channel);
    }
    let pixels = n.max(1) as f64;
    Comparison {
        max_diff,
        mean_diff: sum as f64 / (3.0 * pixels),
        pixels_over: over,
        fraction_over: over as f64 / pixels,
    }
}

/// Where failing tests write their images: `target/test-images/` of the workspace (found from the
/// test binary's path, `target/<profile>/deps/<binary>`), or `$CG_TEST_IMAGES` when set.
#[must_use]
pub fn output_dir() -> PathBuf {
    if let Some(dir) = std::env::var_os("CG_TEST_IMAGES") {
        return PathBuf::from(dir);
    }
    std::env::current_exe()
        .ok()
        .and_then(|exe| exe.ancestors().nth(3).map(Path::to_path_buf))
        .unwrap_or_else(std::env::temp_dir)
        .join("test-images")
}

/// Writes an RGBA8 image as PNG, creating the folder.
///
/// # Panics
/// When the file cannot be written (tests only).
pub fn write_png(path: &Path, pixels: &[[u8; 4]], width: u32, height: u32) {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)
            .unwrap_or_else(|e| panic!("cannot create {}: {e}", dir.display()));
    }
    let bytes: Vec<u8> = pixels.iter().flatten().copied().collect();
    image::save_buffer_with_format(
        path,
        &bytes,
        width,
        height,
        image::ExtendedColorType::Rgba8,
        image::ImageFormat::Png,
    )
    .unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
}

/// Reads an RGBA8 PNG: `None` when the file does not exist.
///
/// # Panics
/// When it exists but cannot be decoded.
#[must_use]
pub fn read_png(path: &Path) -> Option<(Vec<[u8; 4]>, u32, u32)> {
    if !path.exists() {
        return None;
    }
    let img = image::open(path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
        .to_rgba8();
    let (w, h) = img.dimensions();
    Some((img.pixels().map(|p| p.0).collect(), w, h))
}

/// The difference image: each channel's absolute difference times 8 (so small differences show),
/// and pixels over the tolerance outlined in pure red.
fn diff_image(actual: &[[u8; 4]], expected: &[[u8; 4]], per_channel: u8) -> Vec<[u8; 4]> {
    actual
        .iter()
        .zip(expected)
        .map(|(a, e)| {
            let d = [0, 1, 2].map(|c| a[c].abs_diff(e[c]));
            if d.iter().any(|&x| x > per_channel) {
                [255, 0, 0, 255]
            } else {
                [d[0].saturating_mul(8), d[1].saturating_mul(8), d[2].saturating_mul(8), 255]
            }
        })
        .collect()
}

/// Asserts that `actual` matches `expected` within `tolerance`; on failure writes
/// `<name>-actual.png`, `<name>-expected.png`, `<name>-diff.png` to [`output_dir`] and panics
/// with the measurements and the paths.
///
/// # Panics
/// When the images differ by more than the tolerance (or are not `width × height`).
pub fn assert_images_match(
    name: &str,
    actual: &[[u8; 4]],
    expected: &[[u8; 4]],
    width: u32,
    height: u32,
    tolerance: Tolerance,
) -> Comparison {
    assert_images_match_in(&output_dir(), name, actual, expected, width, height, tolerance)
}

/// [`assert_images_match`] writing its failure images to `dir`.
///
/// # Panics
/// As [`assert_images_match`].
pub fn assert_images_match_in(
    dir: &Path,
    name: &str,
    actual: &[[u8; 4]],
    expected: &[[u8; 4]],
    width: u32,
    height: u32,
    tolerance: Tolerance,
) -> Comparison {
    let c = compare(actual, expected, width, height, tolerance.per_channel);
    if c.fraction_over > tolerance.max_fraction {
        let path = |kind: &str| dir.join(format!("{name}-{kind}.png"));
        write_png(&path("actual"), actual, width, height);
        write_png(&path("expected"), expected, width, height);
        write_png(
            &path("diff"),
            &diff_image(actual, expected, tolerance.per_channel),
            width,
            height,
        );
        panic!(
            "image {name} differs: {:.3} % of pixels ({} of {}) differ by more than {}/255 (allowed: {:.3} %); \
             max difference {}/255, mean {:.3}/255.\n  actual:   {}\n  expected: {}\n  diff:     {}",
            100.0 * c.fraction_over,
            c.pixels_over,
            width as usize * height as usize,
            tolerance.per_channel,
            100.0 * tolerance.max_fraction,
            c.max_diff,
            c.mean_diff,
            path("actual").display(),
            path("expected").display(),
            path("diff").display()
        );
    }
    c
}

/// Asserts that `actual` matches the committed reference image at `reference` within
/// `tolerance` (see [`assert_images_match`]). A missing reference fails, unless the environment
/// has `CG_BLESS=1`: then `actual` is written as the new reference and the test passes.
///
/// # Panics
/// When the images differ, the reference has another size, or it is missing without a bless.
pub fn assert_matches_reference(
    reference: &Path,
    actual: &[[u8; 4]],
    width: u32,
    height: u32,
    tolerance: Tolerance,
) -> Option<Comparison> {
    let bless = std::env::var("CG_BLESS").is_ok_and(|v| v == "1");
    let name =
        reference.file_stem().map_or_else(|| "image".into(), |s| s.to_string_lossy().into_owned());
    match read_png(reference) {
        None if bless => {
            write_png(reference, actual, width, height);
            None
        }
        None => panic!(
            "reference image {} is missing: run the test with CG_BLESS=1 to create it, look at it, and commit it",
            reference.display()
        ),
        Some((expected, w, h)) => {
            if (w, h) != (width, height) {
                if bless {
                    write_png(reference, actual, width, height);
                    return None;
                }
                panic!(
                    "reference image {} is {w}×{h}, the actual image is {width}×{height}",
                    reference.display()
                );
            }
            Some(assert_images_match(&name, actual, &expected, width, height, tolerance))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn solid(n: usize, c: [u8; 4]) -> Vec<[u8; 4]> {
        vec![c; n]
    }

    #[test]
    fn compare_measures_max_mean_and_pixels_over() {
        let a = solid(4, [10, 10, 10, 255]);
        let mut e = a.clone();
        e[3] = [10, 13, 10, 255];
        let c = compare(&a, &e, 2, 2, 2);
        assert_eq!((c.max_diff, c.pixels_over), (3, 1));
        assert!((c.fraction_over - 0.25).abs() < 1e-12);
        assert!((c.mean_diff - 3.0 / 12.0).abs() < 1e-12);
        assert_eq!(compare(&a, &e, 2, 2, 3).pixels_over, 0);
    }

    #[test]
    fn a_failing_comparison_writes_three_images_and_says_where() {
        let dir = std::env::temp_dir().join(format!("cg-testkit-images-{}", std::process::id()));
        let a = solid(4, [0, 0, 0, 255]);
        let e = solid(4, [0, 40, 0, 255]);
        let result = std::panic::catch_unwind(|| {
            assert_images_match_in(&dir, "probe", &a, &e, 2, 2, Tolerance::percent_within(99.0, 2))
        });
        let message = *result.unwrap_err().downcast::<String>().unwrap();
        assert!(message.contains("100.000 % of pixels"), "{message}");
        for kind in ["actual", "expected", "diff"] {
            let p = dir.join(format!("probe-{kind}.png"));
            assert!(p.exists() && message.contains(&p.display().to_string()), "{kind}: {message}");
        }
        let (diff, _, _) = read_png(&dir.join("probe-diff.png")).unwrap();
        assert_eq!(diff[0], [255, 0, 0, 255], "pixels over the tolerance are red");
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_missing_reference_fails_without_a_bless() {
        let missing = std::env::temp_dir().join("cg-testkit-no-such-reference.png");
        let r = std::panic::catch_unwind(|| {
            assert_matches_reference(&missing, &[[0, 0, 0, 255]], 1, 1, Tolerance::all_within(0))
        });
        if std::env::var("CG_BLESS").is_ok_and(|v| v == "1") {
            std::fs::remove_file(&missing).ok();
            return;
        }
        let message = *r.unwrap_err().downcast::<String>().unwrap();
        assert!(message.contains("CG_BLESS=1"), "{message}");
        assert!(!missing.exists(), "no reference is created without a bless");
    }
}
