//! The FRF view: Bode plots (magnitude on log axes, phase folded into ±180°) of the controllable bearing — G1,
//! G2, G3, G and the rig's calibrated-shaker chain — against frequency, one unit at a time (a selector; the
//! legend above the plots, never over them or the controls), line modes marked, with sliders for air
//! fraction, line length and valve bandwidth that re-run only the frequency loop, CSV export, and the
//! model's limitations stated.
//!
//! The bearing's equilibrium and linearisation ([`FrfModel`]) come from the FRF stage, run by the solver
//! off the UI thread like every stage while this view is open; the sliders change a copy of the case's
//! hydraulics and re-run only [`FrfModel::sweep`] (400 frequencies, a few milliseconds), no stage.

use egui::{Color32, RichText, Ui};
use egui_plot::{HoverPosition, Line, Plot, VLine};

use crate::app::ink;
use super::plot_kit::{decade_label, legend_ui, phase_label, wrapped_phase, NamedPlot, PALETTE, PHASE_TICKS};

use super::{View, ViewContext};
use crate::bearing::frf::model::{band, FrfModel};
use crate::bearing::stages::StageId;
use crate::model::Case;
use crate::scene::frf::FrfCurves;
use crate::units::{BAR, HZ_ANGULAR, MM, RPM};

/// The curves of one unit, plotted together: `G1 [V/V]`, `G, C [N/V]`, …
#[derive(Debug, Clone, PartialEq)]
pub struct Family {
    pub label: String,
    pub unit: &'static str,
}

/// The curves grouped by unit, in the order they come: one plot per unit, chosen with a selector.
#[must_use]
pub fn families(curves: &FrfCurves) -> Vec<Family> {
    let mut out: Vec<(Vec<String>, &'static str)> = Vec::new();
    for c in &curves.curves {
        // Rig curves are named by their own name; the bearing's by their group (G3 for G3_A_x, …).
        let short = if c.group == "rig" { c.name.clone() } else { c.group.to_string() };
        match out.iter_mut().find(|(_, u)| *u == c.unit) {
            Some((names, _)) if !names.contains(&short) => names.push(short),
            Some(_) => {}
            None => out.push((vec![short], c.unit)),
        }
    }
    out.into_iter().map(|(names, unit)| Family { label: format!("{} [{unit}]", names.join(", ")), unit }).collect()
}

/// The view's runtime state (not persisted).
#[derive(Default)]
pub struct FrfView {
    /// The case the slider values belong to.
    for_case: Option<Case>,
    /// Slider values: air fraction [–], line length [mm], valve natural frequency [Hz]; `None` = the case's.
    air_fraction: Option<f64>,
    line_length_mm: Option<f64>,
    valve_hz: Option<f64>,
    db: bool,
    /// The unit family shown (index into [`families`]).
    pub family: usize,
    curves: Option<(Case, FrfCurves)>,
    /// Control amplitude to check against the valve's small-signal range [V].
    amplitude_v: f64,
}

/// What the view asks the app to do.
pub enum FrfAction {
    ExportCsv(String),
}

impl FrfView {
    /// A new case resets the sliders to its values.
    fn follow(&mut self, case: &Case) {
        if self.for_case.as_ref() != Some(case) {
            self.for_case = Some(case.clone());
            (self.air_fraction, self.line_length_mm, self.valve_hz, self.curves) = (None, None, None, None);
        }
    }
}

impl View for FrfView {
    fn id(&self) -> &'static str {
        "frf"
    }

    fn label(&self) -> &'static str {
        "FRF"
    }

    /// The solution and the bearing linearised for its injection ports.
    fn needs(&self) -> &'static [StageId] {
        &[StageId::Reduction, StageId::Frf]
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        let Some(shown) = cx.shown else { return };
        if let Some(FrfAction::ExportCsv(csv)) = frf_ui(ui, self, &shown.solution.inputs, shown.frf.as_deref()) {
            cx.export("frf", "CSV", "csv", csv.into_bytes());
        }
    }

    fn snapshot_setup(&mut self) -> Option<&'static str> {
        Some(include_str!("../../../cases/test-rig-pub5.toml"))
    }
}

/// The case with the sliders applied to its hydraulics.
fn adjusted(case: &Case, air: f64, length_mm: f64, valve_hz: f64) -> Case {
    let mut c = case.clone();
    if let Some(h) = c.hydraulics.as_mut() {
        h.valve.natural_frequency_rad_s = HZ_ANGULAR.to_si(valve_hz);
        for p in &mut h.ports {
            p.air_fraction = air;
            p.line_length_m = MM.to_si(length_mm);
        }
    }
    c
}

