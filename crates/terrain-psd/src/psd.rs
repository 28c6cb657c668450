//! Displacement PSD models of the terrain elevation (Eqs 1.6, 1.7, 2.8; Tables 1.2, 2.4).
//!
//! All models are power laws `G_d(n) = alpha_r * n^-w` (Eq 2.8) in the spatial frequency
//! `n` (cycles/m); `G_d` is the one-sided PSD in m^2/(cycle/m) = m^3. ISO 8608 states the
//! same law as `G_d(n) = G_d(n0) (n/n0)^-w` with `n0 = 0.1` cycles/m (Eq 1.6), so
//! `alpha_r = G_d(n0) * n0^w`.

use crate::error::{non_negative, positive, Result, TerrainError};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// ISO 8608 reference spatial frequency `n0` (cycles/m), Eq 1.6.
pub const N0: f64 = 0.1;

/// Largest waviness accepted (real terrains have 1.5-3.5; larger values overflow `n^-w`).
pub const MAX_WAVINESS: f64 = 10.0;

/// Power-law displacement PSD `G_d(n) = alpha_r * n^-w` (Eq 2.8, Eq 1.7 with `beta = w`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PowerLawPsd {
    /// Roughness coefficient `alpha_r` (m^3 when `w = 2`; in general m^2/(cycle/m) at n = 1 cycle/m).
    pub alpha_r: f64,
    /// Waviness exponent `w` (dimensionless).
    pub waviness: f64,
}

impl PowerLawPsd {
    /// A validated power law: `alpha_r` finite and > 0 (Eq 1.7), `0 <= w <= 10`.
    /// (`w = 0`, white noise, is accepted as the limiting case of Eq 1.7's `beta > 0`.)
    pub fn new(alpha_r: f64, waviness: f64) -> Result<Self> {
        let m = Self { alpha_r, waviness };
        m.validate()?;
        Ok(m)
    }

    /// Check the fields (see [`PowerLawPsd::new`]).
    pub fn validate(&self) -> Result<()> {
        positive("alpha_r", self.alpha_r)?;
        non_negative("waviness", self.waviness)?;
        if self.waviness > MAX_WAVINESS {
            return Err(TerrainError::Parameter {
                name: "waviness",
                value: self.waviness,
                requirement: format!("must be <= {MAX_WAVINESS}"),
            });
        }
        Ok(())
    }

    /// ISO 8608 class with its geometric-mean `G_d(n0)` and waviness 2 (Table 2.4 for A-E).
    pub fn iso(class: IsoClass) -> Self {
        Self {
            alpha_r: class.gd_n0() * N0 * N0,
            waviness: 2.0,
        }
    }

    /// ISO 8608 general form (Eq 1.6): `G_d(n) = gd_n0 * (n/n0)^-w`, i.e. `alpha_r = gd_n0 * n0^w`.
    pub fn from_gd_n0(gd_n0: f64, waviness: f64) -> Result<Self> {
        positive("gd_n0", gd_n0)?;
        non_negative("waviness", waviness)?;
        Self::new(gd_n0 * N0.powf(waviness), waviness)
    }

    /// One of the off-road terrains of Tables 1.2 / 2.4.
    pub fn off_road(terrain: OffRoadTerrain) -> Self {
        Self {
            alpha_r: terrain.alpha_r(),
            waviness: terrain.waviness(),
        }
    }

    /// The paper's nominal off-road terrain: ISO 8608 class E (sections 2.2.2 and 6.2.3).
    pub fn paper_nominal() -> Self {
        Self::iso(IsoClass::E)
    }

    /// `G_d(n)` (m^3) for `n > 0` cycles/m; 0 for `n <= 0` or NaN.
    pub fn gd(&self, n: f64) -> f64 {
        if n > 0.0 {
            self.alpha_r * n.powf(-self.waviness)
        } else {
            0.0
        }
    }

    /// `G_d(n0)` at the ISO reference frequency `n0 = 0.1` cycles/m.
    pub fn gd_n0(&self) -> f64 {
        self.gd(N0)
    }

    /// ISO 8608 class whose `G_d(n0)` range contains this model's `G_d(n0)`.
    pub fn iso_class(&self) -> IsoClass {
        IsoClass::classify(self.gd_n0())
    }

