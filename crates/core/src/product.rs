//! A transform written as a *product of named factors*, as the report asks:
//! `T(0, 0, -15) · Rx(30°) · T(0, 1, 0)`, symbolically (`Rx(-camera_pitch)`), numerically, as the
//! 4×4 matrices side by side, and as LaTeX `pmatrix`.
//!
//! Factors are listed in the order a program calls glTranslatef / glRotatef / glScalef, so the
//! product is `F₀ · F₁ · … · Fₖ` and the last factor acts on the vertices first.

use std::fmt;

use glam::{Mat4, Vec3};

use cg_student::product as student;

use crate::transform::{self, TransformError};

/// A number in a factor: its value and, optionally, the variable it stands for in the report
/// (`-camera_pitch`, `theta_cycle`, `camera_distance`).
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// The value (degrees for angles, scene units for lengths).
    pub value: f32,
    /// The symbol printed by the symbolic forms; `None` prints the value there too.
    pub symbol: Option<String>,
}

/// The axis of a rotation factor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Axis {
    /// Rx
    X,
    /// Ry
    Y,
    /// Rz
    Z,
    /// R(axis), glRotatef's general form; the axis need not be unit length but must be non-zero.
    Any(Vec3),
}

/// One factor of a [`MatrixProduct`].
#[derive(Clone, Debug, PartialEq)]
pub enum Factor {
    /// T(x, y, z) — glTranslatef.
    Translate([Param; 3]),
    /// R(angle) about an axis, angle in degrees, counter-clockwise looking down the axis towards
    /// the origin — glRotatef.
    Rotate {
        /// The axis.
        axis: Axis,
        /// The angle in degrees.
        angle_deg: Param,
    },
    /// S(x, y, z) — glScalef.
    Scale([Param; 3]),
    /// P(fovy, aspect, near, far) — gluPerspective, with depth mapped to `[0, 1]` (wgpu) or, when
    /// `gl_depth`, to `[-1, 1]` (OpenGL).
    Perspective {
        /// Vertical field of view in degrees.
        fovy_deg: f32,
        /// Width / height.
        aspect: f32,
        /// Near plane distance (> 0).
        near: f32,
        /// Far plane distance (> near).
        far: f32,
        /// `true`: OpenGL's `[-1, 1]` depth; `false`: wgpu's `[0, 1]`.
        gl_depth: bool,
    },
    /// Any matrix, printed by name (`M`, `V`, `LookAt`).
    Matrix {
        /// The name printed in products (`V`, `LookAt`).
        name: String,
        /// The matrix.
        matrix: Mat4,
    },
}

/// A product of named factors, left to right in program order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MatrixProduct {
    /// The factors, leftmost first.
    pub factors: Vec<Factor>,
}

impl Param {
    /// A plain number, printed as itself in both the symbolic and the numeric form.
    #[must_use]
    pub fn num(value: f32) -> Param {
        Param { value, symbol: None }
    }

    /// A number that the symbolic form prints as `symbol` (`Param::sym("-camera_pitch", 30.0)`).
    #[must_use]
    pub fn sym(symbol: impl Into<String>, value: f32) -> Param {
        Param { value, symbol: Some(symbol.into()) }
    }

    /// The symbol when `symbolic` and one is present, the number otherwise.
    fn text(&self, symbolic: bool, unit: &str) -> String {
        match &self.symbol {
            Some(s) if symbolic => s.clone(),
            _ => format!("{}{unit}", format_number(self.value)),
        }
    }
}

