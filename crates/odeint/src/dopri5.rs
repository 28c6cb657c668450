//! Dormand-Prince 5(4) step with error estimate and 4th-order dense output
//! (Hairer, Nørsett & Wanner, *Solving ODEs I*, section II.5/II.6, code DOPRI5).
//!
//! The step, its error estimate and the step-size factors are the
//! shared seven-stage FSAL kernel's ([`crate::explicit_rk`]); this module gives the
//! tableau and the dense output, whose coefficients it keeps in `aux[1..4]`.

use crate::explicit_rk::{FsalKernel, Pair};
use crate::Workspace;

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// Dormand-Prince's tableau and dense output.
#[derive(Debug, Clone, Copy)]
pub(crate) struct DormandPrince;

/// The Dormand-Prince 5(4) kernel.
pub(crate) type Dopri5Kernel = FsalKernel<DormandPrince>;

impl Pair for DormandPrince {
    const C: [f64; 4] = [C2, C3, C4, C5];
    const A2: f64 = A21;
    const A3: [f64; 2] = [A31, A32];
    const A4: [f64; 3] = [A41, A42, A43];
    const A5: [f64; 4] = [A51, A52, A53, A54];
    const A6: [f64; 5] = [A61, A62, A63, A64, A65];
    const B: [f64; 6] = [A71, 0.0, A73, A74, A75, A76];
    const E: [f64; 7] = [E1, 0.0, E3, E4, E5, E6, E7];

    fn prepare_dense(h: f64, ws: &mut Workspace) -> usize {
        let Workspace {
            y,
            y_new: y1,
            k,
            aux,
            ..
        } = ws;
        let [k1, _, k3, k4, k5, k6, k7] = k;
        let [_, r3, r4, r5] = aux;
        for i in 0..y.len() {
            let ydiff = y1[i] - y[i];
            let bspl = h * k1[i] - ydiff;
            r3[i] = bspl;
            r4[i] = ydiff - h * k7[i] - bspl;
            r5[i] =
                h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
        }
        0
    }

    fn dense(theta: f64, _h: f64, ws: &mut Workspace) {
        let Workspace {
            y,
            y_new: y1,
            y_out,
            aux,
            ..
        } = ws;
        let [_, r3, r4, r5] = aux;
        let theta1 = 1.0 - theta;
        for i in 0..y.len() {
            let ydiff = y1[i] - y[i];
            y_out[i] = y[i] + theta * (ydiff + theta1 * (r3[i] + theta * (r4[i] + theta1 * r5[i])));
        }
    }
}
