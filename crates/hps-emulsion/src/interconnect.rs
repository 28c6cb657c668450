//! Hydraulic interconnection of two struts (issue 23, "Interconnected struts";
//! `docs/layouts.md`): two lines cross-connect the piston-side chamber of each strut with
//! the rod-side chamber of the other. Between the two struts of one axle (left, right) it is
//! a roll interconnection, between the front and rear struts of one side a pitch
//! interconnection: the component is the same, only which struts it joins differs.
//!
//! Each line is an oil volume with a gas accumulator (a node at one pressure `P_a`), joined
//! to its two strut chambers by a line resistance each: a port orifice (turbulent, the law of
//! the strut's own bleed orifices, Eq 5.12) in series with a length of line (laminar,
//! Hagen-Poiseuille, the linear law of Eq 5.12's leakage term). The accumulator sits at the
//! piston-side port, so the long run of line leads to the other strut's rod-side annulus,
//! whose small area keeps the line's flow small. The struts are [`HpsStrut::ported`] with a
//! sealed piston: their damping is in the ports.
//!
//! Why cross-connected: a strut's force is `P_hc A_hc - P_hr (A_hc - A_hr)` (Eq 5.1). In
//! bounce both struts compress, each line's piston end pushes `A_hc z'` in and its rod end
//! takes `(A_hc - A_hr) z'` out: the accumulator sees only `A_hr z'`, the soft spring of one
//! rod area. In roll (or pitch) one strut compresses while the other extends: both ends of
//! a line push oil in, the accumulator sees `(2 A_hc - A_hr) z'`, and the pressure rise acts
//! on the piston of one strut and the annulus of the other, both opposing the motion: the
//! roll stiffness is `((2 A_hc - A_hr) / A_hr)^2` times the bounce stiffness. With two
//! different struts (a front and a larger rear strut of a pitch link, each line with its own
//! design) the two circuits differ: [`CrossCoupledPair::stiffness_matrix`] and
//! [`CrossCoupledPair::circuit_pressures`] give the hand model and the statics.
//!
//! States per line: the accumulator's gas volume `V_a` (m^3). The node's continuity, the
//! form of Eq 5.5 with the line's oil compressibility:
//! `V_a' = (q_1 + q_2) / (1 + n P_a V_l / (beta_h V_a))`, `P_a = P_pre (V_pre / V_a)^n`,
//! `q_i` the flow from the node into chamber `i`.

use crate::error::{positive, HpsError};
use crate::params::StrutParams;
use crate::strut::{ChamberInflow, HpsStrut, StrutOutputs};

/// The strut of `p` with a sealed piston for an interconnection: no bleed orifice, check
/// valve or leakage between its chambers (`n_b = n_v = 0`, `k_l = 0`); its damping moves
/// into the lines' port orifices. Everything else (areas, oil, gas, emulsion, friction) is
/// `p`'s. Build it with [`HpsStrut::ported`].
pub fn sealed_piston(p: &StrutParams) -> StrutParams {
    StrutParams {
        n_b: 0,
        n_v: 0,
        k_l: 0.0,
        ..*p
    }
}

/// Length of a pitch line from the accumulator at one axle's strut to the other axle's
/// strut (m): the prototype's 5.12 m between the axles (1.68 m and 3.44 m from the
/// articulation joint, Table 6.1) plus the routing along the frames and the hose loop that
/// crosses the joint (assumption).
pub const PITCH_LINE_M: f64 = 6.0;

/// One end of a line: the length of line from the accumulator to the strut port and the
/// port's orifice.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineEnd {
    /// Length of line from the accumulator to the port (m).
    pub length_m: f64,
    /// Opening area of the port orifice (m^2).
    pub port_area_m2: f64,
}

