//! What a stage reads is what its view holds: an edit reruns exactly the stages that read the edited field,
//! and what the cache serves after it is what a fresh solve of the edited case gives, bit for bit (a stage
//! that read a field missing from its key would serve the result of the case before the edit). The title
//! reaches the published solution without a stage.

use std::sync::Arc;

use crate::bearing::report::progress::NoCancel;
use crate::bearing::report::SolveReport;
use crate::bearing::solution::Solution;
use crate::bearing::stages::id::StageId::{self, *};
use crate::bearing::stages::outcome::Outcome;
use crate::bearing::stages::registry::Stages;
use crate::bearing::stages::request::{Request, Start};
use crate::bearing::stages::sweeps::FrequencySweep;
use crate::bearing::thermal::ThermalReport;
use crate::model::{load_case, Case};
use crate::physics::pad_modes::PadModes;

const FILLON: &str = include_str!("../../../cases/fillon-a.toml");
const FILLON_TEHD: &str = include_str!("../../../cases/fillon-a-tehd.toml");
const ISOTHERMAL: &str = "thermal.model=\"isothermal\"";
/// The stages after the film solution.
const AFTER_FILM: [StageId; 3] = [Coefficients, Reduction, FrequencySweep];

fn case(text: &str, set: &[&str]) -> Case {
    let set: Vec<String> =
        std::iter::once("mesh.fidelity=\"preview\"").chain(set.iter().copied()).map(String::from).collect();
    load_case(text, &set).unwrap().1
}

/// The solution and a frequency sweep, each solve from a centred journal (so that a result does not depend
/// on what was solved before it).
fn request(case: Case) -> Request {
    Request {
        frequency_ratios: vec![0.5, 1.0, 2.0],
        ..Request::of(case, &[Reduction, FrequencySweep]).starting(Start::Cold)
    }
}

/// The numbers of an outcome: the solution but its solve reports (their timings, and their work counts,
/// which a cached factorisation lowers), the warnings kept, and the pad modes' solve times; the frequency
/// sweep.
fn numbers(o: &Outcome) -> (Solution, FrequencySweep) {
    let mut s = Solution::clone(&o.solution().unwrap());
    s.report = SolveReport { warnings: std::mem::take(&mut s.report.warnings), ..SolveReport::default() };
    if let Some(t) = s.thermal.as_mut() {
        t.report = ThermalReport::default();
    }
    for flex in s.pads.iter_mut().filter_map(|p| p.flex.as_mut()) {
        let mut modes = PadModes::clone(&flex.modes);
        modes.report.seconds = 0.0;
        flex.modes = Arc::new(modes);
    }
    (s, FrequencySweep::clone(&o.frequency_sweep().unwrap()))
}

/// From stages that solved `text` with `base`, each edit (with `base`) reruns exactly the stages listed with
/// it, and gives a fresh solve's numbers.
fn edits_rerun_what_reads_them(text: &str, base: &[&str], edits: &[(&str, &[StageId])]) {
    let base_case = case(text, base);
    // Two outputs per stage: going back to the base after an edit mostly runs nothing.
    let mut stages = Stages::keeping(2);
    stages.run(&request(base_case.clone()), &NoCancel).unwrap();
    for &(edit, expected) in edits {
        let edited = case(text, &[base, &[edit]].concat());
        assert_ne!(edited, base_case, "{edit} edits the case");
        let before = stages.all_runs();
        let cached = stages.run(&request(edited.clone()), &NoCancel).unwrap();
        let reran: Vec<StageId> =
            stages.all_runs().iter().zip(&before).filter(|(now, was)| now.1 != was.1).map(|(now, _)| now.0).collect();
        assert_eq!(reran, expected, "{edit} reran other stages");
        let fresh = Stages::new().run(&request(edited), &NoCancel).unwrap();
        assert!(numbers(&cached) == numbers(&fresh), "{edit}: the cached result differs from a fresh solve's");
        stages.run(&request(base_case.clone()), &NoCancel).unwrap();
    }
}