/// A number as the report prints it: integers without decimals (`15`, `-15`), other values with
/// at most 4 decimals and no trailing zeros (`0.4856`, `-0.8`), `-0` (and anything that rounds to
/// it) as `0`, non-finite values as `NaN`, `inf`, `-inf`. Never panics.
///
/// Every number inside a printed matrix product goes through here. (Vertex and normal tables
/// use the lecture's notation instead, with at least one decimal: [`crate::notation::decimal`].)
#[must_use]
pub fn format_number(x: f32) -> String {
    if x.is_nan() {
        return "NaN".to_owned();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.to_owned();
    }
    if x == 0.0 {
        return "0".to_owned();
    }
    if x.fract() == 0.0 {
        // The shortest digits that round-trip: 15, -15, 100000000000000000000.
        return format!("{x}");
    }
    let s = crate::notation::fixed(x, 4);
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// `x` as a LaTeX matrix entry: [`format_number`], with `\infty` and `\mathrm{NaN}` for
/// non-finite values.
fn latex_number(x: f32) -> String {
    match format_number(x).as_str() {
        "NaN" => r"\mathrm{NaN}".to_owned(),
        "inf" => r"\infty".to_owned(),
        "-inf" => r"-\infty".to_owned(),
        s => s.to_owned(),
    }
}

/// Escapes the characters that LaTeX treats specially (`_` → `\_`, …) in a symbol.
fn latex_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for ch in s.chars() {
        match ch {
            '_' | '%' | '&' | '#' | '$' | '{' | '}' => {
                out.push('\\');
                out.push(ch);
            }
            '\\' => out.push_str(r"\backslash{}"),
            '^' => out.push_str(r"\hat{}"),
            '~' => out.push_str(r"\sim{}"),
            _ => out.push(ch),
        }
    }
    out
}

/// The Greek letters a symbol may be named after (`theta` → `\theta`).
const GREEK: [&str; 12] = [
    "alpha", "beta", "gamma", "delta", "theta", "phi", "psi", "omega", "lambda", "mu", "rho", "tau",
];

/// A symbol in LaTeX math: Greek names as letters (`theta` → `\theta`, `theta_1` →
/// `\theta_{1}`), one-letter names with a short index as they are (`x_n` → `x_{n}`), longer
/// names upright-italic as one word (`camera_pitch` → `\mathit{camera\_pitch}`), so TeX does
/// not set them as a product of letters. A leading `-` stays a sign.
fn latex_symbol(s: &str) -> String {
    let (sign, body) = s.strip_prefix('-').map_or(("", s), |b| ("-", b));
    let letter = |name: &str| {
        if GREEK.contains(&name) {
            Some(format!("\\{name}"))
        } else if name.chars().count() == 1 && name.chars().all(|c| c.is_ascii_alphabetic()) {
            Some(name.to_owned())
        } else {
            None
        }
    };
    let short_index =
        |t: &str| !t.is_empty() && t.len() <= 2 && t.chars().all(|c| c.is_ascii_alphanumeric());
    let out = match body.split_once('_') {
        _ if letter(body).is_some() => letter(body).unwrap_or_default(),
        Some((head, tail)) if short_index(tail) && letter(head).is_some() => {
            format!("{}_{{{tail}}}", letter(head).unwrap_or_default())
        }
        Some((head, tail))
            if GREEK.contains(&head) && tail.chars().all(|c| c.is_ascii_alphanumeric()) =>
        {
            format!("\\{head}_{{\\mathrm{{{tail}}}}}")
        }
        _ => format!("\\mathit{{{}}}", latex_escape(body)),
    };
    format!("{sign}{out}")
}

impl Factor {
    /// T(v), glTranslatef(v.x, v.y, v.z), with plain numbers.
    #[must_use]
    pub fn translate(v: Vec3) -> Factor {
        student::Factor::translate(v).into()
    }

    /// S(v), glScalef(v.x, v.y, v.z), with plain numbers.
    #[must_use]
    pub fn scale(v: Vec3) -> Factor {
        student::Factor::scale(v).into()
    }

    /// R(angle) about `axis`, with the angle in degrees as a [`Param`] (for symbols).
    #[must_use]
    pub fn rotate(axis: Axis, angle_deg: Param) -> Factor {
        Factor::Rotate { axis, angle_deg }
    }

    /// Rx(angle_deg), glRotatef(angle_deg, 1, 0, 0).
    #[must_use]
    pub fn rotate_x_deg(angle_deg: f32) -> Factor {
        student::Factor::rotate_x_deg(angle_deg).into()
    }

    /// Ry(angle_deg), glRotatef(angle_deg, 0, 1, 0).
    #[must_use]
    pub fn rotate_y_deg(angle_deg: f32) -> Factor {
        student::Factor::rotate_y_deg(angle_deg).into()
    }