/// Parameters of one interconnection line; the two lines of a pair share them. The oil
/// (density `rho_h`, bulk modulus `beta_h`), the accumulator gas's polytropic exponent `n`
/// and the struts' pressures come from the struts' [`StrutParams`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineParams {
    /// Inner diameter of the line (m).
    pub diameter_m: f64,
    /// Dynamic viscosity of the oil (Pa s).
    pub viscosity_pa_s: f64,
    /// Discharge coefficient of the port orifices (the `C_b` of Eq 5.12).
    pub port_cd: f64,
    /// The end at the piston-side chamber, where the accumulator is mounted.
    pub piston_end: LineEnd,
    /// The end at the other strut's rod-side chamber (the line across the vehicle).
    pub rod_end: LineEnd,
    /// Accumulator size: its gas volume at the precharge (m^3).
    pub accumulator_volume_m3: f64,
    /// Accumulator precharge pressure (Pa, absolute).
    pub precharge_pa: f64,
}

impl LineParams {
    /// The generic roll line of the Table 6.3 front strut (`docs/layouts.md` gives the
    /// reasoning for every value; none is in the dissertation): a 38 mm (1 1/2 in) line,
    /// 0.3 m from the accumulator to the piston port and 2.5 m across the axle to the other
    /// strut's rod port, ISO VG 32 oil at 40 °C, port orifices that together give the
    /// nominal strut's bounce damping, an 8.4 L accumulator precharged to 2.4 MPa (0.9 times
    /// the lowest line pressure of the D2 runs) holding the strut's own gas charge.
    pub fn front_axle_roll() -> Self {
        Self {
            diameter_m: 0.038,
            viscosity_pa_s: 0.027,
            port_cd: 0.7,
            piston_end: LineEnd {
                length_m: 0.3,
                port_area_m2: 3.3e-4,
            },
            rod_end: LineEnd {
                length_m: 2.5,
                port_area_m2: 6.2e-5,
            },
            accumulator_volume_m3: 8.4e-3,
            precharge_pa: 2.4e6,
        }
    }

    /// The generic pitch lines of one side (`docs/layouts.md`, "Pitch interconnection"):
    /// `[line at the front strut's piston side, line at the rear strut's piston side]`, the
    /// rear strut's areas `ratio` times the front's (the prototype's scaled rear strut:
    /// 1.457). Each is [`LineParams::front_axle_roll`] with its long run [`PITCH_LINE_M`]
    /// from the front axle to the rear one across the articulation joint, and every port and
    /// accumulator at a rear-strut chamber `ratio` times the roll line's: at equal stroke
    /// rates the ports then see the roll line's flows per unit area, so its pressure drops,
    /// and each accumulator holds its piston-side strut's gas charge as in the roll line.
    pub fn side_pitch(ratio: f64) -> Result<[Self; 2], HpsError> {
        in_range(
            "ratio",
            ratio,
            0.25,
            4.0,
            "rear-to-front strut area ratio between 0.25 and 4",
        )?;
        let roll = Self::front_axle_roll();
        let long = LineEnd {
            length_m: PITCH_LINE_M,
            ..roll.rod_end
        };
        let at_front = Self {
            rod_end: LineEnd {
                port_area_m2: ratio * roll.rod_end.port_area_m2,
                ..long
            },
            ..roll
        };
        let at_rear = Self {
            piston_end: LineEnd {
                port_area_m2: ratio * roll.piston_end.port_area_m2,
                ..roll.piston_end
            },
            rod_end: long,
            accumulator_volume_m3: ratio * roll.accumulator_volume_m3,
            ..roll
        };
        at_front.validate()?;
        at_rear.validate()?;
        Ok([at_front, at_rear])
    }