#[test]
fn an_isothermal_edit_reruns_exactly_the_stages_that_read_it() {
    let equilibrium_on: &[StageId] = &[Equilibrium, Coefficients, Reduction, FrequencySweep];
    let everything: &[StageId] = &[Films, Equilibrium, Coefficients, Reduction, FrequencySweep];
    edits_rerun_what_reads_them(
        FILLON,
        &[ISOTHERMAL],
        &[
            ("title=\"renamed\"", &[]),
            ("lubricant.name=\"another oil\"", &[]),
            ("mesh.max_nodes=5000000", &[]),
            ("limits.min_film_thickness_um=5", &[]),
            // Rigid pads: their elasticity is read by nothing; an isothermal case reads no thermal value.
            ("bearing.pads.youngs_modulus_gpa=100", &[]),
            ("lubricant.specific_heat_j_per_kg_k=1900", &[]),
            ("thermal.convection_w_per_m2_k=150", &[]),
            ("thermal.carry_over=0.5", &[]),
            ("operating.excitation_ratio=0.5", &[Reduction]),
            ("bearing.pads.density_kg_per_m3=15600", &AFTER_FILM),
            ("operating.load_n=8000", equilibrium_on),
            ("operating.speed_rpm=3000", equilibrium_on),
            // The isothermal film's temperature, not given, is the supply's.
            ("operating.supply_temperature_c=45", equilibrium_on),
            ("lubricant.density_kg_per_m3=900", equilibrium_on),
            ("physics.cavitation=\"gumbel\"", equilibrium_on),
            ("feeding.churning_factor=2", equilibrium_on),
            ("thermal.max_iterations=50", equilibrium_on),
            ("mesh.circumferential_elements=20", everything),
            ("physics.pad_modes=1", everything),
        ],
    );
}

#[test]
fn a_thermal_edit_reruns_exactly_the_stages_that_read_it() {
    let thermal_on: &[StageId] = &[Thermal, Coefficients, Reduction, FrequencySweep];
    edits_rerun_what_reads_them(
        FILLON,
        &[],
        &[
            ("title=\"renamed\"", &[]),
            // Pads that do not grow thermally: their elasticity is read by nothing.
            ("bearing.pads.youngs_modulus_gpa=100", &[]),
            ("operating.excitation_ratio=0.5", &[Reduction]),
            ("bearing.pads.density_kg_per_m3=15600", &AFTER_FILM),
            ("thermal.convection_w_per_m2_k=150", thermal_on),
            ("operating.supply_temperature_c=45", thermal_on),
            ("lubricant.specific_heat_j_per_kg_k=1900", thermal_on),
            ("thermal.carry_over=0.5", thermal_on),
        ],
    );
}

/// The pads' thermal growth reads their elasticity and the fidelity (below the reference level the growth
/// solid takes every second element layer): with the element counts given, the fidelity name alone changes
/// the result.
#[test]
fn a_growing_pad_reads_its_elasticity_and_the_fidelity() {
    let thermal_on: &[StageId] = &[Thermal, Coefficients, Reduction, FrequencySweep];
    let counts = [
        "mesh.circumferential_elements=16",
        "mesh.axial_elements=8",
        "mesh.orifice_elements=6",
        "mesh.pad_radial_elements=4",
    ];
    let reference = "mesh.fidelity=\"reference\"";
    edits_rerun_what_reads_them(
        FILLON_TEHD,
        &counts,
        &[("bearing.pads.youngs_modulus_gpa=100", thermal_on), (reference, thermal_on)],
    );
    // The fidelity changes the numbers: a cache that missed it would serve the preview's.
    let solve = |set: &[&str]| Stages::new().run(&request(case(FILLON_TEHD, set)), &NoCancel).unwrap();
    let (preview, reference) = (solve(&counts), solve(&[&counts[..], &[reference]].concat()));
    let growth = |o: &Outcome| o.solution().unwrap().pads[0].thermal_growth.as_ref().unwrap().film_radial_m.clone();
    assert_ne!(growth(&preview), growth(&reference));
    assert_ne!(preview.solution().unwrap().eccentricity_ratio, reference.solution().unwrap().eccentricity_ratio);
}

#[test]
fn a_new_title_is_published_at_once_and_reruns_nothing() {
    let req = |case: Case| Request::of(case, &[Coefficients, Reduction]);
    let mut s = Stages::new();
    let first = s.run(&req(case(FILLON, &[ISOTHERMAL])), &NoCancel).unwrap().solution().unwrap();
    let runs = s.all_runs();
    let renamed = case(FILLON, &[ISOTHERMAL, "title=\"renamed\""]);
    let o = s.run(&req(renamed.clone()), &NoCancel).unwrap();
    assert_eq!(s.all_runs(), runs, "a stage ran");
    // Both published solutions carry the new title and the edited case, with the same numbers.
    for sol in [o.solution().unwrap(), o.coefficients().unwrap()] {
        assert_eq!(sol.title, "renamed");
        assert_eq!(sol.inputs, renamed);
        assert_eq!(sol.eccentricity_ratio.to_bits(), first.eccentricity_ratio.to_bits());
    }
    // Asked again, the very same solution (the views compare them by pointer to skip repainting).
    let again = s.run(&req(renamed), &NoCancel).unwrap();
    assert!(Arc::ptr_eq(&again.solution().unwrap(), &o.solution().unwrap()));
}
