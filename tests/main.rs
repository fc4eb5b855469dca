//! jamchart's integration tests: one binary (one link step for all of them), a module per
//! subject. `cargo test --release --test integration NAME` runs the tests whose path contains
//! NAME (`range_promise`, `hostile::`, ...).

#[macro_use]
mod common;

mod chart_hashes;
mod cli;
mod cli_conventions;
mod cli_design;
mod cli_dynamics;
mod cli_manifest;
mod cli_outputs;
mod cli_pdf;
mod cli_read_off;
mod cli_render;
mod cli_reports;
mod cli_sweep;
mod cli_uncertain;
mod cli_vlocator;
mod data_golden;
mod dynamics_nonsmooth;
mod dynamics_physics;
mod dynamics_props;
mod dynamics_verdicts;
mod force_drive_rest;
mod gallery_browser;
mod gallery_browser_accuracy;
mod gallery_browser_tables;
mod hostile;
mod names_agree;
mod palm_offset;
mod python_package;
mod questions;
mod range_promise;
mod readme;
mod scene_docs;
#[cfg(feature = "serve")]
mod serve;
mod uncertain_dist;
