//! Conversion of a [`CaseFile`] (engineering units) into a validated SI [`Case`].
//!
//! Every check names the key as it is written in the file. A key's allowed range, its default and its unit
//! are the ones of its row in [`super::schema`] (`key!("…")` finds the row while compiling); what is left
//! here are the rules between keys (pads that overlap, an orifice off its pad, exactly one of preload,
//! clearance and bore) and the ranges that depend on other values. Pads are resolved per pad: the value in
//! `[[bearing.pad]]` entry i, else the common `[bearing.pads]` value, else the row's default, else an error
//! naming the common key.

use std::f64::consts::{PI, TAU};

use super::case::{Bearing, Case, LoadSpec, MeshSpec, Operating, Orifice, Pad, PadKind, Physics};
use super::error::{CaseError, Inconsistency, Range};
use super::file::{CaseFile, Cavitation, OneOrMany, PadFile, PadKindFile};
use super::schema::{KeySpec, MAX_CLEARANCE_RATIO, MAX_TOUCHDOWN_RATIO};
use crate::key;
use crate::units::DEG;

mod contact;
mod hydraulics;
mod lubricant;
mod thermal;

impl CaseFile {
    /// Validates every value and converts to SI.
    ///
    /// # Errors
    /// The first problem found, naming its key, value and allowed range.
    pub fn resolve(&self) -> Result<Case, CaseError> {
        let bearing = resolve_bearing(self)?;
        let lubricant = lubricant::resolve_lubricant(self)?;
        let operating = resolve_operating(self, bearing.pads.len())?;
        let mesh = resolve_mesh(self, &bearing)?;
        let cb = bearing.assembled_clearance_m;
        let touchdown = key!("physics.touchdown_film_um");
        if let Some(v) = self.physics.touchdown_film_um {
            Range::open_lo(0.0, touchdown.from_si(MAX_TOUCHDOWN_RATIO * cb)).check(touchdown.key, v)?;
        }
        let physics = Physics {
            cavitation: self.physics.cavitation.unwrap_or_default(),
            touchdown_film_m: touchdown.value_in(self, self.physics.touchdown_film_um)?,
            pad_modes: key!("physics.pad_modes").count(self.physics.pad_modes)?,
            turbulence: self.physics.turbulence.unwrap_or_default(),
            transition_reynolds: resolve_transition(self)?,
            max_film_solves_per_pad: key!("physics.max_film_solves_per_pad")
                .count(self.physics.max_film_solves_per_pad)?,
            ram_pressure_coefficient: thermal::resolve_ram_pressure(self)?,
        };
        let thermal = thermal::resolve_thermal(self)?;
        thermal::check_groove_width(self, &bearing)?;
        check_sleeve_feed(physics.cavitation, &bearing, &operating)?;
        let hydraulics =
            self.hydraulics.as_ref().map(|h| hydraulics::resolve_hydraulics(h, bearing.pads.len())).transpose()?;
        if let Some(h) = &hydraulics {
            check_ports(h, &bearing, &operating)?;
        }
        let limits = super::limits::resolve_limits(&self.limits)?;
        let case = Case {
            title: self.title.clone().unwrap_or_default(),
            bearing,
            lubricant,
            operating,
            mesh,
            physics,
            thermal,
            hydraulics,
            limits,
            tuning: super::tuning::Tuning::resolve(self)?,
        };
        super::budget::check(&case)?;
        Ok(case)
    }
}

/// The transition band: each end in its row's range, and the end above the start (a band upside down names
/// the end key, its value and the interval the start leaves it).
fn resolve_transition(f: &CaseFile) -> Result<[f64; 2], CaseError> {
    let start = key!("physics.transition_reynolds_start").value(f.physics.transition_reynolds_start)?;
    let end_row = key!("physics.transition_reynolds_end");
    let end = end_row.value(f.physics.transition_reynolds_end)?;
    Range::open_lo(start, super::schema::MAX_TRANSITION_REYNOLDS).check(end_row.key, end)?;
    Ok([start, end])
}