    /// Validate every field (the error names it): positive areas and lengths, and values
    /// in the ranges of hydraulic suspension lines.
    pub fn validate(&self) -> Result<(), HpsError> {
        in_range(
            "diameter_m",
            self.diameter_m,
            2e-3,
            0.1,
            "line bore between 2 and 100 mm",
        )?;
        in_range(
            "viscosity_pa_s",
            self.viscosity_pa_s,
            1e-3,
            1.0,
            "oil viscosity between 1 mPa s and 1 Pa s",
        )?;
        in_range(
            "port_cd",
            self.port_cd,
            0.05,
            1.0,
            "discharge coefficient in [0.05, 1]",
        )?;
        let bore = std::f64::consts::FRAC_PI_4 * self.diameter_m * self.diameter_m;
        for (field_l, field_a, end) in [
            (
                "piston_end.length_m",
                "piston_end.port_area_m2",
                self.piston_end,
            ),
            ("rod_end.length_m", "rod_end.port_area_m2", self.rod_end),
        ] {
            in_range(
                field_l,
                end.length_m,
                0.05,
                30.0,
                "line length between 5 cm and 30 m",
            )?;
            positive(field_a, end.port_area_m2)?;
            if end.port_area_m2 > bore {
                return Err(HpsError::InvalidParameter {
                    field: field_a,
                    value: end.port_area_m2,
                    reason: "port orifice larger than the line's bore",
                });
            }
        }
        in_range(
            "accumulator_volume_m3",
            self.accumulator_volume_m3,
            1e-5,
            0.1,
            "accumulator between 0.01 and 100 L",
        )?;
        in_range(
            "precharge_pa",
            self.precharge_pa,
            2e5,
            5e7,
            "precharge between 0.2 and 50 MPa absolute",
        )?;
        Ok(())
    }
}

fn in_range(
    field: &'static str,
    value: f64,
    lo: f64,
    hi: f64,
    reason: &'static str,
) -> Result<(), HpsError> {
    if value.is_finite() && (lo..=hi).contains(&value) {
        Ok(())
    } else {
        Err(HpsError::InvalidParameter {
            field,
            value,
            reason,
        })
    }
}

/// Series resistance of one line end: `dp = R q + a q |q|`, `R = 128 mu L / (pi d^4)` the
/// laminar line (Hagen-Poiseuille), `a = rho / (2 (C A)^2)` the turbulent port orifice
/// (Eq 5.12's law solved for the pressure drop).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndResistance {
    /// Laminar resistance R (Pa s/m^3).
    pub laminar: f64,
    /// Turbulent coefficient a (Pa s^2/m^6).
    pub turbulent: f64,
}

impl EndResistance {
    /// Flow (m^3/s) driven by the pressure drop `dp` (Pa) across the end, in the direction
    /// of the drop: the root of `R q + a q |q| = dp`,
    /// `q = 2 dp / (R + sqrt(R^2 + 4 a |dp|))`. Odd, increasing, slope `1/R` at zero (no
    /// regularisation needed), `sgn(dp) sqrt(|dp| / a)` for large drops.
    #[inline]
    pub fn flow(&self, dp: f64) -> f64 {
        2.0 * dp
            / (self.laminar
                + (self.laminar * self.laminar + 4.0 * self.turbulent * dp.abs()).sqrt())
    }
}

/// One line: its two end resistances and its accumulator, ready to evaluate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HydraulicLine {
    /// The end at the piston-side chamber (the accumulator's).
    pub piston_end: EndResistance,
    /// The end at the other strut's rod-side chamber.
    pub rod_end: EndResistance,
    /// Oil volume of the line (m^3), compressible with `beta_h`.
    pub oil_volume_m3: f64,
    precharge_pa: f64,
    accumulator_volume_m3: f64,
    n: f64,
    beta: f64,
}

/// What one line evaluation gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineFlows {
    /// Accumulator (node) pressure P_a (Pa).
    pub p_node: f64,
    /// Flow from the node into the piston-side chamber at the line's first end (m^3/s).
    pub q_piston: f64,
    /// Flow from the node into the rod-side chamber at its second end (m^3/s).
    pub q_rod: f64,
    /// Rate of the accumulator's gas volume (m^3/s).
    pub gas_volume_rate: f64,
    /// Power dissipated in the two end resistances (W), `sum (P_a - P_i) q_i >= 0`.
    pub dissipation_w: f64,
}

