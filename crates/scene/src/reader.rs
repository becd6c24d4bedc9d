//! A strict reader over TOML's spanned document tree (`toml::de::DeTable`): every value knows its
//! span and its key path, so every mistake becomes a [`SceneError`] that names the file, the line
//! and column, and the key. Unknown keys are errors, with the closest known key suggested.

use std::ops::Range;
use std::path::Path;

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::math::try_normalize;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use crate::error::{ErrorKind, Expected, Found, Position, Rule, SceneError, closest};

/// The largest value of a colour channel (light colours, reflectances, the clear colour): 1e6.
/// Sums and products of such values (a light's colour times a reflectance, over a few hundred
/// lights and area-light samples, times the attenuation's cap of 1e6) stay far inside f32's
/// range, so no renderer meets ∞ or NaN from scene data.
pub(crate) const MAX_COLOR: f32 = 1.0e6;

/// The text being read and the file it came from.
pub(crate) struct Source<'a> {
    pub text: &'a str,
    pub file: &'a Path,
}

impl Source<'_> {
    /// Line and column (from 1, column in characters) of byte `offset`.
    pub fn position(&self, offset: usize) -> Position {
        let offset = offset.min(self.text.len());
        let before = self.text.as_bytes()[..offset].iter().rposition(|&b| b == b'\n');
        let line_start = before.map_or(0, |i| i + 1);
        let line = 1 + self.text.as_bytes()[..line_start].iter().filter(|&&b| b == b'\n').count();
        // `get` is None only if the span splits a character; count bytes then.
        let column = 1 + self
            .text
            .get(line_start..offset)
            .map_or(offset - line_start, |s| s.chars().count());
        Position { line, column }
    }

    /// An error at `span`, under key path `key` (empty: none).
    pub fn error(&self, span: &Range<usize>, key: &str, kind: ErrorKind) -> SceneError {
        SceneError {
            file: self.file.to_path_buf(),
            position: Some(self.position(span.start)),
            key: (!key.is_empty()).then(|| key.to_owned()),
            kind: Box::new(kind),
        }
    }

    /// The text of `span`, shortened for a message, invisible characters named.
    fn excerpt(&self, span: &Range<usize>) -> String {
        let s = self.text.get(span.clone()).unwrap_or("").trim();
        if s.chars().count() > 40 {
            format!("{}…", cg_core::quote::visible(&s.chars().take(40).collect::<String>()))
        } else {
            cg_core::quote::visible(s)
        }
    }
}

/// `parent.key`, with the key quoted when it is not a bare TOML key.
fn join(parent: &str, key: &str) -> String {
    let bare =
        !key.is_empty() && key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
    let key = if bare { key.to_owned() } else { format!("{key:?}") };
    if parent.is_empty() { key } else { format!("{parent}.{key}") }
}

/// Where a value was, to report problems found after reading (a missing OBJ file, a mesh
/// without texture coordinates).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct At {
    pub span: Range<usize>,
    pub key: String,
}

impl At {
    pub fn error(&self, src: &Source<'_>, kind: ErrorKind) -> SceneError {
        src.error(&self.span, &self.key, kind)
    }
}

/// One value of the document with its key path.
#[derive(Clone)]
pub(crate) struct Value<'a> {
    src: &'a Source<'a>,
    path: String,
    value: &'a Spanned<DeValue<'a>>,
}

/// A table of the document: keys are looked up by name; [`Table::only`] rejects the others.
pub(crate) struct Table<'a> {
    src: &'a Source<'a>,
    path: String,
    span: Range<usize>,
    map: &'a DeTable<'a>,
}

