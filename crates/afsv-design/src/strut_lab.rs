//! The strut on the test bench, as `afsv hps` runs it: a harmonic test and its last
//! cycle's loop ([`harmonic`]), the laboratory programme of section
//! 5.3 run test by test with its table ([`characterize_each`], [`characterize_report`]),
//! and the strut a measured record is identified against ([`identify_strut`]: the one the
//! command names, else the one its sidecar names).

use crate::param_files::StrutSource;
use crate::report::strut::CHARACTERIZE_COLUMNS;
use afsv_records::Record;
use hps_emulsion::{characterize, loop_metrics, simulate_displacement, Excitation};
use hps_emulsion::{HarmonicTest, HpsError, HpsExtensions, LoopMetrics};
use hps_emulsion::{SimOptions, StrutParams, StrutRecord};
use serde_json::{json, Value};
use std::path::Path;

/// `cycles` cycles of the harmonic `test` on `params` (no extensions), and the loop
/// metrics of the last; too short a record for a loop says what to raise.
pub fn harmonic(
    params: &StrutParams,
    test: &HarmonicTest,
    cycles: f64,
    opts: &SimOptions,
) -> Result<(StrutRecord, LoopMetrics), String> {
    let exc = Excitation::harmonic(test.frequency_hz, test.amplitude_m, cycles);
    let rec = simulate_displacement(params, &HpsExtensions::none(), &exc, opts)
        .map_err(|e| e.to_string())?;
    let metrics = loop_metrics(&rec, test).map_err(|e| {
        format!("{e}: raise --rate or --cycles (need >= 1 cycle, 16 samples per cycle)")
    })?;
    Ok((rec, metrics))
}

/// The last-cycle metrics of every test of `tests` on `params` (no extensions, default
/// integration; `hps_emulsion::characterize`), one test at a time; `done` is called after
/// each.
pub fn characterize_each(
    params: &StrutParams,
    tests: &[HarmonicTest],
    done: &dyn Fn(&HarmonicTest),
) -> Result<Vec<LoopMetrics>, HpsError> {
    let mut rows = Vec::with_capacity(tests.len());
    for t in tests {
        let row = characterize(
            params,
            &HpsExtensions::none(),
            std::slice::from_ref(t),
            &SimOptions::default(),
        )?;
        rows.extend(row);
        done(t);
    }
    Ok(rows)
}

/// The report of a characterisation of the strut named `strut` with gas fraction `gamma0`:
/// its table ([`CHARACTERIZE_COLUMNS`]), the whole result as JSON, the line a terminal shows
/// above the table, and the fields of a CSV's sidecar.
pub fn characterize_report(
    strut: &str,
    gamma0: f64,
    rows: &[LoopMetrics],
) -> Result<(Record, Value, String, Value), String> {
    let full = json!({ "strut": strut, "gamma0": gamma0, "tests": rows });
    let table = afsv_records::json::from_rows(
        full["tests"].as_array().map_or(&[], Vec::as_slice),
        &CHARACTERIZE_COLUMNS,
    )?;
    let summary = format!(
        "strut {strut} (gamma0 {gamma0}): the lab programme of section 5.3, last cycle of each test (SI units)\n"
    );
    Ok((
        table,
        full,
        summary,
        json!({ "strut": strut, "gamma0": gamma0 }),
    ))
}

/// The strut a record at `input` (its sidecar's fields `meta`) is identified against:
/// `given` (the command's `--strut`), else the built-in its sidecar names, and which of
/// the two it is (`--strut` or `sidecar`). Neither is an error (a guessed strut fits
/// nothing), and so is a built-in `given` that differs from the sidecar's.
pub fn identify_strut(
    given: Option<&StrutSource>,
    input: &Path,
    meta: &Value,
) -> Result<(StrutSource, &'static str), String> {
    let sidecar = input.with_extension("json");
    let side = match meta.get("strut") {
        None | Some(Value::Null) => None,
        Some(v) => {
            let name = v.as_str().unwrap_or_default();
            Some(StrutSource::builtin(name).ok_or_else(|| {
                format!(
                    "{}: the sidecar names strut {v}, not one of front-axle, lab-1orifice, lab-2orifice (give the strut as a file with --strut FILE)",
                    sidecar.display()
                )
            })?)
        }
    };
    match (given, side) {
        (Some(s), Some(t)) if s.is_builtin() && s.name() != t.name() => Err(format!(
            "--strut {}: the record's sidecar {} says the strut is {}; drop --strut or give --strut {}",
            s.name(),
            sidecar.display(),
            t.name(),
            t.name()
        )),
        (Some(s), _) => Ok((s.clone(), "--strut")),
        (None, Some(t)) => Ok((t, "sidecar")),
        (None, None) => Err(format!(
            "{}: the record does not say which strut it is (no sidecar {} naming one); give --strut (a built-in or a strut file): the fit takes every parameter it does not vary from that strut",
            input.display(),
            sidecar.display()
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_strut_comes_from_the_option_or_the_sidecar() {
        let rec = Path::new("bench.csv");
        let lab = StrutSource::builtin("lab-1orifice").unwrap();
        let side = json!({ "strut": "lab-1orifice" });
        let (s, from) = identify_strut(None, rec, &side).unwrap();
        assert_eq!((s.name(), from), ("lab-1orifice", "sidecar"));
        let (s, from) = identify_strut(Some(&lab), rec, &json!({})).unwrap();
        assert_eq!((s.name(), from), ("lab-1orifice", "--strut"));
        let other = StrutSource::builtin("front-axle").unwrap();
        assert!(identify_strut(Some(&other), rec, &side).is_err());
        assert!(identify_strut(None, rec, &json!({})).is_err());
        assert!(identify_strut(None, rec, &json!({ "strut": "mine" })).is_err());
    }

    #[test]
    fn the_report_tables_every_test() {
        let p = StrutParams::front_axle();
        let tests = [HarmonicTest {
            frequency_hz: 1.0,
            amplitude_m: 0.01,
        }];
        let count = std::sync::atomic::AtomicUsize::new(0);
        let rows = characterize_each(&p, &tests, &|_| {
            count.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        })
        .unwrap();
        assert_eq!(count.into_inner(), 1);
        let (table, full, summary, _) = characterize_report("front-axle", p.gamma0, &rows).unwrap();
        assert_eq!(table.len(), 1);
        assert_eq!(full["tests"].as_array().unwrap().len(), 1);
        assert!(summary.starts_with("strut front-axle"));
    }

    #[test]
    fn a_harmonic_test_has_its_loop_or_says_what_to_raise() {
        let p = StrutParams::front_axle();
        let test = HarmonicTest {
            frequency_hz: 1.0,
            amplitude_m: 0.0075,
        };
        let (rec, m) = harmonic(&p, &test, 2.0, &SimOptions::default()).unwrap();
        assert!(!rec.time.is_empty());
        assert_eq!(m, loop_metrics(&rec, &test).unwrap());
        let coarse = SimOptions {
            output_rate_hz: 5.0,
            ..SimOptions::default()
        };
        assert!(harmonic(&p, &test, 2.0, &coarse)
            .unwrap_err()
            .contains("raise --rate"));
    }
}