impl HydraulicLine {
    /// The line of `p` with the oil and gas of `fluid` (`rho_h`, `beta_h`, `n`).
    pub fn new(p: &LineParams, fluid: &StrutParams) -> Result<Self, HpsError> {
        p.validate()?;
        fluid.validate_ported(true)?;
        let d4 = p.diameter_m.powi(4);
        let end = |e: &LineEnd| EndResistance {
            laminar: 128.0 * p.viscosity_pa_s * e.length_m / (std::f64::consts::PI * d4),
            turbulent: fluid.rho_h / (2.0 * (p.port_cd * e.port_area_m2).powi(2)),
        };
        let bore = std::f64::consts::FRAC_PI_4 * p.diameter_m * p.diameter_m;
        Ok(Self {
            piston_end: end(&p.piston_end),
            rod_end: end(&p.rod_end),
            oil_volume_m3: bore * (p.piston_end.length_m + p.rod_end.length_m),
            precharge_pa: p.precharge_pa,
            accumulator_volume_m3: p.accumulator_volume_m3,
            n: fluid.n,
            beta: fluid.beta_h,
        })
    }

    /// Accumulator pressure (Pa) at gas volume `v_a` (m^3): `P_pre (V_pre / V_a)^n`.
    #[inline]
    pub fn pressure(&self, v_a: f64) -> f64 {
        self.precharge_pa * (self.accumulator_volume_m3 / v_a.max(1e-12)).powf(self.n)
    }

    /// Accumulator gas volume (m^3) at pressure `p` (Pa): the inverse of
    /// [`HydraulicLine::pressure`]. Errors when `p` does not exceed the precharge: the
    /// accumulator would be empty of oil (its bladder at its stop), outside this model.
    pub fn gas_volume_at(&self, p: f64) -> Result<f64, HpsError> {
        if !(p.is_finite() && p > self.precharge_pa) {
            return Err(HpsError::InvalidParameter {
                field: "precharge_pa",
                value: self.precharge_pa,
                reason: "the static pressure must exceed the accumulator precharge",
            });
        }
        Ok(self.accumulator_volume_m3 * (self.precharge_pa / p).powf(1.0 / self.n))
    }

    /// Hydraulic compliance of the node (m^3/Pa) at gas volume `v_a`:
    /// `V_a / (n P_a) + V_l / beta_h`.
    pub fn compliance(&self, v_a: f64) -> f64 {
        v_a / (self.n * self.pressure(v_a)) + self.oil_volume_m3 / self.beta
    }

    /// Energy stored in the node (J) at gas volume `v_a`, from the precharge state: the
    /// gas's polytropic compression work `(P_a V_a - P_pre V_pre) / (n - 1)` (`P_pre V_pre
    /// ln(V_pre / V_a)` for `n = 1`) plus the line oil's `V_l P_a^2 / (2 beta_h)`. Along
    /// [`HydraulicLine::evaluate`]'s rate its derivative is `-P_a (q_1 + q_2)`.
    pub fn stored_energy(&self, v_a: f64) -> f64 {
        let p = self.pressure(v_a);
        let gas = if (self.n - 1.0).abs() < 1e-12 {
            self.precharge_pa * self.accumulator_volume_m3 * (self.accumulator_volume_m3 / v_a).ln()
        } else {
            (p * v_a - self.precharge_pa * self.accumulator_volume_m3) / (self.n - 1.0)
        };
        gas + self.oil_volume_m3 * p * p / (2.0 * self.beta)
    }

