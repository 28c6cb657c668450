//! The three test problems as `odeint` systems, with an RHS counter.

use afs_hydraulics::{AfsParams, AfsSystem};
use afsv_dynamics::{EquationForm, Manoeuvre, SteerSource, VehicleParams, YawPlaneModel};
use hps_emulsion::{HpsExtensions, HpsStrut, StrutParams};
use odeint::OdeSystem;
use std::cell::Cell;
use std::f64::consts::PI;

/// Counts right-hand-side evaluations of the wrapped system.
pub struct Counted<S> {
    pub sys: S,
    pub calls: Cell<usize>,
}

impl<S: OdeSystem> OdeSystem for Counted<S> {
    fn dim(&self) -> usize {
        self.sys.dim()
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        self.calls.set(self.calls.get() + 1);
        self.sys.rhs(t, y, dydt)
    }
}

/// The strut driven by `z = A sin(2 pi f t)` (as `hps_emulsion::simulate_strut` does).
pub struct HarmonicStrut {
    strut: HpsStrut,
    w: f64,
    a: f64,
}

impl OdeSystem for HarmonicStrut {
    fn dim(&self) -> usize {
        self.strut.n_states()
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let (s, c) = (self.w * t).sin_cos();
        self.strut
            .derivatives(self.a * s, self.a * self.w * c, y, dydt);
    }
}

/// One comparison problem.
pub struct Scenario<S> {
    pub name: &'static str,
    pub sys: Counted<S>,
    pub y0: Vec<f64>,
    pub t_out: Vec<f64>,
    pub breakpoints: Vec<f64>,
    pub typical: Vec<f64>,
    /// The model's own step ceiling for odeint (diffsol has none).
    pub max_step: f64,
    /// The model's default rtol and atol (per typical magnitude), and its `Auto` solver.
    pub default_tol: (f64, f64),
    pub auto: odeint::Solver,
}

/// Front-axle strut, `f` Hz, amplitude `a` m, `cycles` periods, 360 Hz output.
pub fn strut(name: &'static str, f: f64, a: f64, cycles: f64) -> Scenario<HarmonicStrut> {
    let p = StrutParams::front_axle();
    let strut = HpsStrut::new(&p, &HpsExtensions::none(), 2.0 * PI * f * a).expect("strut");
    let mut y0 = vec![0.0; strut.n_states()];
    strut.initial_state(0.0, &mut y0).expect("static state");
    let typical = (0..y0.len()).map(|i| strut.state_typical(i)).collect();
    let t_end = cycles / f;
    let mut t_out = odeint::output_grid(0.0, t_end, 1.0 / 360.0);
    if t_end - t_out[t_out.len() - 1] > 1e-9 {
        t_out.push(t_end);
    }
    let auto = if f < hps_emulsion::simulate::AUTO_SWITCH_HZ {
        odeint::Solver::Rosenbrock23
    } else {
        odeint::Solver::Dopri5
    };
    Scenario {
        name,
        sys: Counted {
            sys: HarmonicStrut {
                strut,
                w: 2.0 * PI * f,
                a,
            },
            calls: Cell::new(0),
        },
        y0,
        t_out,
        breakpoints: Vec::new(),
        typical,
        max_step: 1.0 / (20.0 * f),
        default_tol: (1e-6, 1e-9),
        auto,
    }
}

/// What the yaw-plane model borrows.
pub struct YawParts {
    pub vehicle: VehicleParams,
    pub afs: AfsSystem,
    pub manoeuvre: Manoeuvre,
}

impl YawParts {
    /// Section 3.3 pulse: loaded, 50 km/h, 30 deg half-sine of 0.2 s, 10 s.
    pub fn pulse() -> Self {
        Self {
            vehicle: VehicleParams::loaded(),
            afs: AfsSystem::new(AfsParams::nominal()).expect("AFS"),
            manoeuvre: Manoeuvre::pulse(50.0 / 3.6, 30.0),
        }
    }
}

/// The yaw-plane pulse at 200 Hz output, with the pulse's kinks as breakpoints.
pub fn yaw(parts: &YawParts) -> Scenario<YawPlaneModel<'_, AfsSystem>> {
    let model = YawPlaneModel::new(
        &parts.vehicle,
        &parts.afs,
        parts.manoeuvre.speed_m_s,
        &parts.manoeuvre.steer,
        EquationForm::EnergyConsistent,
    );
    let y0 = model.initial_state(0.0);
    // The yaw-plane model integrates the AFS pressures in MPa: every state is O(1).
    let typical = vec![1.0; y0.len()];
    let t_out = odeint::output_grid(0.0, parts.manoeuvre.duration_s, 0.005);
    let mut breakpoints = match &parts.manoeuvre.steer {
        SteerSource::Open(input) => input.breakpoints(),
        SteerSource::Driver(_) => Vec::new(),
    };
    breakpoints.retain(|&b| b > 0.0 && b < parts.manoeuvre.duration_s);
    breakpoints.sort_by(f64::total_cmp);
    Scenario {
        name: "yaw pulse 10 s",
        sys: Counted {
            sys: model,
            calls: Cell::new(0),
        },
        y0,
        t_out,
        breakpoints,
        typical,
        max_step: 0.05,
        default_tol: (1e-5, 1e-6),
        auto: odeint::Solver::Dopri5,
    }
}
