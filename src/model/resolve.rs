//! Conversion of a [`CaseFile`] (engineering units) into a validated SI [`Case`].
//!
//! Every check names the key as it is written in the file. Pads are resolved per pad: the value in
//! `[[bearing.pad]]` entry i, else the common `[bearing.pads]` value, else a documented default, else an
//! error naming the common key.

use std::f64::consts::{PI, TAU};

use super::budget::{DEFAULT_MAX_NODES, MAX_NODES_RANGE};
use super::case::{Bearing, Case, LoadSpec, MeshSpec, Operating, Orifice, Pad, PadFilmBc, PadKind, Physics, Thermal};
use super::error::{CaseError, Range};
use super::file::{CaseFile, OneOrMany, PadFile, PadFilmBcFile, PadKindFile};

mod contact;
mod lubricant;

const MM: f64 = 1e-3;
const UM: f64 = 1e-6;
const BAR: f64 = 1e5;
/// Largest pad count the solver accepts.
pub const MAX_PADS: usize = 24;
/// Most bending modes per pad (the thesis finds the first one carries almost all of the effect).
pub const MAX_PAD_MODES: usize = 3;

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
        let touchdown = match self.physics.touchdown_film_um {
            Some(v) => Range::open_lo(0.0, 0.5 * cb / UM).check("physics.touchdown_film_um", v)? * UM,
            None => 0.01 * cb,
        };
        let pad_modes = match self.physics.pad_modes {
            Some(v) if v > MAX_PAD_MODES => {
                #[allow(clippy::cast_precision_loss)]
                let value = v as f64;
                return Err(CaseError::OutOfRange {
                    key: "physics.pad_modes".into(),
                    value,
                    allowed: format!("an integer in [0, {MAX_PAD_MODES}]"),
                });
            }
            v => v.unwrap_or(0),
        };
        let physics =
            Physics { cavitation: self.physics.cavitation.unwrap_or_default(), touchdown_film_m: touchdown, pad_modes };
        let thermal = resolve_thermal(self, &operating)?;
        let hydraulics = self
            .hydraulics
            .as_ref()
            .map(|h| super::hydraulics::resolve_hydraulics(h, bearing.pads.len()))
            .transpose()?;
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
        };
        super::budget::check(&case)?;
        Ok(case)
    }
}

fn inconsistent(key: &str, message: impl Into<String>) -> CaseError {
    CaseError::Inconsistent { key: key.to_string(), message: message.into() }
}

fn missing(key: &str, meaning: &str) -> CaseError {
    CaseError::MissingKey { key: key.to_string(), meaning: meaning.to_string() }
}

/// Resolves one pad field: per-pad entry first, then the common table.
struct PadSource<'a> {
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
    fn common_key(name: &str) -> String {
        format!("bearing.pads.{name}")
    }
}

fn resolve_bearing(file: &CaseFile) -> Result<Bearing, CaseError> {
    let b = &file.bearing;
    let radius = Range::positive(1e4).check("bearing.journal_radius_mm", b.journal_radius_mm)? * MM;
    let length = Range::positive(1e4).check("bearing.length_mm", b.length_mm)? * MM;
    // Clearance ratio Cb/R up to 5 % (bearings are typically 1–3 ‰).
    let cb_max_um = 0.05 * radius / UM;
    let cb = Range::positive(cb_max_um).check("bearing.assembled_clearance_um", b.assembled_clearance_um)? * UM;

    let common = &b.pads;
    if let Some(i) = b.pad.iter().position(|p| p.count.is_some()) {
        return Err(inconsistent(
            &format!("bearing.pad.{i}.count"),
            "the pad count belongs in [bearing.pads], not in a per-pad entry",
        ));
    }
    let n = pad_count(common, &b.pad)?;
    let pivots = pivot_angles(common, &b.pad, n)?;

    let mut pads = Vec::with_capacity(n);
    for (i, &pivot_deg) in pivots.iter().enumerate() {
        let src = PadSource { common, own: b.pad.get(i), index: i };
        pads.push(resolve_pad(&src, pivot_deg, radius, length, cb, n)?);
    }
    check_overlap(&pads)?;
    Ok(Bearing { journal_radius_m: radius, length_m: length, assembled_clearance_m: cb, pads })
}