    /// `integral_a^b G_d(n) dn` (m^2) for `0 < a <= b`, exact for any waviness (including 1).
    /// Returns 0 when `b <= a` or `a <= 0`.
    pub fn integral(&self, a: f64, b: f64) -> f64 {
        if !(a > 0.0 && b > a) {
            return 0.0;
        }
        // alpha * (b^(1-w) - a^(1-w)) / (1-w), written as a^(1-w) ln(b/a) expm1(t)/t with
        // t = (1-w) ln(b/a) so that it stays accurate as w -> 1.
        let l = (b / a).ln();
        let t = (1.0 - self.waviness) * l;
        let ratio = if t.abs() < 1e-12 { 1.0 } else { t.exp_m1() / t };
        self.alpha_r * a.powf(1.0 - self.waviness) * l * ratio
    }
}

impl Default for PowerLawPsd {
    fn default() -> Self {
        Self::paper_nominal()
    }
}

/// Spatial frequency band `[n_min, n_max]` (cycles/m) outside which the PSD is zero.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Band {
    /// Lower limit (cycles/m), > 0.
    pub n_min: f64,
    /// Upper limit (cycles/m), > `n_min`.
    pub n_max: f64,
}

impl Band {
    /// The paper's band, 0.02-5 cycles/m (section 2.2.2).
    pub const PAPER: Band = Band {
        n_min: 0.02,
        n_max: 5.0,
    };

    /// A validated band: both finite, `0 < n_min < n_max`.
    pub fn new(n_min: f64, n_max: f64) -> Result<Self> {
        let b = Self { n_min, n_max };
        b.validate()?;
        Ok(b)
    }

    /// Check the limits (see [`Band::new`]).
    pub fn validate(&self) -> Result<()> {
        if self.n_min.is_finite()
            && self.n_max.is_finite()
            && self.n_min > 0.0
            && self.n_min < self.n_max
        {
            Ok(())
        } else {
            Err(TerrainError::Band {
                n_min: self.n_min,
                n_max: self.n_max,
            })
        }
    }

    /// True when `n_min <= n <= n_max`.
    pub fn contains(&self, n: f64) -> bool {
        n >= self.n_min && n <= self.n_max
    }

    /// Width `n_max - n_min` (cycles/m).
    pub fn width(&self) -> f64 {
        self.n_max - self.n_min
    }
}

impl Default for Band {
    fn default() -> Self {
        Self::PAPER
    }
}

impl FromStr for Band {
    type Err = TerrainError;

    /// Parse `"N_MIN,N_MAX"` (cycles/m), e.g. `"0.02,5"`.
    fn from_str(s: &str) -> Result<Self> {
        let bad = || TerrainError::Syntax {
            what: "band",
            given: s.to_string(),
            expected: "N_MIN,N_MAX in cycles/m, e.g. 0.02,5",
        };
        let (a, b) = s.split_once(',').ok_or_else(bad)?;
        let a: f64 = a.trim().parse().map_err(|_| bad())?;
        let b: f64 = b.trim().parse().map_err(|_| bad())?;
        Band::new(a, b)
    }
}

impl fmt::Display for Band {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{},{}", self.n_min, self.n_max)
    }
}

/// ISO 8608 road classes A (very good) to H (very poor).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum IsoClass {
    /// `G_d(n0)` = 16e-6 m^3 (range < 32e-6).
    A,
    /// 64e-6 m^3 (32e-6 .. 128e-6).
    B,
    /// 256e-6 m^3 (128e-6 .. 512e-6).
    C,
    /// 1024e-6 m^3 (512e-6 .. 2048e-6).
    D,
    /// 4096e-6 m^3 (2048e-6 .. 8192e-6); the paper's nominal off-road terrain.
    E,
    /// 16384e-6 m^3 (8192e-6 .. 32768e-6).
    F,
    /// 65536e-6 m^3 (32768e-6 .. 131072e-6).
    G,
    /// 262144e-6 m^3 (>= 131072e-6).
    H,
}

impl IsoClass {
    /// All classes, smoothest first.
    pub const ALL: [IsoClass; 8] = [
        IsoClass::A,
        IsoClass::B,
        IsoClass::C,
        IsoClass::D,
        IsoClass::E,
        IsoClass::F,
        IsoClass::G,
        IsoClass::H,
    ];

    fn index(self) -> i32 {
        self as i32
    }

    /// Geometric-mean `G_d(n0)` of the class (m^3): 16e-6 * 4^k for class index k (A = 0).
    pub fn gd_n0(self) -> f64 {
        16e-6 * 4f64.powi(self.index())
    }

    /// Class limits of `G_d(n0)` (m^3): `[gd_n0/2, 2 gd_n0)`, open at the ends for A (0) and H (inf).
    pub fn gd_n0_range(self) -> (f64, f64) {
        let g = self.gd_n0();
        let lo = if self == IsoClass::A { 0.0 } else { g / 2.0 };
        let hi = if self == IsoClass::H {
            f64::INFINITY
        } else {
            g * 2.0
        };
        (lo, hi)
    }

