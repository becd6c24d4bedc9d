//! The grading config: how many points each check is worth.
//!
//! ```toml
//! # Points for a check that no rule below names (default 1).
//! default = 1
//!
//! [points]
//! # By assignment, by task, or by check ID: the longest matching prefix wins.
//! a1 = 2
//! "a1.t3" = 3
//! "a1.t3.unit" = 5
//!
//! [totals]
//! # What an assignment is worth in all, whatever the number of its checks in the student's
//! # variant (a2 with panning has two checks more): its checks' points above are then weights.
//! a2 = 20
//! ```
//!
//! Prefixes match whole dot-separated parts: `a1` names `a1.t2.closed` but not `a10.t1.x`.
//! Quote keys with dots: TOML reads an unquoted `a1.t3 = 3` as a table `a1`, which works only
//! when `a1` has no number of its own.

use std::collections::BTreeMap;

use cg_core::lang::{Lang, Text};

/// Points per check.
#[derive(Clone, Debug, PartialEq)]
pub struct Config {
    /// Points of a check no rule names.
    pub default_points: f64,
    /// Points by check-ID prefix (`a1`, `a1.t3`, `a1.t3.unit`).
    pub points: BTreeMap<String, f64>,
    /// What an assignment is worth in all (`a2` → 20): its checks share it in proportion to
    /// their [`Config::points`], so every student's assignment weighs the same whatever the
    /// number of checks in their variant.
    pub totals: BTreeMap<String, f64>,
}

impl Default for Config {
    fn default() -> Config {
        Config { default_points: 1.0, points: BTreeMap::new(), totals: BTreeMap::new() }
    }
}

/// Why a config could not be read, in both languages.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct ConfigError(pub Text);

impl ConfigError {
    fn new(ja: impl Into<String>, en: impl Into<String>) -> ConfigError {
        ConfigError(Text::new(ja, en))
    }

    /// The message in `lang`.
    #[must_use]
    pub fn message(&self, lang: Lang) -> &str {
        self.0.get(lang)
    }
}

fn number(key: &str, value: &toml::Value) -> Result<f64, ConfigError> {
    #[allow(clippy::cast_precision_loss)]
    let n = match value {
        toml::Value::Integer(i) => *i as f64,
        toml::Value::Float(f) => *f,
        _ => f64::NAN,
    };
    if n.is_finite() && n >= 0.0 {
        Ok(n)
    } else {
        Err(ConfigError::new(
            format!("{key} = {value}: 点数は 0 以上の数にしてください"),
            format!("{key} = {value}: points must be a number, 0 or more"),
        ))
    }
}

fn flatten(
    prefix: &str,
    table: &toml::Table,
    out: &mut BTreeMap<String, f64>,
) -> Result<(), ConfigError> {
    for (key, value) in table {
        let full = if prefix.is_empty() { key.clone() } else { format!("{prefix}.{key}") };
        match value {
            toml::Value::Table(inner) => flatten(&full, inner, out)?,
            other => {
                out.insert(full.clone(), number(&full, other)?);
            }
        }
    }
    Ok(())
}

