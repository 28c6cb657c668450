//! ISO 2631-1:1997 Annex A frequency weightings as analog transfer functions.
//!
//! Each weighting is the product of (Annex A, Eqs A.1-A.5; symbols as in the standard)
//!
//! * band limiting, high pass (2nd-order Butterworth at `f1`):
//!   `Hh(s) = s^2 / (s^2 + sqrt(2) w1 s + w1^2)`
//! * band limiting, low pass (2nd-order Butterworth at `f2`):
//!   `Hl(s) = w2^2 / (s^2 + sqrt(2) w2 s + w2^2)`
//! * acceleration-velocity transition (proportional to acceleration below `f3`, to velocity
//!   above `f4`): `Ht(s) = (1 + s/w3) / (1 + s/(Q4 w4) + s^2/w4^2)`
//! * upward step (steepness about 6 dB/octave, proportional to jerk between `f5` and `f6`):
//!   `Hs(s) = (1 + s/(Q5 w5) + s^2/w5^2) / (1 + s/(Q6 w6) + s^2/w6^2) * (w5/w6)^2`
//!
//! times a gain `K` (1 for all six weightings of ISO 2631-1), with `w_i = 2 pi f_i`.
//! A section whose frequency is infinite in Table A.2 of the standard is absent
//! (`None` here). The parameters are those of ISO 2631-1:1997 Table A.2.

use crate::error::{invalid, MeasureError};
use realfft::num_complex::Complex64;
use serde::{Deserialize, Serialize};
use std::f64::consts::{PI, SQRT_2};
use std::fmt;
use std::str::FromStr;

/// The frequency weightings of ISO 2631-1:1997 (Table 1 and Annex A).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Weighting {
    /// Vertical (z) seat acceleration for health, comfort and perception.
    Wk,
    /// Horizontal (x, y) seat acceleration for health, comfort and perception.
    Wd,
    /// Seat-back x acceleration (comfort, health).
    Wc,
    /// Rotational acceleration (comfort).
    We,
    /// Vertical acceleration under the head of a recumbent person.
    Wj,
    /// Vertical acceleration for motion sickness.
    Wf,
}

impl Weighting {
    /// All six weightings, in the order of the standard's tables (principal, then additional).
    pub const ALL: [Weighting; 6] = [
        Weighting::Wk,
        Weighting::Wd,
        Weighting::Wf,
        Weighting::Wc,
        Weighting::We,
        Weighting::Wj,
    ];

    /// Lower-case name (`"wk"`, ...).
    pub fn name(self) -> &'static str {
        match self {
            Weighting::Wk => "wk",
            Weighting::Wd => "wd",
            Weighting::Wc => "wc",
            Weighting::We => "we",
            Weighting::Wj => "wj",
            Weighting::Wf => "wf",
        }
    }

    /// The weighting's parameters from ISO 2631-1:1997 Table A.2.
    pub fn params(self) -> WeightingParams {
        WeightingParams::of(self)
    }

    /// Analog complex response `H(j 2 pi f)` (Annex A, Eq A.1-A.5).
    pub fn response(self, f_hz: f64) -> Complex64 {
        self.params().response(f_hz)
    }

    /// Analog magnitude `|H(j 2 pi f)|`, the weighting factor at `f_hz`.
    pub fn magnitude(self, f_hz: f64) -> f64 {
        self.response(f_hz).norm()
    }
}

impl fmt::Display for Weighting {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Weighting {
    type Err = MeasureError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "wk" | "k" => Ok(Weighting::Wk),
            "wd" | "d" => Ok(Weighting::Wd),
            "wc" | "c" => Ok(Weighting::Wc),
            "we" | "e" => Ok(Weighting::We),
            "wj" | "j" => Ok(Weighting::Wj),
            "wf" | "f" => Ok(Weighting::Wf),
            other => Err(invalid(
                "weighting",
                format!("unknown weighting `{other}` (expected wk, wd, wc, we, wj or wf)"),
            )),
        }
    }
}