    /// The class whose range contains `gd_n0` (A for anything below 32e-6, H above 131072e-6).
    pub fn classify(gd_n0: f64) -> IsoClass {
        for c in IsoClass::ALL {
            if gd_n0 < c.gd_n0_range().1 {
                return c;
            }
        }
        IsoClass::H
    }

    /// Roughness coefficient `alpha_r = G_d(n0) n0^2` (m^3) with waviness 2 (Table 2.4).
    pub fn alpha_r(self) -> f64 {
        PowerLawPsd::iso(self).alpha_r
    }
}

impl FromStr for IsoClass {
    type Err = TerrainError;
    fn from_str(s: &str) -> Result<Self> {
        match s.trim().to_ascii_uppercase().as_str() {
            "A" => Ok(IsoClass::A),
            "B" => Ok(IsoClass::B),
            "C" => Ok(IsoClass::C),
            "D" => Ok(IsoClass::D),
            "E" => Ok(IsoClass::E),
            "F" => Ok(IsoClass::F),
            "G" => Ok(IsoClass::G),
            "H" => Ok(IsoClass::H),
            _ => Err(TerrainError::Unknown {
                what: "ISO 8608 class",
                given: s.to_string(),
                expected: "A, B, C, D, E, F, G, H",
            }),
        }
    }
}

impl fmt::Display for IsoClass {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self:?}")
    }
}

/// Off-road terrains of Tables 1.2 / 2.4 (Wong's measured roughness data, refs [79, 81]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum OffRoadTerrain {
    /// Forestry terrain: `alpha_r` = 1.00e-4, `w` = 1.76.
    Forestry,
    /// Pasture: 3.00e-4, 1.60.
    Pasture,
    /// MVEE (Military Vehicles and Engineering Establishment) test course: 3.16e-4, 2.27.
    Mvee,
    /// Plowed field: 6.50e-4, 1.60.
    Plowed,
}

impl OffRoadTerrain {
    /// All four terrains, in Table 2.4's order.
    pub const ALL: [OffRoadTerrain; 4] = [
        OffRoadTerrain::Forestry,
        OffRoadTerrain::Pasture,
        OffRoadTerrain::Mvee,
        OffRoadTerrain::Plowed,
    ];

    /// Roughness coefficient `alpha_r` of Tables 1.2 / 2.4.
    pub fn alpha_r(self) -> f64 {
        match self {
            OffRoadTerrain::Forestry => 1.00e-4,
            OffRoadTerrain::Pasture => 3.00e-4,
            OffRoadTerrain::Mvee => 3.16e-4,
            OffRoadTerrain::Plowed => 6.50e-4,
        }
    }

    /// Waviness `w` (`beta` of Table 1.2).
    pub fn waviness(self) -> f64 {
        match self {
            OffRoadTerrain::Forestry => 1.76,
            OffRoadTerrain::Pasture => 1.60,
            OffRoadTerrain::Mvee => 2.27,
            OffRoadTerrain::Plowed => 1.60,
        }
    }

    /// Lower-case name as accepted by [`FromStr`].
    pub fn name(self) -> &'static str {
        match self {
            OffRoadTerrain::Forestry => "forestry",
            OffRoadTerrain::Pasture => "pasture",
            OffRoadTerrain::Mvee => "mvee",
            OffRoadTerrain::Plowed => "plowed",
        }
    }
}

impl FromStr for OffRoadTerrain {
    type Err = TerrainError;
    fn from_str(s: &str) -> Result<Self> {
        match s
            .trim()
            .to_ascii_lowercase()
            .replace(['-', '_', ' '], "")
            .as_str()
        {
            "forestry" => Ok(OffRoadTerrain::Forestry),
            "pasture" => Ok(OffRoadTerrain::Pasture),
            "mvee" => Ok(OffRoadTerrain::Mvee),
            "plowed" | "plowedfield" | "ploughed" | "ploughedfield" => Ok(OffRoadTerrain::Plowed),
            _ => Err(TerrainError::Unknown {
                what: "off-road terrain",
                given: s.to_string(),
                expected: "forestry, pasture, mvee, plowed",
            }),
        }
    }
}