/// Every pad a line feeds has an orifice, and the supply is above each fed pad's static injection pressure.
fn check_ports(
    h: &super::hydraulics::Hydraulics,
    bearing: &super::Bearing,
    operating: &super::Operating,
) -> Result<(), CaseError> {
    for (i, port) in h.ports.iter().enumerate() {
        for &pad in &port.pads {
            if bearing.pads.get(pad).is_some_and(|p| p.orifices.is_empty()) {
                return Err(inconsistent(
                    format!("hydraulics.port[{i}].pads"),
                    Inconsistency::PortPadWithoutOrifice { pad },
                ));
            }
            let injection = operating.injection_pressure_pa.get(pad).copied().unwrap_or(0.0);
            if injection > h.supply_pressure_pa {
                return Err(inconsistent(
                    "hydraulics.supply_pressure_bar",
                    Inconsistency::SupplyBelowInjection {
                        supply_bar: crate::units::BAR.from_si(h.supply_pressure_pa),
                        pad,
                        injection_bar: crate::units::BAR.from_si(injection),
                    },
                ));
            }
        }
    }
    Ok(())
}

/// A 360° sleeve has no leading edge: with the mass-conserving film its only oil is what an injecting orifice
/// feeds (without one the film drains through its ends and carries no load, which the equilibrium would
/// report as a missing stiffness, not as the input's fault).
fn check_sleeve_feed(cavitation: Cavitation, bearing: &Bearing, operating: &Operating) -> Result<(), CaseError> {
    if cavitation != Cavitation::Jfo {
        return Ok(());
    }
    let unfed = bearing.pads.iter().enumerate().find(|(k, pad)| {
        pad.is_full_circle() && (pad.orifices.is_empty() || operating.injection_pressure_pa[*k] <= 0.0)
    });
    match unfed {
        Some((pad, _)) => Err(inconsistent("physics.cavitation", Inconsistency::JfoSleeveWithoutFeed { pad })),
        None => Ok(()),
    }
}

fn inconsistent(key: impl Into<String>, reason: Inconsistency) -> CaseError {
    CaseError::inconsistent(key, reason)
}

fn missing(key: &str, meaning: &str) -> CaseError {
    CaseError::missing(key, meaning)
}

/// Resolves one pad field: per-pad entry first, then the common table.
struct PadSource<'a> {
    file: &'a CaseFile,
    common: &'a PadFile,
    own: Option<&'a PadFile>,
    index: usize,
}

impl PadSource<'_> {
    /// Returns the value and the key it came from.
    fn get<T: Copy>(&self, name: &str, f: impl Fn(&PadFile) -> Option<T>) -> Option<(T, String)> {
        if let Some(v) = self.own.and_then(&f) {
            return Some((v, format!("bearing.pad.{}.{name}", self.index)));
        }
        f(self.common).map(|v| (v, format!("bearing.pads.{name}")))
    }

    /// The pad's value of a numeric key in SI: given (per pad, else common) and checked against the row,
    /// else the row's default (`None` for a key without one).
    fn si(&self, row: &KeySpec, f: impl Fn(&PadFile) -> Option<f64>) -> Result<Option<f64>, CaseError> {
        match self.get(pad_name(row), f) {
            Some((v, key)) => row.value_at(&key, Some(v)).map(Some),
            None => Ok(row.default_in(self.file).map(|v| row.to_si(v))),
        }
    }
}

/// The name of a `bearing.pads.<name>` row inside a pad table.
fn pad_name(row: &KeySpec) -> &'static str {
    row.key.strip_prefix("bearing.pads.").unwrap_or(row.key)
}

