//! The chapter-6 HPS design vector chi = [A_hc, A_v, A_b] (section 6.5, Table 6.5, Eq 6.19)
//! and its application to a strut parameter set.
//!
//! The gas charge pressure P_h0 and the rod area A_hr stay as they are "in order to maintain
//! identical load carrying capacity" (section 6.5.1). The dissertation does not say how the
//! chamber volumes follow a new piston area; here every column height is kept: the free gas
//! volume V_g0 and the piston-side emulsion V_c0 scale with A_hc, the rod-side emulsion V_r0
//! with the annulus A_hc - A_hr (an assumption, docs/design.md).

use crate::error::{positive, DesignError};
use hps_emulsion::StrutParams;
use serde::Serialize;

/// One chapter-6 design (SI units, as in [`StrutParams`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HpsDesign {
    /// A_hc: effective piston area (m^2).
    pub a_hc: f64,
    /// A_v: opening area of one check valve (m^2).
    pub a_v: f64,
    /// A_b: opening area of one bleed orifice (m^2).
    pub a_b: f64,
}

impl HpsDesign {
    /// A design with every area finite, positive and inside the strut registry's plausible
    /// range (`afsv params list strut`: A_hc up to 0.2 m², A_v and A_b up to 1e-3 m²).
    pub fn new(a_hc: f64, a_v: f64, a_b: f64) -> Result<Self, DesignError> {
        Ok(Self {
            a_hc: plausible("a_hc", a_hc)?,
            a_v: plausible("a_v", a_v)?,
            a_b: plausible("a_b", a_b)?,
        })
    }

    /// The design a strut carries (the nominal design for [`StrutParams::front_axle`]).
    pub fn of(p: &StrutParams) -> Self {
        Self {
            a_hc: p.a_hc,
            a_v: p.a_v,
            a_b: p.a_b,
        }
    }

    /// `base` with this design: the three areas set, V_g0 and V_c0 scaled by the piston-area
    /// ratio, V_r0 by the annulus ratio, P_h0 and A_hr kept. The result is validated
    /// ([`StrutParams::validate`]; a piston no wider than the rod is refused there).
    pub fn apply(&self, base: &StrutParams) -> Result<StrutParams, DesignError> {
        let mut p = *base;
        let piston = self.a_hc / base.a_hc;
        let annulus = (self.a_hc - base.a_hr) / (base.a_hc - base.a_hr);
        p.a_hc = self.a_hc;
        p.a_v = self.a_v;
        p.a_b = self.a_b;
        p.v_g0 = base.v_g0 * piston;
        p.v_c0 = base.v_c0 * piston;
        p.v_r0 = base.v_r0 * annulus;
        p.validate()?;
        Ok(p)
    }
}

/// `value` if positive and inside the strut registry's range of `name`.
fn plausible(name: &'static str, value: f64) -> Result<f64, DesignError> {
    use vehicle_components::ParamSet;
    let v = positive(name, value)?;
    let nominal = StrutParams::front_axle();
    let (_, spec) = nominal.find(name).map_err(|_| DesignError::Invalid {
        field: name,
        value,
        reason: "not a strut parameter",
    })?;
    if v > spec.upper || v < spec.lower {
        return Err(DesignError::Invalid {
            field: name,
            value,
            reason: "outside the strut's plausible range (afsv params list strut)",
        });
    }
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn implausible_areas_are_refused() {
        assert!(HpsDesign::new(0.038, 8e-6, 1.1e-5).is_ok());
        assert!(HpsDesign::new(0.038, 9999.0, 1.1e-5).is_err());
        assert!(HpsDesign::new(5.0, 8e-6, 1.1e-5).is_err());
        assert!(HpsDesign::new(0.038, 8e-6, f64::NAN).is_err());
    }

    #[test]
    fn zero_design_change_returns_the_nominal_set() {
        let p = StrutParams::front_axle();
        assert_eq!(HpsDesign::of(&p).apply(&p).unwrap(), p);
    }

    #[test]
    fn table_6_5_optimum_scales_the_volumes() {
        let p = StrutParams::front_axle();
        let d = HpsDesign::new(0.0474, 4.28e-6, 27.3e-6).unwrap();
        let q = d.apply(&p).unwrap();
        assert_eq!((q.a_hc, q.a_v, q.a_b), (0.0474, 4.28e-6, 27.3e-6));
        assert_eq!((q.a_hr, q.p_h0), (p.a_hr, p.p_h0));
        assert!((q.v_g0 / p.v_g0 - 0.0474 / 0.038).abs() < 1e-12);
        let ann = (0.0474 - p.a_hr) / (0.038 - p.a_hr);
        assert!((q.v_r0 / p.v_r0 - ann).abs() < 1e-12);
    }

    #[test]
    fn invalid_designs_are_refused() {
        let e = HpsDesign::new(0.04, 0.0, 1e-5).unwrap_err();
        assert!(e.to_string().contains("a_v"), "{e}");
        // A piston no wider than the rod leaves no annulus.
        let p = StrutParams::front_axle();
        let d = HpsDesign::new(p.a_hr, p.a_v, p.a_b).unwrap();
        assert!(d.apply(&p).is_err());
    }
}