impl fmt::Display for OffRoadTerrain {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * b.abs()
    }

    #[test]
    fn iso_classes_match_table_2_4_and_iso_8608() {
        // Table 2.4: alpha_r of classes A-E with w = 2.
        let table = [1.6e-7, 6.4e-7, 2.56e-6, 1.024e-5, 4.096e-5];
        for (c, a) in IsoClass::ALL.iter().zip(table) {
            assert!(close(c.alpha_r(), a, 1e-12), "{c}: {} vs {a}", c.alpha_r());
        }
        // ISO 8608 geometric means, x1e-6 m^3.
        let gm = [
            16.0, 64.0, 256.0, 1024.0, 4096.0, 16384.0, 65536.0, 262144.0,
        ];
        for (c, g) in IsoClass::ALL.iter().zip(gm) {
            assert!(close(c.gd_n0(), g * 1e-6, 1e-12));
            assert!(close(PowerLawPsd::iso(*c).gd_n0(), g * 1e-6, 1e-12));
            assert_eq!(IsoClass::classify(g * 1e-6), *c);
            assert_eq!(PowerLawPsd::iso(*c).iso_class(), *c);
        }
        assert!(close(IsoClass::H.alpha_r(), 2.62144e-3, 1e-12));
        assert_eq!(IsoClass::classify(31.9e-6), IsoClass::A);
        assert_eq!(IsoClass::classify(32.1e-6), IsoClass::B);
        assert_eq!(IsoClass::classify(1.0), IsoClass::H);
    }

    #[test]
    fn off_road_terrains_match_table_1_2() {
        let p = PowerLawPsd::off_road(OffRoadTerrain::Mvee);
        assert_eq!((p.alpha_r, p.waviness), (3.16e-4, 2.27));
        assert_eq!(
            "Plowed-field".parse::<OffRoadTerrain>().unwrap(),
            OffRoadTerrain::Plowed
        );
        for t in OffRoadTerrain::ALL {
            assert_eq!(t.name().parse::<OffRoadTerrain>().unwrap(), t);
            assert!(PowerLawPsd::off_road(t).validate().is_ok());
        }
        assert!("gravel".parse::<OffRoadTerrain>().is_err());
    }

    #[test]
    fn eq_1_6_and_eq_2_8_agree() {
        let m = PowerLawPsd::from_gd_n0(4096e-6, 2.0).unwrap();
        assert!(close(m.alpha_r, 4.096e-5, 1e-12));
        let m = PowerLawPsd::from_gd_n0(1e-3, 2.5).unwrap();
        for n in [0.02, 0.1, 1.0, 4.0] {
            assert!(close(m.gd(n), 1e-3 * (n / N0).powf(-2.5), 1e-12));
        }
    }

    #[test]
    fn integral_is_exact_including_w_equal_one() {
        let m = PowerLawPsd::new(4.096e-5, 2.0).unwrap();
        assert!(close(m.integral(0.02, 5.0), 4.096e-5 * (50.0 - 0.2), 1e-12));
        let m1 = PowerLawPsd::new(2.0, 1.0).unwrap();
        assert!(close(m1.integral(0.5, 8.0), 2.0 * 16f64.ln(), 1e-12));
        let near = PowerLawPsd::new(2.0, 1.0 + 1e-9).unwrap();
        assert!(close(near.integral(0.5, 8.0), 2.0 * 16f64.ln(), 1e-7));
        let m0 = PowerLawPsd::new(3.0, 0.0).unwrap();
        assert!(close(m0.integral(1.0, 2.0), 3.0, 1e-12));
        assert_eq!(m.integral(2.0, 1.0), 0.0);
    }

    #[test]
    fn invalid_inputs_are_errors() {
        assert!(PowerLawPsd::new(-1.0, 2.0).is_err());
        assert!(PowerLawPsd::new(0.0, 2.0).is_err());
        assert!(PowerLawPsd::new(f64::NAN, 2.0).is_err());
        assert!(PowerLawPsd::new(1e-5, f64::NAN).is_err());
        assert!(PowerLawPsd::new(1e-5, -0.1).is_err());
        assert!(PowerLawPsd::new(1e-5, 11.0).is_err());
        assert!(Band::new(5.0, 0.02).is_err());
        assert!(Band::new(0.02, 0.02).is_err());
        assert!(Band::new(0.0, 1.0).is_err());
        assert!(Band::new(f64::NAN, 1.0).is_err());
        assert!(Band::new(0.1, f64::INFINITY).is_err());
        assert_eq!("0.02, 5".parse::<Band>().unwrap(), Band::PAPER);
        assert!("0.02".parse::<Band>().is_err());
        assert!("a,b".parse::<Band>().is_err());
        assert!("5,0.02".parse::<Band>().is_err());
        assert_eq!("e".parse::<IsoClass>().unwrap(), IsoClass::E);
        assert!("Z".parse::<IsoClass>().is_err());
    }
}