fn resolve_bearing(file: &CaseFile) -> Result<Bearing, CaseError> {
    let b = &file.bearing;
    let radius = key!("bearing.journal_radius_mm").value(Some(b.journal_radius_mm))?;
    let length = key!("bearing.length_mm").value(Some(b.length_mm))?;
    let clearance = key!("bearing.assembled_clearance_um");
    let cb = clearance.to_si(
        Range::positive(clearance.from_si(MAX_CLEARANCE_RATIO * radius))
            .check(clearance.key, b.assembled_clearance_um)?,
    );

    let common = &b.pads;
    if let Some(i) = b.pad.iter().position(|p| p.count.is_some()) {
        return Err(inconsistent(format!("bearing.pad.{i}.count"), Inconsistency::PadCountInPadEntry));
    }
    let n = pad_count(common, &b.pad)?;
    let pivots = pivot_angles(common, &b.pad, n)?;

    let mut pads = Vec::with_capacity(n);
    for (i, &pivot) in pivots.iter().enumerate() {
        let src = PadSource { file, common, own: b.pad.get(i), index: i };
        pads.push(resolve_pad(&src, pivot, radius, length, cb, n)?);
    }
    check_overlap(&pads)?;
    Ok(Bearing { journal_radius_m: radius, length_m: length, assembled_clearance_m: cb, pads })
}

fn pad_count(common: &PadFile, per_pad: &[PadFile]) -> Result<usize, CaseError> {
    let listed = match &common.pivot_deg {
        Some(OneOrMany::Many(v)) => Some(v.len()),
        _ => None,
    };
    let count = key!("bearing.pads.count");
    let n = common
        .count
        .or(if per_pad.is_empty() { None } else { Some(per_pad.len()) })
        .or(listed)
        .ok_or_else(|| missing(count.key, "number of pads"))?;
    let n = count.count(Some(n))?;
    if !per_pad.is_empty() && per_pad.len() != n {
        return Err(inconsistent("bearing.pad", Inconsistency::PadEntries { entries: per_pad.len(), pads: n }));
    }
    if let Some(m) = listed {
        if m != n {
            return Err(inconsistent("bearing.pads.pivot_deg", Inconsistency::PerPadValues { given: m, pads: n }));
        }
    }
    Ok(n)
}

/// Each pad's pivot angle [rad].
#[allow(clippy::cast_precision_loss)]
fn pivot_angles(common: &PadFile, per_pad: &[PadFile], n: usize) -> Result<Vec<f64>, CaseError> {
    let row = key!("bearing.pads.pivot_deg");
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let own = per_pad.get(i).and_then(|p| p.pivot_deg.as_ref());
        let (deg, key) = match (own, &common.pivot_deg) {
            (Some(OneOrMany::One(v)), _) => (*v, format!("bearing.pad.{i}.pivot_deg")),
            (Some(OneOrMany::Many(_)), _) => {
                return Err(CaseError::WrongType {
                    key: format!("bearing.pad.{i}.pivot_deg"),
                    message: "a per-pad pivot is one angle, not a list".into(),
                })
            }
            (None, Some(OneOrMany::Many(v))) => (v[i], format!("bearing.pads.pivot_deg[{i}]")),
            (None, Some(OneOrMany::One(first))) => {
                (first + 360.0 * i as f64 / n as f64, "bearing.pads.pivot_deg".into())
            }
            (None, None) => {
                return Err(missing(row.key, "pivot angle(s), degrees from +x counter-clockwise"));
            }
        };
        out.push(row.value_at(&key, Some(deg))?);
    }
    Ok(out)
}

