//! Film and pad fields as VTK XML unstructured grids (`.vtu`) that ParaView opens, and `.pvd`
//! collections that step through a sweep.
//!
//! Geometry, in the bearing frame (x horizontal, y up, z axial; metres): the journal centre sits at
//! `e = (e_x, e_y)`, so the journal surface at angle θ is `e + R (cos θ, sin θ)` and the pad's film-side
//! surface, a film thickness further out along the same ray, is
//!
//! `x(θ, z) = e + (R + h(θ, z)) (cos θ, sin θ) + z e_z`.
//!
//! That is the real pad surface (preload, tilt and pivot displacement are all in `h`), to the order of the
//! film model. A pad solid layer at radius `r` of the pad's own curvature (from its bore `Rp` to `Rp + t`)
//! lies `r − Rp` further out along the ray. Half models are mirrored to the full length (as the views do).
//!
//! Film grid (`VTK_QUAD` cells, one per film element, every pad in one piece): point data
//! `pressure_pa`, `film_thickness_m`, `viscosity_pa_s`, `cavitated` (0/1), `pad`, the mean film velocity
//! `mean_velocity_m_s` (a 3-vector tangent to the surface: `v̄ = q/h`, docs/MODEL.md §3a) and, from the thermal
//! model, `film_temperature_c` and `pad_surface_temperature_c`. Pad grid (`VTK_HEXAHEDRON` cells between
//! the solid's layers): `pad_temperature_c` (thermal model), `pad`, and for flexible pads (also isothermal)
//! the mechanical displacement vector `pad_displacement_m` (Σ q_i ψ_i of the retained modes, bearing frame; the
//! pads' thermal growth is not in it yet).
//!
//! The files are ASCII XML with every number in Rust's shortest round-trip form, so a value read back is
//! bit-identical to the solver's.

use std::fmt::Write as _;

use crate::bearing::solution::{PadField, PadResult, Solution};
use crate::scene::field::{full_rows, full_values};
use crate::scene::flowlines::VelocityField;

/// VTK cell type ids.
const VTK_QUAD: u8 = 9;
const VTK_HEXAHEDRON: u8 = 12;

/// A named point-data array with 1 or 3 components.
#[derive(Debug, Clone, PartialEq)]
pub struct PointArray {
    pub name: &'static str,
    pub components: usize,
    pub values: Vec<f64>,
}

/// An unstructured grid as plain data.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Grid {
    /// Point coordinates, `[x, y, z]` [m].
    pub points: Vec<[f64; 3]>,
    /// Cell connectivity (point indices), cell by cell.
    pub connectivity: Vec<usize>,
    /// End offset of each cell in `connectivity`.
    pub offsets: Vec<usize>,
    pub types: Vec<u8>,
    pub arrays: Vec<PointArray>,
}

impl Grid {
    fn add_cell(&mut self, kind: u8, nodes: &[usize]) {
        self.connectivity.extend_from_slice(nodes);
        self.offsets.push(self.connectivity.len());
        self.types.push(kind);
    }

    fn array_mut(&mut self, name: &'static str, components: usize) -> &mut Vec<f64> {
        if let Some(i) = self.arrays.iter().position(|a| a.name == name) {
            return &mut self.arrays[i].values;
        }
        self.arrays.push(PointArray { name, components, values: Vec::new() });
        let last = self.arrays.len() - 1;
        &mut self.arrays[last].values
    }