/// Parameters of one weighting (ISO 2631-1:1997 Table A.2). Frequencies in Hz; `None`
/// means the standard lists the frequency as infinite, i.e. the section is absent.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct WeightingParams {
    /// High-pass band-limiting corner `f1` (Hz).
    pub f1_hz: f64,
    /// Low-pass band-limiting corner `f2` (Hz).
    pub f2_hz: f64,
    /// a-v transition numerator corner `f3` (Hz); `None` = infinite.
    pub f3_hz: Option<f64>,
    /// a-v transition denominator corner `f4` (Hz); `None` = no a-v transition.
    pub f4_hz: Option<f64>,
    /// a-v transition quality factor `Q4`.
    pub q4: Option<f64>,
    /// Upward step numerator corner `f5` (Hz); `None` = no upward step.
    pub f5_hz: Option<f64>,
    /// Upward step numerator quality factor `Q5`.
    pub q5: Option<f64>,
    /// Upward step denominator corner `f6` (Hz).
    pub f6_hz: Option<f64>,
    /// Upward step denominator quality factor `Q6`.
    pub q6: Option<f64>,
    /// Overall gain `K` (1 for every weighting of ISO 2631-1).
    pub k: f64,
}

impl WeightingParams {
    /// ISO 2631-1:1997 Table A.2 values.
    pub fn of(w: Weighting) -> Self {
        let base = WeightingParams {
            f1_hz: 0.4,
            f2_hz: 100.0,
            f3_hz: None,
            f4_hz: None,
            q4: None,
            f5_hz: None,
            q5: None,
            f6_hz: None,
            q6: None,
            k: 1.0,
        };
        match w {
            Weighting::Wk => WeightingParams {
                f3_hz: Some(12.5),
                f4_hz: Some(12.5),
                q4: Some(0.63),
                f5_hz: Some(2.37),
                q5: Some(0.91),
                f6_hz: Some(3.35),
                q6: Some(0.91),
                ..base
            },
            Weighting::Wd => WeightingParams {
                f3_hz: Some(2.0),
                f4_hz: Some(2.0),
                q4: Some(0.63),
                ..base
            },
            Weighting::Wc => WeightingParams {
                f3_hz: Some(8.0),
                f4_hz: Some(8.0),
                q4: Some(0.63),
                ..base
            },
            Weighting::We => WeightingParams {
                f3_hz: Some(1.0),
                f4_hz: Some(1.0),
                q4: Some(0.63),
                ..base
            },
            Weighting::Wj => WeightingParams {
                f5_hz: Some(3.75),
                q5: Some(0.91),
                f6_hz: Some(5.32),
                q6: Some(0.91),
                ..base
            },
            Weighting::Wf => WeightingParams {
                f1_hz: 0.08,
                f2_hz: 0.63,
                f3_hz: None,
                f4_hz: Some(0.25),
                q4: Some(0.86),
                f5_hz: Some(0.0625),
                q5: Some(0.80),
                f6_hz: Some(0.1),
                q6: Some(0.80),
                k: 1.0,
            },
        }
    }

    /// The analog sections as `(numerator, denominator)` polynomials in `s`, ascending
    /// powers `[c0, c1, c2]`, each paired with a characteristic angular frequency (rad/s)
    /// used to pre-warp its bilinear transform. The gain `K` is folded into the first.
    pub fn sections(&self) -> Vec<AnalogSection> {
        let mut out = Vec::with_capacity(4);
        let w1 = 2.0 * PI * self.f1_hz;
        out.push(AnalogSection {
            num: [0.0, 0.0, self.k],
            den: [w1 * w1, SQRT_2 * w1, 1.0],
            w_char: w1,
            kind: SectionKind::HighPass,
        });
        let w2 = 2.0 * PI * self.f2_hz;
        out.push(AnalogSection {
            num: [w2 * w2, 0.0, 0.0],
            den: [w2 * w2, SQRT_2 * w2, 1.0],
            w_char: w2,
            kind: SectionKind::LowPass,
        });
        if let (Some(f4), Some(q4)) = (self.f4_hz, self.q4) {
            let w4 = 2.0 * PI * f4;
            let num1 = self.f3_hz.map_or(0.0, |f3| 1.0 / (2.0 * PI * f3));
            out.push(AnalogSection {
                num: [1.0, num1, 0.0],
                den: [1.0, 1.0 / (q4 * w4), 1.0 / (w4 * w4)],
                w_char: w4,
                kind: SectionKind::AvTransition,
            });
        }
        if let (Some(f5), Some(q5), Some(f6), Some(q6)) = (self.f5_hz, self.q5, self.f6_hz, self.q6)
        {
            let w5 = 2.0 * PI * f5;
            let w6 = 2.0 * PI * f6;
            let g = (w5 / w6).powi(2);
            out.push(AnalogSection {
                num: [g, g / (q5 * w5), g / (w5 * w5)],
                den: [1.0, 1.0 / (q6 * w6), 1.0 / (w6 * w6)],
                w_char: (w5 * w6).sqrt(),
                kind: SectionKind::UpwardStep,
            });
        }
        out
    }