#[allow(clippy::too_many_lines)]
fn resolve_pad(src: &PadSource<'_>, pivot: f64, radius: f64, length: f64, cb: f64, n: usize) -> Result<Pad, CaseError> {
    let kind = match src.get("kind", |p| p.kind).map(|(k, _)| k).unwrap_or_default() {
        PadKindFile::Tilting => PadKind::Tilting,
        PadKindFile::Fixed => PadKind::Fixed,
    };
    let fixed = kind == PadKind::Fixed;
    let arc_row = key!("bearing.pads.arc_deg");
    let (arc_deg, arc_key) =
        src.get("arc_deg", |p| p.arc_deg).ok_or_else(|| missing(arc_row.key, "pad arc, degrees"))?;
    #[allow(clippy::cast_precision_loss)]
    let arc_max = if fixed && n == 1 { 360.0 } else { 360.0 / n as f64 };
    let arc_deg = Range::open_lo(0.0, arc_max).check(&arc_key, arc_deg)?;
    let arc = arc_row.to_si(arc_deg);
    let full_circle = (arc_deg - 360.0).abs() < 1e-12;

    let offset_row = key!("bearing.pads.offset");
    let offset = match src.get("offset", |p| p.offset) {
        Some((v, key)) => if fixed { Range::closed(0.0, 1.0) } else { Range::open(0.0, 1.0) }.check(&key, v)?,
        None if fixed => offset_row.value(None)?,
        None => return Err(missing(offset_row.key, "pivot offset, fraction of the arc from the leading edge")),
    };

    // Exactly one of preload, clearance, bore radius (per pad, else common).
    let cp = pad_clearance(src, radius, cb)?;
    let preload = 1.0 - cb / cp;

    let thickness_row = key!("bearing.pads.thickness_mm");
    let thickness = match src.get("thickness_mm", |p| p.thickness_mm) {
        Some((v, key)) => thickness_row.value_at(&key, Some(v))?,
        None if fixed => thickness_row.value(None)?,
        None => return Err(missing(thickness_row.key, "pad thickness, mm")),
    };
    let pivot_spring = |row: &KeySpec, f: fn(&PadFile) -> Option<f64>| -> Result<Option<f64>, CaseError> {
        match src.get(pad_name(row), f) {
            Some((_, key)) if fixed => Err(inconsistent(key, Inconsistency::FixedSectorPivot)),
            Some((v, key)) => row.value_at(&key, Some(v)).map(Some),
            None => Ok(None),
        }
    };
    let pivot_stiffness = pivot_spring(key!("bearing.pads.pivot_stiffness_n_per_m"), |p| p.pivot_stiffness_n_per_m)?;
    let pivot_transverse_stiffness = pivot_spring(key!("bearing.pads.pivot_transverse_stiffness_n_per_m"), |p| {
        p.pivot_transverse_stiffness_n_per_m
    })?;
    let massless = src.get("massless", |p| p.massless).is_some_and(|(m, _)| m);
    let density_row = key!("bearing.pads.density_kg_per_m3");
    if let (true, Some((_, key))) = (massless, src.get("density_kg_per_m3", |p| p.density_kg_per_m3)) {
        return Err(inconsistent(key, Inconsistency::MasslessWithDensity));
    }
    let density = src.si(density_row, |p| p.density_kg_per_m3)?.unwrap_or_default();
    let youngs = src.si(key!("bearing.pads.youngs_modulus_gpa"), |p| p.youngs_modulus_gpa)?.unwrap_or_default();
    let poisson = src.si(key!("bearing.pads.poisson_ratio"), |p| p.poisson_ratio)?.unwrap_or_default();
    let pivot_contact = contact::resolve_contact(src, kind, pivot_stiffness.is_some(), (youngs, poisson))?;

    let leading_edge = if full_circle { pivot - PI } else { pivot - offset * arc };
    let orifices = resolve_orifices(src, arc, arc_deg, full_circle, leading_edge, radius, length)?;

    Ok(Pad {
        kind,
        leading_edge_rad: leading_edge,
        arc_rad: if full_circle { TAU } else { arc },
        pivot_rad: pivot,
        offset,
        clearance_m: cp,
        preload,
        thickness_m: thickness,
        pivot_stiffness_n_per_m: pivot_stiffness,
        pivot_transverse_stiffness_n_per_m: pivot_transverse_stiffness,
        density_kg_per_m3: density,
        massless,
        youngs_modulus_pa: youngs,
        poisson_ratio: poisson,
        pivot_contact,
        orifices,
    })
}

