//! The problem the options of `afsv optimize layout` define ([`problem_desc`]): one layout
//! of the described vehicle by name (`crate::layout_names`), the cab and seat, the
//! variables, objective and constraints as the registries name them
//! (`crate::layout_optimum`), the rides' conditions and the common terrain seeds.

use crate::layout_optimum::{MAX_D4_SPEEDS, MAX_SEEDS};
use crate::{LayoutConstraint, LayoutMeasure, LayoutProblemDesc, LayoutVariable};
use std::path::Path;
use vehicle_3d::Load;

/// The options of `afsv optimize layout` that define its problem, as given.
#[derive(Debug, Clone, Copy)]
pub struct LayoutOptions<'a> {
    /// Vehicle description (the prototype when `None`).
    pub vehicle: Option<&'a Path>,
    /// The layout's name (one of `crate::layout_names::LAYOUT_NAMES`).
    pub layout: &'a str,
    /// The cab and seat: `generic`, `off`, `described` (default: the description's, else
    /// generic).
    pub seat: Option<&'a str>,
    /// Design variables `NAME=LO..HI`.
    pub vary: &'a [String],
    /// The measure to minimise (or maximise).
    pub objective: &'a str,
    /// Maximise the objective instead.
    pub maximise: bool,
    /// Constraints `MEASURE <= BOUND` or `MEASURE >= BOUND`.
    pub constraints: &'a [String],
    /// Load case of the rides.
    pub load: Load,
    /// Speed of the rides (km/h).
    pub speed_kmh: f64,
    /// Measured window of the rides (m).
    pub ride_length_m: f64,
    /// The D4 speeds (km/h, comma separated), read when a D4 measure is asked for.
    pub d4_speeds: &'a str,
    /// Terrain seeds of every design.
    pub seeds: usize,
    /// First terrain seed.
    pub terrain_seed: u64,
}

/// The problem `o` defines; errors name the option (`--layout`, `--seeds`, `--objective`,
/// `--constraint`, `--vary`, `--d4-speeds`, `--seat`).
pub fn problem_desc(o: &LayoutOptions) -> Result<LayoutProblemDesc, String> {
    if o.layout.contains(',') {
        return Err(format!("--layout {}: one layout", o.layout));
    }
    let v = crate::described::articulated(o.vehicle)?;
    let layout = crate::layout_names::build_layouts(&v, o.layout)?
        .pop()
        .ok_or("--layout: no layout named")?;
    if o.seeds == 0 || o.seeds > MAX_SEEDS {
        return Err(format!("--seeds {}: must be 1 to 100", o.seeds));
    }
    let flag = |f: &'static str| move |e: String| format!("--{f}: {e}");
    let link = layout.link();
    let objective = LayoutMeasure::parse(o.objective).map_err(flag("objective"))?;
    let constraints: Vec<LayoutConstraint> = o
        .constraints
        .iter()
        .map(|t| LayoutConstraint::parse(t).map_err(flag("constraint")))
        .collect::<Result<_, _>>()?;
    let d4 = [LayoutMeasure::D4Speed, LayoutMeasure::D4SpeedSeat];
    let d4_speeds_kmh =
        if d4.contains(&objective) || constraints.iter().any(|c| d4.contains(&c.measure)) {
            crate::value_lists::list("--d4-speeds", o.d4_speeds, MAX_D4_SPEEDS)?
        } else {
            Vec::new()
        };
    Ok(LayoutProblemDesc {
        vehicle: v.name.clone(),
        layout: layout.name,
        params: layout.params,
        front_axle: layout.front_axle,
        link,
        seat: crate::layout_names::seat_of(&v, o.seat)?,
        load: o.load,
        speed_kmh: o.speed_kmh,
        ride_length_m: o.ride_length_m,
        seeds: crate::fan_out::seed_range(o.terrain_seed, o.seeds as u64),
        variables: o
            .vary
            .iter()
            .map(|t| LayoutVariable::parse(t).map_err(flag("vary")))
            .collect::<Result<_, _>>()?,
        d4_speeds_kmh,
        objective,
        maximise: o.maximise,
        constraints,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_options_define_one_layouts_problem() {
        let vary = ["front.a_b=5e-6..3e-5".to_string()];
        let o = LayoutOptions {
            vehicle: None,
            layout: "front-hps",
            seat: Some("off"),
            vary: &vary,
            objective: "awz_frame",
            maximise: false,
            constraints: &[],
            load: Load::Loaded,
            speed_kmh: 20.0,
            ride_length_m: 100.0,
            d4_speeds: "10,20",
            seeds: 2,
            terrain_seed: 3,
        };
        let d = problem_desc(&o).unwrap();
        assert_eq!(
            (d.layout.as_str(), d.seeds.clone()),
            ("front-hps", vec![3, 4])
        );
        assert!(d.d4_speeds_kmh.is_empty());
        let d4 = problem_desc(&LayoutOptions {
            objective: "d4_speed",
            ..o
        })
        .unwrap();
        assert_eq!(d4.d4_speeds_kmh, vec![10.0, 20.0]);
        assert!(problem_desc(&LayoutOptions {
            layout: "rigid,front-hps",
            ..o
        })
        .is_err());
        assert!(problem_desc(&LayoutOptions { seeds: 0, ..o }).is_err());
        assert!(problem_desc(&LayoutOptions {
            objective: "comfort",
            ..o
        })
        .unwrap_err()
        .starts_with("--objective: "));
    }
}