    /// Rz(angle_deg), glRotatef(angle_deg, 0, 0, 1).
    #[must_use]
    pub fn rotate_z_deg(angle_deg: f32) -> Factor {
        student::Factor::rotate_z_deg(angle_deg).into()
    }

    /// R(angle_deg, axis), glRotatef(angle_deg, x, y, z). An axis along +X, +Y or +Z (any
    /// positive finite length) becomes [`Axis::X`], [`Axis::Y`] or [`Axis::Z`], so
    /// `glRotatef(30, 1, 0, 0)` prints as `Rx(30°)` (the matrix is the same, entry for entry).
    /// Other axes are kept as given and checked by [`Factor::matrix`], not here.
    #[must_use]
    pub fn rotate_deg(angle_deg: f32, axis: Vec3) -> Factor {
        // One rule for the kit and the students' recorder: cg_student's.
        student::Factor::rotate_deg(angle_deg, axis).into()
    }

    /// P(fovy, aspect, near, far) with wgpu's `[0, 1]` depth; checked by [`Factor::matrix`].
    #[must_use]
    pub fn perspective(fovy_deg: f32, aspect: f32, near: f32, far: f32) -> Factor {
        student::Factor::perspective(fovy_deg, aspect, near, far).into()
    }

    /// P(fovy, aspect, near, far) with OpenGL's `[-1, 1]` depth (gluPerspective's matrix).
    #[must_use]
    pub fn perspective_gl(fovy_deg: f32, aspect: f32, near: f32, far: f32) -> Factor {
        student::Factor::perspective_gl(fovy_deg, aspect, near, far).into()
    }

    /// Any matrix, printed as `name` in products.
    #[must_use]
    pub fn named(name: impl Into<String>, matrix: Mat4) -> Factor {
        Factor::Matrix { name: name.into(), matrix }
    }