/// A pad's orifices: the per-pad list replaces the common one; each must lie on its pad, and no two overlap.
fn resolve_orifices(
    src: &PadSource<'_>,
    arc: f64,
    arc_deg: f64,
    full_circle: bool,
    leading_edge: f64,
    radius: f64,
    length: f64,
) -> Result<Vec<Orifice>, CaseError> {
    let (orifice_files, okey) = match (src.own.and_then(|p| p.orifice.as_ref()), src.common.orifice.as_ref()) {
        (Some(list), _) => (list.as_slice(), format!("bearing.pad.{}.orifice", src.index)),
        (None, Some(list)) => (list.as_slice(), "bearing.pads.orifice".to_string()),
        (None, None) => (&[][..], String::new()),
    };
    let diameter_row = key!("bearing.pads.orifice[].diameter_mm");
    let mut orifices = Vec::with_capacity(orifice_files.len());
    for (k, o) in orifice_files.iter().enumerate() {
        let key = |f: &str| format!("{okey}[{k}].{f}");
        let field =
            |row: &KeySpec, v: Option<f64>| row.value_at(&key(row.key.rsplit('.').next().unwrap_or(row.key)), v);
        let d = field(diameter_row, Some(o.diameter_mm))?;
        let l0 = field(key!("bearing.pads.orifice[].length_mm"), Some(o.length_mm))?;
        let frac = field(key!("bearing.pads.orifice[].position_frac"), Some(o.position_frac))?;
        let afrac = field(key!("bearing.pads.orifice[].axial_frac"), o.axial_frac)?;
        let s0 = frac * arc * radius;
        let z0 = (afrac - 0.5) * length;
        let r = 0.5 * d;
        if !full_circle && (s0 - r <= 0.0 || s0 + r >= arc * radius) {
            return Err(inconsistent(
                key("position_frac"),
                Inconsistency::OrificeOffArc {
                    diameter_mm: diameter_row.from_si(d),
                    position_frac: frac,
                    arc_deg,
                    arc_length_mm: diameter_row.from_si(arc * radius),
                    lowest: r / (arc * radius),
                    highest: 1.0 - r / (arc * radius),
                },
            ));
        }
        if z0.abs() + r >= 0.5 * length {
            return Err(inconsistent(
                key("axial_frac"),
                Inconsistency::OrificeOffLength { diameter_mm: diameter_row.from_si(d), axial_frac: afrac },
            ));
        }
        orifices.push(Orifice { angle_rad: leading_edge + frac * arc, axial_m: z0, diameter_m: d, length_m: l0 });
    }
    // Orifices on one pad must not overlap one another.
    for a in 0..orifices.len() {
        for b in a + 1..orifices.len() {
            let (oa, ob) = (&orifices[a], &orifices[b]);
            let ds = (oa.angle_rad - ob.angle_rad) * radius;
            let dz = oa.axial_m - ob.axial_m;
            if ds.hypot(dz) < 0.5 * (oa.diameter_m + ob.diameter_m) {
                return Err(inconsistent(format!("{okey}[{b}]"), Inconsistency::OrificesOverlap { other: a }));
            }
        }
    }
    Ok(orifices)
}

/// The machined pad clearance Cp [m] from exactly one of preload, clearance_um, bore_radius_mm (the per-pad
/// table wins as a whole; within one table only one of the three may be given).
fn pad_clearance(src: &PadSource<'_>, radius: f64, cb: f64) -> Result<f64, CaseError> {
    let pick = |p: &PadFile| -> Result<Option<(f64, &'static str)>, Vec<String>> {
        let given: Vec<(f64, &'static str)> = [
            p.preload.map(|v| (v, "preload")),
            p.clearance_um.map(|v| (v, "clearance_um")),
            p.bore_radius_mm.map(|v| (v, "bore_radius_mm")),
        ]
        .into_iter()
        .flatten()
        .collect();
        match given.len() {
            0 => Ok(None),
            1 => Ok(Some(given[0])),
            _ => Err(given.iter().map(|g| g.1.to_string()).collect()),
        }
    };
    let twice = |table: String, given| inconsistent(table, Inconsistency::PadGeometryTwice { given });
    let own_table = format!("bearing.pad.{}", src.index);
    let (prefix, (value, name)) = match src.own.map(pick).transpose().map_err(|g| twice(own_table.clone(), g))? {
        Some(Some(v)) => (own_table, v),
        _ => match pick(src.common).map_err(|g| twice("bearing.pads".into(), g))? {
            Some(v) => ("bearing.pads".to_string(), v),
            None => {
                return Err(missing(
                    "bearing.pads.preload",
                    "pad geometry: one of preload, clearance_um or bore_radius_mm",
                ))
            }
        },
    };
    let key = format!("{prefix}.{name}");
    let cp = match name {
        "preload" => cb / (1.0 - key!("bearing.pads.preload").value_at(&key, Some(value))?),
        "clearance_um" => key!("bearing.pads.clearance_um").value_at(&key, Some(value))?,
        _ => {
            let row = key!("bearing.pads.bore_radius_mm");
            let rp = row.value_at(&key, Some(value))?;
            if rp <= radius {
                return Err(CaseError::OutOfRange {
                    key,
                    value,
                    allowed: format!("greater than the journal radius {} mm", row.from_si(radius)),
                });
            }
            rp - radius
        }
    };
    // Preload m = 1 − Cb/Cp must stay in [−1, 1).
    let m = 1.0 - cb / cp;
    if !(-1.0..1.0).contains(&m) {
        return Err(inconsistent(key, Inconsistency::PreloadOutOfRange { preload: m }));
    }
    Ok(cp)
}

