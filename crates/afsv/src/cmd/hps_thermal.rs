//! `afsv hps thermal`: the struts of a vehicle over a working shift, their gas and body
//! temperatures and the ride height these set, with and without a levelling valve
//! (`hps_emulsion::thermal`, docs/layouts.md "HPS temperature and ride height").
//!
//! The shift is `afsv_design::strut_shift`'s; the dissipation is given (`--power-w`), read
//! from a D1 ride of the vehicle (`--ride`: each strut's travel replayed through it) or from
//! a simulated harmonic stroke of that strut (`--stroke-hz`, `--stroke-mm`).

use super::{args, CmdResult};
use afsv::output::OutputGuard;
use afsv_design::report::strut_shift::shift_report;
use afsv_design::shift_case::{shift_case, ShiftOptions};
use afsv_design::strut_shift::{strut_shift, Shift};
use serde_json::json;
use std::path::PathBuf;
use vehicle_3d::Load;

/// Options of `afsv hps thermal`.
#[derive(clap::Args)]
pub struct ThermalArgs {
    #[arg(long, help = super::described::HELP)]
    pub vehicle: Option<PathBuf>,
    /// Load case whose static strut loads are carried.
    #[arg(long, default_value = "loaded")]
    pub load: Load,
    /// Also a rear strut when the description's rear axle is rigid: the front strut scaled
    /// for the rear static load (the designer's default rear strut, docs/layouts.md).
    #[arg(long)]
    pub with_rear: bool,
    /// Ambient temperature (degC).
    #[arg(long = "ambient-c", default_value_t = 20.0, allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub ambient_c: f64,
    /// Temperature at which the gas was charged and the ride height set (degC).
    #[arg(long = "charge-c", default_value_t = 20.0, allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub charge_c: f64,
    /// Strut temperature at the start of the shift (degC); default: the ambient (parked
    /// overnight).
    #[arg(long = "start-c", allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub start_c: Option<f64>,
    /// Mean damping dissipation of each strut (W). Without it, each strut's dissipation is
    /// read from a simulated harmonic stroke (--stroke-hz, --stroke-mm).
    #[arg(long = "power-w", allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub power_w: Option<f64>,
    /// Read each strut's dissipation from a D1 ride of the vehicle (class E terrain, the
    /// struts' recorded travel replayed through the strut) instead of a harmonic stroke.
    #[arg(long, conflicts_with = "power_w")]
    pub ride: bool,
    /// Speed of that ride (km/h), in (0, 80].
    #[arg(long = "speed-kmh", default_value_t = 20.0, allow_hyphen_values = true, value_parser = args::positive_f64, requires = "ride")]
    pub speed_kmh: f64,
    /// Terrain seed of that ride.
    #[arg(long, default_value_t = 1, requires = "ride")]
    pub seed: u64,
    /// Frequency of the harmonic stroke that sets the dissipation (Hz).
    #[arg(long = "stroke-hz", default_value_t = 1.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub stroke_hz: f64,
    /// Amplitude of that stroke (mm); the default 1 Hz, 10 mm (63 mm/s peak) is an
    /// assumed moderate working ride, not a measured one.
    #[arg(long = "stroke-mm", default_value_t = 10.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub stroke_mm: f64,
    /// Length of the shift (h), at most 72.
    #[arg(long, default_value_t = 8.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub hours: f64,
    /// Time between table rows (min).
    #[arg(long = "step-min", default_value_t = 30.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub step_min: f64,
    /// Levelling valve deadband, half width (mm).
    #[arg(long = "deadband-mm", default_value_t = 5.0, allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub deadband_mm: f64,
    /// Levelling valve time constant (s).
    #[arg(long = "levelling-tau-s", default_value_t = 30.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub levelling_tau_s: f64,
    /// Levelling valve's largest flow (L/min).
    #[arg(long = "levelling-flow-l-min", default_value_t = 6.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub levelling_flow_l_min: f64,
    /// Write the front strut as it is at the end of the shift without levelling (its
    /// parameter set at the gas and body temperatures reached: the same hardware, gas and
    /// oil; docs/layouts.md) to FILE, for `afsv vehicle ride --hps FILE` and the other
    /// `--hps FILE` options.
    #[arg(long)]
    pub strut_out: Option<PathBuf>,
    /// The same with the levelling valve's oil (the strut as the valve left it).
    #[arg(long)]
    pub strut_out_levelled: Option<PathBuf>,
    /// Replace an existing -o or --strut-out file afsv did not write (never the --vehicle
    /// file).
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub table: afsv::table::TableOutput,
}

/// Run `afsv hps thermal`.
pub fn run(a: ThermalArgs) -> CmdResult {
    let options = ShiftOptions {
        load: a.load,
        with_rear: a.with_rear,
        ambient_c: a.ambient_c,
        charge_c: a.charge_c,
        start_c: a.start_c,
        power_w: a.power_w,
        ride: a.ride.then_some((a.speed_kmh, a.seed)),
        stroke: (a.stroke_hz, a.stroke_mm),
        hours: a.hours,
        step_min: a.step_min,
        valve: (a.deadband_mm, a.levelling_tau_s, a.levelling_flow_l_min),
    };
    options.check_size()?;
    let mut guard = OutputGuard::new(a.force);
    super::described::declare(&mut guard, a.vehicle.as_deref())?;
    a.table.declare(&mut guard)?;
    let other = afsv::output::OutputKind::Other;
    guard.output_if("--strut-out", a.strut_out.as_deref(), other)?;
    guard.output_if(
        "--strut-out-levelled",
        a.strut_out_levelled.as_deref(),
        other,
    )?;
    let v = super::described::articulated(a.vehicle.as_deref())?;
    let (params, spec, conditions) = shift_case(&v, &options)?;
    let shift = strut_shift(&params, &spec).map_err(|e| format!("`{}`: {e}", v.name))?;
    write_end_struts(&a, &shift)?;
    let (table, mut full, summary) = shift_report(&v.name, &conditions, &spec, &shift)?;
    full["provenance"] = afsv::provenance::stamp();
    a.table.emit(
        &table,
        &full,
        &summary,
        "afsv hps thermal",
        json!({ "vehicle": v.name, "conditions": full["conditions"] }),
    )?;
    Ok(())
}

/// `--strut-out` and `--strut-out-levelled`: the front strut's parameter set at the end of
/// the shift, without and with the levelling valve
/// ([`afsv_design::strut_shift::AxleShift::end_strut`]).
fn write_end_struts(a: &ThermalArgs, shift: &Shift) -> CmdResult {
    let Some(front) = shift.axles.iter().find(|x| x.axle == "front") else {
        if a.strut_out.is_some() || a.strut_out_levelled.is_some() {
            return Err("--strut-out: the front strut rests on an end stop under this load".into());
        }
        return Ok(());
    };
    for (flag, path, levelled) in [
        ("--strut-out", &a.strut_out, false),
        ("--strut-out-levelled", &a.strut_out_levelled, true),
    ] {
        let Some(path) = path else { continue };
        let strut = front
            .end_strut(levelled)
            .map_err(|e| format!("{flag}: the strut at the end of the shift: {e}"))?;
        afsv::output::write_json_file(path, &strut)?;
    }
    Ok(())
}
