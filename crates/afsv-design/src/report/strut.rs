//! The strut records and tables of `afsv hps` (crate `hps-emulsion`, Chapter 5): the
//! sidecar of a harmonic test's record, the table of the laboratory programme, and a
//! measured record read as the channels an identification compares with.

use afsv_records::{Record, RecordError};
use hps_emulsion::Measured;
use serde_json::{json, Value};
use std::path::Path;

/// The columns of the laboratory programme's table (`afsv hps characterize`), SI units:
/// the loop metrics of the last cycle of each test.
pub const CHARACTERIZE_COLUMNS: [&str; 14] = [
    "frequency_hz",
    "amplitude_m",
    "peak_velocity_m_s",
    "effective_stiffness_n_m",
    "equivalent_damping_n_s_m",
    "peak_damping_compression_n",
    "peak_damping_extension_n",
    "dissipated_energy_j",
    "spring_loop_area_j",
    "damping_loop_area_n_m_s",
    "p_piston_min_pa",
    "p_piston_max_pa",
    "p_rod_min_pa",
    "p_rod_max_pa",
];

/// The harmonic test of `afsv hps harmonic` whose record a sidecar describes.
#[derive(Debug, Clone, Copy)]
pub struct HarmonicRun<'a> {
    /// The strut's name (a built-in or the file it was read from).
    pub strut: &'a str,
    /// Gas volume fraction of the emulsion.
    pub gamma0: f64,
    /// Output sample rate of the record (Hz).
    pub sample_rate_hz: f64,
    /// Excitation frequency (Hz).
    pub frequency_hz: f64,
    /// Displacement amplitude (m, + compression).
    pub amplitude_m: f64,
    /// Cycles simulated.
    pub cycles: f64,
}

/// The sidecar of a harmonic test's record: the model, the strut, the excitation and the
/// units and signs of the record's channels (deflection and force positive in
/// compression, pressures absolute).
pub fn harmonic_sidecar(run: &HarmonicRun) -> Value {
    json!({
        "written_by": "afsv hps harmonic",
        "model": "hps-emulsion",
        "strut": run.strut,
        "sample_rate_hz": run.sample_rate_hz,
        "excitation": {"kind": "harmonic", "frequency_hz": run.frequency_hz, "amplitude_m": run.amplitude_m, "cycles": run.cycles},
        "gamma0": run.gamma0,
        "units": {"time_s": "s", "displacement_m": "m (+ compression)", "velocity_m_s": "m/s",
                  "force_n": "N (+ compressive)", "p_piston_pa": "Pa absolute", "p_rod_pa": "Pa absolute"},
    })
}

/// The measured channels of a strut record (`path` names it in errors): `time_s` and
/// `displacement_m` required, `velocity_m_s`, `force_n`, `p_piston_pa` and `p_rod_pa`
/// compared when present.
pub fn measured(rec: &Record, path: &Path) -> Result<Measured, RecordError> {
    let col = |n: &str| rec.column(n).map(<[f64]>::to_vec);
    Ok(Measured {
        time: rec.require("time_s", path)?.to_vec(),
        displacement: rec.require("displacement_m", path)?.to_vec(),
        velocity: col("velocity_m_s"),
        force: col("force_n"),
        p_piston: col("p_piston_pa"),
        p_rod: col("p_rod_pa"),
    })
}