    /// Flows and the gas-volume rate at gas volume `v_a` with the piston-side chamber at
    /// `p_piston` and the rod-side chamber at `p_rod` (Pa). No allocation.
    #[inline]
    pub fn evaluate(&self, v_a: f64, p_piston: f64, p_rod: f64) -> LineFlows {
        let p_node = self.pressure(v_a);
        let q_piston = self.piston_end.flow(p_node - p_piston);
        let q_rod = self.rod_end.flow(p_node - p_rod);
        let stiff = 1.0 + self.n * p_node * self.oil_volume_m3 / (self.beta * v_a.max(1e-12));
        LineFlows {
            p_node,
            q_piston,
            q_rod,
            gas_volume_rate: (q_piston + q_rod) / stiff,
            dissipation_w: (p_node - p_piston) * q_piston + (p_node - p_rod) * q_rod,
        }
    }
}

/// Two struts cross-connected by two lines (module docs): line 0 joins strut 0's piston
/// side (its accumulator end) to strut 1's rod side, line 1 strut 1's piston side to strut
/// 0's rod side. Circuit `k` is line `k` with the two chambers it joins. State: strut 0's
/// states, strut 1's, then the two accumulator gas volumes. The struts may differ (a front
/// and a rear strut of a pitch interconnection); so may the lines.
#[derive(Debug, Clone, PartialEq)]
pub struct CrossCoupledPair {
    struts: [HpsStrut; 2],
    lines: [HydraulicLine; 2],
    n0: usize,
    n1: usize,
}

/// What a pair evaluation gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairOutputs {
    /// Each strut's outputs (Eq 5.1 force with its pressures).
    pub struts: [StrutOutputs; 2],
    /// Each line's flows and node pressure.
    pub lines: [LineFlows; 2],
}

impl CrossCoupledPair {
    /// The pair of two struts (each validated as [`HpsStrut::ported`], so a sealed piston is
    /// accepted) and one line design for both lines (a roll interconnection of two equal
    /// struts). The struts must share the oil and the gas exponent (the lines carry their
    /// oil).
    pub fn new(struts: [HpsStrut; 2], line: &LineParams) -> Result<Self, HpsError> {
        Self::with_lines(struts, [line, line])
    }

    /// The pair with its own design for each line: `lines[k]` is line `k`, whose
    /// accumulator sits at strut `k`'s piston side (a pitch interconnection of a front and
    /// a larger rear strut, [`LineParams::side_pitch`]).
    pub fn with_lines(struts: [HpsStrut; 2], lines: [&LineParams; 2]) -> Result<Self, HpsError> {
        let (a, b) = (struts[0].params(), struts[1].params());
        if a.rho_h != b.rho_h || a.beta_h != b.beta_h || a.n != b.n {
            return Err(HpsError::InvalidParameter {
                field: "rho_h",
                value: b.rho_h,
                reason: "the interconnected struts must share the oil and gas (rho_h, beta_h, n)",
            });
        }
        let lines = [
            HydraulicLine::new(lines[0], a)?,
            HydraulicLine::new(lines[1], a)?,
        ];
        let (n0, n1) = (struts[0].n_states(), struts[1].n_states());
        Ok(Self {
            struts,
            lines,
            n0,
            n1,
        })
    }

    /// The struts.
    pub fn struts(&self) -> &[HpsStrut; 2] {
        &self.struts
    }

    /// Line `k` (0 or 1).
    pub fn line(&self, k: usize) -> &HydraulicLine {
        &self.lines[k]
    }

    /// Number of states: both struts' plus two.
    pub fn n_states(&self) -> usize {
        self.n0 + self.n1 + 2
    }

    /// Index of strut `k`'s first state in the pair's state.
    pub fn strut_state(&self, k: usize) -> usize {
        if k == 0 {
            0
        } else {
            self.n0
        }
    }

    /// Index of line `k`'s accumulator gas volume in the state.
    pub fn line_state(&self, k: usize) -> usize {
        self.n0 + self.n1 + k
    }

    /// The rest state at pressure `p` (Pa) in every chamber and both accumulators
    /// ([`CrossCoupledPair::rest_state_at`] with both circuits at `p`).
    pub fn rest_state(&self, p: f64, state: &mut [f64]) -> Result<(), HpsError> {
        self.rest_state_at([p, p], state)
    }