impl Config {
    /// Reads a config from TOML text.
    ///
    /// # Errors
    /// The text is not TOML, has keys other than `default`, `[points]` and `[totals]`, a
    /// `[totals]` key that is no assignment's ID, or a number that is negative or not a number.
    pub fn parse(text: &str) -> Result<Config, ConfigError> {
        let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
            let said = cg_core::toml_syntax::at(text, e.message(), e.span());
            ConfigError::new(
                format!("採点設定を読めません（TOML の構文エラー）: {}", said.ja),
                format!("the grading config is not valid TOML: {}", said.en),
            )
        })?;
        let mut config = Config::default();
        for (key, value) in &table {
            match (key.as_str(), value) {
                ("default", v) => config.default_points = number("default", v)?,
                ("points", toml::Value::Table(points)) => {
                    flatten("", points, &mut config.points)?;
                }
                ("totals", toml::Value::Table(totals)) => {
                    for (id, value) in totals {
                        if !cg_assign::IDS.contains(&id.as_str()) {
                            let ids = cg_assign::IDS.join(", ");
                            return Err(ConfigError::new(
                                format!(
                                    "採点設定の [totals] の {} は課題の ID ではありません（{ids} のどれか）",
                                    cg_core::quote::visible(id)
                                ),
                                format!(
                                    "{} in the grading config's [totals] is no assignment's ID (one of {ids})",
                                    cg_core::quote::visible(id)
                                ),
                            ));
                        }
                        config.totals.insert(id.clone(), number(&format!("totals.{id}"), value)?);
                    }
                }
                _ => {
                    return Err(ConfigError::new(
                        format!(
                            "採点設定の {key} は使えません（default、[points]、[totals] のみ）"
                        ),
                        format!(
                            "unknown key {key} in the grading config (only default, [points] and [totals])"
                        ),
                    ));
                }
            }
        }
        Ok(config)
    }

    /// The points check `id` is worth: the rule with the longest prefix of `id` (whole
    /// dot-separated parts), else the default.
    #[must_use]
    pub fn points(&self, id: &str) -> f64 {
        let mut best: Option<(usize, f64)> = None;
        for (prefix, &points) in &self.points {
            let matches = id == prefix
                || id.strip_prefix(prefix.as_str()).is_some_and(|rest| rest.starts_with('.'));
            if matches && best.is_none_or(|(len, _)| prefix.len() > len) {
                best = Some((prefix.len(), points));
            }
        }
        best.map_or(self.default_points, |(_, p)| p)
    }

    /// The factor that makes the checks `ids` of `assignment` (one student's run) sum to the
    /// assignment's `[totals]` entry; 1 without one, or when the checks are worth nothing.
    #[must_use]
    pub fn scale<'a>(&self, assignment: &str, ids: impl IntoIterator<Item = &'a str>) -> f64 {
        let Some(&total) = self.totals.get(assignment) else { return 1.0 };
        let raw: f64 = ids.into_iter().map(|id| self.points(id)).sum();
        if raw > 0.0 { total / raw } else { 1.0 }
    }

    /// Whether every rule of `[points]` names a check of `ids` (the kit's check IDs) or a prefix
    /// of one: a rule that names none (`a1.t9`, a typo) would give its points to nothing, and
    /// every check it was meant for would get the default, without a word.
    ///
    /// # Errors
    /// The rules that name no check (at most five, then a count), with the assignments' IDs.
    pub fn check_names<'a>(
        &self,
        ids: impl IntoIterator<Item = &'a str> + Clone,
    ) -> Result<(), ConfigError> {
        let names = |prefix: &str| {
            ids.clone().into_iter().any(|id| {
                id == prefix || id.strip_prefix(prefix).is_some_and(|rest| rest.starts_with('.'))
            })
        };
        let unknown: Vec<&str> =
            self.points.keys().map(String::as_str).filter(|k| !names(k)).collect();
        if unknown.is_empty() {
            return Ok(());
        }
        let mut list: Vec<String> =
            unknown.iter().take(5).map(|k| cg_core::quote::visible(k)).collect();
        if unknown.len() > 5 {
            list.push(format!("… (+{})", unknown.len() - 5));
        }
        let list = list.join(", ");
        Err(ConfigError::new(
            format!(
                "採点設定の [points] に、どのチェックも指さない規則があります: {list}（課題・タスク・チェックの ID か、その先頭の部分を書きます。例: a1、\"a1.t3\"、\"a1.t3.unit\"。ID は cg check の表示にあります）"
            ),
            format!(
                "the grading config's [points] has rules that name no check: {list} (name an assignment, a task or a check by its ID, or the start of one: a1, \"a1.t3\", \"a1.t3.unit\"; cg check shows the IDs)"
            ),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_longest_prefix_wins_and_parts_match_whole() {
        let c = Config::parse(
            "default = 0.5\n[points]\na1 = 2\n\"a1.t3\" = 3\n\"a1.t3.unit\" = 5\ns = 1.5\na4.t2 = 4\n",
        )
        .unwrap();
        assert_eq!(c.points("a1.t2.closed"), 2.0);
        assert_eq!(c.points("a1.t3.count"), 3.0);
        assert_eq!(c.points("a1.t3.unit"), 5.0);
        assert_eq!(c.points("a1.t3.unitx"), 3.0);
        assert_eq!(c.points("s.t1.ambient"), 1.5);
        assert_eq!(c.points("a10.t1.x"), 0.5);
        assert_eq!(c.points("a2.t1.x"), 0.5);
        assert_eq!(c.points("a4.t2.corners"), 4.0);
        assert_eq!(Config::default().points("a1.t1.count"), 1.0);
    }

    /// An assignment's total is shared by its checks in proportion to their points, so two
    /// variants with 14 and 16 checks weigh the same (they weighed 14 and 16).
    #[test]
    fn totals_make_an_assignment_weigh_the_same_for_every_variant() {
        let c = Config::parse("[points]\n\"a2.t1\" = 2\n[totals]\na2 = 20\n").unwrap();
        let fourteen: Vec<String> = (0..14).map(|k| format!("a2.t2.c{k}")).collect();
        let sixteen: Vec<String> = (0..16).map(|k| format!("a2.t2.c{k}")).collect();
        let scale = |ids: &[String]| c.scale("a2", ids.iter().map(String::as_str));
        assert!((scale(&fourteen) * 14.0 - 20.0).abs() < 1e-12);
        assert!((scale(&sixteen) * 16.0 - 20.0).abs() < 1e-12);
        // Points stay weights: a t1 check is worth twice a t2 one.
        let mixed = ["a2.t1.x", "a2.t2.y"];
        let s = c.scale("a2", mixed);
        assert!((s * c.points("a2.t1.x") - 40.0 / 3.0).abs() < 1e-12);
        // No total: the points as they are.
        assert_eq!(c.scale("a1", ["a1.t1.count"]), 1.0);
        let e = Config::parse("[totals]\na9 = 20\n").unwrap_err();
        assert!(
            e.message(Lang::En)
                .contains("a9 in the grading config's [totals] is no assignment's ID"),
            "{e}"
        );
        assert!(Config::parse("[totals]\na1 = -1\n").is_err());
    }

    #[test]
    fn bad_configs_say_why() {
        assert!(Config::parse("default = -1").is_err());
        assert!(Config::parse("[points]\na1 = \"two\"").is_err());
        assert!(Config::parse("weights = 3").unwrap_err().message(Lang::En).contains("weights"));
        // The parser's English is said in Japanese too, with its line and column.
        let e = Config::parse("default = 1\n[points\n").unwrap_err();
        assert_eq!(
            e.message(Lang::Ja),
            "採点設定を読めません（TOML の構文エラー）: 2 行 8 列: [ ] が閉じていません（ここに来るはずのもの: `]`）"
        );
        assert!(e.message(Lang::En).contains("line 2, column 8: unclosed table"), "{e}");
    }

    /// A rule that names no check of the kit (a typo, a task that does not exist) is said with
    /// the rule; it gave its points to nothing, and the checks it was meant for got the default.
    #[test]
    fn rules_that_name_no_check_are_said() {
        let ids = crate::check_ids();
        assert!(ids.contains("a1.t2.closed") && ids.len() > 40, "{ids:?}");
        let ids = || ids.iter().map(String::as_str);
        let fine =
            Config::parse("[points]\na1 = 2\n\"a1.t2\" = 3\n\"a1.t2.closed\" = 5\ns = 1").unwrap();
        assert_eq!(fine.check_names(ids()), Ok(()));
        let typo = Config::parse("[points]\n\"a1.t9\" = 3\n\"a1.t2.close\" = 5\na10 = 1").unwrap();
        let e = typo.check_names(ids()).unwrap_err();
        assert!(e.message(Lang::En).contains("name no check: a1.t2.close, a1.t9, a10"), "{e}");
        assert!(e.message(Lang::Ja).contains("どのチェックも指さない規則"), "{e}");
    }
}