    /// This factor's 4×4 matrix, built with [`crate::transform`]'s builders (rotations in exact
    /// degrees).
    ///
    /// # Errors
    /// [`TransformError::NotFinite`] for a non-finite translation, scale or angle;
    /// [`TransformError::RotationAxis`] for a zero or non-finite axis; the perspective errors of
    /// [`transform::perspective`]; [`TransformError::MatrixNotFinite`] for a named matrix with a
    /// non-finite entry.
    pub fn matrix(&self) -> Result<Mat4, TransformError> {
        let finite = |what: &'static str, p: &Param| {
            if p.value.is_finite() {
                Ok(p.value)
            } else {
                Err(TransformError::NotFinite { what, value: p.value })
            }
        };
        let vec3 = |what: &'static str, p: &[Param; 3]| -> Result<Vec3, TransformError> {
            Ok(Vec3::new(finite(what, &p[0])?, finite(what, &p[1])?, finite(what, &p[2])?))
        };
        match self {
            Factor::Translate(p) => Ok(transform::translate(vec3("translation", p)?)),
            Factor::Scale(p) => Ok(transform::scale(vec3("scale", p)?)),
            Factor::Rotate { axis, angle_deg } => {
                let a = finite("rotation angle", angle_deg)?;
                match axis {
                    Axis::X => Ok(transform::rotate_x_deg(a)),
                    Axis::Y => Ok(transform::rotate_y_deg(a)),
                    Axis::Z => Ok(transform::rotate_z_deg(a)),
                    Axis::Any(v) => transform::rotate_deg(a, *v),
                }
            }
            &Factor::Perspective { fovy_deg, aspect, near, far, gl_depth } => {
                if gl_depth {
                    transform::perspective_gl(fovy_deg, aspect, near, far)
                } else {
                    transform::perspective(fovy_deg, aspect, near, far)
                }
            }
            Factor::Matrix { name, matrix } => {
                match matrix.to_cols_array().into_iter().find(|x| !x.is_finite()) {
                    Some(value) => {
                        Err(TransformError::MatrixNotFinite { name: name.clone(), value })
                    }
                    None => Ok(*matrix),
                }
            }
        }
    }

    /// Whether this factor's matrix is exactly the identity: T(0, 0, 0), R(0°) (or any multiple
    /// of 360°), S(1, 1, 1), a named identity matrix. An invalid factor is not the identity.
    #[must_use]
    pub fn is_identity(&self) -> bool {
        self.matrix().is_ok_and(|m| m == Mat4::IDENTITY)
    }

    /// The factor's name in the report's notation: `T(0, 0, -15)`, `Rx(30°)`,
    /// `R(30°, 1, 1, 0)`, `S(2, 2, 2)`, `P(45°, 1, 1, 500)` (`P_gl(…)` for `[-1, 1]` depth), or the
    /// name of a [`Factor::Matrix`]. With `symbolic`, parameters print their symbol where present.
    #[must_use]
    pub fn label(&self, symbolic: bool) -> String {
        let three = |p: &[Param; 3]| {
            format!(
                "{}, {}, {}",
                p[0].text(symbolic, ""),
                p[1].text(symbolic, ""),
                p[2].text(symbolic, "")
            )
        };
        match self {
            Factor::Translate(p) => format!("T({})", three(p)),
            Factor::Scale(p) => format!("S({})", three(p)),
            Factor::Rotate { axis, angle_deg } => {
                let a = angle_deg.text(symbolic, "°");
                match axis {
                    Axis::X => format!("Rx({a})"),
                    Axis::Y => format!("Ry({a})"),
                    Axis::Z => format!("Rz({a})"),
                    Axis::Any(v) => format!(
                        "R({a}, {}, {}, {})",
                        format_number(v.x),
                        format_number(v.y),
                        format_number(v.z)
                    ),
                }
            }
            &Factor::Perspective { fovy_deg, aspect, near, far, gl_depth } => format!(
                "{}({}°, {}, {}, {})",
                if gl_depth { "P_gl" } else { "P" },
                format_number(fovy_deg),
                format_number(aspect),
                format_number(near),
                format_number(far)
            ),
            Factor::Matrix { name, .. } => name.clone(),
        }
    }

    /// The factor in LaTeX: a `pmatrix` with symbolic entries (`\cos(-\mathit{camera\_pitch})`) where a
    /// parameter has a symbol and `symbolic` is set, numbers elsewhere. A rotation about a general
    /// axis by a symbolic angle has no short closed form and prints as `R_{(x, y, z)}(θ)`.
    fn latex(&self, symbolic: bool) -> Result<String, TransformError> {
        let mut rows = rows_of(self.matrix()?, latex_number);
        let sym = |p: &Param| match &p.symbol {
            Some(s) if symbolic => Some(latex_symbol(s)),
            _ => None,
        };
        match self {
            Factor::Translate(p) => {
                for (i, p) in p.iter().enumerate() {
                    if let Some(s) = sym(p) {
                        rows[i][3] = s;
                    }
                }
            }
            Factor::Scale(p) => {
                for (i, p) in p.iter().enumerate() {
                    if let Some(s) = sym(p) {
                        rows[i][i] = s;
                    }
                }
            }
            Factor::Rotate { axis, angle_deg } => {
                if let Some(s) = sym(angle_deg) {
                    let (i, j) = match axis {
                        Axis::X => (1, 2),
                        Axis::Y => (2, 0),
                        Axis::Z => (0, 1),
                        Axis::Any(v) => {
                            let (x, y, z) =
                                (latex_number(v.x), latex_number(v.y), latex_number(v.z));
                            return Ok(format!("R_{{({x}, {y}, {z})}}({s})"));
                        }
                    };
                    // The (i, j) plane turns counter-clockwise: rows i = (c, −s), j = (s, c).
                    rows[i][i] = format!(r"\cos({s})");
                    rows[i][j] = format!(r"-\sin({s})");
                    rows[j][i] = format!(r"\sin({s})");
                    rows[j][j] = format!(r"\cos({s})");
                }
            }
            Factor::Perspective { .. } | Factor::Matrix { .. } => {}
        }
        Ok(pmatrix(&rows))
    }
}

impl fmt::Display for Factor {
    /// The numeric label, `Rx(30°)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label(false))
    }
}

