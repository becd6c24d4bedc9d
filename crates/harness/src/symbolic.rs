//! Naming the variables of a recorded product, for the report.
//!
//! The student's code runs once more at a *probe* — a mouse state (a2) or a frame (a3) where
//! every variable has a value of its own — and each factor parameter that equals a variable
//! there (or its negative; an angle also up to whole turns) is named after it
//! (`Rx(-camera_pitch)`, `Ry(theta_2)`), keeping the value it has at the stated state, so the
//! symbolic and the numeric product are the same matrix. Constants stay numbers; names the
//! student gave (`Param::sym`) are kept.

use cg_core::glam::Mat4;
use cg_core::product::{Factor, MatrixProduct, Param};
/// A variable and its value at the probe.
#[derive(Clone, Debug, PartialEq)]
pub struct Var {
    /// Its name (`camera_pitch`).
    pub name: String,
    /// Its value at the probe.
    pub value: f32,
}

/// Whether `x` is `v` within `1e-4` relative (absolute below 1).
fn close(x: f32, v: f32) -> bool {
    (x - v).abs() <= 1e-4 * v.abs().max(1.0)
}

/// Whether the angles `x` and `v` (degrees) differ by whole turns only.
fn close_turns(x: f32, v: f32) -> bool {
    let d = (f64::from(x) - f64::from(v)).rem_euclid(360.0);
    d <= 1e-3 || 360.0 - d <= 1e-3
}

/// The variable `x` is (`camera_pitch`) or is the negative of (`-camera_pitch`); an angle may
/// also differ by whole turns.
#[must_use]
pub fn match_var(x: f32, vars: &[Var], angle: bool) -> Option<String> {
    if !x.is_finite() {
        return None;
    }
    for v in vars {
        if close(x, v.value) {
            return Some(v.name.clone());
        }
        if close(x, -v.value) {
            return Some(format!("-{}", v.name));
        }
    }
    if angle {
        for v in vars {
            if close_turns(x, v.value) {
                return Some(v.name.clone());
            }
            if close_turns(x, -v.value) {
                return Some(format!("-{}", v.name));
            }
        }
    }
    None
}

/// Whether two factors are the same kind of call (translate, rotate about the same axis, …), so
/// that their parameters correspond.
fn same_kind(a: &Factor, b: &Factor) -> bool {
    match (a, b) {
        (Factor::Translate(_), Factor::Translate(_)) | (Factor::Scale(_), Factor::Scale(_)) => true,
        (Factor::Rotate { axis: x, .. }, Factor::Rotate { axis: y, .. }) => x == y,
        (Factor::Perspective { .. }, Factor::Perspective { .. }) => a == b,
        (Factor::Matrix { name: m, .. }, Factor::Matrix { name: n, .. }) => m == n,
        _ => false,
    }
}

/// Whether `a` and `b` are the same calls in the same order (their numbers may differ).
#[must_use]
pub fn aligned(a: &MatrixProduct, b: &MatrixProduct) -> bool {
    a.factors.len() == b.factors.len()
        && a.factors.iter().zip(&b.factors).all(|(x, y)| same_kind(x, y))
}

/// The symbols of a symbolized product, each with the variable it was found to be (`None`: a
/// name of the student's own that matches no variable).
pub type Names = Vec<(String, Option<String>)>;

/// `at` with each parameter named after the variable its counterpart in `probe` equals (the
/// value stays `at`'s); the student's own symbols are kept. `at` unchanged when the two are not
/// the same calls. Also returns every symbol used, sign stripped, with the variable it is.
#[must_use]
pub fn symbolize(
    probe: &MatrixProduct,
    at: &MatrixProduct,
    vars: &[Var],
) -> (MatrixProduct, Names) {
    let mut names: Names = Vec::new();
    let mut note = |symbol: &str, var: Option<String>| {
        let symbol = symbol.trim_start_matches('-').to_owned();
        let var = var.map(|v| v.trim_start_matches('-').to_owned());
        if !names.iter().any(|(s, _)| *s == symbol) {
            names.push((symbol, var));
        }
    };
    if !aligned(probe, at) {
        for f in &at.factors {
            for p in params(f) {
                if let Some(s) = &p.symbol {
                    note(s, None);
                }
            }
        }
        return (at.clone(), names);
    }
    let mut name = |p: &Param, a: &Param, angle: bool| -> Param {
        let found = match_var(p.value, vars, angle);
        match &a.symbol {
            Some(s) => {
                note(s, found);
                a.clone()
            }
            None => match found {
                Some(n) => {
                    note(&n, Some(n.clone()));
                    Param::sym(n, a.value)
                }
                None => Param::num(a.value),
            },
        }
    };
    let factors = probe
        .factors
        .iter()
        .zip(&at.factors)
        .map(|(p, a)| match (p, a) {
            (Factor::Translate(p), Factor::Translate(a)) => Factor::Translate([
                name(&p[0], &a[0], false),
                name(&p[1], &a[1], false),
                name(&p[2], &a[2], false),
            ]),
            (Factor::Scale(p), Factor::Scale(a)) => Factor::Scale([
                name(&p[0], &a[0], false),
                name(&p[1], &a[1], false),
                name(&p[2], &a[2], false),
            ]),
            (Factor::Rotate { angle_deg: p, .. }, Factor::Rotate { axis, angle_deg: a }) => {
                Factor::Rotate { axis: *axis, angle_deg: name(p, a, true) }
            }
            (_, other) => other.clone(),
        })
        .collect();
    (MatrixProduct { factors }, names)
}

