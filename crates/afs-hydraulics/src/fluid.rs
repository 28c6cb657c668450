//! Fluid compliance: chamber-group volumes (Eq 3.7 / 6.7), cavitation floor, and the stored
//! compression energy consistent with the continuity equations (Eqs 3.4 / 4.5).

/// Chamber-group volumes (V_1, V_2) of Eq 3.7 / 6.7 from the strut displacements
/// d_L = l_L - l_0, d_R = l_R - l_0:
/// V_1 = V_0 + A_c d_L - A_r d_R (left piston side + right rod side, pressure P_c),
/// V_2 = V_0 - A_r d_L + A_c d_R (left rod side + right piston side, pressure P_r),
/// each clamped below at `v_min`.
#[inline]
pub fn chamber_volumes(
    v0: f64,
    ac: f64,
    ar: f64,
    disp_left: f64,
    disp_right: f64,
    v_min: f64,
) -> (f64, f64) {
    let v1 = v0 + ac * disp_left - ar * disp_right;
    let v2 = v0 - ar * disp_left + ac * disp_right;
    (v1.max(v_min), v2.max(v_min))
}

/// Cavitation factor s(p) in [0, 1] that multiplies the bulk modulus while a chamber is
/// expanding (net inflow < 0): 0 at and below `p_cav`, 1 at and above `p_cav + band`,
/// C¹ cubic smoothstep between. As p approaches p_cav, dp/dt -> 0 (the fluid releases
/// vapour/air instead of sustaining tension), so the pressure cannot cross p_cav.
#[inline]
pub fn cavitation_factor(p: f64, p_cav: f64, band: f64) -> f64 {
    let u = (p - p_cav) / band;
    if u >= 1.0 {
        1.0
    } else if u <= 0.0 {
        0.0
    } else {
        u * u * (3.0 - 2.0 * u)
    }
}

/// Stored compression energy (J) of a fluid volume `v` at pressure `p` with constant bulk
/// modulus `b`, relative to the reference pressure `p_ref`.
///
/// The continuity law V dp/dt = -B dV/dt (closed chamber) conserves the fluid mass
/// V·exp((p - p_ref)/B); the work -∫p dV done on the fluid along that path is
/// E(V, p) = V [ B (e^x - 1 - x) + p_ref (e^x - 1) ], x = (p - p_ref)/B,
/// which satisfies dE/dt = -p dV/dt exactly for every trajectory of that law.
#[inline]
pub fn chamber_energy_const(v: f64, p: f64, b: f64, p_ref: f64) -> f64 {
    let x = (p - p_ref) / b;
    let em1 = x.exp_m1();
    v * (b * (em1 - x) + p_ref * em1)
}

/// Stored compression energy (J) for a pressure-dependent bulk modulus `b(p)`, relative to
/// `p_ref`: E = V e^{Λ(p)} ∫_{p_ref}^{p} p' e^{-Λ(p')}/b(p') dp', Λ(p) = ∫_{p_ref}^{p} dp'/b,
/// integrated with `steps` classical Runge-Kutta steps (no allocation).
///
/// When both pressures are positive the steps are uniform in s = ln p (dp = p ds): they
/// crowd at low pressure, where an entrained-air modulus (roughly proportional to p) changes
/// fastest. Otherwise they are uniform in p.
pub fn chamber_energy_general<F: Fn(f64) -> f64>(
    v: f64,
    p: f64,
    p_ref: f64,
    b: F,
    steps: usize,
) -> f64 {
    let n = steps.max(1);
    let logarithmic = p > 0.0 && p_ref > 0.0;
    // integration variable u: p itself, or ln p; dp/du = 1 or p
    let (u0, u1) = if logarithmic {
        (p_ref.ln(), p.ln())
    } else {
        (p_ref, p)
    };
    let h = (u1 - u0) / n as f64;
    // state (Λ, F); dΛ/du = (dp/du)/b, dF/du = (dp/du) p e^{-Λ}/b
    let f = |u: f64, lam: f64| {
        let (pp, dp_du) = if logarithmic {
            (u.exp(), u.exp())
        } else {
            (u, 1.0)
        };
        let w = dp_du / b(pp);
        (w, w * pp * (-lam).exp())
    };
    let (mut lam, mut acc) = (0.0_f64, 0.0_f64);
    for i in 0..n {
        let u = u0 + i as f64 * h;
        let (k1l, k1f) = f(u, lam);
        let (k2l, k2f) = f(u + 0.5 * h, lam + 0.5 * h * k1l);
        let (k3l, k3f) = f(u + 0.5 * h, lam + 0.5 * h * k2l);
        let (k4l, k4f) = f(u + h, lam + h * k3l);
        lam += h / 6.0 * (k1l + 2.0 * k2l + 2.0 * k3l + k4l);
        acc += h / 6.0 * (k1f + 2.0 * k2f + 2.0 * k3f + k4f);
    }
    v * lam.exp() * acc
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn general_energy_matches_closed_form_for_constant_modulus() {
        let (v, b, pref) = (7.6e-3, 1.6e9, 1.0e5);
        for p in [2.0e4, 1.0e6, 1.2e7] {
            let e1 = chamber_energy_const(v, p, b, pref);
            let e2 = chamber_energy_general(v, p, pref, |_| b, 400);
            assert!((e1 - e2).abs() <= 1e-9 * e1.abs().max(1e-3), "{e1} vs {e2}");
        }
        // small-strain limit: V (p - p_ref)^2 / (2B) + p_ref V (p - p_ref)/B
        let p = 5.0e6;
        let approx = v * ((p - pref).powi(2) / (2.0 * b) + pref * (p - pref) / b);
        assert!((chamber_energy_const(v, p, b, pref) / approx - 1.0).abs() < 1e-2);
    }

    #[test]
    fn cavitation_factor_shape() {
        assert_eq!(cavitation_factor(0.0, 1.0e4, 4.0e4), 0.0);
        assert_eq!(cavitation_factor(1.0e4, 1.0e4, 4.0e4), 0.0);
        assert_eq!(cavitation_factor(5.0e4, 1.0e4, 4.0e4), 1.0);
        assert_eq!(cavitation_factor(1.0e7, 1.0e4, 4.0e4), 1.0);
        assert!((cavitation_factor(3.0e4, 1.0e4, 4.0e4) - 0.5).abs() < 1e-12);
    }
}