    /// Analog complex response `K Hh Hl Ht Hs` at `s = j 2 pi f` (Annex A).
    pub fn response(&self, f_hz: f64) -> Complex64 {
        let s = Complex64::new(0.0, 2.0 * PI * f_hz);
        self.sections()
            .iter()
            .fold(Complex64::new(1.0, 0.0), |acc, sec| acc * sec.response(s))
    }

    /// Analog magnitude at `f_hz`.
    pub fn magnitude(&self, f_hz: f64) -> f64 {
        self.response(f_hz).norm()
    }

    /// Validate a user-supplied parameter set (all frequencies and Q finite and > 0,
    /// `f1 < f2`).
    pub fn validate(&self) -> Result<(), MeasureError> {
        fn pos(field: &'static str, v: f64) -> Result<(), MeasureError> {
            crate::error::positive(field, v).map(|_| ())
        }
        pos("f1_hz", self.f1_hz)?;
        pos("f2_hz", self.f2_hz)?;
        pos("k", self.k)?;
        if self.f1_hz >= self.f2_hz {
            return Err(invalid("f2_hz", "must exceed f1_hz"));
        }
        for (field, v) in [
            ("f3_hz", self.f3_hz),
            ("f4_hz", self.f4_hz),
            ("q4", self.q4),
            ("f5_hz", self.f5_hz),
            ("q5", self.q5),
            ("f6_hz", self.f6_hz),
            ("q6", self.q6),
        ] {
            if let Some(v) = v {
                pos(field, v)?;
            }
        }
        if self.f4_hz.is_some() != self.q4.is_some() {
            return Err(invalid("q4", "f4_hz and q4 must be given together"));
        }
        let step = [self.f5_hz, self.q5, self.f6_hz, self.q6];
        if step.iter().any(Option::is_some) && !step.iter().all(Option::is_some) {
            return Err(invalid(
                "f5_hz",
                "f5_hz, q5, f6_hz and q6 must be given together",
            ));
        }
        Ok(())
    }
}

/// Which factor of the weighting a section is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum SectionKind {
    /// Band-limiting high pass (`f1`).
    HighPass,
    /// Band-limiting low pass (`f2`).
    LowPass,
    /// Acceleration-velocity transition (`f3`, `f4`, `Q4`).
    AvTransition,
    /// Upward step (`f5`, `Q5`, `f6`, `Q6`).
    UpwardStep,
}

/// One second-order analog section `N(s)/D(s)`, coefficients in ascending powers of `s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnalogSection {
    /// Numerator `[n0, n1, n2]`.
    pub num: [f64; 3],
    /// Denominator `[d0, d1, d2]`.
    pub den: [f64; 3],
    /// Characteristic angular frequency (rad/s), the bilinear pre-warping frequency.
    pub w_char: f64,
    /// Which factor this is.
    pub kind: SectionKind,
}

impl AnalogSection {
    /// Complex response at the Laplace variable `s`.
    pub fn response(&self, s: Complex64) -> Complex64 {
        let n = self.num[0] + s * (self.num[1] + s * self.num[2]);
        let d = self.den[0] + s * (self.den[1] + s * self.den[2]);
        n / d
    }

    /// Slowest decay rate (1/s) of the section's poles: the smallest `|Re(p)|` of the roots
    /// of `d2 s^2 + d1 s + d0`.
    pub fn decay_rate(&self) -> f64 {
        let [d0, d1, d2] = self.den;
        let disc = d1 * d1 - 4.0 * d0 * d2;
        if disc < 0.0 {
            d1 / (2.0 * d2)
        } else {
            (d1 - disc.sqrt()) / (2.0 * d2)
        }
    }
}
