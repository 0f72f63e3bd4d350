//! The integration tests, one binary (one link instead of one per file): each file is a module named after
//! what it checks. `common` holds the helpers they share.

mod architecture;
mod bad_inputs;
mod case_validation;
mod cli;
mod cli_study;
mod closed_form_short_bearing;
mod common;
mod control;
mod convergence_thd;
mod equilibrium_robustness;
mod extremes;
mod feeding;
mod fidelity_arc;
mod film_checks;
mod flexible_pads;
mod literature_fillon;
mod literature_someya;
mod mass_conserving;
mod node_budget;
mod pivot_ball_start;
mod pivot_hertz;
mod pivot_series;
mod proptest_cases;
mod reynolds_convergence;
mod rotor_compressor;
mod scene_data;
mod supg_benchmarks;
mod tehd;
mod thermal_checks;
mod thermal_compressor;
mod thermal_convergence;
mod thermal_slider;
mod turbulence;
mod work_budgets;
mod workbench_ui;
