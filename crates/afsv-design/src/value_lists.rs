//! The numbers and lists of numbers options give: a finite number, within a rule
//! ([`finite_f64`], [`positive_f64`], [`nonneg_f64`], [`fraction_f64`],
//! [`open_fraction_f64`]; errors naming the value and the rule); a value or an inclusive range
//! `start:stop:step` ([`range`], tire sweeps), comma-separated numbers ([`list`], speeds,
//! designs; [`point`], x,y) and percent changes ([`changes`], Table 6.4). Errors name the option and the
//! item.

fn number(s: &str) -> Result<f64, String> {
    let t = s.trim();
    if t.is_empty() {
        return Err("expected a number, got an empty value".into());
    }
    let v: f64 = t.parse().map_err(|_| format!("`{t}` is not a number"))?;
    if !v.is_finite() {
        return Err(format!("`{t}` is not a finite number"));
    }
    Ok(v)
}

/// Any finite number.
pub fn finite_f64(s: &str) -> Result<f64, String> {
    number(s)
}

/// A finite number > 0.
pub fn positive_f64(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err("must be > 0".into())
    }
}

/// A finite number >= 0.
pub fn nonneg_f64(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v >= 0.0 {
        Ok(v)
    } else {
        Err("must be >= 0".into())
    }
}

/// A finite fraction in [0, 1).
pub fn fraction_f64(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if (0.0..1.0).contains(&v) {
        Ok(v)
    } else {
        Err("must lie in [0, 1)".into())
    }
}

/// A finite fraction in (0, 1).
pub fn open_fraction_f64(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v > 0.0 && v < 1.0 {
        Ok(v)
    } else {
        Err("must lie in (0, 1)".into())
    }
}

/// Largest number of values of a range.
pub const MAX_RANGE_VALUES: f64 = 1e6;

/// `v` or `start:stop:step` (inclusive end) of `option` as values, at most
/// [`MAX_RANGE_VALUES`] of them.
pub fn range(text: &str, option: &str) -> Result<Vec<f64>, String> {
    let num = |s: &str, what: &str| -> Result<f64, String> {
        let v: f64 = s.trim().parse().map_err(|_| {
            format!(
                "{option}: {what} `{}` is not a number (in `{text}`)",
                s.trim()
            )
        })?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(format!("{option}: {what} `{}` is not finite", s.trim()))
        }
    };
    let parts: Vec<&str> = text.split(':').collect();
    match parts.as_slice() {
        [v] => Ok(vec![num(v, "value")?]),
        [a, b, s] => {
            let (a, b, s) = (num(a, "start")?, num(b, "stop")?, num(s, "step")?);
            if s <= 0.0 {
                return Err(format!("{option}: step must be > 0 in `{text}`"));
            }
            if b < a {
                return Err(format!("{option}: stop {b} is below start {a} in `{text}`"));
            }
            let n = ((b - a) / s + 1e-9).floor() + 1.0;
            if n > MAX_RANGE_VALUES {
                return Err(format!(
                    "{option}: `{text}` gives {n} values (at most 1000000)"
                ));
            }
            Ok((0..n as usize).map(|i| a + i as f64 * s).collect())
        }
        _ => Err(format!(
            "{option}: expected a value or start:stop:step, got `{text}`"
        )),
    }
}

/// A point `"x,y"` of two finite numbers (the Eq 4.9 geometry of `afsv optimize afs`).
pub fn point(s: &str) -> Result<[f64; 2], String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|t| t.trim().parse::<f64>().map_err(|e| format!("{t:?}: {e}")))
        .collect::<Result<_, _>>()?;
    match v[..] {
        [x, y] if x.is_finite() && y.is_finite() => Ok([x, y]),
        _ => Err(format!(
            "expected \"x,y\" with two finite numbers, got {s:?}"
        )),
    }
}

/// Comma-separated finite numbers of option `name`, at most `max` of them.
pub fn list(name: &str, text: &str, max: usize) -> Result<Vec<f64>, String> {
    let out = text
        .split(',')
        .enumerate()
        .map(|(i, item)| match item.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(format!(
                "{name}: item {} `{item}` is not a finite number",
                i + 1
            )),
        })
        .collect::<Result<Vec<f64>, String>>()?;
    if out.len() > max {
        return Err(format!("{name}: at most {max} values, got {}", out.len()));
    }
    Ok(out)
}