/// `\begin{pmatrix} a & b & c & d \\ … \end{pmatrix}` for rows of entries.
fn pmatrix(rows: &[[String; 4]; 4]) -> String {
    let body: Vec<String> = rows.iter().map(|r| r.join(" & ")).collect();
    format!("\\begin{{pmatrix}} {} \\end{{pmatrix}}", body.join(r" \\ "))
}

/// The rows of `m` (students read rows; glam stores columns), each entry printed by `print`.
fn rows_of(m: Mat4, print: fn(f32) -> String) -> [[String; 4]; 4] {
    m.transpose().to_cols_array_2d().map(|r| r.map(print))
}

/// A matrix as text lines, `| 1  0  0  -15 |`, each column right-aligned.
fn text_block(m: Mat4) -> Vec<String> {
    let rows = rows_of(m, format_number);
    let widths: Vec<usize> =
        (0..4).map(|c| rows.iter().map(|r| r[c].chars().count()).max().unwrap_or(1)).collect();
    rows.iter()
        .map(|r| {
            let cells: Vec<String> =
                r.iter().zip(&widths).map(|(x, w)| format!("{x:>w$}")).collect();
            format!("| {} |", cells.join("  "))
        })
        .collect()
}

impl MatrixProduct {
    /// The empty product: the identity.
    #[must_use]
    pub fn identity() -> MatrixProduct {
        MatrixProduct { factors: Vec::new() }
    }

    /// This product times `factor` on the right (the next glTranslatef/glRotatef call).
    #[must_use]
    pub fn then(mut self, factor: Factor) -> MatrixProduct {
        self.factors.push(factor);
        self
    }

    /// Appends `factor` on the right, in place.
    pub fn push(&mut self, factor: Factor) {
        self.factors.push(factor);
    }

    /// `self · other`: the factors of `self`, then those of `other`.
    #[must_use]
    pub fn concat(&self, other: &MatrixProduct) -> MatrixProduct {
        MatrixProduct { factors: self.factors.iter().chain(&other.factors).cloned().collect() }
    }

    /// The product `F₀ · F₁ · … · Fₖ`, multiplied left to right in f32 (as the matrix stack does,
    /// so a stack's top equals its product's matrix exactly). The empty product is the identity.
    ///
    /// # Errors
    /// [`TransformError::InFactor`] with the index of the first invalid factor and its error;
    /// [`TransformError::Overflow`] when valid factors multiply out of f32's range.
    pub fn matrix(&self) -> Result<Mat4, TransformError> {
        let m = self.factors.iter().enumerate().try_fold(Mat4::IDENTITY, |acc, (index, f)| {
            f.matrix()
                .map(|m| acc * m)
                .map_err(|e| TransformError::InFactor { index, source: Box::new(e) })
        })?;
        // Valid factors can still multiply out of f32's range (a scale of 3e38 times a
        // translation of 3e38): an error, never a matrix of infinities and NaNs.
        if m.is_finite() { Ok(m) } else { Err(TransformError::Overflow { what: "the product" }) }
    }

    /// The same product without its identity factors ([`Factor::is_identity`]): for the course
    /// camera (yaw 0) `T(0, 0, -15) · Rx(30°) · Ry(0°) · T(0, 1, 0)` becomes
    /// `T(0, 0, -15) · Rx(30°) · T(0, 1, 0)`. The matrix is unchanged.
    #[must_use]
    pub fn simplified(&self) -> MatrixProduct {
        MatrixProduct {
            factors: self.factors.iter().filter(|f| !f.is_identity()).cloned().collect(),
        }
    }

    fn labels(&self, symbolic: bool) -> String {
        if self.factors.is_empty() {
            return "I".to_owned();
        }
        let labels: Vec<String> = self.factors.iter().map(|f| f.label(symbolic)).collect();
        labels.join(" · ")
    }

    /// The product with symbols where present:
    /// `T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw) · T(0, 1, 0)`.
    /// The empty product prints as `I`.
    #[must_use]
    pub fn symbolic(&self) -> String {
        self.labels(true)
    }

    /// The product with numbers: `T(0, 0, -15) · Rx(30°) · Ry(0°) · T(0, 1, 0)`.
    /// The empty product prints as `I`.
    #[must_use]
    pub fn numeric(&self) -> String {
        self.labels(false)
    }

