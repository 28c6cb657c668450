//! Progress of long commands on stderr, the same everywhere: on a terminal an indicatif
//! bar (count, elapsed, ETA); otherwise (a pipe, a log file, CI) one plain line per
//! finished step with the count, the elapsed time and the ETA:
//!
//! `afsv yaw sensitivity: 12/34 configurations, 0.1 s elapsed, ETA 0.2 s`
//!
//! When the number of steps is not known in advance, lines carry the count and the elapsed
//! time only. `afsv --quiet` switches progress off ([`set_quiet`]). stdout is never touched,
//! so JSON on stdout stays machine-readable. [`Progress`] is `Sync`: steps may finish on
//! any rayon thread.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

static QUIET: AtomicBool = AtomicBool::new(false);

/// Switch progress reports off (`afsv --quiet`) or on for the rest of the process.
pub fn set_quiet(quiet: bool) {
    QUIET.store(quiet, Ordering::Relaxed);
}

/// Whether `afsv --quiet` switched progress off (commands that report on stderr outside a
/// [`Progress`], e.g. a per-run summary line, stay silent too).
pub fn is_quiet() -> bool {
    QUIET.load(Ordering::Relaxed)
}

enum Sink {
    /// Nothing is reported.
    Off,
    /// An indicatif bar on the terminal.
    Bar(indicatif::ProgressBar),
    /// One line per step on a stderr that is not a terminal.
    Lines,
}

/// Progress of one long command: `what` (e.g. `afsv yaw sensitivity`), the unit of a step
/// (e.g. `configurations`) and the number of steps when known.
pub struct Progress {
    what: String,
    unit: String,
    total: Option<usize>,
    start: Instant,
    done: AtomicUsize,
    sink: Sink,
    /// Serialises the plain lines so that concurrent steps print in count order.
    line: Mutex<()>,
}

impl Progress {
    /// Start reporting: a bar when stderr is a terminal, plain lines otherwise, nothing
    /// after [`set_quiet`].
    pub fn new(what: &str, unit: &str, total: Option<usize>) -> Self {
        let sink = if QUIET.load(Ordering::Relaxed) {
            Sink::Off
        } else if std::io::stderr().is_terminal() {
            Sink::Bar(bar(what, unit, total))
        } else {
            Sink::Lines
        };
        Self::with_sink(what, unit, total, sink)
    }

    /// Plain lines whatever stderr is (for tests of the line format).
    pub fn lines(what: &str, unit: &str, total: Option<usize>) -> Self {
        Self::with_sink(what, unit, total, Sink::Lines)
    }

    fn with_sink(what: &str, unit: &str, total: Option<usize>, sink: Sink) -> Self {
        Self {
            what: what.to_string(),
            unit: unit.to_string(),
            total,
            start: Instant::now(),
            done: AtomicUsize::new(0),
            sink,
            line: Mutex::new(()),
        }
    }

    /// One more step finished; `detail` (may be empty) names it.
    pub fn step(&self, detail: &str) {
        match &self.sink {
            Sink::Off => {
                self.done.fetch_add(1, Ordering::Relaxed);
            }
            Sink::Bar(b) => {
                self.done.fetch_add(1, Ordering::Relaxed);
                b.inc(1);
                if !detail.is_empty() {
                    b.set_message(detail.to_string());
                }
            }
            Sink::Lines => {
                let _order = self.line.lock().unwrap_or_else(|e| e.into_inner());
                let n = self.done.fetch_add(1, Ordering::Relaxed) + 1;
                eprintln!(
                    "{}",
                    self.line_text(n, self.start.elapsed().as_secs_f64(), detail)
                );
            }
        }
    }

    /// The plain line after `n` steps at `elapsed` seconds.
    fn line_text(&self, n: usize, elapsed: f64, detail: &str) -> String {
        let detail = if detail.is_empty() {
            String::new()
        } else {
            format!(" ({detail})")
        };
        match self.total {
            Some(total) => format!(
                "{}: {n}/{total} {}{detail}, {} elapsed, ETA {}",
                self.what,
                self.unit,
                seconds(elapsed),
                eta(n, total, elapsed)
            ),
            None => format!(
                "{}: {n} {}{detail}, {} elapsed",
                self.what,
                self.unit,
                seconds(elapsed)
            ),
        }
    }

