//! `afsv study`: design studies on the 3-D vehicle. `hps-sensitivity` is Table 6.4 (section
//! 6.5.1): A_hc, A_v and A_b of the front-axle HPS one at a time, with a_wz unloaded and
//! loaded (D1), SP-DRT (D2) and omega_z (D3) over common terrain seeds
//! (`afsv_design::hps_sensitivity`).

use super::CmdResult;
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::hps_sensitivity::{
    HpsSensitivity, HpsVariable, SensitivityRow, StudyScope, MAX_SEEDS,
};
use std::io::IsTerminal;
use std::path::PathBuf;

/// `afsv study` subcommands.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Table 6.4: sensitivity of the ride, roll and yaw measures to A_hc, A_v and A_b.
    HpsSensitivity(HpsArgs),
}

/// Options of `afsv study hps-sensitivity`.
#[derive(clap::Args)]
pub struct HpsArgs {
    /// Terrain seeds per measure, 1 to 100 (each variant runs on the same seeds). About
    /// 13 x (3 N + 1) vehicle runs with the HPS: minutes for 10 seeds on 2 cores.
    #[arg(long, default_value_t = 10)]
    pub seeds: usize,
    /// First terrain seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Changes in percent, comma separated (Table 6.4: -30,-15,15,30).
    #[arg(long, default_value = "-30,-15,15,30", allow_hyphen_values = true)]
    pub changes: String,
    /// Skip the D2 roll runs (SP-DRT), the costliest part.
    #[arg(long)]
    pub no_roll: bool,
    /// Skip the D3 yaw runs (omega_z).
    #[arg(long)]
    pub no_yaw: bool,
    /// Write an SVG of a_wz against the change, one line per variable and load.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing plot file that afsv did not write.
    #[arg(long)]
    pub force: bool,
    /// Print JSON even on a terminal.
    #[arg(long)]
    pub json: bool,
}

/// Run a study.
pub fn run(c: Command) -> CmdResult {
    match c {
        Command::HpsSensitivity(a) => hps(a),
    }
}

/// `--changes` as fractions: finite percents above -100, at most 20 of them.
fn parse_changes(text: &str) -> Result<Vec<f64>, String> {
    let mut out = Vec::new();
    for (i, item) in text.split(',').enumerate() {
        let v: f64 = item
            .trim()
            .parse()
            .map_err(|_| format!("--changes: item {} `{item}` is not a number", i + 1))?;
        if !(v.is_finite() && v > -100.0 && v <= 1000.0) {
            return Err(format!(
                "--changes: {v} % must be above -100 and at most 1000"
            ));
        }
        out.push(v / 100.0);
    }
    if out.len() > 20 {
        return Err(format!("--changes: at most 20 changes, got {}", out.len()));
    }
    Ok(out)
}

fn hps(a: HpsArgs) -> CmdResult {
    if a.seeds == 0 || a.seeds > MAX_SEEDS {
        return Err(format!("--seeds {}: must be 1 to {MAX_SEEDS}", a.seeds).into());
    }
    let changes = parse_changes(&a.changes)?;
    let mut guard = OutputGuard::new(a.force);
    if let Some(p) = &a.plot {
        guard.output("--plot", p, OutputKind::Svg)?;
    }
    let seeds: Vec<u64> = (0..a.seeds as u64)
        .map(|i| a.seed.wrapping_add(i))
        .collect();
    let scope = StudyScope {
        roll: !a.no_roll,
        yaw: !a.no_yaw,
    };
    let designs = 1 + 3 * changes.len();
    let runs = designs * (seeds.len() * (2 + usize::from(scope.roll)) + usize::from(scope.yaw));
    let progress = afsv::progress::Progress::new("afsv study hps-sensitivity", "runs", Some(runs));
    let p = vehicle_3d::VehicleParams::nominal();
    let s = afsv_design::hps_sensitivity(&p, &changes, &seeds, scope, &|d| progress.step(d))?;
    progress.finish();
    if let Some(path) = &a.plot {
        plot(path, &s)?;
    }
    if a.json || !std::io::stdout().is_terminal() {
        afsv::output::print_json(&serde_json::to_value(&s)?)?;
    } else {
        print!("{}", text(&s));
    }
    Ok(())
}