    /// The rest state with circuit `k` (line `k`'s node, strut `k`'s piston side and the
    /// other strut's rod side) at pressure `p[k]` (Pa): the static equilibrium of the pair
    /// (the oil in each circuit is what this state holds, so it is the equilibrium at
    /// whatever deflections the struts are at). Errors when a pressure does not exceed its
    /// line's precharge or the vapour pressure, or the buffer has the wrong length.
    pub fn rest_state_at(&self, p: [f64; 2], state: &mut [f64]) -> Result<(), HpsError> {
        if state.len() != self.n_states() {
            return Err(HpsError::InvalidExcitation(format!(
                "state buffer has {} entries, the pair has {}",
                state.len(),
                self.n_states()
            )));
        }
        let (s0, rest) = state.split_at_mut(self.n0);
        let (s1, lines) = rest.split_at_mut(self.n1);
        // each pressure is checked by the strut whose piston side it fills
        for (k, s) in [s0, s1].into_iter().enumerate() {
            self.struts[k].rest_state_at_pressure(p[k], s)?;
            // the rod side's state is its pressure (Eq 5.6): the other circuit's
            s[ROD_PRESSURE] = p[1 - k];
        }
        for k in 0..2 {
            lines[k] = self.lines[k].gas_volume_at(p[k])?;
        }
        Ok(())
    }

    /// State derivatives and outputs at deflections `z` and rates `zdot` (m, m/s,
    /// compression positive) of the two struts. No allocation.
    #[inline]
    pub fn evaluate(
        &self,
        z: [f64; 2],
        zdot: [f64; 2],
        state: &[f64],
        dstate: &mut [f64],
    ) -> PairOutputs {
        let (s0, rest) = state.split_at(self.n0);
        let (s1, lines) = rest.split_at(self.n1);
        let (pc0, pr0) = self.struts[0].chamber_pressures(s0);
        let (pc1, pr1) = self.struts[1].chamber_pressures(s1);
        // line 0: strut 0's piston side to strut 1's rod side; line 1 the mirror
        let l0 = self.lines[0].evaluate(lines[0], pc0, pr1);
        let l1 = self.lines[1].evaluate(lines[1], pc1, pr0);
        let (d0, rest) = dstate.split_at_mut(self.n0);
        let (d1, dlines) = rest.split_at_mut(self.n1);
        let in0 = ChamberInflow {
            piston: l0.q_piston,
            rod: l1.q_rod,
        };
        let in1 = ChamberInflow {
            piston: l1.q_piston,
            rod: l0.q_rod,
        };
        let o0 = self.struts[0].evaluate_with_inflow(z[0], zdot[0], in0, s0, d0);
        let o1 = self.struts[1].evaluate_with_inflow(z[1], zdot[1], in1, s1, d1);
        dlines[0] = l0.gas_volume_rate;
        dlines[1] = l1.gas_volume_rate;
        PairOutputs {
            struts: [o0, o1],
            lines: [l0, l1],
        }
    }

    /// The circuit pressures (Pa) at which the pair at rest carries what its struts carry
    /// at rest alone with both chambers of strut `k` at `strut_p[k]`, the pressure force
    /// `(P_k - p_amb) A_hr,k` (Eq 5.1). Eq 5.1 for both struts, with circuit `k` at `Q_k`,
    /// `Q_0 A_hc,0 - Q_1 A_ann,0 = P_0 A_hr,0` and `Q_1 A_hc,1 - Q_0 A_ann,1 = P_1 A_hr,1`,
    /// solve to
    /// `Q_0 = P_0 + (P_1 - P_0) A_ann,0 A_hr,1 / D`, `Q_1 = P_1 - (P_1 - P_0) A_ann,1 A_hr,0 / D`,
    /// `D = A_hc,0 A_hc,1 - A_ann,0 A_ann,1 > 0`: the struts' own pressures when they are
    /// equal (the similar struts of a loaded vehicle), otherwise the circuits share the
    /// difference.
    pub fn circuit_pressures(&self, strut_p: [f64; 2]) -> [f64; 2] {
        let [a, b] = [self.struts[0].params(), self.struts[1].params()];
        let d = a.a_hc * b.a_hc - a.a_ann() * b.a_ann();
        let dp = strut_p[1] - strut_p[0];
        [
            strut_p[0] + dp * a.a_ann() * b.a_hr / d,
            strut_p[1] - dp * b.a_ann() * a.a_hr / d,
        ]
    }

