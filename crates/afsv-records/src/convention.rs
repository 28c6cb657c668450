//! Sign conventions of records: the toolkit's own (`afsv-v1`, docs/records.md) and the
//! machine-readable per-channel form a sidecar may state, which the reader honours by
//! flipping or offsetting the channels named.
//!
//! A sidecar's `"sign_convention"` may be
//! - absent or `"afsv-v1"`: the record is read as it is;
//! - an object mapping channel names to terms of [`TERMS`], e.g.
//!   `{"displacement_m": "compression_positive", "force_n": "tension_positive"}`: each named
//!   channel is converted to `afsv-v1`, channels not named are taken as `afsv-v1`;
//! - any other text (a description in words): refused, unless the user has checked the
//!   words and passes `--assume-convention afsv-v1` ([`ReadOptions::assume_convention`]).

use serde_json::Value;

/// The sign convention this toolkit writes and accepts (docs/records.md).
pub const SIGN_CONVENTION: &str = "afsv-v1";

/// Standard atmospheric pressure (Pa), added to gauge pressures.
pub const ATMOSPHERE_PA: f64 = 101_325.0;

/// What a convention term does to a channel to bring it to `afsv-v1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Conversion {
    /// Already `afsv-v1`.
    Keep,
    /// Multiply by -1.
    Negate,
    /// Add one atmosphere (gauge to absolute pressure).
    GaugeToAbsolute,
}

/// The accepted vocabulary: (channel, term, conversion). The `afsv-v1` term is accepted for
/// every channel.
pub const TERMS: [(&str, &str, Conversion); 24] = [
    ("displacement_m", "compression_positive", Conversion::Keep),
    ("displacement_m", "extension_positive", Conversion::Negate),
    ("velocity_m_s", "compression_positive", Conversion::Keep),
    ("velocity_m_s", "extension_positive", Conversion::Negate),
    ("force_n", "compression_positive", Conversion::Keep),
    ("force_n", "tension_positive", Conversion::Negate),
    ("p_piston_pa", "absolute", Conversion::Keep),
    ("p_piston_pa", "gauge", Conversion::GaugeToAbsolute),
    ("p_rod_pa", "absolute", Conversion::Keep),
    ("p_rod_pa", "gauge", Conversion::GaugeToAbsolute),
    ("steer_wheel_deg", "right_turn_positive", Conversion::Keep),
    ("steer_wheel_deg", "left_turn_positive", Conversion::Negate),
    ("articulation_deg", "right_turn_positive", Conversion::Keep),
    ("articulation_deg", "left_turn_positive", Conversion::Negate),
    (
        "yaw_rate_front_deg_s",
        "right_turn_positive",
        Conversion::Keep,
    ),
    (
        "yaw_rate_front_deg_s",
        "left_turn_positive",
        Conversion::Negate,
    ),
    ("strut_left_disp_m", "extension_positive", Conversion::Keep),
    (
        "strut_left_disp_m",
        "compression_positive",
        Conversion::Negate,
    ),
    ("p_c_pa", "absolute", Conversion::Keep),
    ("p_c_pa", "gauge", Conversion::GaugeToAbsolute),
    ("p_r_pa", "absolute", Conversion::Keep),
    ("p_r_pa", "gauge", Conversion::GaugeToAbsolute),
    ("speed_m_s", "forward_positive", Conversion::Keep),
    ("speed_m_s", "backward_positive", Conversion::Negate),
];

/// Options of [`super::Record::read_with`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReadOptions {
    /// Read records whose sidecar describes its convention in words as this convention
    /// (only `afsv-v1` is known): for a user who has checked that the words mean it.
    pub assume_convention: Option<String>,
}

impl ReadOptions {
    /// Check the assumed convention names one the reader knows.
    pub fn validate(&self) -> Result<(), String> {
        match self.assume_convention.as_deref() {
            None | Some(SIGN_CONVENTION) => Ok(()),
            Some(other) => Err(format!(
                "--assume-convention {other}: the only convention known is `{SIGN_CONVENTION}`"
            )),
        }
    }
}