/// A measure's mean with 3 decimals, or "n/a" when it was not run.
fn cell(v: f64) -> String {
    if v.is_finite() {
        format!("{v:.3}")
    } else {
        "n/a".into()
    }
}

/// Table 6.4 as text: one block per measure, rows = changes, columns = variables.
fn text(s: &HpsSensitivity) -> String {
    let mut changes: Vec<f64> = s.rows.iter().map(|r| r.change).collect();
    changes.push(0.0);
    changes.sort_by(f64::total_cmp);
    changes.dedup();
    let find = |v: HpsVariable, c: f64| -> Option<&SensitivityRow> {
        s.rows.iter().find(|r| r.variable == v && r.change == c)
    };
    type Pick = fn(&afsv_design::hps_sensitivity::HpsMeasures) -> f64;
    let blocks: [(&str, Pick); 4] = [
        ("a_wz unloaded (m/s²)", |m| m.a_wz_unloaded_m_s2.mean),
        ("a_wz loaded (m/s²)", |m| m.a_wz_loaded_m_s2.mean),
        ("SP-DRT loaded (m/s²)", |m| m.sp_drt_m_s2.mean),
        ("omega_z loaded (Hz)", |m| m.omega_z_hz),
    ];
    let mut out = format!(
        "HPS sensitivity (Table 6.4), 3-D vehicle with the front-axle HPS, mean over {} terrain seeds\n",
        s.seeds.len()
    );
    for (name, pick) in blocks {
        out += &format!(
            "\n{name}\n  {:>9} {:>9} {:>9} {:>9}\n",
            "change", "A_hc", "A_v", "A_b"
        );
        for &c in &changes {
            let col = |v| {
                if c == 0.0 {
                    cell(pick(&s.nominal))
                } else {
                    find(v, c).map_or("-".into(), |r| cell(pick(&r.measures)))
                }
            };
            out += &format!(
                "  {:>8.0}% {:>9} {:>9} {:>9}\n",
                100.0 * c,
                col(HpsVariable::PistonArea),
                col(HpsVariable::CheckValveArea),
                col(HpsVariable::BleedArea)
            );
        }
    }
    out
}

fn plot(path: &std::path::Path, s: &HpsSensitivity) -> CmdResult {
    let mut columns: Vec<(String, Vec<f64>, Vec<f64>)> = Vec::new();
    for v in HpsVariable::ALL {
        for (load, pick) in [
            (
                "unloaded",
                (|m: &afsv_design::hps_sensitivity::HpsMeasures| m.a_wz_unloaded_m_s2.mean)
                    as fn(&afsv_design::hps_sensitivity::HpsMeasures) -> f64,
            ),
            ("loaded", |m| m.a_wz_loaded_m_s2.mean),
        ] {
            let mut pts: Vec<(f64, f64)> = s
                .rows
                .iter()
                .filter(|r| r.variable == v)
                .map(|r| (100.0 * r.change, pick(&r.measures)))
                .collect();
            pts.push((0.0, pick(&s.nominal)));
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            columns.push((
                format!("{} {load}", v.symbol()),
                pts.iter().map(|p| p.0).collect(),
                pts.iter().map(|p| p.1).collect(),
            ));
        }
    }
    let series: Vec<afsv_plot::Series> = columns
        .iter()
        .map(|(label, x, y)| afsv_plot::Series { label, x, y })
        .collect();
    afsv_plot::line_plot(
        path,
        &format!(
            "HPS sensitivity of a_wz (D1, class E, 20 km/h), {} seeds",
            s.seeds.len()
        ),
        "change of the area (%)",
        "a_wz (m/s²)",
        &series,
    )?;
    afsv::output::mark_svg(path)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn changes_parse_and_bad_ones_are_named() {
        assert_eq!(parse_changes("-30, 15").unwrap(), vec![-0.3, 0.15]);
        assert!(parse_changes("-100").unwrap_err().contains("above -100"));
        assert!(parse_changes("x").unwrap_err().contains("item 1"));
        assert!(parse_changes("nan").is_err());
        let many = vec!["1"; 21].join(",");
        assert!(parse_changes(&many).unwrap_err().contains("at most 20"));
    }
}
