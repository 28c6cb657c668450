//! Unit suffixes of record channels. The toolkit's channels are SI with the unit in the name
//! (`az_m_s2`, `force_n`, `p_rod_pa`, `steer_wheel_deg`; docs/records.md). A record made
//! elsewhere may carry a known quantity in another unit: `az_g`, `force_kn`, `p_rod_bar`,
//! `displacement_mm`. On reading, such a channel is converted to the toolkit's channel when
//! the unit is known, and refused when it is a unit the toolkit cannot convert for that
//! quantity. It is never dropped without a word: [`Record::unit_conversions`] lists what was
//! converted.
//!
//! [`Record::unit_conversions`]: crate::Record::unit_conversions

/// Standard gravity (m/s²), for accelerations in g.
pub const STANDARD_GRAVITY: f64 = 9.806_65;

const DEG_PER_RAD: f64 = 180.0 / std::f64::consts::PI;

/// One quantity: its channel-name prefix, its SI unit token, and the other units it may be
/// written in with the factor to the SI unit.
struct Quantity {
    prefix: &'static str,
    unit: &'static str,
    others: &'static [(&'static str, f64)],
}

const LENGTH: &[(&str, f64)] = &[("mm", 1e-3), ("cm", 1e-2), ("km", 1e3)];
const PRESSURE: &[(&str, f64)] = &[
    ("kpa", 1e3),
    ("mpa", 1e6),
    ("bar", 1e5),
    ("psi", 6_894.757_293_168),
];
const ANGLE: &[(&str, f64)] = &[("rad", DEG_PER_RAD)];

/// The quantities of the record formats (docs/records.md).
const QUANTITIES: &[Quantity] = &[
    Quantity {
        prefix: "time",
        unit: "s",
        others: &[("ms", 1e-3), ("min", 60.0)],
    },
    Quantity {
        prefix: "displacement",
        unit: "m",
        others: LENGTH,
    },
    Quantity {
        prefix: "velocity",
        unit: "m_s",
        others: &[("mm_s", 1e-3)],
    },
    Quantity {
        prefix: "force",
        unit: "n",
        others: &[("kn", 1e3)],
    },
    Quantity {
        prefix: "p_piston",
        unit: "pa",
        others: PRESSURE,
    },
    Quantity {
        prefix: "p_rod",
        unit: "pa",
        others: PRESSURE,
    },
    Quantity {
        prefix: "p_c",
        unit: "pa",
        others: PRESSURE,
    },
    Quantity {
        prefix: "p_r",
        unit: "pa",
        others: PRESSURE,
    },
    Quantity {
        prefix: "steer_wheel",
        unit: "deg",
        others: ANGLE,
    },
    Quantity {
        prefix: "articulation",
        unit: "deg",
        others: ANGLE,
    },
    Quantity {
        prefix: "yaw_rate_front",
        unit: "deg_s",
        others: &[("rad_s", DEG_PER_RAD)],
    },
    Quantity {
        prefix: "speed",
        unit: "m_s",
        others: &[("kmh", 1.0 / 3.6)],
    },
    Quantity {
        prefix: "strut_left_disp",
        unit: "m",
        others: LENGTH,
    },
    Quantity {
        prefix: "ax",
        unit: "m_s2",
        others: &[("g", STANDARD_GRAVITY)],
    },
    Quantity {
        prefix: "ay",
        unit: "m_s2",
        others: &[("g", STANDARD_GRAVITY)],
    },
    Quantity {
        prefix: "az",
        unit: "m_s2",
        others: &[("g", STANDARD_GRAVITY)],
    },
    Quantity {
        prefix: "x",
        unit: "m",
        others: LENGTH,
    },
    Quantity {
        prefix: "left",
        unit: "m",
        others: LENGTH,
    },
    Quantity {
        prefix: "right",
        unit: "m",
        others: LENGTH,
    },
];

