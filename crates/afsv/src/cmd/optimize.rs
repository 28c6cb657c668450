//! `afsv optimize afs`: the chapter-4 design optimisation of the frame-steering system
//! (section 4.3; `afsv_design::afs_optimum`). Text on a terminal, JSON with `--json` or
//! when piped; progress on stderr; resumable through `--checkpoint`.

use super::CmdResult;
use afsv::output::{is_afsv_json, OutputGuard, OutputKind};
use afsv_design::afs_problem::FullLockGeometry;
use afsv_design::{
    optimise, AfsDesign, AfsDesignBounds, AfsOptimisationSettings, AfsOptimum, AfsProblem,
    AfsProblemSpec, AfsRunState, AfsVariable, AhpHierarchy, DesignEvaluation, InterferenceGeometry,
    Measure, Objective,
};
use afsv_dynamics::EquationForm;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

/// `afsv optimize` subcommands.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Chapter 4: optimise the frame-steering design [A_0, l_1, l_2, a_v, B_eff] (Eq 4.8 with the AHP weights of Eq 4.17, Eq 4.10 and a minimum full-lock steering arm as constraints) by multi-start pattern search and SQP.
    Afs(AfsArgs),
}

/// Options of `afsv optimize afs`.
#[derive(clap::Args)]
pub struct AfsArgs {
    /// Relax the upper B_eff bound to 2.08 GPa (Table 4.4) instead of 1.7 GPa (Table 4.3).
    #[arg(long)]
    pub relaxed: bool,
    /// Minimum steering arm at +-45 deg articulation (m); the printed compact optima have 0.25-0.27 m.
    #[arg(long, default_value_t = afsv_design::afs_problem::DEFAULT_MIN_STEERING_ARM_M, value_parser = super::args::positive_f64)]
    pub min_arm_m: f64,
    /// Leave out the second run without the steering-arm constraint.
    #[arg(long)]
    pub no_arm_comparison: bool,
    /// Pattern-search starts besides the current design (maximin Latin hypercube).
    #[arg(long, default_value_t = 4)]
    pub starts: usize,
    /// Seed of the starts and search hypercubes.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Relative tolerance of the simulations (the noise of F grows above 1e-8).
    #[arg(long, default_value_t = 1e-8, value_parser = super::args::positive_f64)]
    pub rtol: f64,
    /// Form of the yaw equations.
    #[arg(long, value_enum, default_value_t = FormArg::EnergyConsistent)]
    pub form: FormArg,
    /// Eq 4.9: direction of the left front mount from the joint (deg from the x axis); give with --tire-point and --engine-point.
    #[arg(long, allow_hyphen_values = true, value_parser = super::args::finite_f64, requires_all = ["tire_point", "engine_point"])]
    pub front_mount_dir_deg: Option<f64>,
    /// Eq 4.9: inner extremity of the left front tire, "x,y" in m (front-unit frame, origin at the joint).
    #[arg(long, allow_hyphen_values = true, value_parser = point, requires_all = ["front_mount_dir_deg", "engine_point"])]
    pub tire_point: Option<[f64; 2]>,
    /// Eq 4.9: extremity of the engine supporting structure, "x,y" in m.
    #[arg(long, allow_hyphen_values = true, value_parser = point, requires_all = ["front_mount_dir_deg", "tire_point"])]
    pub engine_point: Option<[f64; 2]>,
    /// Write the step responses of the optimum and the current design (SVG, Fig 4.9).
    #[arg(long)]
    pub plot_step: Option<PathBuf>,
    /// Write the pulse responses of the optimum and the current design (SVG, Fig 4.9).
    #[arg(long)]
    pub plot_pulse: Option<PathBuf>,
    /// Checkpoint file: written after every iteration; an existing one is resumed.
    #[arg(long)]
    pub checkpoint: Option<PathBuf>,
    /// Replace existing output files afsv did not write.
    #[arg(long)]
    pub force: bool,
    /// Print JSON even on a terminal.
    #[arg(long)]
    pub json: bool,
}

