//! The case as a stage sees it: a [`Case`] that holds the fields the stage reads, every other field blank.
//!
//! A stage's `Inputs` hold its view of the case, built by the stage's builder: it destructures the case and
//! each sub-struct it looks into **exhaustively (no `..`)** and copies what the stage reads onto the blank
//! case below. `poll` sees its inputs and the outputs of the stages it reads — no path leads from a running
//! stage to the request's case — so whatever a stage reads, itself or in the solver functions it hands its
//! view to, is in its cache key. A field a stage reads but does not copy into its view reads blank for
//! every case: a wrong value (the same one every time, so a test that sets the field finds it), never the
//! value of an earlier case served from the cache.
//!
//! A stage that reads another stage's output derives that stage's inputs from its own view
//! (`FilmsInputs::of(&inputs.case)`), so its key covers everything upstream. A view therefore holds the
//! views of the stages it reads; a builder that forgets a field of one makes the read fail as "not current"
//! ([`super::Ctx::output`]) rather than serve the output of other inputs.
//!
//! Blank: 0 for numbers and counts, empty texts and lists, `None`, a pad without orifices or pivot springs,
//! the first variant of an enum; the limits and the tuning keys at their defaults.

use crate::model::case::{ContactKind, PivotContact};
use crate::model::limits::Limits;
use crate::model::tuning::Tuning;
use crate::model::{
    Bearing, Case, CavitatedFilm, Cavitation, Feeding, Fidelity, LoadSpec, Lubricant, MeshSpec, Operating, Pad,
    PadFilmBc, PadKind, Physics, Thermal, ThermalModelKind, Turbulence, ViscosityLaw,
};

/// A number no stage reads.
pub const BLANK: f64 = 0.0;

/// The case with every field blank and no pads.
#[must_use]
pub fn case() -> Case {
    Case {
        title: String::new(),
        bearing: Bearing { journal_radius_m: BLANK, length_m: BLANK, assembled_clearance_m: BLANK, pads: Vec::new() },
        lubricant: Lubricant {
            name: String::new(),
            viscosity: ViscosityLaw { mu_ref_pa_s: BLANK, t_ref_c: BLANK, eta_per_k: BLANK },
            density_kg_per_m3: BLANK,
            specific_heat_j_per_kg_k: BLANK,
            conductivity_w_per_m_k: BLANK,
        },
        operating: Operating {
            speed_rad_s: BLANK,
            load: LoadSpec::Force { magnitude_n: BLANK, angle_rad: BLANK },
            supply_temperature_c: BLANK,
            film_temperature_c: BLANK,
            injection_pressure_pa: Vec::new(),
            injection_temperature_c: BLANK,
            supply_flow_m3_s: None,
            excitation_ratio: BLANK,
        },
        mesh: MeshSpec {
            fidelity: Fidelity::Preview,
            circumferential_elements: 0,
            axial_elements: 0,
            orifice_elements: 0,
            half_model: false,
            pad_radial_elements: 0,
            max_nodes: 0,
        },
        physics: Physics {
            cavitation: Cavitation::Reynolds,
            touchdown_film_m: BLANK,
            pad_modes: 0,
            turbulence: Turbulence::Off,
            transition_reynolds: [BLANK; 2],
            max_film_solves_per_pad: 0,
            ram_pressure_coefficient: BLANK,
        },
        thermal: Thermal {
            model: ThermalModelKind::Isothermal,
            pad_film_bc: PadFilmBc::Bc1,
            convection_w_per_m2_k: BLANK,
            ambient_temperature_c: BLANK,
            pad_conductivity_w_per_m_k: BLANK,
            inlet_temperature_c: None,
            journal_temperature_c: None,
            cavitated_film: CavitatedFilm::Striated,
            pad_expansion_per_k: BLANK,
            journal_expansion_per_k: BLANK,
            reference_temperature_c: None,
            housing_expansion_per_k: BLANK,
            housing_temperature_c: None,
            feeding: Feeding::Flooded { carry_over: BLANK, churning_factor: BLANK },
        },
        hydraulics: None,
        limits: Limits::default(),
        tuning: Tuning::default(),
    }
}

/// A pad with every field blank.
#[must_use]
pub fn pad() -> Pad {
    Pad {
        kind: PadKind::Tilting,
        leading_edge_rad: BLANK,
        arc_rad: BLANK,
        pivot_rad: BLANK,
        offset: BLANK,
        clearance_m: BLANK,
        preload: BLANK,
        thickness_m: BLANK,
        pivot_stiffness_n_per_m: None,
        pivot_transverse_stiffness_n_per_m: None,
        density_kg_per_m3: BLANK,
        massless: false,
        youngs_modulus_pa: BLANK,
        poisson_ratio: BLANK,
        pivot_contact: None,
        orifices: Vec::new(),
    }
}

/// A pivot contact with every value blank: where only whether a pad has one is read (its coordinates).
#[must_use]
pub fn contact() -> PivotContact {
    PivotContact {
        kind: ContactKind::Rocker,
        pivot_radius_m: BLANK,
        seat_radius_m: BLANK,
        length_m: BLANK,
        pivot_youngs_modulus_pa: BLANK,
        pivot_poisson_ratio: BLANK,
        seat_youngs_modulus_pa: BLANK,
        seat_poisson_ratio: BLANK,
    }
}