/// Unit tokens that are recognisably a unit (of some quantity) although no quantity above
/// converts them: a channel of a known quantity in one of these is refused.
const FOREIGN_UNITS: &[&str] = &[
    "ft", "in", "mi", "um", "lbf", "kgf", "kip", "mbar", "atm", "mrad", "grad", "rev", "rpm",
    "ft_s", "ft_s2", "in_s", "mph", "h", "us", "mm_s2", "cm_s2", "gal",
];

/// What to do with one channel name.
#[derive(Debug, Clone, PartialEq)]
pub enum ChannelUnit {
    /// Not a quantity of the record formats, or already in the toolkit's unit: keep it.
    Keep,
    /// A known quantity in another known unit: rename to `to` and multiply by `factor`.
    Convert {
        /// The toolkit's channel name.
        to: String,
        /// Factor from the channel's unit to SI.
        factor: f64,
    },
    /// A known quantity in a unit the toolkit cannot convert.
    Refuse {
        /// Why, naming the units that are accepted.
        reason: String,
    },
}

/// Classify the channel `name` (see the module documentation).
pub fn classify(name: &str) -> ChannelUnit {
    for q in QUANTITIES {
        let Some(rest) = name
            .strip_prefix(q.prefix)
            .and_then(|r| r.strip_prefix('_'))
        else {
            continue;
        };
        if rest == q.unit {
            return ChannelUnit::Keep;
        }
        if let Some((_, factor)) = q.others.iter().find(|(u, _)| *u == rest) {
            return ChannelUnit::Convert {
                to: format!("{}_{}", q.prefix, q.unit),
                factor: *factor,
            };
        }
        let known_elsewhere = FOREIGN_UNITS.contains(&rest)
            || QUANTITIES
                .iter()
                .any(|o| o.unit == rest || o.others.iter().any(|(u, _)| *u == rest));
        if known_elsewhere {
            let accepted: Vec<&str> = std::iter::once(q.unit)
                .chain(q.others.iter().map(|(u, _)| *u))
                .collect();
            return ChannelUnit::Refuse {
                reason: format!(
                    "`{name}` gives {} in `{rest}`, which cannot be converted; accepted units: {}",
                    q.prefix,
                    accepted.join(", ")
                ),
            };
        }
    }
    ChannelUnit::Keep
}

/// How a channel reads on a plot axis: a readable quantity with an engineering unit, and
/// the factor from the channel's SI values to that unit ([`plot_axis`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PlotAxis {
    /// Axis label, e.g. `rod-side pressure (MPa)`.
    pub label: String,
    /// Multiply the channel's values by this to plot them in the label's unit.
    pub scale: f64,
}

/// SI unit suffixes of channel names, longest first, with the engineering unit a plot uses
/// and the factor to it. Lengths are plotted in mm only for displacements (`disp` in the
/// name); other lengths stay in m.
const PLOT_UNITS: &[(&str, &str, f64)] = &[
    ("m_s2", "m/s²", 1.0),
    ("deg_s", "deg/s", 1.0),
    ("rad_s", "rad/s", 1.0),
    ("m_s", "m/s", 1.0),
    ("pa", "MPa", 1e-6),
    ("deg", "deg", 1.0),
    ("rad", "rad", 1.0),
    ("n", "kN", 1e-3),
    ("m", "m", 1.0),
    ("s", "s", 1.0),
];

/// Readable names of the record formats' quantities (docs/records.md).
const PLOT_NAMES: &[(&str, &str)] = &[
    ("p_piston", "piston-side pressure"),
    ("p_rod", "rod-side pressure"),
    ("p_c", "chamber-group pressure P_c"),
    ("p_r", "chamber-group pressure P_r"),
    ("force", "strut force"),
    ("displacement", "strut displacement"),
    ("velocity", "strut velocity"),
    ("steer_wheel", "steering-wheel angle"),
    ("articulation", "articulation angle"),
    ("yaw_rate_front", "front-unit yaw rate"),
    ("strut_left_disp", "left steering-strut displacement"),
    ("speed", "speed"),
    ("time", "time"),
];