impl<'a> Table<'a> {
    /// The whole document.
    pub fn root(src: &'a Source<'a>, doc: &'a Spanned<DeTable<'a>>) -> Table<'a> {
        Table { src, path: String::new(), span: doc.span(), map: doc.get_ref() }
    }

    /// Where this table is, for errors found later.
    pub fn at(&self) -> At {
        At { span: self.span.clone(), key: self.path.clone() }
    }

    /// Rejects every key not in `allowed`: the first one in the file becomes
    /// [`ErrorKind::UnknownKey`], pointing at the key, with the closest allowed key suggested.
    pub fn only(&self, allowed: &[&'static str]) -> Result<(), SceneError> {
        let unknown = self
            .map
            .iter()
            .filter(|(k, _)| !allowed.contains(&k.get_ref().as_ref()))
            .min_by_key(|(k, _)| k.span().start);
        match unknown {
            None => Ok(()),
            Some((k, _)) => {
                let key: &str = k.get_ref();
                Err(self.src.error(
                    &k.span(),
                    &join(&self.path, key),
                    ErrorKind::UnknownKey {
                        key: key.to_owned(),
                        suggestion: closest(key, allowed.iter().copied()).map(str::to_owned),
                        allowed: allowed.to_vec(),
                    },
                ))
            }
        }
    }

    /// The value of `key`, if given.
    pub fn get(&self, key: &str) -> Option<Value<'a>> {
        self.map.get(key).map(|value| Value { src: self.src, path: join(&self.path, key), value })
    }

    /// Whether `key` is given.
    pub fn has(&self, key: &str) -> bool {
        self.map.contains_key(key)
    }

    /// The keys given, in file order.
    pub fn keys(&self) -> Vec<&'a str> {
        let mut keys: Vec<_> = self.map.keys().collect();
        keys.sort_by_key(|k| k.span().start);
        keys.into_iter().map(|k| k.get_ref().as_ref()).collect()
    }

    /// The entries, in file order.
    pub fn entries(&self) -> Vec<(&'a str, Value<'a>)> {
        self.keys().into_iter().filter_map(|k| Some((k, self.get(k)?))).collect()
    }

    /// The value of `key`, or [`ErrorKind::MissingKey`] pointing at this table.
    pub fn require(&self, key: &str) -> Result<Value<'a>, SceneError> {
        self.get(key).ok_or_else(|| self.error(ErrorKind::MissingKey { key: key.to_owned() }))
    }

    /// An error about this table as a whole.
    pub fn error(&self, kind: ErrorKind) -> SceneError {
        self.src.error(&self.span, &self.path, kind)
    }

    /// `key` read by `read`, or `default` when it is not given.
    pub fn or<T>(
        &self,
        key: &str,
        default: T,
        read: impl FnOnce(&Value<'a>) -> Result<T, SceneError>,
    ) -> Result<T, SceneError> {
        self.get(key).map_or(Ok(default), |v| read(&v))
    }

    /// `key` read by `read`, if given.
    pub fn optional<T>(
        &self,
        key: &str,
        read: impl FnOnce(&Value<'a>) -> Result<T, SceneError>,
    ) -> Result<Option<T>, SceneError> {
        self.get(key).map(|v| read(&v)).transpose()
    }
}

impl<'a> Value<'a> {
    /// Where this value is, for errors found later.
    pub fn at(&self) -> At {
        At { span: self.value.span(), key: self.path.clone() }
    }

    /// An error about this value.
    pub fn error(&self, kind: ErrorKind) -> SceneError {
        self.src.error(&self.value.span(), &self.path, kind)
    }

    /// The value as written in the file (shortened).
    pub fn written(&self) -> String {
        self.src.excerpt(&self.value.span())
    }

    /// [`ErrorKind::BadValue`] for this value, quoting it as written.
    pub fn bad(&self, rule: Rule) -> SceneError {
        self.error(ErrorKind::BadValue { rule, got: self.src.excerpt(&self.value.span()) })
    }

    fn found(&self) -> Found {
        match self.value.get_ref() {
            DeValue::String(_) => Found::String,
            DeValue::Integer(_) => Found::Integer,
            DeValue::Float(_) => Found::Float,
            DeValue::Boolean(_) => Found::Boolean,
            DeValue::Datetime(_) => Found::Datetime,
            DeValue::Array(a) => Found::Array { len: a.len() },
            DeValue::Table(_) => Found::Table,
        }
    }

    /// [`ErrorKind::WrongType`] for this value.
    pub fn wrong_type(&self, expected: Expected) -> SceneError {
        self.error(ErrorKind::WrongType { expected, found: self.found() })
    }

    /// An integer or a float, in f64 (integers beyond 2⁵³ round).
    fn number(&self) -> Result<f64, SceneError> {
        let parsed = match self.value.get_ref() {
            DeValue::Integer(i) => {
                i128::from_str_radix(i.as_str(), i.radix()).ok().map(|i| i as f64)
            }
            DeValue::Float(f) => f.as_str().parse::<f64>().ok(),
            _ => return Err(self.wrong_type(Expected::Number)),
        };
        parsed.ok_or_else(|| self.bad(Rule::Finite))
    }

    /// A number that satisfies `rule`, as f32 (a value that is finite in f64 but overflows f32
    /// fails [`Rule::Finite`] and the like).
    pub fn f32(&self, rule: Rule) -> Result<f32, SceneError> {
        let x = self.number()? as f32;
        if rule.accepts(f64::from(x)) { Ok(x) } else { Err(self.bad(rule)) }
    }

    /// An integer in `min..=max` (a float such as `10.0` is the wrong type).
    pub fn integer(&self, min: i64, max: i64) -> Result<i64, SceneError> {
        let DeValue::Integer(i) = self.value.get_ref() else {
            return Err(self.wrong_type(Expected::Integer));
        };
        match i64::from_str_radix(i.as_str(), i.radix()) {
            Ok(n) if (min..=max).contains(&n) => Ok(n),
            _ => Err(self.bad(Rule::Integer { min, max })),
        }
    }

    /// An integer in `min..=max`.
    pub fn u32(&self, min: u32, max: u32) -> Result<u32, SceneError> {
        // Fits u32: the range says so.
        self.integer(i64::from(min), i64::from(max)).map(|n| n as u32)
    }

    /// A string.
    pub fn str(&self) -> Result<&'a str, SceneError> {
        match self.value.get_ref() {
            DeValue::String(s) => Ok(s),
            _ => Err(self.wrong_type(Expected::String)),
        }
    }

    /// `true` or `false`.
    pub fn bool(&self) -> Result<bool, SceneError> {
        match self.value.get_ref() {
            DeValue::Boolean(b) => Ok(*b),
            _ => Err(self.wrong_type(Expected::Boolean)),
        }
    }

    /// A table (call [`Table::only`] on it).
    pub fn table(&self) -> Result<Table<'a>, SceneError> {
        match self.value.get_ref() {
            DeValue::Table(map) => {
                Ok(Table { src: self.src, path: self.path.clone(), span: self.value.span(), map })
            }
            _ => Err(self.wrong_type(Expected::Table)),
        }
    }

    /// Whether this value is a table.
    pub fn is_table(&self) -> bool {
        matches!(self.value.get_ref(), DeValue::Table(_))
    }

    /// Whether this value is `true` or `false`.
    pub fn is_bool(&self) -> bool {
        matches!(self.value.get_ref(), DeValue::Boolean(_))
    }

    /// Whether this value is an integer or a float.
    pub fn is_number(&self) -> bool {
        matches!(self.value.get_ref(), DeValue::Integer(_) | DeValue::Float(_))
    }

    /// Whether this value is a string.
    pub fn is_str(&self) -> bool {
        matches!(self.value.get_ref(), DeValue::String(_))
    }

    /// An array's elements, with paths `key[i]`; anything else is `expected`'s type error.
    pub fn array(&self, expected: Expected) -> Result<Vec<Value<'a>>, SceneError> {
        match self.value.get_ref() {
            DeValue::Array(items) => Ok(items
                .iter()
                .enumerate()
                .map(|(i, value)| Value {
                    src: self.src,
                    path: format!("{}[{i}]", self.path),
                    value,
                })
                .collect()),
            _ => Err(self.wrong_type(expected)),
        }
    }

    /// An array of exactly `N` elements, else `expected`'s type error.
    pub fn array_of<const N: usize>(
        &self,
        expected: Expected,
    ) -> Result<[Value<'a>; N], SceneError> {
        self.array(expected)?.try_into().map_err(|_| self.wrong_type(expected))
    }

    /// `[x, y, z]`, each finite.
    pub fn vec3(&self) -> Result<Vec3, SceneError> {
        let [x, y, z] = self.array_of(Expected::Vec3)?;
        Ok(Vec3::new(x.f32(Rule::Finite)?, y.f32(Rule::Finite)?, z.f32(Rule::Finite)?))
    }

    /// `[x, y, z]`, finite and not zero (a direction or an axis; returned as written).
    pub fn direction(&self) -> Result<Vec3, SceneError> {
        let v = self.vec3()?;
        try_normalize(v).map(|_| v).ok_or_else(|| self.bad(Rule::NonZeroVector))
    }

    /// `[r, g, b]`, each finite, ≥ 0 and at most [`MAX_COLOR`].
    pub fn color(&self) -> Result<Rgb, SceneError> {
        let [r, g, b] = self.array_of(Expected::Color)?;
        let channel = |v: Value<'a>| {
            let x = v.f32(Rule::NonNegative)?;
            if x <= MAX_COLOR { Ok(x) } else { Err(v.bad(Rule::AtMost { max: MAX_COLOR.into() })) }
        };
        Ok(Rgb::new(channel(r)?, channel(g)?, channel(b)?))
    }

    /// One of `choices` by its name, with the closest name suggested on a typo.
    pub fn choice<T: Copy>(&self, choices: &[(&'static str, T)]) -> Result<T, SceneError> {
        let DeValue::String(word) = self.value.get_ref() else {
            return Err(self.wrong_type(Expected::Choice));
        };
        let names = || choices.iter().map(|(name, _)| *name);
        choices.iter().find(|(name, _)| name == word).map(|&(_, t)| t).ok_or_else(|| {
            self.error(ErrorKind::UnknownChoice {
                value: word.to_string(),
                suggestion: closest(word, names()),
                allowed: names().collect(),
            })
        })
    }
}