/// Form of the yaw equations.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum FormArg {
    /// Newton-Euler about the joint, conserves energy (default).
    EnergyConsistent,
    /// Eq 3.13 as printed.
    PaperEq313,
}

fn point(s: &str) -> Result<[f64; 2], String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|t| t.trim().parse::<f64>().map_err(|e| format!("{t:?}: {e}")))
        .collect::<Result<_, _>>()?;
    match v[..] {
        [x, y] if x.is_finite() && y.is_finite() => Ok([x, y]),
        _ => Err(format!(
            "expected \"x,y\" with two finite numbers, got {s:?}"
        )),
    }
}

/// Run `afsv optimize`.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Afs(a) => run_afs(&a),
    }
}

/// The checkpoint file: one run state per configuration, with the settings it belongs to.
#[derive(Serialize, Deserialize)]
struct Checkpoint {
    written_by: String,
    sign_convention: String,
    /// The settings of the command line the checkpoint belongs to.
    settings: Value,
    runs: Vec<AfsRunState>,
}

/// One configuration's result.
struct RunOutcome {
    label: &'static str,
    min_arm_m: Option<f64>,
    optimum: AfsOptimum,
    seconds: f64,
}

fn spec_of(a: &AfsArgs, min_arm: Option<f64>) -> Result<AfsProblemSpec, String> {
    let mut spec = AfsProblemSpec {
        bounds: if a.relaxed {
            AfsDesignBounds::table_4_2_relaxed()
        } else {
            AfsDesignBounds::table_4_2()
        },
        min_steering_arm_m: min_arm,
        ..AfsProblemSpec::default()
    };
    spec.measure.options.rtol = a.rtol;
    spec.measure.options.form = match a.form {
        FormArg::EnergyConsistent => EquationForm::EnergyConsistent,
        FormArg::PaperEq313 => EquationForm::PaperEq313,
    };
    if let (Some(dir), Some(t), Some(e)) = (a.front_mount_dir_deg, a.tire_point, a.engine_point) {
        spec.interference =
            Some(InterferenceGeometry::new(dir.to_radians(), t, e).map_err(|e| e.to_string())?);
    }
    Ok(spec)
}