/// A factor's parameters.
#[must_use]
pub fn params(f: &Factor) -> Vec<&Param> {
    match f {
        Factor::Translate(p) | Factor::Scale(p) => p.iter().collect(),
        Factor::Rotate { angle_deg, .. } => vec![angle_deg],
        Factor::Perspective { .. } | Factor::Matrix { .. } => Vec::new(),
    }
}

/// `p` with every parameter a plain number.
#[must_use]
pub fn numeric(p: &MatrixProduct) -> MatrixProduct {
    let num = |x: &Param| Param::num(x.value);
    let factors = p
        .factors
        .iter()
        .map(|f| match f {
            Factor::Translate(p) => Factor::Translate([num(&p[0]), num(&p[1]), num(&p[2])]),
            Factor::Scale(p) => Factor::Scale([num(&p[0]), num(&p[1]), num(&p[2])]),
            Factor::Rotate { axis, angle_deg } => {
                Factor::Rotate { axis: *axis, angle_deg: num(angle_deg) }
            }
            other => other.clone(),
        })
        .collect();
    MatrixProduct { factors }
}

/// Drops the factors that are the identity in every one of `products` (a translation by the
/// target that stays at the origin), when all are the same calls; otherwise changes nothing.
pub fn drop_constant_identities(products: &mut [MatrixProduct]) {
    let Some(first) = products.first() else { return };
    if !products.iter().all(|p| aligned(first, p)) {
        return;
    }
    let keep: Vec<bool> = (0..first.factors.len())
        .map(|k| !products.iter().all(|p| p.factors[k].is_identity()))
        .collect();
    for p in products.iter_mut() {
        let factors = std::mem::take(&mut p.factors);
        p.factors = factors.into_iter().zip(&keep).filter(|(_, k)| **k).map(|(f, _)| f).collect();
    }
}

/// Whether two matrices agree entry by entry within `1e-4 · (1 + |b|)`.
#[must_use]
pub fn matrices_close(a: &Mat4, b: &Mat4) -> bool {
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array().iter())
        .all(|(x, y)| (x - y).abs() <= 1e-4 * (1.0 + y.abs()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_core::gl::Gl;

    // --- naming the variables -------------------------------------------------------------

    #[test]
    fn symbols_name_variables_keep_constants_and_evaluate_to_the_numbers() {
        let vars = [
            Var { name: "camera_pitch".into(), value: -23.0 },
            Var { name: "camera_distance".into(), value: 13.5 },
        ];
        let record = |pitch: f32, distance: f32| {
            let mut gl = Gl::new();
            gl.translate(0.0, 0.0, -distance);
            gl.rotate(-pitch, 1.0, 0.0, 0.0);
            gl.rotate(pitch.to_radians(), 0.0, 1.0, 0.0); // radians: matches no variable
            gl.translate(0.0, 1.0, 0.0);
            gl.model_view().clone()
        };
        let probe = record(-23.0, 13.5);
        let at = record(-30.0, 15.0);
        let (s, names) = symbolize(&probe, &at, &vars);
        assert_eq!(
            s.symbolic(),
            "T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-0.5236°) · T(0, 1, 0)"
        );
        assert_eq!(s.matrix().unwrap(), at.matrix().unwrap());
        assert_eq!(
            names,
            vec![
                ("camera_distance".to_owned(), Some("camera_distance".to_owned())),
                ("camera_pitch".to_owned(), Some("camera_pitch".to_owned()))
            ]
        );
        // An angle a whole turn off is still the variable.
        let turned = Param::num(337.0);
        assert_eq!(match_var(turned.value, &vars, true).as_deref(), Some("camera_pitch"));
        assert_eq!(match_var(turned.value, &vars, false), None);
        // Not the same calls: the product stays as recorded.
        let other = MatrixProduct::identity().then(Factor::rotate_x_deg(30.0));
        assert_eq!(symbolize(&probe, &other, &vars).0, other);
    }
}
