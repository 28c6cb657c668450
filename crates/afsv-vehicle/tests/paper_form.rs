//! The printed Eq 3.13 in the 3-D vehicle (`YawInertiaForm::PaperEq313`, `--paper-form`):
//! each unit's yaw inertia grows by m L² about the joint, as the yaw-plane model's printed
//! form does. Both models must then lower the yaw frequency by the same factor, because
//! the mode is the steering struts' torsional stiffness against the units' yaw inertias
//! (docs/vehicle-3d.md, "Yaw mode"); the 3-D model's tire and roll compliances, in series
//! with much stiffer paths, may move the ratio by a few percent.

use afsv_dynamics::{measures_for, EquationForm, Load as YawLoad, MeasureSpec};
use afsv_vehicle::derived_yaw_plane;
use vehicle_3d::scenarios::{yaw, YawSpec};
use vehicle_3d::{FrontAxle, Load, VehicleParams, YawInertiaForm};

fn yaw_plane_hz(p: &VehicleParams, form: EquationForm) -> f64 {
    let y = derived_yaw_plane(p, Load::Loaded).unwrap();
    let mut spec = MeasureSpec::default();
    spec.options.form = form;
    measures_for(&y, &p.steering, Some(YawLoad::Loaded), 50.0 / 3.6, &spec)
        .unwrap()
        .natural_frequency_hz
}

fn three_d_hz(p: &VehicleParams, form: YawInertiaForm) -> f64 {
    let p = VehicleParams {
        yaw_inertia_form: form,
        ..p.clone()
    };
    yaw(&p, &YawSpec::d3(FrontAxle::Rigid), 0)
        .unwrap()
        .1
        .omega_z_hz
}

#[test]
fn the_printed_form_lowers_the_3d_yaw_mode_as_it_lowers_the_yaw_plane_one() {
    let p = VehicleParams::nominal();
    let plane = yaw_plane_hz(&p, EquationForm::PaperEq313)
        / yaw_plane_hz(&p, EquationForm::EnergyConsistent);
    let three_d = three_d_hz(&p, YawInertiaForm::PaperEq313)
        / three_d_hz(&p, YawInertiaForm::EnergyConsistent);
    assert!(plane < 0.7, "yaw-plane ratio {plane}");
    assert!(
        (three_d / plane - 1.0).abs() < 0.10,
        "3-D ratio {three_d} against the yaw-plane ratio {plane}"
    );
}

#[test]
fn the_form_is_left_out_of_a_parameter_file_unless_it_is_the_printed_one() {
    let nominal = serde_json::to_value(VehicleParams::nominal()).unwrap();
    assert!(nominal.get("yaw_inertia_form").is_none());
    let paper = VehicleParams {
        yaw_inertia_form: YawInertiaForm::PaperEq313,
        ..VehicleParams::nominal()
    };
    let text = serde_json::to_string(&paper).unwrap();
    assert!(text.contains("\"yaw_inertia_form\":\"paper_eq_3_13\""));
    let back: VehicleParams = serde_json::from_str(&text).unwrap();
    assert_eq!(back, paper);
}