/// The conversions a sidecar's `sign_convention` asks for, per channel name (only channels
/// that need one), or why the convention cannot be honoured.
pub fn conversions(
    convention: Option<&Value>,
    opts: &ReadOptions,
) -> Result<Vec<(String, Conversion)>, String> {
    let Some(conv) = convention else {
        return Ok(Vec::new());
    };
    match conv {
        Value::String(s) if s == SIGN_CONVENTION => Ok(Vec::new()),
        Value::String(_) if opts.assume_convention.as_deref() == Some(SIGN_CONVENTION) => {
            Ok(Vec::new())
        }
        Value::Object(map) => {
            let mut out = Vec::new();
            for (channel, term) in map {
                let Some(term) = term.as_str() else {
                    return Err(format!(
                        "sign_convention.{channel} must be a text term, got {term}"
                    ));
                };
                match lookup(channel, term)? {
                    Conversion::Keep => {}
                    c => out.push((channel.clone(), c)),
                }
            }
            Ok(out)
        }
        other => Err(format!(
            "sign_convention {other} is not machine-readable, so it is not guessed at. Either \
             state it per channel, e.g. \"sign_convention\": {{\"displacement_m\": \
             \"compression_positive\", \"force_n\": \"tension_positive\"}} (terms in \
             docs/records.md), or, if the words describe the {SIGN_CONVENTION} convention, pass \
             --assume-convention {SIGN_CONVENTION}"
        )),
    }
}

fn lookup(channel: &str, term: &str) -> Result<Conversion, String> {
    if term == SIGN_CONVENTION {
        return Ok(Conversion::Keep);
    }
    if let Some((_, _, c)) = TERMS.iter().find(|(ch, t, _)| *ch == channel && *t == term) {
        return Ok(*c);
    }
    let known: Vec<&str> = TERMS
        .iter()
        .filter(|(ch, _, _)| *ch == channel)
        .map(|(_, t, _)| *t)
        .collect();
    if known.is_empty() {
        Err(format!(
            "sign_convention names channel `{channel}`, which has no convention terms (channels with terms: {})",
            channels_with_terms().join(", ")
        ))
    } else {
        Err(format!(
            "sign_convention.{channel} = `{term}` is not a known term (accepted: {}, {SIGN_CONVENTION})",
            known.join(", ")
        ))
    }
}

fn channels_with_terms() -> Vec<&'static str> {
    let mut v: Vec<&str> = TERMS.iter().map(|(c, _, _)| *c).collect();
    v.dedup();
    v
}

/// Apply a conversion to a channel's values.
pub fn apply(conversion: Conversion, values: &mut [f64]) {
    match conversion {
        Conversion::Keep => {}
        Conversion::Negate => values.iter_mut().for_each(|v| *v = -*v),
        Conversion::GaugeToAbsolute => values.iter_mut().for_each(|v| *v += ATMOSPHERE_PA),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn own_and_absent_conventions_need_nothing() {
        let o = ReadOptions::default();
        assert!(conversions(None, &o).unwrap().is_empty());
        assert!(conversions(Some(&json!("afsv-v1")), &o).unwrap().is_empty());
    }

    #[test]
    fn words_are_refused_unless_assumed_and_the_message_names_both_ways() {
        let words = json!("z_s > 0 = compression, force > 0 = compressive");
        let e = conversions(Some(&words), &ReadOptions::default()).unwrap_err();
        assert!(e.contains("--assume-convention afsv-v1"), "{e}");
        assert!(e.contains("compression_positive"), "{e}");
        let assumed = ReadOptions {
            assume_convention: Some("afsv-v1".into()),
        };
        assert!(conversions(Some(&words), &assumed).unwrap().is_empty());
        let bad = ReadOptions {
            assume_convention: Some("sae".into()),
        };
        assert!(bad.validate().is_err());
    }

    #[test]
    fn per_channel_terms_convert_and_unknown_terms_are_named() {
        let c = conversions(
            Some(&json!({"displacement_m": "extension_positive", "force_n": "compression_positive", "p_rod_pa": "gauge"})),
            &ReadOptions::default(),
        )
        .unwrap();
        assert_eq!(
            c,
            vec![
                ("displacement_m".to_string(), Conversion::Negate),
                ("p_rod_pa".to_string(), Conversion::GaugeToAbsolute)
            ]
        );
        let e = conversions(
            Some(&json!({"force_n": "pull_positive"})),
            &ReadOptions::default(),
        )
        .unwrap_err();
        assert!(e.contains("tension_positive"), "{e}");
        let e = conversions(Some(&json!({"zz_m": "up"})), &ReadOptions::default()).unwrap_err();
        assert!(e.contains("zz_m"), "{e}");
        let mut v = [1.0, -2.0];
        apply(Conversion::Negate, &mut v);
        assert_eq!(v, [-1.0, 2.0]);
        apply(Conversion::GaugeToAbsolute, &mut v);
        assert_eq!(v, [-1.0 + ATMOSPHERE_PA, 2.0 + ATMOSPHERE_PA]);
    }
}
