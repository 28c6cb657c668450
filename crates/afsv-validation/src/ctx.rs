//! The state handed to the checks: fixtures in, rows and plots out.

use super::fixtures::{descend, Fixtures};
use super::report::{fmt_num, CheckResult, PlotData};
use super::tolerance::{Echo, Status, Tolerance};
use afsv_dynamics::SensitivityTable;
use serde_json::Value;

/// State handed to the checks: fixtures in, rows and plots out.
pub struct Ctx<'a> {
    fixtures: &'a Fixtures,
    /// Rows so far, in check order.
    pub(super) results: Vec<CheckResult>,
    /// Plots so far.
    pub(super) plots: Vec<PlotData>,
    /// Shared expensive computations (filled lazily by the checks that need them).
    pub(super) cache: Cache,
}

/// Results several checks share.
#[derive(Default)]
pub(super) struct Cache {
    /// Sensitivity tables, energy-consistent and printed Eq 3.13 forms.
    pub(super) sens: Option<[SensitivityTable; 2]>,
    /// Composite AHP weights of Eq 4.17.
    pub(super) ahp_w: Option<Vec<f64>>,
    /// D1 a_wz of the unsuspended unloaded 3-D vehicle, mean over the validation seeds.
    pub(super) rigid_awz_unloaded: Option<f64>,
}

impl<'a> Ctx<'a> {
    /// A context with no rows yet.
    pub(super) fn new(fixtures: &'a Fixtures) -> Self {
        Self {
            fixtures,
            results: Vec::new(),
            plots: Vec::new(),
            cache: Cache::default(),
        }
    }

    fn row(&self, id: &str, key: Option<&str>, variant: Option<&str>) -> CheckResult {
        let f = self.fixtures.get(id);
        let reported = f.and_then(|f| f.number(key));
        let reported_text = match (reported, f) {
            (Some(v), _) => fmt_num(v),
            (None, Some(f)) => {
                let path: Vec<&str> = key.map(|k| k.split('.').collect()).unwrap_or_default();
                let v = descend(&f.value, &path).unwrap_or(&Value::Null);
                let t = match v {
                    Value::Null => String::new(),
                    Value::String(s) => s.clone(),
                    other => other.to_string(),
                };
                t.chars().take(60).collect()
            }
            _ => String::new(),
        };
        CheckResult {
            id: id.to_string(),
            key: key.map(String::from),
            variant: variant.map(String::from),
            kind: f.map(|f| f.kind.clone()).unwrap_or_default(),
            description: f.map(|f| f.description.clone()).unwrap_or_default(),
            unit: f.map(|f| f.unit.clone()).unwrap_or_default(),
            reported,
            reported_text,
            simulated: None,
            error: None,
            tolerance: None,
            status: Status::NotReproducible,
            guarded: f.is_some_and(|f| f.guards(key)),
            note: String::new(),
        }
    }

    /// Compare a model-computed number (in the fixture's printed unit) with fixture `id` at
    /// `key`: [`Status::Reproduced`] within tolerance, else [`Status::Differs`].
    pub fn compare(
        &mut self,
        id: &str,
        key: Option<&str>,
        variant: Option<&str>,
        simulated: f64,
        note: impl Into<String>,
    ) {
        self.compare_as(Status::Reproduced, id, key, variant, simulated, note.into());
    }

    /// Compare a number that only echoes an input or holds by construction: within
    /// tolerance the row gets the echo's status ([`Status::Input`],
    /// [`Status::ByConstruction`]), not [`Status::Reproduced`]; outside it, it differs.
    pub fn echo(
        &mut self,
        echo: Echo,
        id: &str,
        key: Option<&str>,
        variant: Option<&str>,
        simulated: f64,
        note: impl Into<String>,
    ) {
        self.compare_as(echo.status(), id, key, variant, simulated, note.into());
    }