/// `--changes` as fractions: finite percents above -100 and at most 1000, at most 20 of
/// them.
pub fn changes(text: &str) -> Result<Vec<f64>, String> {
    let mut out = Vec::new();
    for (i, item) in text.split(',').enumerate() {
        let v: f64 = item
            .trim()
            .parse()
            .map_err(|_| format!("--changes: item {} `{item}` is not a number", i + 1))?;
        if !(v.is_finite() && v > -100.0 && v <= 1000.0) {
            return Err(format!(
                "--changes: {v} % must be above -100 and at most 1000"
            ));
        }
        out.push(v / 100.0);
    }
    if out.len() > 20 {
        return Err(format!("--changes: at most 20 changes, got {}", out.len()));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn refuses_non_finite_and_empty() {
        for bad in [
            "nan", "NaN", "inf", "-inf", "infinity", "", " ", "1e309", "abc", "2^64",
        ] {
            assert!(finite_f64(bad).is_err(), "{bad}");
            assert!(positive_f64(bad).is_err(), "{bad}");
            assert!(nonneg_f64(bad).is_err(), "{bad}");
        }
        assert_eq!(positive_f64("1e-320").unwrap(), 1e-320);
        assert!(positive_f64("0").is_err());
        assert!(positive_f64("-1").is_err());
        assert!(nonneg_f64("-1").is_err());
        assert_eq!(nonneg_f64("0").unwrap(), 0.0);
        assert!(fraction_f64("1").is_err());
        assert!(open_fraction_f64("0").is_err());
    }

    proptest! {
        #[test]
        fn finite_numbers_round_trip(v in proptest::num::f64::ANY) {
            let s = v.to_string();
            let r = finite_f64(&s);
            prop_assert_eq!(r.is_ok(), v.is_finite());
            if let Ok(x) = r {
                prop_assert_eq!(x, v);
            }
            prop_assert_eq!(positive_f64(&s).is_ok(), v.is_finite() && v > 0.0);
            prop_assert_eq!(nonneg_f64(&s).is_ok(), v.is_finite() && v >= 0.0);
            prop_assert_eq!(fraction_f64(&s).is_ok(), v.is_finite() && (0.0..1.0).contains(&v));
        }

        #[test]
        fn never_panics_on_any_text(s in ".*") {
            let _ = finite_f64(&s);
            let _ = positive_f64(&s);
            let _ = nonneg_f64(&s);
            let _ = open_fraction_f64(&s);
        }

        #[test]
        fn accepted_values_are_in_range(s in "[-+]?[0-9]{0,4}(\\.[0-9]{0,3})?(e[-+]?[0-9]{1,3})?") {
            if let Ok(v) = positive_f64(&s) { prop_assert!(v.is_finite() && v > 0.0); }
            if let Ok(v) = nonneg_f64(&s) { prop_assert!(v.is_finite() && v >= 0.0); }
            if let Ok(v) = open_fraction_f64(&s) { prop_assert!(v > 0.0 && v < 1.0); }
        }
    }

    #[test]
    fn ranges_include_their_end() {
        assert_eq!(range("2", "--x").unwrap(), vec![2.0]);
        assert_eq!(range("0:1:0.5", "--x").unwrap(), vec![0.0, 0.5, 1.0]);
        assert_eq!(range("-20:20:0.5", "--x").unwrap().len(), 81);
        assert!(range("1:0:1", "--x").unwrap_err().contains("below start"));
        assert!(range("0:1:0", "--x")
            .unwrap_err()
            .contains("step must be > 0"));
        assert!(range("0:1e9:1", "--x")
            .unwrap_err()
            .contains("at most 1000000"));
        assert!(range("nan", "--x").unwrap_err().contains("not finite"));
        assert!(range("1:2", "--x").is_err());
    }

    #[test]
    fn points_are_two_finite_numbers() {
        assert_eq!(point(" 1.5, -2").unwrap(), [1.5, -2.0]);
        assert!(point("1,2,3").unwrap_err().contains("two finite numbers"));
        assert!(point("1,inf").is_err() && point("1").is_err());
        assert!(point("1,x").unwrap_err().contains("\"x\""));
    }

    #[test]
    fn lists_and_changes() {
        assert_eq!(list("--s", "10, 20", 5).unwrap(), vec![10.0, 20.0]);
        assert!(list("--s", "10,x", 5).unwrap_err().contains("item 2"));
        assert!(list("--s", "1,2,3", 2).is_err());
        assert_eq!(changes("-30,15").unwrap(), vec![-0.3, 0.15]);
        assert!(changes("-100").is_err() && changes("a").is_err());
    }
}
