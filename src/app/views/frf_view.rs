//! The FRF view: Bode plots (magnitude, unwrapped phase) of the controllable bearing — G1, G2, G3, G and the
//! rig's calibrated-shaker chain — against frequency on a log axis, line modes marked, with sliders for air
//! fraction, line length and valve bandwidth that re-run only the frequency loop, CSV export, and the
//! model's limitations stated.
//!
//! The bearing's equilibrium and linearisation ([`FrfModel`]) come from the FRF stage, run by the solver
//! off the UI thread like every stage while this view is open; the sliders change a copy of the case's
//! hydraulics and re-run only [`FrfModel::sweep`] (400 frequencies, a few milliseconds), no stage.

use egui::{Color32, RichText, Ui};
use egui_plot::{HoverPosition, Legend, Line, Plot, VLine};

use super::{View, ViewContext};
use crate::bearing::frf::model::{band, FrfModel};
use crate::bearing::stages::StageId;
use crate::model::Case;
use crate::scene::frf::FrfCurves;
use crate::units::{BAR, HZ_ANGULAR, MM, RPM};

const COLORS: [Color32; 12] = [
    Color32::from_rgb(86, 180, 233),
    Color32::from_rgb(230, 159, 0),
    Color32::from_rgb(0, 158, 115),
    Color32::from_rgb(204, 121, 167),
    Color32::from_rgb(213, 94, 0),
    Color32::from_rgb(0, 114, 178),
    Color32::from_rgb(240, 228, 66),
    Color32::from_gray(160),
    Color32::from_rgb(150, 110, 220),
    Color32::from_rgb(120, 200, 120),
    Color32::from_rgb(240, 120, 120),
    Color32::from_rgb(100, 210, 210),
];

const GROUPS: [&str; 5] = ["G1", "G2", "G3", "G", "rig"];

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
    hidden: [bool; 5],
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

fn log_ticks(value: f64) -> String {
    let v = 10f64.powf(value);
    if v >= 1.0 {
        format!("{v:.0}")
    } else {
        format!("{v:.2}")
    }
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
    ui.spacing_mut().slider_width = 110.0;
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
    ui.horizontal_wrapped(|ui| {
        for (g, hidden) in GROUPS.iter().zip(view.hidden.iter_mut()) {
            let mut shown = !*hidden;
            if ui.checkbox(&mut shown, *g).changed() {
                *hidden = !shown;
            }
        }
        ui.separator();
        ui.selectable_value(&mut view.db, false, "log |G|");
        ui.selectable_value(&mut view.db, true, "dB");
        if ui.button("Export CSV").clicked() {
            action = Some(FrfAction::ExportCsv(curves.csv()));
        }
    });
    ui.label(RichText::new(format!("Bode — {}", curves.title)).strong());
    bode_ui(ui, curves, &view.hidden, view.db);
    let limit = 0.1 * h.valve.full_scale_v;
    if view.amplitude_v > limit {
        ui.label(RichText::new(format!("Signal {:.2} V exceeds the small-signal range of the linear valve model ({limit:.2} V, 10 % of full scale).", view.amplitude_v)).color(Color32::from_rgb(230, 120, 60)));
    }
    for n in &curves.notes {
        ui.label(RichText::new(n).italics().weak());
    }
    action
}

fn bode_ui(ui: &mut Ui, curves: &FrfCurves, hidden: &[bool; 5], db: bool) {
    let visible = |g: &str| GROUPS.iter().position(|x| *x == g).is_none_or(|i| !hidden[i]);
    let lf: Vec<f64> = curves.frequency_hz.iter().map(|f| f.log10()).collect();
    let height = ((ui.available_height() - 60.0) / 2.0).max(140.0);
    // The central area can be wider than what is visible beside the results panel: keep to the visible part.
    let width = ui.available_width().min(ui.clip_rect().width());
    let modes: Vec<f64> =
        curves.line_modes_hz.iter().flatten().copied().filter(|f| (1.0..=1000.0).contains(f)).collect();
    let hover = |p: &HoverPosition<'_>, unit: &str| -> Option<String> {
        match p {
            HoverPosition::NearDataPoint { plot_name, position, .. } => {
                Some(format!("{plot_name}\n{:.1} Hz\n{:.3} {unit}", 10f64.powf(position.x), position.y))
            }
            HoverPosition::Elsewhere { .. } => None,
        }
    };
    let link = ui.scope_id().with("frf_bode");
    let mag_unit = if db { "dB" } else { "log10 |G|" };
    for (id, unit) in [("frf_magnitude", mag_unit), ("frf_phase", "deg")] {
        let mut plot = Plot::new(id).height(height).width(width);
        if id == "frf_magnitude" {
            plot = plot.legend(Legend::default().position(egui_plot::Corner::LeftBottom));
        }
        plot.x_axis_label("frequency [Hz]")
            .y_axis_label(unit)
            .x_axis_formatter(|m, _| log_ticks(m.value))
            .label_formatter(move |p| hover(p, unit))
            .link_axis(link, [true, false])
            .allow_scroll(false)
            .show(ui, |p| {
                for (c, color) in curves.curves.iter().filter(|c| visible(c.group)).zip(COLORS.iter().cycle()) {
                    let y: Vec<f64> = if id == "frf_phase" {
                        c.phase_deg.clone()
                    } else if db {
                        c.magnitude.iter().map(|m| 20.0 * m.max(1e-300).log10()).collect()
                    } else {
                        c.magnitude.iter().map(|m| m.max(1e-300).log10()).collect()
                    };
                    let pts: Vec<[f64; 2]> = lf.iter().zip(&y).map(|(x, y)| [*x, *y]).collect();
                    p.line(Line::new(format!("{} [{}]", c.name, c.unit), pts).color(*color).width(1.6));
                }
                for f in &modes {
                    p.vline(
                        VLine::new("line modes", f.log10())
                            .color(Color32::from_gray(140))
                            .style(egui_plot::LineStyle::dashed_loose()),
                    );
                }
            });
    }
}