fn check_overlap(pads: &[Pad]) -> Result<(), CaseError> {
    if pads.len() < 2 {
        return Ok(());
    }
    let mut order: Vec<usize> = (0..pads.len()).collect();
    order.sort_by(|&a, &b| {
        pads[a].leading_edge_rad.rem_euclid(TAU).total_cmp(&pads[b].leading_edge_rad.rem_euclid(TAU))
    });
    for w in 0..order.len() {
        let (ia, ib) = (order[w], order[(w + 1) % order.len()]);
        let (a, b) = (&pads[ia], &pads[ib]);
        // Angle from a's leading edge to the next leading edge, counter-clockwise.
        let room = (b.leading_edge_rad - a.leading_edge_rad).rem_euclid(TAU);
        if a.arc_rad > room + 1e-9 {
            let deg = |rad: f64| DEG.from_si(rad);
            let from = deg(a.leading_edge_rad).rem_euclid(360.0);
            return Err(inconsistent(
                "bearing.pads.pivot_deg",
                Inconsistency::PadsOverlap {
                    first: ia,
                    second: ib,
                    first_from_deg: from,
                    first_to_deg: from + deg(a.arc_rad),
                    second_from_deg: deg(b.leading_edge_rad).rem_euclid(360.0),
                },
            ));
        }
    }
    Ok(())
}

fn resolve_operating(file: &CaseFile, n_pads: usize) -> Result<Operating, CaseError> {
    let o = &file.operating;
    let speed = key!("operating.speed_rpm").value(Some(o.speed_rpm))?;
    let load = match (o.load_n, o.eccentricity_ratio) {
        (Some(_), Some(_)) => {
            return Err(inconsistent("operating.eccentricity_ratio", Inconsistency::LoadAndEccentricity));
        }
        (Some(w), None) => LoadSpec::Force {
            magnitude_n: key!("operating.load_n").value(Some(w))?,
            angle_rad: key!("operating.load_angle_deg").value(o.load_angle_deg)?,
        },
        (None, Some(e)) => {
            if o.load_angle_deg.is_some() {
                return Err(inconsistent("operating.load_angle_deg", Inconsistency::LoadAngleWithEccentricity));
            }
            LoadSpec::Position {
                eccentricity_ratio: key!("operating.eccentricity_ratio").value(Some(e))?,
                angle_rad: key!("operating.eccentricity_angle_deg").value(o.eccentricity_angle_deg)?,
            }
        }
        (None, None) => {
            return Err(missing("operating.load_n", "static load on the journal, N (or eccentricity_ratio)"));
        }
    };
    if o.eccentricity_angle_deg.is_some() && o.eccentricity_ratio.is_none() {
        return Err(inconsistent("operating.eccentricity_angle_deg", Inconsistency::EccentricityAngleWithoutRatio));
    }
    let supply = key!("operating.supply_temperature_c").value(Some(o.supply_temperature_c))?;
    let film = key!("operating.film_temperature_c").value_in(file, o.film_temperature_c)?;
    let pressure = key!("operating.injection_pressure_bar");
    let injection = match &o.injection_pressure_bar {
        None => vec![pressure.value(None)?; n_pads],
        Some(OneOrMany::One(p)) => vec![pressure.value(Some(*p))?; n_pads],
        Some(OneOrMany::Many(v)) => {
            if v.len() != n_pads {
                return Err(inconsistent(pressure.key, Inconsistency::PerPadValues { given: v.len(), pads: n_pads }));
            }
            v.iter()
                .enumerate()
                .map(|(i, p)| pressure.value_at(&format!("{}[{i}]", pressure.key), Some(*p)))
                .collect::<Result<_, CaseError>>()?
        }
    };
    let supply_flow_m3_s = resolve_supply_flow(file, n_pads)?;
    Ok(Operating {
        supply_flow_m3_s,
        speed_rad_s: speed,
        load,
        supply_temperature_c: supply,
        film_temperature_c: film,
        injection_pressure_pa: injection,
        injection_temperature_c: key!("operating.injection_temperature_c").value_in(file, o.injection_temperature_c)?,
        excitation_ratio: key!("operating.excitation_ratio").value(o.excitation_ratio)?,
    })
}