    /// The grid as a VTK XML `UnstructuredGrid` file.
    #[must_use]
    pub fn to_vtu(&self) -> String {
        let mut s = String::with_capacity(64 * self.points.len() * (2 + self.arrays.len()));
        s.push_str("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n");
        let _ = writeln!(s, "<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">", self.points.len(), self.types.len());
        let scalars = self.arrays.iter().find(|a| a.components == 1).map_or("", |a| a.name);
        let vectors = self.arrays.iter().find(|a| a.components == 3).map_or("", |a| a.name);
        let _ = writeln!(s, "<PointData Scalars=\"{scalars}\" Vectors=\"{vectors}\">");
        for a in &self.arrays {
            let _ = writeln!(
                s,
                "<DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">",
                a.name, a.components
            );
            push_numbers(&mut s, a.values.iter().copied());
            s.push_str("</DataArray>\n");
        }
        s.push_str("</PointData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
        push_numbers(&mut s, self.points.iter().flatten().copied());
        s.push_str(
            "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n",
        );
        push_ints(&mut s, self.connectivity.iter().copied());
        s.push_str("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
        push_ints(&mut s, self.offsets.iter().copied());
        s.push_str("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
        push_ints(&mut s, self.types.iter().map(|&t| usize::from(t)));
        s.push_str("</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
        s
    }
}

fn push_numbers(s: &mut String, values: impl Iterator<Item = f64>) {
    for (k, v) in values.enumerate() {
        // Non-finite values never leave a solve; guard anyway so the XML stays parseable.
        let v = if v.is_finite() { v } else { 0.0 };
        let _ = write!(s, "{v:e}{}", if k % 6 == 5 { '\n' } else { ' ' });
    }
    s.push('\n');
}

fn push_ints(s: &mut String, values: impl Iterator<Item = usize>) {
    for (k, v) in values.enumerate() {
        let _ = write!(s, "{v}{}", if k % 12 == 11 { '\n' } else { ' ' });
    }
    s.push('\n');
}

/// One pad's full (mirrored) film grid: nodes `(i, row)` with `i` circumferential, rows ascending in z.
struct PadGrid<'a> {
    field: &'a PadField,
    rows: Vec<(f64, usize)>,
    /// Radius of the film-side pad surface along each node's ray, and the node's direction.
    radius_m: Vec<f64>,
}

impl<'a> PadGrid<'a> {
    fn new(pad: &'a PadResult, journal_radius_m: f64) -> Self {
        let field = &pad.field;
        let rows = full_rows(field);
        let h = full_values(field, &rows, &field.film_thickness_m);
        Self { field, rows, radius_m: h.iter().map(|h| journal_radius_m + h).collect() }
    }

    fn nz(&self) -> usize {
        self.rows.len()
    }

    fn nodes(&self) -> usize {
        self.field.s_m.len() * self.nz()
    }

    /// Position of node `(i, j)` pushed `extra` metres further out along its ray.
    fn point(&self, centre: [f64; 2], i: usize, j: usize, extra: f64) -> [f64; 3] {
        let th = self.field.theta_rad[i];
        let r = self.radius_m[i * self.nz() + j] + extra;
        [centre[0] + r * th.cos(), centre[1] + r * th.sin(), self.rows[j].0]
    }

    /// Quad corners of cell `(i, j)` in the local numbering `i * nz + j`, counter-clockwise seen from the
    /// journal.
    fn quad(&self, i: usize, j: usize) -> [usize; 4] {
        let nz = self.nz();
        [i * nz + j, (i + 1) * nz + j, (i + 1) * nz + j + 1, i * nz + j + 1]
    }
}

#[allow(clippy::cast_precision_loss)]
fn push_pad_index(grid: &mut Grid, pad: usize, count: usize) {
    grid.array_mut("pad", 1).extend(std::iter::repeat_n(pad as f64, count));
}

/// The film fields of every pad on the 3-D pad surfaces.
#[must_use]
pub fn film_grid(solution: &Solution) -> Grid {
    let r = solution.inputs.bearing.journal_radius_m;
    let centre = solution.journal_position_m;
    let u = solution.derived.speed_rad_s * r;
    let mut grid = Grid::default();
    // Flexible pads: the film face's elastic radial displacement (zero on rigid pads, so that every point has one).
    let flexible = solution.pads.iter().any(|p| !p.elastic_displacement_m.is_empty());
    for pad in &solution.pads {
        let pg = PadGrid::new(pad, r);
        let (nx, nz) = (pg.field.s_m.len(), pg.nz());
        let base = grid.points.len();
        for i in 0..nx {
            for j in 0..nz {
                grid.points.push(pg.point(centre, i, j, 0.0));
            }
        }
        for i in 0..nx.saturating_sub(1) {
            for j in 0..nz.saturating_sub(1) {
                let q = pg.quad(i, j).map(|k| base + k);
                grid.add_cell(VTK_QUAD, &q);
            }
        }
        let f = pg.field;
        let scalar = |grid: &mut Grid, name: &'static str, nodal: &[f64]| {
            grid.array_mut(name, 1).extend(full_values(f, &pg.rows, nodal))
        };
        scalar(&mut grid, "pressure_pa", &f.pressure_pa);
        scalar(&mut grid, "film_thickness_m", &f.film_thickness_m);
        scalar(&mut grid, "viscosity_pa_s", &f.viscosity_pa_s);
        let cav: Vec<f64> = f.cavitated.iter().map(|&c| if c { 1.0 } else { 0.0 }).collect();
        scalar(&mut grid, "cavitated", &cav);
        if let Some(t) = &f.film_temperature_c {
            scalar(&mut grid, "film_temperature_c", t);
        }
        if let Some(t) = &f.pad_surface_temperature_c {
            scalar(&mut grid, "pad_surface_temperature_c", t);
        }
        if flexible {
            let u = if pad.elastic_displacement_m.is_empty() {
                vec![0.0; f.pressure_pa.len()]
            } else {
                pad.elastic_displacement_m.clone()
            };
            scalar(&mut grid, "elastic_radial_displacement_m", &u);
        }
        push_pad_index(&mut grid, pad.index, pg.nodes());
        // Mean velocity: circumferential component along the surface tangent (−sin θ, cos θ, 0).
        let v = VelocityField::new(f, u);
        let vel = grid.array_mut("mean_velocity_m_s", 3);
        for i in 0..nx {
            let th = f.theta_rad[i];
            for j in 0..nz {
                let k = i * nz + j;
                vel.extend([-v.vs[k] * th.sin(), v.vs[k] * th.cos(), v.vz[k]]);
            }
        }
    }
    grid
}

/// The layer radii of a pad's solid (film face first) and its temperature field, when it has one: the
/// thermal model's solid, else a flexible pad's.
fn solid_layers(pad: &PadResult) -> Option<(&[f64], Option<&[f64]>)> {
    match (pad.thermal.as_ref().and_then(|t| t.solid.as_ref()), pad.flex.as_ref()) {
        (Some(s), _) => Some((&s.radii_m, Some(&s.temperature_c))),
        (None, Some(f)) => Some((&f.radii_m, None)),
        (None, None) => None,
    }
}

/// Mechanical displacement of a flexible pad's solid node `(layer, film node)` in the bearing frame:
/// `Σ q_i ψ_i` from the modes' polar components (u_r, u_θ, u_z) at the node's angle `theta`; `mirror`
/// flips u_z on the mirrored half of a half model.
fn modal_displacement(pad: &PadResult, node: usize, theta: f64, mirror: bool) -> [f64; 3] {
    let Some(flex) = &pad.flex else { return [0.0; 3] };
    let (mut ur, mut ut, mut uz) = (0.0, 0.0, 0.0);
    for (m, q) in flex.modes.modes.iter().zip(&pad.mode_amplitudes_m) {
        if let Some(v) = m.nodal.get(3 * node..3 * node + 3) {
            ur += q * v[0];
            ut += q * v[1];
            uz += q * v[2];
        }
    }
    let (c, s) = (theta.cos(), theta.sin());
    [ur * c - ut * s, ur * s + ut * c, if mirror { -uz } else { uz }]
}

/// The pad solids: the thermal model's (with `pad_temperature_c`) and flexible pads' (also isothermal),
/// with the mechanical displacement vector `pad_displacement_m` (Σ q_i ψ_i of the retained modes, bearing
/// frame; zero on rigid pads of the same grid) when any pad flexes.
#[must_use]
pub fn pad_solid_grid(solution: &Solution) -> Option<Grid> {
    let r = solution.inputs.bearing.journal_radius_m;
    let centre = solution.journal_position_m;
    let pads: Vec<&PadResult> =
        solution.pads.iter().filter(|p| solid_layers(p).is_some_and(|(radii, _)| radii.len() >= 2)).collect();
    let with_temperature = !pads.is_empty() && pads.iter().all(|p| solid_layers(p).is_some_and(|(_, t)| t.is_some()));
    let flexible = pads.iter().any(|p| p.flex.is_some());
    let mut grid = Grid::default();
    for pad in pads {
        let Some((radii, temperature)) = solid_layers(pad) else { continue };
        let pg = PadGrid::new(pad, r);
        let (nx, nz, layers) = (pg.field.s_m.len(), pg.nz(), radii.len());
        let n_film = pg.field.pressure_pa.len();
        let base = grid.points.len();
        let per_layer = pg.nodes();
        let mut temps = Vec::with_capacity(per_layer * layers);
        let mut disp = Vec::with_capacity(3 * per_layer * layers);
        for (l, &rl) in radii.iter().enumerate() {
            let extra = rl - radii[0];
            for i in 0..nx {
                for j in 0..nz {
                    grid.points.push(pg.point(centre, i, j, extra));
                    let (z, row) = pg.rows[j];
                    let node = l * n_film + pg.field.index(i, row);
                    if let Some(t) = temperature {
                        temps.push(t.get(node).copied().unwrap_or(f64::NAN));
                    }
                    if flexible {
                        let mirror = pg.field.half && z < 0.0;
                        disp.extend(modal_displacement(pad, node, pg.field.theta_rad[i], mirror));
                    }
                }
            }
        }
        for l in 0..layers - 1 {
            for i in 0..nx.saturating_sub(1) {
                for j in 0..nz.saturating_sub(1) {
                    let q = pg.quad(i, j);
                    let lo = q.map(|k| base + l * per_layer + k);
                    let hi = q.map(|k| base + (l + 1) * per_layer + k);
                    grid.add_cell(VTK_HEXAHEDRON, &[lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]);
                }
            }
        }
        if with_temperature {
            grid.array_mut("pad_temperature_c", 1).extend(temps);
        }
        if flexible {
            grid.array_mut("pad_displacement_m", 3).extend(disp);
        }
        push_pad_index(&mut grid, pad.index, per_layer * layers);
    }
    (!grid.points.is_empty()).then_some(grid)
}

/// A `.pvd` collection: one data set per `(timestep, part, file)`; ParaView steps through the timesteps
/// (a sweep's values) and overlays the parts (film, pads).
#[must_use]
pub fn pvd(entries: &[(f64, usize, String)]) -> String {
    let mut s = String::from("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n");
    for (t, part, file) in entries {
        let _ = writeln!(s, "<DataSet timestep=\"{t:e}\" group=\"\" part=\"{part}\" file=\"{}\"/>", xml_escape(file));
    }
    s.push_str("</Collection>\n</VTKFile>\n");
    s
}

fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('"', "&quot;").replace('<', "&lt;").replace('>', "&gt;")
}