fn run_afs(a: &AfsArgs) -> CmdResult {
    if a.starts >= afsv_design::afs_optimum::MAX_STARTS {
        return Err(format!(
            "--starts must be below {}",
            afsv_design::afs_optimum::MAX_STARTS
        )
        .into());
    }
    let mut guard = OutputGuard::new(a.force);
    for (label, p) in [
        ("--plot-step", &a.plot_step),
        ("--plot-pulse", &a.plot_pulse),
    ] {
        if let Some(p) = p {
            guard.output(label, p, OutputKind::Svg)?;
        }
    }
    if let Some(p) = &a.checkpoint {
        guard.output("--checkpoint", p, OutputKind::Sidecar)?;
    }
    let settings = AfsOptimisationSettings {
        extra_starts: a.starts,
        seed: a.seed,
        ..AfsOptimisationSettings::default()
    };
    let objective = Objective::new(AhpHierarchy::chapter4().weights()?.composite)?;
    let mut configs: Vec<(&'static str, Option<f64>)> =
        vec![("with the steering-arm constraint", Some(a.min_arm_m))];
    if !a.no_arm_comparison {
        configs.push(("without the steering-arm constraint", None));
    }
    let settings_json = json!({
        "relaxed": a.relaxed, "min_arm_m": a.min_arm_m, "arm_comparison": !a.no_arm_comparison,
        "starts": a.starts, "seed": a.seed, "rtol": a.rtol,
        "form": match a.form { FormArg::EnergyConsistent => "energy_consistent", FormArg::PaperEq313 => "paper_eq_3_13" },
        "eq_4_9": {"front_mount_dir_deg": a.front_mount_dir_deg, "tire_point": a.tire_point, "engine_point": a.engine_point},
        "solver": settings,
    });
    let mut ck = match &a.checkpoint {
        Some(p) => load_checkpoint(p, &settings_json)?,
        None => None,
    }
    .unwrap_or(Checkpoint {
        written_by: "afsv optimize afs".into(),
        sign_convention: "afsv-v1".into(),
        settings: settings_json,
        runs: Vec::new(),
    });
    let progress = Bar::new()?;
    let mut outcomes = Vec::new();
    let mut problems = Vec::new();
    for (i, (label, arm)) in configs.iter().enumerate() {
        let t = std::time::Instant::now();
        let problem = AfsProblem::new(spec_of(a, *arm)?, objective)?;
        let resume = ck.runs.get(i).cloned().unwrap_or_default();
        let optimum = optimise(&problem, &settings, resume, &progress, &mut |st| {
            let Some(path) = &a.checkpoint else {
                return Ok(());
            };
            ck.runs.truncate(i);
            ck.runs.push(st.clone());
            write_checkpoint(path, &ck)
        })?;
        progress.done(label, &optimum, t.elapsed().as_secs_f64());
        outcomes.push(RunOutcome {
            label,
            min_arm_m: *arm,
            optimum,
            seconds: t.elapsed().as_secs_f64(),
        });
        problems.push(problem);
    }
    progress.finish();
    let main = &outcomes[0];
    write_plots(a, &problems[0], &main.optimum.ps_sqp.design)?;
    let current = problems[0].evaluate_design(&problems[0].current_design())?;
    if a.json || !std::io::stdout().is_terminal() {
        afsv::output::print_json(&to_json(a, &objective, &current, &outcomes))?;
    } else {
        print!("{}", to_text(a, &current, &outcomes));
    }
    Ok(())
}

fn load_checkpoint(path: &Path, settings: &Value) -> Result<Option<Checkpoint>, String> {
    let Ok(text) = std::fs::read_to_string(path) else {
        return Ok(None);
    };
    if !is_afsv_json(&text) {
        return Err(format!(
            "--checkpoint {}: exists and was not written by afsv",
            path.display()
        ));
    }
    let ck: Checkpoint = serde_json::from_str(&text).map_err(|e| {
        format!(
            "--checkpoint {}: line {} column {}: {e}",
            path.display(),
            e.line(),
            e.column()
        )
    })?;
    if &ck.settings != settings {
        return Err(format!(
            "--checkpoint {}: written for other settings ({}); remove it or use the same options",
            path.display(),
            ck.settings
        ));
    }
    Ok(Some(ck))
}

fn write_checkpoint(path: &Path, ck: &Checkpoint) -> Result<(), String> {
    let text = serde_json::to_string(ck).map_err(|e| e.to_string())?;
    let tmp = path.with_extension("partial");
    std::fs::write(&tmp, text).map_err(|e| format!("{}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| format!("{}: {e}", path.display()))
}

fn write_plots(a: &AfsArgs, problem: &AfsProblem, opt: &AfsDesign) -> Result<(), String> {
    if a.plot_step.is_none() && a.plot_pulse.is_none() {
        return Ok(());
    }
    let (p_opt, s_opt) = problem.responses(opt).map_err(|e| e.to_string())?;
    let (p_cur, s_cur) = problem
        .responses(&problem.current_design())
        .map_err(|e| e.to_string())?;
    for (path, title, opt, cur) in [
        (
            &a.plot_step,
            "30 deg steering step, loaded, 50 km/h",
            &s_opt,
            &s_cur,
        ),
        (
            &a.plot_pulse,
            "0.2 s steering pulse, loaded, 50 km/h",
            &p_opt,
            &p_cur,
        ),
    ] {
        let Some(path) = path else { continue };
        let series = [
            afsv_plot::Series {
                label: "optimum (PS/SQP)",
                x: &opt.time_s,
                y: &opt.articulation_deg,
            },
            afsv_plot::Series {
                label: "current design",
                x: &cur.time_s,
                y: &cur.articulation_deg,
            },
        ];
        afsv_plot::line_plot(path, title, "time (s)", "articulation angle (deg)", &series)?;
        afsv::output::mark_svg(path)?;
    }
    Ok(())
}

/// Progress on stderr: a spinner on a terminal, a line per finished run otherwise.
struct Bar(Option<indicatif::ProgressBar>);

impl Bar {
    fn new() -> Result<Self, String> {
        if !std::io::stderr().is_terminal() {
            return Ok(Bar(None));
        }
        let bar = indicatif::ProgressBar::new_spinner();
        bar.set_style(
            indicatif::ProgressStyle::with_template("{spinner} {elapsed} {msg}")
                .map_err(|e| e.to_string())?,
        );
        bar.enable_steady_tick(std::time::Duration::from_millis(200));
        Ok(Bar(Some(bar)))
    }

    fn done(&self, label: &str, o: &AfsOptimum, seconds: f64) {
        let line = format!(
            "afsv optimize afs: run {label} done: F = {:.4}, {} evaluations, {seconds:.1} s",
            o.ps_sqp.f,
            o.evaluations_ps + o.evaluations_sqp
        );
        match &self.0 {
            Some(b) => b.println(line),
            None => eprintln!("{line}"),
        }
    }

    fn finish(&self) {
        if let Some(b) = &self.0 {
            b.finish_and_clear();
        }
    }
}

impl optimize::Progress for Bar {
    fn report(&self, phase: &str, done: usize, total: usize, best: f64) {
        if let Some(b) = &self.0 {
            let best = if best < optimize::BARRIER {
                format!("{best:.4}")
            } else {
                "-".into()
            };
            b.set_message(format!(
                "{phase}: {done} evaluations (limit {total}), best F {best}"
            ));
        }
    }
}

fn design_json(d: &AfsDesign) -> Value {
    let mut m = serde_json::Map::new();
    for v in AfsVariable::ALL {
        m.insert(v.name().into(), json!(d.get(v)));
    }
    let t = d.table_units();
    m.insert(
        "table_units".into(),
        json!({"a0_deg": t[0], "l1_m": t[1], "l2_m": t[2], "a_v": t[3], "b_eff_gpa": t[4]}),
    );
    Value::Object(m)
}

fn evaluation_json(e: &DesignEvaluation) -> Value {
    let ratios: serde_json::Map<String, Value> = Measure::ALL
        .iter()
        .map(|m| (m.name().to_string(), json!(e.ratios.get(*m))))
        .collect();
    let v: serde_json::Map<String, Value> = Measure::ALL
        .iter()
        .zip(e.objective_vector)
        .map(|(m, v)| (m.name().to_string(), json!(v)))
        .collect();
    json!({
        "design": design_json(&e.design),
        "f": e.f,
        "ratios_as_tables_4_3_4_4": ratios,
        "objective_vector_eq_4_8": v,
        "measures": e.measures,
        "geometry": e.geometry,
        "constraints": e.constraints.iter().map(|(c, v)| json!({"name": c.name(), "value": v, "active": v.abs() < 1e-3})).collect::<Vec<_>>(),
    })
}

fn to_json(
    a: &AfsArgs,
    objective: &Objective,
    current: &DesignEvaluation,
    runs: &[RunOutcome],
) -> Value {
    json!({
        "problem": {
            "variables": AfsVariable::ALL.iter().map(|v| v.name()).collect::<Vec<_>>(),
            "b_eff_upper_bound_gpa": if a.relaxed { 2.08 } else { 1.7 },
            "load": "loaded", "speed_kmh": 50.0, "rtol": a.rtol,
            "weights_eq_4_17": Measure::ALL.iter().map(|m| (m.name().to_string(), json!(objective.weight(*m)))).collect::<serde_json::Map<_, _>>(),
        },
        "current": evaluation_json(current),
        "runs": runs.iter().map(|r| json!({
            "label": r.label,
            "min_steering_arm_m": r.min_arm_m,
            "ps": evaluation_json(&r.optimum.ps),
            "ps_sqp": evaluation_json(&r.optimum.ps_sqp),
            "sqp_improved": r.optimum.sqp_improved,
            "sqp_status": r.optimum.sqp_status,
            "evaluations": {"pattern_search": r.optimum.evaluations_ps, "sqp": r.optimum.evaluations_sqp},
            "starts": r.optimum.starts,
            "start_spread_f": r.optimum.start_spread_f,
            "seconds": r.seconds,
        })).collect::<Vec<_>>(),
    })
}

fn geometry_line(g: &FullLockGeometry) -> String {
    format!(
        "L_max/L_min {:.3} (Eq 4.10: < 2), smallest full-lock arm {:.3} m, l_2/l_1 {:.3}",
        g.stroke_ratio, g.min_arm_m, g.l2_over_l1
    )
}

fn to_text(a: &AfsArgs, current: &DesignEvaluation, runs: &[RunOutcome]) -> String {
    let mut s = format!(
        "Chapter 4 AFS design optimisation (loaded, 50 km/h; B_eff <= {} GPa, {})\n",
        if a.relaxed { "2.08" } else { "1.7" },
        if a.relaxed { "Table 4.4" } else { "Table 4.3" }
    );
    for r in runs {
        let (ps, sq) = (&r.optimum.ps, &r.optimum.ps_sqp);
        s += &format!(
            "\n{} ({:.1} s, {} PS + {} SQP evaluations, SQP {}):\n",
            r.label,
            r.seconds,
            r.optimum.evaluations_ps,
            r.optimum.evaluations_sqp,
            r.optimum.sqp_status
        );
        s += &format!(
            "  {:<22} {:>10} {:>10} {:>10}\n",
            "parameter", "current", "PS", "PS/SQP"
        );
        let (tc, tp, ts) = (
            current.design.table_units(),
            ps.design.table_units(),
            sq.design.table_units(),
        );
        for (i, v) in AfsVariable::ALL.iter().enumerate() {
            s += &format!(
                "  {:<22} {:>10.3} {:>10.3} {:>10.3}\n",
                v.table_label(),
                tc[i],
                tp[i],
                ts[i]
            );
        }
        s += "  ratio to current (Tables 4.3/4.4 print these; Eq 4.8 inverts omega, zeta, Gamma, psi)\n";
        for m in Measure::ALL {
            s += &format!(
                "  {:<22} {:>10} {:>10.3} {:>10.3}\n",
                m.name(),
                "1",
                ps.ratios.get(m),
                sq.ratios.get(m)
            );
        }
        s += "  V of Eq 4.8 (L/L_0, omega_0/omega, zeta_0/zeta, Gamma_0/Gamma, OS/OS_0, psi_0/psi)\n";
        for (name, e) in [("PS", ps), ("PS/SQP", sq)] {
            let v: Vec<String> = e
                .objective_vector
                .iter()
                .map(|v| format!("{v:.3}"))
                .collect();
            s += &format!("  {:<22} {}\n", name, v.join(" "));
        }
        s += &format!(
            "  {:<22} {:>10.3} {:>10.4} {:>10.4}\n",
            "F = W.V (Eq 4.8)", current.f, ps.f, sq.f
        );
        s += &format!(
            "  PS:     {}\n  PS/SQP: {}\n",
            geometry_line(&ps.geometry),
            geometry_line(&sq.geometry)
        );
        s += &format!(
            "  {} starts, spread of their F {:.4}\n",
            r.optimum.starts.len(),
            r.optimum.start_spread_f
        );
    }
    s += &format!("\ncurrent design: {}\n", geometry_line(&current.geometry));
    s
}
