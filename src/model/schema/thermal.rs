//! Rows of `[thermal]`: the film model, the film–pad exchange, the pads' conduction and surroundings, the
//! groove mixing and the thermal growth (TEHD).

use super::running::SUPPLY;
use super::Group::Thermal;
use super::Widget::{Choice, Optional};
use super::{Fallback, KeySpec, TEMPERATURE};
use crate::model::error::Range;
use crate::model::file::{CaseFile, FeedingKind, PadFilmBcFile, ThermalModelKind};
use crate::units::{CELSIUS, COUNT, ONE, PPM_PER_K, W_PER_M2_K, W_PER_M_K};

type Key = KeySpec;

/// Thermal expansion coefficients: 0 (no growth) to 100 (well above any bearing metal's ≈ 10–25).
const EXPANSION: Range = Range::closed(0.0, 100.0);

/// The thermal rows apply to the thermal (THD) model only.
fn thd(f: &CaseFile) -> bool {
    f.thermal.model == Some(ThermalModelKind::Thd)
}
/// The feedings whose hot-oil carry-over is `thermal.carry_over` (not the leading-edge groove).
fn carried_by_journal(f: &CaseFile) -> bool {
    thd(f) && f.feeding.kind != Some(FeedingKind::LeadingEdgeGroove)
}
fn bc2(f: &CaseFile) -> bool {
    thd(f) && f.thermal.pad_film_bc == Some(PadFilmBcFile::Bc2)
}