    /// A compared row that gets `agrees` within tolerance.
    fn compare_as(
        &mut self,
        agrees: Status,
        id: &str,
        key: Option<&str>,
        variant: Option<&str>,
        simulated: f64,
        note: String,
    ) {
        let mut r = self.row(id, key, variant);
        r.simulated = Some(simulated);
        r.note = note;
        let tol = self
            .fixtures
            .get(id)
            .and_then(|f| Tolerance::from_fixture(&f.tolerance, key));
        match (r.reported, tol) {
            (Some(rep), Some(t)) => {
                r.tolerance = Some(t);
                r.error = Some(t.error(rep, simulated));
                r.status = if t.within(rep, simulated) {
                    agrees
                } else {
                    Status::Differs
                };
            }
            _ => {
                r.status = Status::NotReproducible;
                r.note = format!("fixture has no number or tolerance here; {}", r.note);
            }
        }
        self.results.push(r);
    }

    /// A qualitative (sign / trend) check.
    pub fn qualitative(
        &mut self,
        id: &str,
        key: Option<&str>,
        passed: bool,
        note: impl Into<String>,
    ) {
        let mut r = self.row(id, key, None);
        r.status = if passed {
            Status::Reproduced
        } else {
            Status::Differs
        };
        r.note = note.into();
        self.results.push(r);
    }

    /// A model-computed number that the paper's data cannot pin down (it depends on
    /// inputs the paper does not state): the row shows the number, its error and the
    /// tolerance, and gets [`Status::NotReproducibleFromPaperData`] whatever the error,
    /// with `reason` (which inputs, and how much the number moves with them).
    pub fn not_reproducible_from_paper_data(
        &mut self,
        id: &str,
        key: Option<&str>,
        simulated: f64,
        reason: impl Into<String>,
    ) {
        self.compare_as(
            Status::NotReproducibleFromPaperData,
            id,
            key,
            None,
            simulated,
            reason.into(),
        );
        if let Some(r) = self.results.last_mut() {
            r.status = Status::NotReproducibleFromPaperData;
        }
    }

    /// A fixture (or one key of it) we cannot compute, with the reason.
    pub fn not_reproducible(&mut self, id: &str, key: Option<&str>, reason: impl Into<String>) {
        let mut r = self.row(id, key, None);
        r.note = reason.into();
        self.results.push(r);
    }

    pub(super) fn plot(
        &mut self,
        file: &str,
        title: &str,
        x: &str,
        y: &str,
        series: Vec<(String, Vec<f64>, Vec<f64>)>,
    ) {
        self.plots.push(PlotData {
            file: file.into(),
            title: title.into(),
            x_label: x.into(),
            y_label: y.into(),
            series,
        });
    }

    pub(super) fn fx(&self) -> &'a Fixtures {
        self.fixtures
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::tests::fixture;
    use serde_json::json;

    #[test]
    fn regression_only_for_guarded_rows_out_of_tolerance() {
        let mut fx = Fixtures::default();
        let mut f = fixture("partially reproduced", &["a"]);
        f.value = json!({"a": 1.0, "c": 1.0});
        fx.by_id.insert("q".into(), f);
        let mut ctx = Ctx::new(&fx);
        ctx.compare("q", Some("a"), None, 1.05, "");
        ctx.compare("q", Some("c"), None, 2.0, "");
        assert_eq!(ctx.results[0].status, Status::Reproduced);
        assert!(!ctx.results[0].regressed());
        assert_eq!(ctx.results[1].status, Status::Differs);
        assert!(!ctx.results[1].regressed(), "unguarded key may differ");
        ctx.compare("q", Some("a"), None, 1.5, "");
        assert!(ctx.results[2].regressed());
        // An echo within tolerance agrees (no regression) without counting as reproduced;
        // outside it, it differs and regresses like any guarded row.
        ctx.echo(Echo::Input, "q", Some("a"), None, 1.0, "");
        assert_eq!(ctx.results[3].status, Status::Input);
        assert!(!ctx.results[3].regressed());
        ctx.echo(Echo::ByConstruction, "q", Some("a"), None, 1.5, "");
        assert_eq!(ctx.results[4].status, Status::Differs);
        assert!(ctx.results[4].regressed());
        // A number the paper cannot pin down keeps its error but never agrees, in
        // tolerance or not.
        for v in [1.0, 3.0] {
            ctx.not_reproducible_from_paper_data("q", Some("c"), v, "unstated input");
            let r = ctx.results.last().unwrap();
            assert_eq!(r.status, Status::NotReproducibleFromPaperData);
            assert!(r.error.is_some() && r.note == "unstated input");
        }
    }
}
