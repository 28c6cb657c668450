//! `afsv optimize hps`: the chapter-6 HPS design optimisation (Eqs 6.19-6.20) on the 3-D
//! vehicle by a genetic algorithm (`afsv_design::hps_optimum`), then the optimum and the
//! nominal design re-evaluated over terrain seeds with SP-DRT and omega_z.

use crate::cmd::CmdResult;
use afsv_design::hps_optimum::{optimise_hps, HpsGaSettings, HpsOptimum};
use afsv_design::hps_speed_sweep::hps_speed_sweep;
use std::io::IsTerminal;

/// Options of `afsv optimize hps`.
#[derive(clap::Args)]
pub struct HpsArgs {
    /// GA population (even, 4 to 1000).
    #[arg(long, default_value_t = 20)]
    pub population: usize,
    /// GA generations (1 to 1000); each costs `population` vehicle runs.
    #[arg(long, default_value_t = 10)]
    pub generations: usize,
    /// Seed of the GA.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// The fixed terrain seed of the search (the first of the re-evaluation seeds).
    #[arg(long, default_value_t = 1)]
    pub terrain_seed: u64,
    /// Terrain seeds of the re-evaluation of the optimum and the nominal design (1 to 100).
    #[arg(long, default_value_t = 10)]
    pub reevaluation_seeds: usize,
    /// Skip the SP-DRT re-evaluation (D2, the costliest runs).
    #[arg(long)]
    pub no_roll: bool,
    /// Write the optimum's strut parameters to FILE (the `--hps FILE` of `afsv vehicle` and
    /// `afsv study speed-sweep`). An existing file afsv did not write needs --force.
    #[arg(long)]
    pub strut_out: Option<std::path::PathBuf>,
    /// Replace an existing --strut-out file.
    #[arg(long)]
    pub force: bool,
    /// Then run D4 on the optimum (Fig 6.16): both loads at 10, 15, 20, 25 and 30 km/h on the
    /// re-evaluation seeds, with the speed at which a_wz crosses the 8 h caution zone.
    #[arg(long)]
    pub speed_sweep: bool,
    #[arg(long, help = crate::cmd::described::HELP)]
    pub vehicle: Option<std::path::PathBuf>,
    /// Print JSON even on a terminal.
    #[arg(long)]
    pub json: bool,
}

/// The D4 speeds of section 6.5.2 (km/h).
const D4_SPEEDS_KMH: [f64; 5] = [10.0, 15.0, 20.0, 25.0, 30.0];

/// GA progress: one step per generation.
struct Generations(afsv::progress::Progress);

impl optimize::Progress for Generations {
    fn report(&self, _phase: &str, done: usize, _total: usize, best: f64) {
        self.0.step(&format!("generation {done}, best F {best:.4}"));
    }
}

