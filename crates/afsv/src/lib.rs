//! The afsv toolkit: output and progress helpers shared by the `afsv` command-line tool
//! (records: the `afsv-records` crate; plots: `afsv-plot`; validation: `afsv-validation`). The physics lives in the subsystem crates
//! (`terrain-psd`, `tire-fiala`, `afs-hydraulics`, `hps-emulsion`, `perf-measures`,
//! `afsv-dynamics`); this crate composes them for users.

pub mod output;
pub mod progress;
pub mod provenance;
pub mod table;