/// Draws the view for `case` (the shown solution's inputs) and its linearised bearing `model` (the FRF
/// stage's output; `None` while it is computed).
pub fn frf_ui(ui: &mut Ui, view: &mut FrfView, case: &Case, model: Option<&FrfModel>) -> Option<FrfAction> {
    let Some(h) = case.hydraulics.clone() else {
        ui.add_space(16.0);
        ui.label(RichText::new("Frequency response of the controllable bearing").heading());
        ui.label("This case has no [hydraulics] section (servovalve, ports, injection lines). Open the shipped \"Test rig, Publ. 5\" case to see the FRFs.");
        return None;
    };
    let Some(model) = model else {
        ui.label("Linearising the bearing for its injection ports…");
        return None;
    };
    view.follow(case);
    let (air0, len0, hz0) = (
        h.ports[0].air_fraction,
        MM.from_si(h.ports[0].line_length_m),
        HZ_ANGULAR.from_si(h.valve.natural_frequency_rad_s),
    );
    let mut air = view.air_fraction.unwrap_or(air0);
    let mut len = view.line_length_mm.unwrap_or(len0);
    let mut hz = view.valve_hz.unwrap_or(hz0);
    let mut changed = false;
    // Two rows of two sliders: a slider with its text is laid out as one piece, so a wrapping row would
    // let the second of a pair run past the view's edge at 1280×720.
    ui.spacing_mut().slider_width = 90.0;
    ui.horizontal(|ui| {
        changed |= ui.add(egui::Slider::new(&mut air, 0.0..=0.03).text("air fraction")).changed();
        changed |= ui.add(egui::Slider::new(&mut len, 100.0..=3000.0).text("line length [mm]")).changed();
    });
    ui.horizontal(|ui| {
        changed |=
            ui.add(egui::Slider::new(&mut hz, 20.0..=500.0).logarithmic(true).text("valve ω_V/2π [Hz]")).changed();
        ui.add(egui::Slider::new(&mut view.amplitude_v, 0.0..=h.valve.full_scale_v).text("signal [V]"));
    });
    if changed {
        (view.air_fraction, view.line_length_mm, view.valve_hz) = (Some(air), Some(len), Some(hz));
    }
    let adj = adjusted(case, air, len, hz);
    if view.curves.as_ref().is_none_or(|(c, _)| *c != adj) {
        match model.sweep(&adj, &band(1.0, 1000.0, 400)) {
            Ok(s) => {
                let names: Vec<&str> = h.ports.iter().map(|p| if p.sign > 0.0 { "A" } else { "B" }).collect();
                let title = format!(
                    "{:.0} rpm, ε = {:.3}, supply {:.0} bar",
                    RPM.from_si(case.operating.speed_rad_s),
                    model.eccentricity_ratio,
                    BAR.from_si(h.supply_pressure_pa)
                );
                view.curves = Some((adj.clone(), FrfCurves::new(&s, &names, title)));
            }
            Err(e) => {
                ui.label(e.to_string());
                return None;
            }
        }
    }
    let (_, curves) = view.curves.as_ref()?;
    let mut action = None;
    let families = families(curves);
    view.family = view.family.min(families.len().saturating_sub(1));
    ui.horizontal_wrapped(|ui| {
        let label = ui.label("Show");
        egui::ComboBox::from_id_salt("frf-family")
            .selected_text(families.get(view.family).map_or("", |f| f.label.as_str()))
            .show_ui(ui, |ui| {
                for (i, f) in families.iter().enumerate() {
                    ui.selectable_value(&mut view.family, i, &f.label);
                }
            })
            .response
            .on_hover_text("One plot per unit: the transfer functions that share it.")
            .labelled_by(label.id);
        ui.separator();
        ui.selectable_value(&mut view.db, false, "|G| log scale");
        ui.selectable_value(&mut view.db, true, "dB");
        if ui.button("Export CSV").clicked() {
            action = Some(FrfAction::ExportCsv(curves.csv()));
        }
    });
    ui.label(RichText::new(format!("Bode — {}", curves.title)).strong());
    if let Some(f) = families.get(view.family) {
        bode_ui(ui, curves, f, view.db);
    }
    let limit = 0.1 * h.valve.full_scale_v;
    if view.amplitude_v > limit {
        ui.label(RichText::new(format!("Signal {:.2} V exceeds the small-signal range of the linear valve model ({limit:.2} V, 10 % of full scale).", view.amplitude_v)).color(ink::WARNING.of(ui)));
    }
    for n in &curves.notes {
        ui.label(RichText::new(n).italics().weak());
    }
    action
}