    /// Hand-derived quasi-static stiffness matrix (N/m) of the pair at rest with circuit
    /// `k` at pressure `p[k]` and the struts at deflections `z` (`docs/layouts.md`):
    /// `K = G^T diag(1/C_0, 1/C_1) G`, `G = [[A_hc,0, -A_ann,1], [-A_ann,0, A_hc,1]]`
    /// (row `k`: the oil the struts' compressions push into circuit `k`), `C_k` the
    /// compliance of circuit `k` (strut `k`'s piston side gas and emulsion, the other
    /// strut's rod-side emulsion, line `k`'s accumulator and oil); `dF = K dz`.
    pub fn stiffness_matrix(&self, p: [f64; 2], z: [f64; 2]) -> Result<[[f64; 2]; 2], HpsError> {
        let mut s = [0.0; MAX_PAIR_STATES];
        let n = self.n_states();
        if n > MAX_PAIR_STATES {
            return Err(HpsError::InvalidExcitation(format!(
                "the pair has {n} states, the hand stiffness takes up to {MAX_PAIR_STATES}"
            )));
        }
        self.rest_state_at(p, &mut s[..n])?;
        let c = [0, 1].map(|k| {
            let at = self.strut_state(k);
            self.struts[k].chamber_compliances(z[k], &s[at..at + self.struts[k].n_states()])
        });
        let circuit = [0, 1]
            .map(|k| c[k].piston + c[1 - k].rod + self.lines[k].compliance(s[self.line_state(k)]));
        let [a, b] = [self.struts[0].params(), self.struts[1].params()];
        let g = [[a.a_hc, -b.a_ann()], [-a.a_ann(), b.a_hc]];
        let mut k = [[0.0; 2]; 2];
        for (i, row) in k.iter_mut().enumerate() {
            for (j, kij) in row.iter_mut().enumerate() {
                *kij = (0..2).map(|c| g[c][i] * g[c][j] / circuit[c]).sum();
            }
        }
        Ok(k)
    }

    /// Hand-derived quasi-static stiffness (N/m per strut) of the motion `shape` (bounce
    /// `[1, 1]`; roll or pitch `[1, -1]`): the Rayleigh quotient `u^T K u / u^T u` of
    /// [`CrossCoupledPair::stiffness_matrix`]. For two equal struts at one pressure it is
    /// `A_hr^2 / C` in bounce and `(A_hc + A_ann)^2 / C` against it.
    pub fn mode_stiffness(
        &self,
        p: [f64; 2],
        z: [f64; 2],
        shape: [f64; 2],
    ) -> Result<f64, HpsError> {
        let k = self.stiffness_matrix(p, z)?;
        let ku = [0, 1].map(|i| k[i][0] * shape[0] + k[i][1] * shape[1]);
        Ok((shape[0] * ku[0] + shape[1] * ku[1]) / (shape[0] * shape[0] + shape[1] * shape[1]))
    }
}

/// Largest pair state [`CrossCoupledPair::stiffness_matrix`] takes (two struts with every
/// extension and two lines).
const MAX_PAIR_STATES: usize = 18;

/// Index of the rod-side pressure in a strut's state (Eq 5.6's state, [`HpsStrut`]).
const ROD_PRESSURE: usize = 1;

#[cfg(test)]
mod tests;