    /// Each factor's 4×4 matrix by rows, side by side under its label, joined by `·`, then `=`
    /// and the product:
    ///
    /// ```text
    /// T(1, 2, 3)         S(2, 2, 2)
    /// | 1  0  0  1 |     | 2  0  0  0 |     | 2  0  0  1 |
    /// | 0  1  0  2 |  ·  | 0  2  0  0 |  =  | 0  2  0  2 |
    /// | 0  0  1  3 |     | 0  0  2  0 |     | 0  0  2  3 |
    /// | 0  0  0  1 |     | 0  0  0  1 |     | 0  0  0  1 |
    /// ```
    ///
    /// Lines carry no trailing spaces. The empty product prints the identity alone.
    ///
    /// # Errors
    /// As [`MatrixProduct::matrix`].
    pub fn matrices_text(&self) -> Result<String, TransformError> {
        let product = self.matrix()?;
        let mut blocks: Vec<(String, Vec<String>)> = Vec::new();
        for f in &self.factors {
            blocks.push((f.label(false), text_block(f.matrix()?)));
        }
        let mut lines = vec![String::new(); 5];
        for (k, (label, block)) in blocks.iter().enumerate() {
            let width = block[0].chars().count();
            let op = if k + 1 == blocks.len() { "=" } else { "·" };
            let pad = label.chars().count().max(width);
            lines[0].push_str(&format!("{label:<pad$}     "));
            for (r, row) in block.iter().enumerate() {
                let sep = if r == 1 { op } else { " " };
                lines[r + 1].push_str(&format!("{row:<pad$}  {sep}  "));
            }
        }
        for (r, row) in text_block(product).iter().enumerate() {
            lines[r + 1].push_str(row);
        }
        let lines: Vec<&str> = lines.iter().map(|l| l.trim_end()).collect();
        let start = usize::from(lines[0].is_empty());
        Ok(lines[start..].join("\n"))
    }

    /// The product in LaTeX, each factor as a `pmatrix` in program order (juxtaposed, as in the
    /// lecture's slides), one per line. With `symbolic`, parameters with a symbol appear as
    /// `\cos(-\mathit{camera\_pitch})`, `-\sin(…)`, `-\mathit{camera\_distance}` (`_` and other specials escaped);
    /// a rotation about a general axis by a symbolic angle appears as `R_{(x, y, z)}(θ)`.
    /// Without `symbolic`, every factor is numeric and the last line is `= ` and the product's
    /// `pmatrix`. Meant for a math environment (`$$ … $$`, `\[ … \]`).
    ///
    /// # Errors
    /// As [`MatrixProduct::matrix`].
    pub fn latex(&self, symbolic: bool) -> Result<String, TransformError> {
        let product = self.matrix()?;
        let mut parts =
            self.factors.iter().map(|f| f.latex(symbolic)).collect::<Result<Vec<_>, _>>()?;
        if self.factors.is_empty() {
            parts.push(pmatrix(&rows_of(product, latex_number)));
        } else if !symbolic {
            parts.push(format!("= {}", pmatrix(&rows_of(product, latex_number))));
        }
        Ok(parts.join("\n"))
    }
}

impl fmt::Display for MatrixProduct {
    /// The numeric form, [`MatrixProduct::numeric`].
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.numeric())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symbols_print_as_math_names() {
        assert_eq!(latex_symbol("theta"), "\\theta");
        assert_eq!(latex_symbol("-theta_1"), "-\\theta_{1}");
        assert_eq!(latex_symbol("x_n"), "x_{n}");
        assert_eq!(latex_symbol("t"), "t");
        assert_eq!(latex_symbol("theta_cycle"), "\\theta_{\\mathrm{cycle}}");
        assert_eq!(latex_symbol("-camera_pitch"), "-\\mathit{camera\\_pitch}");
        assert_eq!(latex_symbol("thetas_longname"), "\\mathit{thetas\\_longname}");
        let p = MatrixProduct::identity()
            .then(Factor::rotate(Axis::X, Param::sym("camera_pitch", 30.0)));
        assert!(p.latex(true).unwrap().contains("\\cos(\\mathit{camera\\_pitch})"));
    }
}
