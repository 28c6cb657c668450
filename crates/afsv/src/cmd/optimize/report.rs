//! What `afsv optimize afs` draws: the Fig 4.9 plots and the progress spinner (its JSON and
//! text reports are `afsv_design::report::afs`).

use super::AfsArgs;
use afsv_design::{AfsDesign, AfsOptimum, AfsProblem};
use std::io::IsTerminal;

pub(super) fn write_plots(
    a: &AfsArgs,
    problem: &AfsProblem,
    opt: &AfsDesign,
) -> Result<(), Box<dyn std::error::Error>> {
    if a.plot_step.is_none() && a.plot_pulse.is_none() {
        return Ok(());
    }
    let (p_opt, s_opt) = problem.responses(opt)?;
    let (p_cur, s_cur) = problem.responses(&problem.current_design())?;
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
        if let Some(path) = path {
            let chart = afsv_design::figures::studies::afs_response(title, opt, cur);
            crate::cmd::write_chart(path, &chart)?;
        }
    }
    Ok(())
}

/// Progress on stderr: a spinner on a terminal, a line per finished run otherwise;
/// nothing under `afsv --quiet`.
pub(super) struct Bar(Option<indicatif::ProgressBar>);

impl Bar {
    pub(super) fn new() -> Result<Self, String> {
        if afsv::progress::is_quiet() || !std::io::stderr().is_terminal() {
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

    pub(super) fn done(&self, label: &str, o: &AfsOptimum, seconds: f64) {
        if afsv::progress::is_quiet() {
            return;
        }
        let line = format!(
            "afsv optimize afs: run {label} done: F = {:.4}{}, {} evaluations, {seconds:.1} s",
            o.ps_sqp.f,
            if o.feasible() {
                ""
            } else {
                " (no feasible design)"
            },
            o.evaluations_ps + o.evaluations_sqp
        );
        match &self.0 {
            Some(b) => b.println(line),
            None => eprintln!("{line}"),
        }
    }

    pub(super) fn finish(&self) {
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