/// The plot axis of channel `name`: its quantity in words and its SI values in an
/// engineering unit (pressures in MPa, forces in kN, displacements in mm). A name without a
/// known unit suffix is kept as it is, unscaled.
pub fn plot_axis(name: &str) -> PlotAxis {
    for (suffix, unit, scale) in PLOT_UNITS {
        let Some(quantity) = name
            .strip_suffix(suffix)
            .and_then(|q| q.strip_suffix('_'))
            .filter(|q| !q.is_empty())
        else {
            continue;
        };
        let (unit, scale) = if *suffix == "m" && (quantity.contains("disp")) {
            ("mm", 1e3)
        } else {
            (*unit, *scale)
        };
        let words = PLOT_NAMES
            .iter()
            .find(|(q, _)| *q == quantity)
            .map_or_else(|| quantity.replace('_', " "), |(_, w)| (*w).to_string());
        return PlotAxis {
            label: format!("{words} ({unit})"),
            scale,
        };
    }
    PlotAxis {
        label: name.to_string(),
        scale: 1.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn convert(name: &str) -> (String, f64) {
        match classify(name) {
            ChannelUnit::Convert { to, factor } => (to, factor),
            other => panic!("{name}: {other:?}"),
        }
    }

    #[test]
    fn known_units_convert_to_the_si_channel() {
        assert_eq!(convert("az_g"), ("az_m_s2".into(), STANDARD_GRAVITY));
        assert_eq!(convert("force_kn"), ("force_n".into(), 1e3));
        assert_eq!(convert("p_rod_bar"), ("p_rod_pa".into(), 1e5));
        assert_eq!(convert("p_piston_mpa"), ("p_piston_pa".into(), 1e6));
        assert_eq!(convert("displacement_mm"), ("displacement_m".into(), 1e-3));
        assert_eq!(convert("speed_kmh"), ("speed_m_s".into(), 1.0 / 3.6));
        let (to, f) = convert("steer_wheel_rad");
        assert_eq!(to, "steer_wheel_deg");
        assert!((f * std::f64::consts::PI - 180.0).abs() < 1e-12);
    }

    #[test]
    fn si_channels_and_other_names_are_kept() {
        for name in [
            "az_m_s2",
            "force_n",
            "time_s",
            "articulation_deg",
            "articulation_rate_deg_s",
            "p_c_pa",
            "strut_left_disp_m",
            "kinetic_energy_j",
            "valve_opening",
            "x_m",
        ] {
            assert_eq!(classify(name), ChannelUnit::Keep, "{name}");
        }
    }

    #[test]
    fn a_known_quantity_in_an_unconvertible_unit_is_refused() {
        for name in [
            "az_ft_s2",
            "force_lbf",
            "displacement_in",
            "p_rod_atm",
            "az_kn",
        ] {
            match classify(name) {
                ChannelUnit::Refuse { reason } => {
                    assert!(
                        reason.contains(name) && reason.contains("accepted"),
                        "{reason}"
                    )
                }
                other => panic!("{name}: {other:?}"),
            }
        }
    }

    #[test]
    fn plot_axes_read_in_engineering_units() {
        let a = plot_axis("p_rod_pa");
        assert_eq!(a.label, "rod-side pressure (MPa)");
        assert_eq!(a.scale, 1e-6);
        assert_eq!(plot_axis("force_n").label, "strut force (kN)");
        assert_eq!(plot_axis("force_n").scale, 1e-3);
        let d = plot_axis("strut_left_disp_m");
        assert_eq!(
            (d.label.as_str(), d.scale),
            ("left steering-strut displacement (mm)", 1e3)
        );
        assert_eq!(
            plot_axis("yaw_rate_front_deg_s").label,
            "front-unit yaw rate (deg/s)"
        );
        assert_eq!(plot_axis("az_m_s2").label, "az (m/s²)");
        assert_eq!(plot_axis("x_m").label, "x (m)");
        let odd = plot_axis("counts");
        assert_eq!((odd.label.as_str(), odd.scale), ("counts", 1.0));
        assert_eq!(plot_axis("_pa").label, "_pa");
    }
}