fn pad_count(common: &PadFile, per_pad: &[PadFile]) -> Result<usize, CaseError> {
    let listed = match &common.pivot_deg {
        Some(OneOrMany::Many(v)) => Some(v.len()),
        _ => None,
    };
    let n = common
        .count
        .or(if per_pad.is_empty() { None } else { Some(per_pad.len()) })
        .or(listed)
        .ok_or_else(|| missing("bearing.pads.count", "number of pads"))?;
    #[allow(clippy::cast_precision_loss)]
    if n == 0 || n > MAX_PADS {
        return Err(CaseError::OutOfRange {
            key: "bearing.pads.count".into(),
            value: n as f64,
            allowed: format!("an integer in [1, {MAX_PADS}]"),
        });
    }
    if !per_pad.is_empty() && per_pad.len() != n {
        return Err(inconsistent(
            "bearing.pad",
            format!("{} per-pad entries for {n} pads (bearing.pads.count)", per_pad.len()),
        ));
    }
    if let Some(m) = listed {
        if m != n {
            return Err(inconsistent("bearing.pads.pivot_deg", format!("{m} pivot angles for {n} pads")));
        }
    }
    Ok(n)
}

#[allow(clippy::cast_precision_loss)]
fn pivot_angles(common: &PadFile, per_pad: &[PadFile], n: usize) -> Result<Vec<f64>, CaseError> {
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
                return Err(missing("bearing.pads.pivot_deg", "pivot angle(s), degrees from +x counter-clockwise"))
            }
        };
        out.push(Range::closed(-3600.0, 3600.0).check(&key, deg)?);
    }
    Ok(out)
}