/// The magnitude and the phase (folded into ±180°) of the curves of `family`, the legend above them.
fn bode_ui(ui: &mut Ui, curves: &FrfCurves, family: &Family, db: bool) {
    let shown: Vec<_> = curves.curves.iter().filter(|c| c.unit == family.unit).collect();
    let colors: Vec<Color32> = PALETTE.iter().copied().cycle().take(shown.len()).collect();
    let mut entries: Vec<(String, Color32)> = shown.iter().zip(&colors).map(|(c, k)| (c.name.clone(), *k)).collect();
    let modes: Vec<f64> =
        curves.line_modes_hz.iter().flatten().copied().filter(|f| (1.0..=1000.0).contains(f)).collect();
    if !modes.is_empty() {
        entries.push(("line modes (dashed)".into(), Color32::from_gray(140)));
    }
    legend_ui(ui, &entries);
    let lf: Vec<f64> = curves.frequency_hz.iter().map(|f| f.log10()).collect();
    let height = ((ui.available_height() - 70.0) / 2.0).max(140.0);
    // The central area can be wider than what is visible beside the results panel: keep to the visible part.
    let width = ui.available_width().min(ui.clip_rect().width());
    let unit = family.unit;
    let hover = move |p: &HoverPosition<'_>, phase: bool| -> Option<String> {
        match p {
            HoverPosition::NearDataPoint { plot_name, position, .. } => {
                let f = crate::number::sig(10f64.powf(position.x), 4);
                let value = match (phase, db) {
                    (true, _) => format!("{:.1}°", position.y),
                    (false, true) => format!("{:.2} dB re 1 {unit}", position.y),
                    (false, false) => format!("{} {unit}", crate::number::sig(10f64.powf(position.y), 4)),
                };
                Some(format!("{plot_name}\n{f} Hz\n{value}"))
            }
            HoverPosition::Elsewhere { .. } => None,
        }
    };
    let link = ui.scope_id().with("frf_bode");
    let mag_label = if db { format!("|G| [dB re 1 {unit}]") } else { format!("|G| [{unit}]") };
    for phase in [false, true] {
        let mut plot = Plot::new(if phase { "frf_phase" } else { "frf_magnitude" })
            .height(height)
            .width(width)
            .x_axis_label("frequency [Hz]")
            .x_axis_formatter(|m, _| decade_label(m.value))
            .x_grid_spacer(egui_plot::log_grid_spacer(10))
            .label_formatter(move |p| hover(p, phase))
            .link_axis(link, [true, false])
            .allow_scroll(false);
        plot = if phase {
            plot.y_axis_label("phase [°]")
                .y_grid_spacer(egui_plot::uniform_grid_spacer(|_| PHASE_TICKS))
                .y_axis_formatter(|m, _| phase_label(m.value))
                .include_y(-180.0)
                .include_y(180.0)
        } else if db {
            plot.y_axis_label(mag_label.clone())
        } else {
            plot.y_axis_label(mag_label.clone())
                .y_grid_spacer(egui_plot::log_grid_spacer(10))
                .y_axis_formatter(|m, _| decade_label(m.value))
        };
        // "|G| [V/V] of G1 against frequency [Hz]": the curves' names without the family's unit.
        let names = family.label.split(" [").next().unwrap_or_default();
        let name = format!("{} of {names} against frequency [Hz]", if phase { "phase [°]" } else { &mag_label });
        plot.show(ui, |p| {
            for (c, color) in shown.iter().zip(&colors) {
                if phase {
                    for piece in wrapped_phase(&lf, &c.phase_deg) {
                        p.line(Line::new(c.name.clone(), piece).color(*color).width(1.6));
                    }
                    continue;
                }
                let y: Vec<f64> = if db {
                    c.magnitude.iter().map(|m| 20.0 * m.max(1e-300).log10()).collect()
                } else {
                    c.magnitude.iter().map(|m| m.max(1e-300).log10()).collect()
                };
                let pts: Vec<[f64; 2]> = lf.iter().zip(&y).map(|(x, y)| [*x, *y]).collect();
                p.line(Line::new(c.name.clone(), pts).color(*color).width(1.6));
            }
            for f in &modes {
                p.vline(
                    VLine::new("line modes", f.log10())
                        .color(Color32::from_gray(140))
                        .style(egui_plot::LineStyle::dashed_loose()),
                );
            }
        })
        .named(&name);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::frf::Curve;

    /// The rig's curves grouped one unit per plot: the bearing's by group, the rig's by name; G and the
    /// shaker force C share N/V.
    #[test]
    fn curves_are_grouped_one_unit_per_plot() {
        let curve = |name: &str, unit: &'static str, group: &'static str| Curve {
            name: name.into(),
            unit,
            group,
            magnitude: vec![1.0],
            phase_deg: vec![0.0],
        };
        let curves = FrfCurves {
            frequency_hz: vec![1.0],
            curves: vec![
                curve("G1", "V/V", "G1"),
                curve("G2_A", "bar/V", "G2"),
                curve("G2_B", "bar/V", "G2"),
                curve("G3_A_x", "N/bar", "G3"),
                curve("G_x", "N/V", "G"),
                curve("C", "N/V", "rig"),
                curve("H_pseudo", "µm/V", "rig"),
                curve("H_chain", "µm/N", "rig"),
                curve("H_direct", "µm/N", "rig"),
            ],
            line_modes_hz: Vec::new(),
            title: String::new(),
            notes: Vec::new(),
        };
        let labels: Vec<String> = families(&curves).into_iter().map(|f| f.label).collect();
        assert_eq!(
            labels,
            ["G1 [V/V]", "G2 [bar/V]", "G3 [N/bar]", "G, C [N/V]", "H_pseudo [µm/V]", "H_chain, H_direct [µm/N]"]
        );
    }
}