    /// Steps finished so far.
    pub fn done(&self) -> usize {
        self.done.load(Ordering::Relaxed)
    }

    /// Stop reporting (clears the bar).
    pub fn finish(&self) {
        if let Sink::Bar(b) = &self.sink {
            b.finish_and_clear();
        }
    }
}

fn bar(what: &str, unit: &str, total: Option<usize>) -> indicatif::ProgressBar {
    let (b, template) = match total {
        Some(n) => (
            indicatif::ProgressBar::new(n as u64),
            format!("{what}: {{bar:30}} {{pos}}/{{len}} {unit}, {{elapsed}} elapsed, ETA {{eta}} {{msg}}"),
        ),
        None => (
            indicatif::ProgressBar::new_spinner(),
            format!("{what}: {{spinner}} {{pos}} {unit}, {{elapsed}} elapsed {{msg}}"),
        ),
    };
    if let Ok(style) = indicatif::ProgressStyle::with_template(&template) {
        // indicatif's own ETA reads 0 s before the first step and swings with its moving
        // average after; the mean pace so far is steadier and says when it cannot tell.
        b.set_style(style.with_key(
            "eta",
            |s: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
                let total = s.len().unwrap_or(0) as usize;
                let _ = write!(
                    w,
                    "{}",
                    eta(s.pos() as usize, total, s.elapsed().as_secs_f64())
                );
            },
        ));
    }
    b.enable_steady_tick(std::time::Duration::from_millis(200));
    b
}

/// The time left after `done` of `total` steps in `elapsed` seconds, at the mean pace so
/// far; `estimating` until the first step has finished (no pace to go by yet).
fn eta(done: usize, total: usize, elapsed: f64) -> String {
    if done == 0 {
        return "estimating".into();
    }
    seconds(elapsed / done as f64 * total.saturating_sub(done) as f64)
}

/// `s` seconds as `0.12 s`, `12 s`, `3 min 20 s`.
fn seconds(s: f64) -> String {
    if !s.is_finite() {
        "n/a".into()
    } else if s < 10.0 {
        format!("{s:.2} s")
    } else if s < 120.0 {
        format!("{s:.0} s")
    } else {
        format!("{} min {:.0} s", (s / 60.0).floor(), s % 60.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_eta_waits_for_the_first_step_then_follows_the_mean_pace() {
        assert_eq!(eta(0, 10, 3.0), "estimating");
        assert_eq!(eta(1, 10, 3.2), "29 s");
        assert_eq!(eta(10, 10, 32.0), "0.00 s");
    }

    #[test]
    fn lines_carry_count_elapsed_and_eta() {
        let p = Progress::lines("afsv yaw sensitivity", "configurations", Some(34));
        assert_eq!(
            p.line_text(17, 0.5, ""),
            "afsv yaw sensitivity: 17/34 configurations, 0.50 s elapsed, ETA 0.50 s"
        );
        assert_eq!(
            p.line_text(34, 1.0, "unloaded k_l +30%"),
            "afsv yaw sensitivity: 34/34 configurations (unloaded k_l +30%), 1.00 s elapsed, ETA 0.00 s"
        );
        let open = Progress::lines("afsv discover", "fits", None);
        assert_eq!(
            open.line_text(3, 42.0, ""),
            "afsv discover: 3 fits, 42 s elapsed"
        );
        p.step("");
        p.step("");
        assert_eq!(p.done(), 2);
    }

    #[test]
    fn times_read_naturally() {
        assert_eq!(seconds(0.123), "0.12 s");
        assert_eq!(seconds(42.4), "42 s");
        assert_eq!(seconds(200.0), "3 min 20 s");
        assert_eq!(seconds(f64::NAN), "n/a");
    }
}