#[allow(clippy::too_many_lines)]
fn resolve_pad(
    src: &PadSource<'_>,
    pivot_deg: f64,
    radius: f64,
    length: f64,
    cb: f64,
    n: usize,
) -> Result<Pad, CaseError> {
    let kind = match src.get("kind", |p| p.kind).map(|(k, _)| k).unwrap_or_default() {
        PadKindFile::Tilting => PadKind::Tilting,
        PadKindFile::Fixed => PadKind::Fixed,
    };
    let (arc_deg, arc_key) = src
        .get("arc_deg", |p| p.arc_deg)
        .ok_or_else(|| missing(&PadSource::common_key("arc_deg"), "pad arc, degrees"))?;
    let arc_max = if kind == PadKind::Fixed && n == 1 { 360.0 } else { 360.0 / n as f64 };
    let arc_deg = Range::open_lo(0.0, arc_max).check(&arc_key, arc_deg)?;
    let arc = arc_deg.to_radians();
    let full_circle = (arc_deg - 360.0).abs() < 1e-12;

    let offset = match src.get("offset", |p| p.offset) {
        Some((v, key)) => {
            if kind == PadKind::Tilting { Range::open(0.0, 1.0) } else { Range::closed(0.0, 1.0) }.check(&key, v)?
        }
        None if kind == PadKind::Fixed => 0.5,
        None => {
            return Err(missing(
                &PadSource::common_key("offset"),
                "pivot offset, fraction of the arc from the leading edge",
            ))
        }
    };

    // Exactly one of preload, clearance, bore radius (per pad, else common).
    let cp = pad_clearance(src, radius, cb)?;
    let preload = 1.0 - cb / cp;

    let thickness = match src.get("thickness_mm", |p| p.thickness_mm) {
        Some((v, key)) => Range::positive(1e4).check(&key, v)? * MM,
        None if kind == PadKind::Fixed => 0.0,
        None => return Err(missing(&PadSource::common_key("thickness_mm"), "pad thickness, mm")),
    };
    // Real pivots are 1e7–1e10 N/m; below 1e5 N/m a pad would float millimetres off its seat.
    let pivot_spring = |name: &str, f: fn(&PadFile) -> Option<f64>| -> Result<Option<f64>, CaseError> {
        match src.get(name, f) {
            Some((_, key)) if kind == PadKind::Fixed => Err(inconsistent(&key, "a fixed sector has no pivot")),
            Some((v, key)) => Ok(Some(Range::closed(1e5, 1e14).check(&key, v)?)),
            None => Ok(None),
        }
    };
    let pivot_stiffness = pivot_spring("pivot_stiffness_n_per_m", |p| p.pivot_stiffness_n_per_m)?;
    let pivot_transverse_stiffness =
        pivot_spring("pivot_transverse_stiffness_n_per_m", |p| p.pivot_transverse_stiffness_n_per_m)?;
    let massless = src.get("massless", |p| p.massless).is_some_and(|(m, _)| m);
    let density = match src.get("density_kg_per_m3", |p| p.density_kg_per_m3) {
        Some((_, key)) if massless => {
            return Err(inconsistent(&key, "massless pads have no density: remove it, or set massless = false"))
        }
        Some((v, key)) => Range::positive(3e4).check(&key, v)?,
        None => 7800.0,
    };
    let (youngs, poisson) =
        material(src, ("youngs_modulus_gpa", |p| p.youngs_modulus_gpa), ("poisson_ratio", |p| p.poisson_ratio))?;
    let pivot_contact = contact::resolve_contact(src, kind, pivot_stiffness.is_some(), (youngs, poisson), length)?;

    let pivot = pivot_deg.to_radians();
    let leading_edge = if full_circle { pivot - PI } else { pivot - offset * arc };

    // Orifices: per pad list replaces the common one.
    let (orifice_files, okey) = match (src.own.and_then(|p| p.orifice.as_ref()), src.common.orifice.as_ref()) {
        (Some(list), _) => (list.as_slice(), format!("bearing.pad.{}.orifice", src.index)),
        (None, Some(list)) => (list.as_slice(), "bearing.pads.orifice".to_string()),
        (None, None) => (&[][..], String::new()),
    };
    let mut orifices = Vec::with_capacity(orifice_files.len());
    for (k, o) in orifice_files.iter().enumerate() {
        let key = |f: &str| format!("{okey}[{k}].{f}");
        let d = Range::positive(1e3).check(&key("diameter_mm"), o.diameter_mm)? * MM;
        let l0 = Range::positive(1e4).check(&key("length_mm"), o.length_mm)? * MM;
        let frac = Range::open(0.0, 1.0).check(&key("position_frac"), o.position_frac)?;
        let afrac = Range::open(0.0, 1.0).check(&key("axial_frac"), o.axial_frac.unwrap_or(0.5))?;
        let s0 = frac * arc * radius;
        let z0 = (afrac - 0.5) * length;
        let r = 0.5 * d;
        if !full_circle && (s0 - r <= 0.0 || s0 + r >= arc * radius) {
            return Err(inconsistent(
                &key("position_frac"),
                format!(
                    "orifice outside its pad: an orifice of {:.3} mm at {frac} of a {arc_deg}° arc (arc length {:.3} mm) \
                     crosses the pad edge; allowed position_frac in ({:.4}, {:.4})",
                    d / MM,
                    arc * radius / MM,
                    r / (arc * radius),
                    1.0 - r / (arc * radius)
                ),
            ));
        }
        if z0.abs() + r >= 0.5 * length {
            return Err(inconsistent(
                &key("axial_frac"),
                format!(
                    "orifice outside its pad: a {:.3} mm orifice at axial_frac {afrac} crosses the pad's axial end",
                    d / MM
                ),
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
                return Err(inconsistent(
                    &format!("{okey}[{b}]"),
                    format!("orifice overlaps orifice {a} of the same pad"),
                ));
            }
        }
    }

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

/// A key of the pad tables and how to read it.
type PadKey = (&'static str, fn(&PadFile) -> Option<f64>);

/// An elastic material from a Young's modulus key [GPa] and a Poisson ratio key (steel when absent):
/// (E [Pa], ν).
fn material(src: &PadSource<'_>, youngs: PadKey, poisson: PadKey) -> Result<(f64, f64), CaseError> {
    let e = match src.get(youngs.0, youngs.1) {
        Some((v, key)) => Range::positive(2000.0).check(&key, v)? * 1e9,
        None => 200e9,
    };
    let nu = match src.get(poisson.0, poisson.1) {
        Some((v, key)) => Range::open(-1.0, 0.5).check(&key, v)?,
        None => 0.3,
    };
    Ok((e, nu))
}

fn pad_clearance(src: &PadSource<'_>, radius: f64, cb: f64) -> Result<f64, CaseError> {
    // The per-pad table wins as a whole; within one table only one of the three may be given.
    let pick = |p: &PadFile| -> Result<Option<(f64, &'static str)>, String> {
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
            _ => Err(given.iter().map(|g| g.1).collect::<Vec<_>>().join(" and ")),
        }
    };
    let (prefix, chosen) = {
        let own = match src.own.map(pick) {
            Some(Err(both)) => {
                return Err(inconsistent(
                    &format!("bearing.pad.{}", src.index),
                    format!("give one of preload, clearance_um, bore_radius_mm, not {both}"),
                ))
            }
            Some(Ok(v)) => v,
            None => None,
        };
        match own {
            Some(v) => (format!("bearing.pad.{}", src.index), v),
            None => match pick(src.common) {
                Err(both) => {
                    return Err(inconsistent(
                        "bearing.pads",
                        format!("give one of preload, clearance_um, bore_radius_mm, not {both}"),
                    ))
                }
                Ok(Some(v)) => ("bearing.pads".to_string(), v),
                Ok(None) => {
                    return Err(missing(
                        "bearing.pads.preload",
                        "pad geometry: one of preload, clearance_um or bore_radius_mm",
                    ))
                }
            },
        }
    };
    let (value, name) = chosen;
    let key = format!("{prefix}.{name}");
    let cp = match name {
        "preload" => {
            let m = Range { lo: -1.0, hi: 1.0, open_lo: false, open_hi: true }.check(&key, value)?;
            cb / (1.0 - m)
        }
        "clearance_um" => Range::positive(1e6).check(&key, value)? * UM,
        _ => {
            let rp = Range::positive(1e4).check(&key, value)? * MM;
            if rp <= radius {
                return Err(CaseError::OutOfRange {
                    key,
                    value,
                    allowed: format!("greater than the journal radius {} mm", radius / MM),
                });
            }
            rp - radius
        }
    };
    // Preload m = 1 − Cb/Cp must stay in [−1, 1).
    let m = 1.0 - cb / cp;
    if !(-1.0..1.0).contains(&m) {
        return Err(inconsistent(&key, format!("gives preload {m:.4} (1 − Cb/Cp); allowed [-1, 1)")));
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
            return Err(inconsistent(
                "bearing.pads.pivot_deg",
                format!(
                    "pads {ia} and {ib} overlap: pad {ia} spans {:.2}°–{:.2}°, pad {ib} starts at {:.2}°",
                    a.leading_edge_rad.to_degrees().rem_euclid(360.0),
                    a.leading_edge_rad.to_degrees().rem_euclid(360.0) + a.arc_rad.to_degrees(),
                    b.leading_edge_rad.to_degrees().rem_euclid(360.0)
                ),
            ));
        }
    }
    Ok(())
}

fn resolve_operating(file: &CaseFile, n_pads: usize) -> Result<Operating, CaseError> {
    let o = &file.operating;
    let speed_rpm = Range::closed(0.0, 1e6).check("operating.speed_rpm", o.speed_rpm)?;
    let angle = |key: &str, v: Option<f64>| -> Result<f64, CaseError> {
        Ok(Range::closed(-3600.0, 3600.0).check(key, v.unwrap_or(270.0))?.to_radians())
    };
    let load = match (o.load_n, o.eccentricity_ratio) {
        (Some(_), Some(_)) => {
            return Err(inconsistent(
                "operating.eccentricity_ratio",
                "give either load_n (find the position) or eccentricity_ratio (find the load), not both",
            ))
        }
        (Some(w), None) => LoadSpec::Force {
            magnitude_n: Range::closed(0.0, 1e10).check("operating.load_n", w)?,
            angle_rad: angle("operating.load_angle_deg", o.load_angle_deg)?,
        },
        (None, Some(e)) => {
            if o.load_angle_deg.is_some() {
                return Err(inconsistent(
                    "operating.load_angle_deg",
                    "with a prescribed eccentricity use eccentricity_angle_deg",
                ));
            }
            LoadSpec::Position {
                eccentricity_ratio: Range::closed(0.0, 10.0).check("operating.eccentricity_ratio", e)?,
                angle_rad: angle("operating.eccentricity_angle_deg", o.eccentricity_angle_deg)?,
            }
        }
        (None, None) => {
            return Err(missing("operating.load_n", "static load on the journal, N (or eccentricity_ratio)"))
        }
    };
    if o.eccentricity_angle_deg.is_some() && o.eccentricity_ratio.is_none() {
        return Err(inconsistent("operating.eccentricity_angle_deg", "only meaningful with eccentricity_ratio"));
    }
    let t_range = Range::closed(-60.0, 400.0);
    let supply = t_range.check("operating.supply_temperature_c", o.supply_temperature_c)?;
    let film = match o.film_temperature_c {
        Some(t) => t_range.check("operating.film_temperature_c", t)?,
        None => supply,
    };
    let p_range = Range::closed(0.0, 5000.0);
    let injection = match &o.injection_pressure_bar {
        None => vec![0.0; n_pads],
        Some(OneOrMany::One(p)) => vec![p_range.check("operating.injection_pressure_bar", *p)? * BAR; n_pads],
        Some(OneOrMany::Many(v)) => {
            if v.len() != n_pads {
                return Err(inconsistent(
                    "operating.injection_pressure_bar",
                    format!("{} values for {n_pads} pads (give one value, or one per pad)", v.len()),
                ));
            }
            v.iter()
                .enumerate()
                .map(|(i, p)| p_range.check(&format!("operating.injection_pressure_bar[{i}]"), *p).map(|p| p * BAR))
                .collect::<Result<_, _>>()?
        }
    };
    let injection_t = match o.injection_temperature_c {
        Some(t) => t_range.check("operating.injection_temperature_c", t)?,
        None => supply,
    };
    let excitation = Range::closed(0.0, 1e3).check("operating.excitation_ratio", o.excitation_ratio.unwrap_or(1.0))?;
    Ok(Operating {
        speed_rad_s: speed_rpm * TAU / 60.0,
        load,
        supply_temperature_c: supply,
        film_temperature_c: film,
        injection_pressure_pa: injection,
        injection_temperature_c: injection_t,
        excitation_ratio: excitation,
    })
}

#[allow(clippy::cast_precision_loss)]
fn resolve_mesh(file: &CaseFile, bearing: &Bearing) -> Result<MeshSpec, CaseError> {
    let m = &file.mesh;
    let fidelity = m.fidelity.unwrap_or_default();
    let (nx0, nz0, no0) = fidelity.elements();
    let count = |key: &str, v: Option<usize>, default: usize, lo: usize, hi: usize| -> Result<usize, CaseError> {
        let v = v.unwrap_or(default);
        if v < lo || v > hi {
            return Err(CaseError::OutOfRange {
                key: key.into(),
                value: v as f64,
                allowed: format!("an integer in [{lo}, {hi}]"),
            });
        }
        Ok(v)
    };
    let nx0 = fidelity.circumferential_elements(bearing.longest_arc_rad()).max(nx0);
    let nx = count("mesh.circumferential_elements", m.circumferential_elements, nx0, 4, 2000)?;
    let nz = count("mesh.axial_elements", m.axial_elements, nz0, 2, 1000)?;
    let no = count("mesh.orifice_elements", m.orifice_elements, no0, 2, 64)?;
    let nr = count("mesh.pad_radial_elements", m.pad_radial_elements, fidelity.pad_radial_elements(), 1, 200)?;
    let max_nodes = count("mesh.max_nodes", m.max_nodes, DEFAULT_MAX_NODES, MAX_NODES_RANGE.0, MAX_NODES_RANGE.1)?;
    let all_mid = bearing.pads.iter().flat_map(|p| &p.orifices).all(|o| o.axial_m.abs() < 1e-12);
    let half = match m.half_model {
        Some(true) if !all_mid => {
            return Err(inconsistent(
                "mesh.half_model",
                "the half model needs every orifice on the mid-plane (axial_frac = 0.5)",
            ))
        }
        Some(h) => h,
        None => all_mid,
    };
    if half && nz % 2 != 0 {
        return Err(CaseError::OutOfRange {
            key: "mesh.axial_elements".into(),
            value: nz as f64,
            allowed: "an even number with the half model".into(),
        });
    }
    Ok(MeshSpec {
        fidelity,
        circumferential_elements: nx,
        axial_elements: nz,
        orifice_elements: no,
        half_model: half,
        pad_radial_elements: nr,
        max_nodes,
    })
}

/// Thermal expansion coefficients [10⁻⁶/K]: 0 (no growth) to 100 (well above any bearing metal's ≈ 10–25).
const EXPANSION_PPM: Range = Range::closed(0.0, 100.0);

/// `[thermal]`: documented defaults — isothermal model, BC1, H∞ = 100 W/(m² K), T∞ = supply temperature,
/// pad conductivity 45 W/(m K) (steel), carry-over λ = 0.8, inlet and journal temperatures computed,
/// striated cavitated film.
fn resolve_thermal(file: &CaseFile, operating: &Operating) -> Result<Thermal, CaseError> {
    let t = &file.thermal;
    let t_range = Range::closed(-60.0, 400.0);
    let bc = t.pad_film_bc.unwrap_or_default();
    let pad_film_bc = match (bc, t.h_oil_pad_w_per_m2_k) {
        (PadFilmBcFile::Bc2, Some(h)) => {
            PadFilmBc::Bc2 { h_w_per_m2_k: Range::positive(1e8).check("thermal.h_oil_pad_w_per_m2_k", h)? }
        }
        (PadFilmBcFile::Bc2, None) => {
            return Err(missing(
                "thermal.h_oil_pad_w_per_m2_k",
                "film–pad exchange coefficient for pad_film_bc = \"bc2\", W/(m² K)",
            ))
        }
        (_, Some(_)) => {
            return Err(inconsistent("thermal.h_oil_pad_w_per_m2_k", "only used with pad_film_bc = \"bc2\""))
        }
        (PadFilmBcFile::Bc1, None) => PadFilmBc::Bc1,
        (PadFilmBcFile::Bc3, None) => PadFilmBc::Bc3,
    };
    let opt_t =
        |key: &str, v: Option<f64>| -> Result<Option<f64>, CaseError> { v.map(|x| t_range.check(key, x)).transpose() };
    Ok(Thermal {
        model: t.model.unwrap_or_default(),
        pad_film_bc,
        convection_w_per_m2_k: Range::closed(0.0, 1e6)
            .check("thermal.convection_w_per_m2_k", t.convection_w_per_m2_k.unwrap_or(100.0))?,
        ambient_temperature_c: opt_t("thermal.ambient_temperature_c", t.ambient_temperature_c)?
            .unwrap_or(operating.supply_temperature_c),
        pad_conductivity_w_per_m_k: Range::positive(1e4)
            .check("thermal.pad_conductivity_w_per_m_k", t.pad_conductivity_w_per_m_k.unwrap_or(45.0))?,
        carry_over: Range::closed(0.0, 1.0).check("thermal.carry_over", t.carry_over.unwrap_or(0.8))?,
        inlet_temperature_c: opt_t("thermal.inlet_temperature_c", t.inlet_temperature_c)?,
        journal_temperature_c: opt_t("thermal.journal_temperature_c", t.journal_temperature_c)?,
        cavitated_film: t.cavitated_film.unwrap_or_default(),
        pad_expansion_per_k: 1e-6
            * EXPANSION_PPM.check("thermal.pad_expansion_ppm_per_k", t.pad_expansion_ppm_per_k.unwrap_or(0.0))?,
        journal_expansion_per_k: 1e-6
            * EXPANSION_PPM
                .check("thermal.journal_expansion_ppm_per_k", t.journal_expansion_ppm_per_k.unwrap_or(0.0))?,
        reference_temperature_c: opt_t("thermal.reference_temperature_c", t.reference_temperature_c)?,
        housing_expansion_per_k: 1e-6
            * EXPANSION_PPM
                .check("thermal.housing_expansion_ppm_per_k", t.housing_expansion_ppm_per_k.unwrap_or(0.0))?,
        housing_temperature_c: opt_t("thermal.housing_temperature_c", t.housing_temperature_c)?,
    })
}
