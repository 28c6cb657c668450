//! Gas-oil emulsion properties versus pressure (Eqs 5.8-5.11 = 6.14-6.17).

/// Gas fraction, density and bulk modulus of the emulsion in one chamber at one pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Emulsion {
    /// Gas volume fraction gamma_i = V_gi / V_hi (-), Eq 5.9.
    pub gamma: f64,
    /// Mass density rho_i (kg/m^3), Eq 5.10.
    pub rho: f64,
    /// Effective bulk modulus beta_i (Pa), Eq 5.11.
    pub beta: f64,
}

/// Emulsion state at absolute pressure `p` (Pa) for reference pressure `p0`, polytropic
/// exponent `n`, oil bulk modulus `beta_h`, oil density `rho_h` and reference gas fraction
/// `gamma0` (Eqs 5.8-5.11). With `gamma0 = 0` this is pure oil: `gamma = 0`,
/// `rho = rho_h / (1 - (p - p0)/beta_h)`, `beta = beta_h`. `p` must be positive.
#[inline]
pub fn emulsion(p: f64, p0: f64, n: f64, beta_h: f64, rho_h: f64, gamma0: f64) -> Emulsion {
    let ratio = if gamma0 > 0.0 {
        (p0 / p).powf(1.0 / n)
    } else {
        0.0
    };
    emulsion_from_ratio(p, ratio, p0, n, beta_h, rho_h, gamma0)
}

/// As [`emulsion`] with the entrapped gas's volume ratio `(p0 / p)^(1/n)` of Eq 5.9 given
/// (`gas_ratio`), for a caller that already has it (the strut's piston side, where it is the
/// relative free gas volume `V_g / V_g0` of Eq 5.4).
#[inline]
pub fn emulsion_from_ratio(
    p: f64,
    gas_ratio: f64,
    p0: f64,
    n: f64,
    beta_h: f64,
    rho_h: f64,
    gamma0: f64,
) -> Emulsion {
    // Eq 5.8: oil volume ratio V_hi / V_hi0.
    let oil = 1.0 - (p - p0) / beta_h;
    let gamma = if gamma0 > 0.0 {
        // Eq 5.9.
        gamma0 * gas_ratio / oil
    } else {
        0.0
    };
    // Eq 5.10.
    let rho = rho_h / (oil * (1.0 + gamma));
    // Eq 5.11.
    let beta = if gamma > 0.0 {
        n * (1.0 + gamma) * p * beta_h / (n * p + gamma * beta_h)
    } else {
        beta_h
    };
    Emulsion { gamma, rho, beta }
}

/// Volume at pressure `p` of an emulsion that occupies `v0` at `p0` (Eq 5.8 summed over gas
/// and oil): `v0 / (1 + gamma0) * [(1 - (p - p0)/beta_h) + gamma0 (p0/p)^(1/n)]`.
pub fn emulsion_volume(v0: f64, p: f64, p0: f64, n: f64, beta_h: f64, gamma0: f64) -> f64 {
    let oil = 1.0 - (p - p0) / beta_h;
    let gas = if gamma0 > 0.0 {
        gamma0 * (p0 / p).powf(1.0 / n)
    } else {
        0.0
    };
    v0 / (1.0 + gamma0) * (oil + gas)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_state_is_gamma0_and_oil_density() {
        let e = emulsion(1e6, 1e6, 1.4, 1.7e9, 850.0, 0.03);
        assert!((e.gamma - 0.03).abs() < 1e-15);
        assert!((e.rho - 850.0 / 1.03).abs() < 1e-9);
        // beta = n (1+g) p bh / (n p + g bh) by hand: 1.4*1.03*1e6*1.7e9/(1.4e6+0.03*1.7e9)
        let hand = 1.4 * 1.03 * 1e6 * 1.7e9 / (1.4e6 + 0.03 * 1.7e9);
        assert!((e.beta - hand).abs() < 1e-3);
        assert!((e.beta - 4.6783e7).abs() < 1e4, "{}", e.beta);
    }

    #[test]
    fn pure_oil_limit() {
        let e = emulsion(2e6, 1e6, 1.4, 1.7e9, 850.0, 0.0);
        assert_eq!(e.gamma, 0.0);
        assert_eq!(e.beta, 1.7e9);
        assert!((e.rho - 850.0 / (1.0 - 1e6 / 1.7e9)).abs() < 1e-9);
    }

    #[test]
    fn bulk_modulus_matches_volume_derivative() {
        // beta = -V / (dV/dP) from the volume law of Eq 5.8 (with the same approximation as
        // Eq 5.11: dV_h/dP = -V_h/beta_h).
        let (p0, n, bh, g0) = (1e6, 1.4, 1.7e9, 0.05);
        let p = 1.7e6;
        let e = emulsion(p, p0, n, bh, 850.0, g0);
        let vg = g0 * (p0 / p).powf(1.0 / n);
        let vh = 1.0 - (p - p0) / bh;
        let dv = -vg / (n * p) - vh / bh;
        let beta = -(vg + vh) / dv;
        assert!((e.beta - beta).abs() / beta < 1e-12);
        // and the gas fraction falls with pressure, the bulk modulus rises.
        let e2 = emulsion(2.5e6, p0, n, bh, 850.0, g0);
        assert!(e2.gamma < e.gamma && e2.beta > e.beta);
    }
}