/// Run the optimisation and print the result.
pub fn run(a: &HpsArgs) -> CmdResult {
    if !(4..=1000).contains(&a.population) || a.population % 2 == 1 {
        return Err(format!("--population {}: must be even, 4 to 1000", a.population).into());
    }
    if !(1..=1000).contains(&a.generations) {
        return Err(format!("--generations {}: must be 1 to 1000", a.generations).into());
    }
    if !(1..=100).contains(&a.reevaluation_seeds) {
        return Err(format!(
            "--reevaluation-seeds {}: must be 1 to 100",
            a.reevaluation_seeds
        )
        .into());
    }
    let settings = HpsGaSettings {
        population: a.population,
        generations: a.generations,
        ga_seed: a.seed,
        terrain_seed: a.terrain_seed,
        reevaluation_seeds: a.reevaluation_seeds,
        reevaluate_roll: !a.no_roll,
        ..HpsGaSettings::default()
    };
    let progress = Generations(afsv::progress::Progress::new(
        "afsv optimize hps",
        "generations",
        Some(a.generations),
    ));
    let mut guard = afsv::output::OutputGuard::new(a.force);
    if let Some(v) = a
        .vehicle
        .as_deref()
        .filter(|v| crate::cmd::described::is_file(v))
    {
        guard.input("--vehicle", v)?;
    }
    if let Some(path) = &a.strut_out {
        guard.output("--strut-out", path, afsv::output::OutputKind::Other)?;
    }
    let base = crate::cmd::described::with_front_strut(a.vehicle.as_deref(), "optimize hps")?;
    let r = optimise_hps(&base, &settings, &progress)?;
    progress.0.finish();
    let mut best = base.clone();
    best.hps = r.design.apply(&base.hps)?;
    if let Some(path) = &a.strut_out {
        let text = serde_json::to_string_pretty(&best.hps)? + "\n";
        afsv_records::atomic::write(path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    let sweep = if a.speed_sweep {
        let seeds: Vec<u64> = (0..a.reevaluation_seeds as u64)
            .map(|i| a.terrain_seed.wrapping_add(i))
            .collect();
        let runs = 2 * D4_SPEEDS_KMH.len() * seeds.len();
        let p = afsv::progress::Progress::new("afsv optimize hps: D4", "runs", Some(runs));
        let s = hps_speed_sweep(&best, &D4_SPEEDS_KMH, &seeds, &|d| p.step(d))?;
        p.finish();
        Some(s)
    } else {
        None
    };
    if a.json || !std::io::stdout().is_terminal() {
        let mut v = serde_json::to_value(&r)?;
        if let Some(s) = &sweep {
            v["speed_sweep"] = serde_json::to_value(s)?;
        }
        afsv::output::print_json(&v)?;
    } else {
        print!("{}", text(&r));
        if let Some(s) = &sweep {
            print!("\n{}", crate::cmd::study::sweep_text(s));
        }
    }
    if r.feasible {
        Ok(())
    } else {
        Err(afsv::output::NotEarned(format!(
            "optimize hps: no design met the a_wz limit of Eq 6.20 on the search seed (best a_wz {} m/s²); the best found is printed, not an optimum (more generations or another vehicle)",
            v(r.optimum_ride.a_wz_m_s2, 3)
        ))
        .into())
    }
}

/// A value or "n/a".
fn v(x: f64, digits: usize) -> String {
    if x.is_finite() {
        format!("{x:.digits$}")
    } else {
        "n/a".into()
    }
}

fn text(r: &HpsOptimum) -> String {
    let (n, o) = (&r.nominal_design, &r.design);
    let (an, ao) = (&r.nominal_over_seeds, &r.optimum_over_seeds);
    // (row, nominal, optimum, decimals)
    let rows = [
        ("A_hc (m²)".to_string(), n.a_hc, o.a_hc, 4),
        ("A_v (mm²)".into(), n.a_v * 1e6, o.a_v * 1e6, 2),
        ("A_b (mm²)".into(), n.a_b * 1e6, o.a_b * 1e6, 2),
        (
            "a_wz, search seed (m/s²)".into(),
            r.nominal_ride.a_wz_m_s2,
            r.optimum_ride.a_wz_m_s2,
            3,
        ),
        (
            "d_s, search seed (m)".into(),
            r.nominal_ride.d_s_m,
            r.optimum_ride.d_s_m,
            4,
        ),
        ("F (Eq 6.19)".into(), 2.0, r.objective, 3),
        (
            format!("a_wz, {} seeds (m/s²)", an.a_wz_m_s2.n),
            an.a_wz_m_s2.mean,
            ao.a_wz_m_s2.mean,
            3,
        ),
        (
            "SP-DRT loaded (m/s²)".into(),
            an.sp_drt_m_s2.mean,
            ao.sp_drt_m_s2.mean,
            2,
        ),
        (
            "omega_z loaded (Hz)".into(),
            an.omega_z_hz,
            ao.omega_z_hz,
            2,
        ),
    ];
    let mut s = format!(
        "HPS design (Eq 6.19: F = a_wz/a_wzn + d_s/d_sn, a_wz <= {} m/s²), unloaded, 20 km/h, class E, terrain seed {}\n",
        r.settings.a_wz_limit_m_s2, r.settings.terrain_seed
    );
    s += &format!("  {:<26} {:>12} {:>12}\n", "", "nominal", "optimum");
    for (name, a, b, digits) in rows {
        s += &format!("  {name:<26} {:>12} {:>12}\n", v(a, digits), v(b, digits));
    }
    s += &format!(
        "  {} vehicle runs in the search; the optimum is {}\n",
        r.evaluations,
        if r.feasible {
            "feasible"
        } else {
            "NOT feasible (a_wz above the limit)"
        }
    );
    s
}