fn resolve_mesh(file: &CaseFile, bearing: &Bearing) -> Result<MeshSpec, CaseError> {
    let m = &file.mesh;
    let nx = key!("mesh.circumferential_elements").count_in(file, m.circumferential_elements)?;
    let nz = key!("mesh.axial_elements").count_in(file, m.axial_elements)?;
    let no = key!("mesh.orifice_elements").count_in(file, m.orifice_elements)?;
    let nr = key!("mesh.pad_radial_elements").count_in(file, m.pad_radial_elements)?;
    let max_nodes = key!("mesh.max_nodes").count(m.max_nodes)?;
    let all_mid = bearing.pads.iter().flat_map(|p| &p.orifices).all(|o| o.axial_m.abs() < 1e-12);
    let half = match m.half_model {
        Some(true) if !all_mid => return Err(inconsistent("mesh.half_model", Inconsistency::HalfModelOffMidPlane)),
        Some(h) => h,
        None => all_mid,
    };
    if half && nz % 2 != 0 {
        #[allow(clippy::cast_precision_loss)]
        return Err(CaseError::OutOfRange {
            key: "mesh.axial_elements".into(),
            value: nz as f64,
            allowed: "an even number with the half model".into(),
        });
    }
    Ok(MeshSpec {
        fidelity: m.fidelity.unwrap_or_default(),
        circumferential_elements: nx,
        axial_elements: nz,
        orifice_elements: no,
        half_model: half,
        pad_radial_elements: nr,
        max_nodes,
    })
}

/// Each pad's supply flow [m³/s]: the bearing's `operating.supply_flow_l_per_min` shared equally, or
/// `operating.pad_supply_flow_l_per_min` per pad; `None` (flooded) without either. Both need the
/// mass-conserving cavitation option.
fn resolve_supply_flow(file: &CaseFile, n_pads: usize) -> Result<Option<Vec<f64>>, CaseError> {
    let o = &file.operating;
    let (bearing, pad) = (key!("operating.supply_flow_l_per_min"), key!("operating.pad_supply_flow_l_per_min"));
    let flows = match (o.supply_flow_l_per_min, &o.pad_supply_flow_l_per_min) {
        (None, None) => return Ok(None),
        (Some(_), Some(_)) => {
            return Err(inconsistent(pad.key, Inconsistency::SupplyFlowTwice));
        }
        #[allow(clippy::cast_precision_loss)]
        (Some(q), None) => vec![bearing.value(Some(q))? / n_pads as f64; n_pads],
        (None, Some(OneOrMany::One(q))) => vec![pad.value(Some(*q))?; n_pads],
        (None, Some(OneOrMany::Many(v))) => {
            if v.len() != n_pads {
                return Err(inconsistent(pad.key, Inconsistency::PerPadValues { given: v.len(), pads: n_pads }));
            }
            v.iter()
                .enumerate()
                .map(|(i, q)| pad.value_at(&format!("{}[{i}]", pad.key), Some(*q)))
                .collect::<Result<_, CaseError>>()?
        }
    };
    if file.physics.cavitation != Some(Cavitation::Jfo) {
        let key = if o.supply_flow_l_per_min.is_some() { bearing.key } else { pad.key };
        return Err(inconsistent(key, Inconsistency::SupplyFlowWithoutJfo));
    }
    Ok(Some(flows))
}