pub(super) const KEYS: &[Key] = &[
    Key::choice("thermal.model", &["isothermal", "thd"])
        .default(Fallback::Word("isothermal"))
        .edit(Thermal, "Film model", Choice(&["Isothermal", "Thermohydrodynamic (THD)"]))
        .meaning("Isothermal: one viscosity, at the film temperature. THD: the film energy equation (shear heating, convection, conduction, injection), 3-D pad conduction and the groove mixing between pads, iterated with the equilibrium until the viscosity field converges. THD lowers stiffness and damping."),
    Key::choice("thermal.pad_film_bc", &["bc1", "bc2", "bc3"])
        .default(Fallback::Word("bc1"))
        .edit(
            Thermal,
            "Film–pad condition",
            Choice(&["BC1 — adiabatic film", "BC2 — exchange coefficient", "BC3 — Knight & Barrett parabola"]),
        )
        .when(thd)
        .meaning("BC1: adiabatic film, the pad surface takes the film temperature (decoupled, fast; laminar bearings). BC2: convective exchange with a constant coefficient. BC3 (Knight & Barrett): parabolic temperature across the film, coupled with the pad and the journal (near the laminar limit)."),
    Key::choice("thermal.cavitated_film", &["striated", "full_film"])
        .default(Fallback::Word("striated"))
        .edit(Thermal, "Cavitated film", Choice(&["Striated (film fraction)", "Full film"]))
        .when(thd)
        .meaning("Striated: in a ruptured zone oil fills only the fraction of the gap that carries the flow entering it (mass conservation of the Couette flow); shear and heat capacity scale with it. Full film: as the thesis assumes."),
    Key::number("thermal.h_oil_pad_w_per_m2_k", W_PER_M2_K, Range::positive(1e8))
        .typical(100.0, 20_000.0)
        .default(Fallback::Rule("required with bc2, not allowed otherwise"))
        .edit(Thermal, "Film–pad exchange H", Optional(0))
        .when(bc2)
        .meaning("BC2 only: heat flux from the film into the pad surface per kelvin of difference. A single coefficient cannot describe the laminar film well (the thesis shows BC2 is poor); offered for comparison."),
    Key::number("thermal.convection_w_per_m2_k", W_PER_M2_K, Range::closed(0.0, 1e6))
        .typical(10.0, 1000.0)
        .or(100.0)
        .edit(Thermal, "Free convection H∞", Optional(0))
        .when(thd)
        .meaning("Heat-transfer coefficient from the pads' free faces (back, sides, edges) to the surrounding oil at T∞."),
    Key::number("thermal.ambient_temperature_c", CELSIUS, TEMPERATURE)
        .typical(0.0, 150.0)
        .default(SUPPLY)
        .edit(Thermal, "Surroundings T∞", Optional(1))
        .when(thd)
        .meaning("Temperature of the oil around the pads (default: the supply temperature)."),
    Key::number("thermal.pad_conductivity_w_per_m_k", W_PER_M_K, Range::positive(1e4))
        .typical(1.0, 400.0)
        .or(45.0)
        .edit(Thermal, "Pad conductivity", Optional(1))
        .when(thd)
        .meaning("Thermal conductivity of the pad material (steel ≈ 45, brass ≈ 109, bronze ≈ 60)."),
    Key::number("thermal.carry_over", ONE, Range::closed(0.0, 1.0))
        .typical(0.0, 1.0)
        .or(0.8)
        .edit(Thermal, "Hot-oil carry-over λ", Optional(2))
        .when(carried_by_journal)
        .meaning("Flooded housing and spray bar (feeding.kind): fraction of the hot oil leaving a pad's trailing edge that the journal carries to the next pad's leading edge (typically 0.7–0.9). Flooded, it enters the film first and fresh supply oil makes up the rest; with a spray bar it mixes fully with the sprayed oil. A leading-edge groove uses feeding.groove_carry_over instead."),
    Key::number("thermal.inlet_temperature_c", CELSIUS, TEMPERATURE)
        .typical(0.0, 150.0)
        .default(Fallback::Rule("from the groove mixing"))
        .edit(Thermal, "Given inlet temperature", Optional(1))
        .when(thd)
        .meaning("Leading-edge oil temperature of every pad, when measured. Unset: from the groove mixing balance."),
    Key::number("thermal.journal_temperature_c", CELSIUS, TEMPERATURE)
        .typical(0.0, 150.0)
        .default(Fallback::Rule("from zero net heat flux"))
        .edit(Thermal, "Given journal temperature", Optional(1))
        .when(thd)
        .meaning("Journal surface temperature, when known. Unset: from zero net heat flux into the journal."),
    Key::number("thermal.pad_expansion_ppm_per_k", PPM_PER_K, EXPANSION)
        .typical(10.0, 20.0)
        .or(0.0)
        .edit(Thermal, "Pad expansion α", Optional(1))
        .when(thd)
        .meaning("TEHD: thermal expansion of the pads (steel ≈ 12, bronze ≈ 18). The pad's 3-D temperature strains its solid (clamped on the pivot patch); the film-face radial displacement changes the film thickness inside the thermal loop. 0: no pad growth."),
    Key::number("thermal.journal_expansion_ppm_per_k", PPM_PER_K, EXPANSION)
        .typical(10.0, 20.0)
        .or(0.0)
        .edit(Thermal, "Journal expansion α", Optional(1))
        .when(thd)
        .meaning("TEHD: thermal expansion of the journal (steel ≈ 11–12): it grows by α R (T_journal − T_ref), closing every film by as much. 0: no journal growth."),
    Key::number("thermal.reference_temperature_c", CELSIUS, TEMPERATURE)
        .typical(0.0, 60.0)
        .default(SUPPLY)
        .edit(Thermal, "Clearance reference temperature", Optional(1))
        .when(thd)
        .meaning("TEHD: temperature at which the clearances are given (the assembly temperature); growth is counted from it."),
    Key::number("thermal.housing_expansion_ppm_per_k", PPM_PER_K, EXPANSION)
        .typical(10.0, 24.0)
        .or(0.0)
        .edit(Thermal, "Housing expansion α", Optional(1))
        .when(thd)
        .meaning("TEHD: thermal expansion of the housing and pivots (steel ≈ 12, aluminium ≈ 23) at the housing temperature: each pivot moves out by α R_p (T_housing − T_ref) (R_p: the pivot radius, journal radius + assembled clearance + pad thickness), opening its film by that times cos(θ − θ_pivot); a fixed sector's bore grows by α times its radius. 0: no housing growth."),
    Key::number("thermal.housing_temperature_c", CELSIUS, TEMPERATURE)
        .typical(20.0, 80.0)
        .default(SUPPLY)
        .edit(Thermal, "Housing temperature", Optional(1))
        .when(thd)
        .meaning("TEHD: temperature of the housing and pivots, for their growth (thermal.housing_expansion_ppm_per_k)."),
    Key::integer("thermal.max_iterations", COUNT, 10, 100_000)
        .typical(100.0, 1000.0)
        .default(Fallback::Count(300))
        .tuning()
        .edit(Thermal, "Iteration budget", Optional(0))
        .when(thd)
        .meaning("Outer iterations (equilibrium, temperatures, viscosity update) the THD loop may take before it stops and says it did not converge. Shipped cases converge in 10–60; points near touchdown or with lightly loaded pads can need a few hundred. A loop stopped by this budget names it in its error: raise it there."),
    Key::number("thermal.viscosity_tolerance", ONE, Range::open_lo(0.0, 1e-2))
        .typical(1e-7, 1e-3)
        .or(1e-4)
        .tuning()
        .edit(Thermal, "Viscosity tolerance", Optional(8))
        .when(thd)
        .meaning("The THD loop has converged when no node's film viscosity changed by more than this fraction in the last outer iteration. 1e-4 moves temperatures by well under 0.1 K; tighten it (1e-6 … 1e-8) for reference solutions and convergence studies, at a few more outer iterations per decade."),
];
