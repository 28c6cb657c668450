//! The design layer shared by the design optimisers and by validation:
//!
//! - [`measures`]: the six measures of the chapter-4 objective and their ratios to the
//!   current design (Tables 4.3/4.4), the objective vector V of Eq 4.8;
//! - [`objective`]: F(chi) = V . W (Eq 4.8);
//! - [`ahp`]: the AHP weights W (Eqs 4.11-4.17) from the pairwise-comparison matrices;
//! - [`afs_design`]: the chapter-4 design vector [A_0, l_1, l_2, a_v, B_eff] (Table 4.2)
//!   applied to the AFS parameters, its bounds, and the A_0 of the longest steering arm;
//! - [`afs_problem`]: the chapter-4 optimisation problem (Eq 4.8 over chi with Eq 4.10,
//!   a minimum steering arm and the optional Eq 4.9 as constraints) for the `optimize`
//!   solvers;
//! - [`afs_optimum`]: the solver sequence of section 4.3.5 (multi-start pattern search
//!   with a Latin-hypercube search step, then SQP), resumable;
//! - [`afs_ask_tell`]: the same sequence split into ask (the next batch of design points)
//!   and tell (advance by their evaluations), for evaluation elsewhere;
//! - [`afs_batch`]: the problem descriptions, batch and results files (JSON Lines) of
//!   that split, and the evaluation of one shard of a batch; [`afs_state`]: its state
//!   file, the batch a state asks for and the results that answer it;
//! - [`hps_optimum`]: `afsv optimize hps`, the chapter-6 GA over [A_hc, A_v, A_b] (Eq
//!   6.19-6.20) and the re-evaluation over terrain seeds; [`hps_ask_tell`]: the same run
//!   split into ask and tell, with its batch, results and state files;
//! - [`batch_files`]: the checks shared by the batch and results files of every ask/tell
//!   optimisation (afs, layout, HPS); [`batch_shard`]: one shard of any of their batch
//!   files evaluated and its results file written (`afsv batch evaluate`);
//! - [`hps_design`]: the chapter-6 design vector [A_hc, A_v, A_b] (Table 6.5) applied to
//!   a strut parameter set;
//! - [`sweep`]: the optimum of a one-variable design sweep (parabolic peak);
//! - [`evaluate`]: the assessment of `afsv evaluate` (design measures, yaw-plane measures,
//!   strut, terrain) of one vehicle description;
//! - `figures` (cargo feature `plots`): the figures of the commands' `--plot` options as
//!   `afsv_plot::Chart` values, pure functions of a result like the reports;
//! - [`layouts`]: `afsv study layouts`, several suspension layouts of one vehicle through
//!   D1-D4 on common seeds, on the frame and at the seat;
//! - [`layout_names`]: the layouts of those commands by name (`--layouts`, `--seat`),
//!   built from one vehicle description;
//! - [`layout_optimum`]: `afsv optimize layout`, a GA over registry-named parameters of
//!   one layout with constraints on its measures; [`layout_ask_tell`]: the same run split
//!   into ask and tell, with its batch, results and state files;
//! - [`ga_ask_tell`]: one `--ask` or `--tell` of either GA run (HPS, layout) against its
//!   state file, written once over the drivers' [`ga_ask_tell::GaAskTell`];
//! - [`strut_shift`]: `afsv hps thermal`, a vehicle's struts over a working shift (gas and
//!   body temperatures, ride height and stiffness, with and without a levelling valve);
//! - [`report`]: the reports of those results (JSON objects and text tables), shared by
//!   the CLI and the Python package;
//! - [`yaw_leakage`]: `afsv yaw leakage`, the steady-turn decay and the gain-efficiency
//!   correlation of the steering circuit's leakage (section 3.4.1, Fig 4.7);
//! - [`fan_out`]: the one scheduler of the studies on the 3-D vehicle (per-case caches
//!   built once, runs in parallel, results in order) and the plain seed fan-out.
//!
//! Every constructor validates its input and returns a [`DesignError`] naming the field.
//! `docs/design.md` maps each equation to its code.

pub mod afs_ask_tell;
pub mod afs_batch;
pub mod afs_design;
pub mod afs_optimum;
pub mod afs_problem;
pub mod afs_resume;
pub mod afs_run;
pub mod afs_state;
pub mod ahp;
pub mod batch_files;
pub mod batch_shard;
pub mod described;
pub mod design_3d;
pub mod error;
pub mod evaluate;
pub mod fan_out;
#[cfg(feature = "plots")]
pub mod figures;
pub mod ga_ask_tell;
pub mod hps_ask_tell;
pub mod hps_design;
pub mod hps_optimum;
pub mod hps_sensitivity;
pub mod hps_speed_sweep;
pub mod layout_ask_tell;
pub mod layout_names;
pub mod layout_optimum;
pub mod layout_problem;
pub mod layouts;
pub mod measured_road;
pub mod measures;
pub mod objective;
pub mod param_files;
pub mod record_measures;
pub mod report;
pub mod sample_bounds;
pub mod shift_case;
pub mod strut_lab;
pub mod strut_shift;
pub mod study_strut;
pub mod sweep;
pub mod terrain_choice;
pub mod tire_sweep;
pub mod truck_case;
pub mod value_lists;
pub mod vehicle_case;
pub mod vehicle_options;
pub mod yaw_leakage;
pub mod yaw_manoeuvre;

pub use afs_ask_tell::{AfsAsk, AfsAskTell, AfsBatch, AfsPhase};
pub use afs_design::{a0_of_longest_initial_arm, AfsDesign, AfsDesignBounds, AfsVariable};
pub use afs_optimum::{optimise, AfsOptimisationSettings, AfsOptimum, AfsRunState};
pub use afs_problem::{
    AfsConstraint, AfsProblem, AfsProblemSpec, DesignEvaluation, InterferenceGeometry,
};
pub use afs_resume::check_run_state;
pub use ahp::{AhpHierarchy, AhpLevels, GoalComparison};
pub use error::DesignError;
pub use hps_ask_tell::{HpsAsk, HpsAskTell, HpsAskTellState, HpsProblemDesc, HpsRunState};
pub use hps_design::HpsDesign;
pub use hps_optimum::{optimise_hps, HpsGaSettings, HpsOptimum};
pub use hps_sensitivity::{hps_sensitivity, HpsSensitivity, HpsVariable, StudyScope};
pub use hps_speed_sweep::{hps_speed_sweep, SpeedSweep};
pub use layout_ask_tell::{LayoutAsk, LayoutAskTell, LayoutAskTellState, LayoutRunState};
pub use layout_optimum::{
    optimise_layout, LayoutConstraint, LayoutGaSettings, LayoutMeasure, LayoutOptimum,
    LayoutProblem, LayoutProblemDesc, LayoutVariable,
};
pub use measures::{DesignMeasures, Measure, MeasureRatios};
pub use objective::Objective;
pub use sweep::{parabolic_peak, SweepPeak};
