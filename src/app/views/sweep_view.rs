//! The sweep view: any numeric case key against any output columns ([`crate::scene::sweep`]), one plot
//! per output with its unit, the current case's point marked, points beyond a design limit marked, the
//! Sommerfeld chart one click away (a load sweep drawn as ε, φ, h_min/Cb and the reduced coefficients
//! against S, with the closed-form curves of a plain bearing; [`crate::scene::sommerfeld`]), CSV export with
//! every column.
//!
//! The points are solved by a [`SweepRun`] (a thread on native, one point per frame on the web); the view
//! only reads its table.

use egui::{Color32, ComboBox, DragValue, RichText, Ui};
use egui_plot::{Line, MarkerShape, Plot, Points, VLine};

use super::{View, ViewContext};
use crate::app::ink::{self, Ink};
use crate::app::frame_probe::Job;
use crate::app::sweep_run::SweepRun;
use crate::bearing::stages::StageId;
use crate::bearing::Solution;
use crate::number::sig;
use crate::scene::sommerfeld::{chart, ChartGeometry, ChartPlot};
use crate::scene::sweep::{column_label, sweepable_keys, SweepSpec, MAX_POINTS};

use super::plot_kit::{decade_label, legend_ui, log_spacer, LabelledAxes, NamedPlot, PALETTE};
use crate::study::COLUMNS;

/// The swept curve and the current case's point (sky blue and amber on the dark theme; darker on the light).
const LINE: Ink = Ink { dark: Color32::from_rgb(86, 180, 233), light: Color32::from_rgb(0, 105, 170) };
const CURRENT: Ink = Ink { dark: Color32::from_rgb(230, 159, 0), light: Color32::from_rgb(165, 100, 0) };

/// The sweep view: its spec (kept between sessions) and the sweep run from it.
#[derive(Default)]
pub struct SweepView {
    /// The input, its range and the outputs.
    pub spec: SweepSpec,
    pub job: Option<SweepRun>,
    pub error: Option<String>,
    /// What the swept key replaces in the case (an alternative pad-geometry key), said above the plots.
    pub replaced: Vec<String>,
    /// Whether the sweep belongs to the edited design, as last checked (at this document revision).
    checked: Option<(u64, bool)>,
}

impl View for SweepView {
    fn id(&self) -> &'static str {
        "sweep"
    }

    fn label(&self) -> &'static str {
        "Sweep"
    }

    /// The solution of the edited case, marked on the plots.
    fn needs(&self) -> &'static [StageId] {
        &[StageId::Reduction]
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        let current = cx.shown.map(|s| s.solution.clone());
        let design = Design { text: cx.case_text(), revision: cx.doc.revision() };
        if let Some(SweepAction::ExportCsv(csv)) = sweep_view_ui(ui, self, design, current.as_deref()) {
            cx.export("sweep", "CSV", "csv", csv.into_bytes());
        }
    }

    /// The controls: a sweep starts from the case text, not from its solution.
    fn placeholder_ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        self.ui(ui, cx);
    }

    fn settings(&mut self) -> Option<&mut dyn super::view::Settings> {
        Some(&mut self.spec)
    }

    fn busy(&self) -> Option<Job> {
        self.job.as_ref().is_some_and(|j| !j.done()).then_some(Job::Sweep)
    }
}

/// What the view asks the app to do.
pub enum SweepAction {
    ExportCsv(String),
}

/// The value of a dotted key in a case text (the first entry of a per-pad list); `None` when absent.
#[must_use]
pub fn key_value(text: &str, key: &str) -> Option<f64> {
    let table: toml::Table = text.parse().ok()?;
    let mut v = toml::Value::Table(table);
    for part in key.split('.') {
        v = v.get(part)?.clone();
    }
    match v {
        toml::Value::Float(x) => Some(x),
        #[allow(clippy::cast_precision_loss)]
        toml::Value::Integer(i) => Some(i as f64),
        toml::Value::Array(a) => a.first().and_then(|x| x.as_float().or_else(|| x.as_integer().map(|i| i as f64))),
        _ => None,
    }
}

/// The controls; `case`: the shown solution's case (the Sommerfeld chart sweeps around its load).
fn controls_ui(ui: &mut Ui, spec: &mut SweepSpec, case: Option<&crate::model::Case>) -> bool {
    let mut run = false;
    ui.horizontal_wrapped(|ui| {
        let label = ui.label("Input");
        let before = spec.key.clone();
        ComboBox::from_id_salt("sweep-key")
            .selected_text(&spec.key)
            .height(400.0)
            .show_ui(ui, |ui| {
                for k in sweepable_keys() {
                    ui.selectable_value(&mut spec.key, k.key.to_string(), k.key).on_hover_text(k.meaning);
                }
            })
            .response
            .labelled_by(label.id);
        if spec.key != before {
            if let Some((lo, hi)) = crate::model::schema::spec(&spec.key).and_then(|s| s.typical) {
                (spec.from, spec.to) = (lo, hi);
            }
            // The chart is a load sweep: another input is drawn against itself, not against an S that
            // hardly moves (a preload sweep's points piled on one S).
            if spec.chart {
                (spec.chart, spec.against_sommerfeld) = (false, false);
            }
        }
        let unit = spec.unit();
        let speed = 0.01 * (spec.to - spec.from).abs().max(1e-9);
        let label = ui.label("from");
        ui.add(DragValue::new(&mut spec.from).speed(speed)).labelled_by(label.id);
        let label = ui.label("to");
        ui.add(DragValue::new(&mut spec.to).speed(speed)).labelled_by(label.id);
        ui.label(unit);
        let label = ui.label("points");
        ui.add(DragValue::new(&mut spec.count).range(2..=MAX_POINTS)).labelled_by(label.id);
        ui.checkbox(&mut spec.preview, "preview fidelity").on_hover_text(
            "Solve the points on the coarse preview mesh (faster; see the Fidelity group for its error).",
        );
        run = ui.button("Run sweep").clicked();
    });
    ui.horizontal_wrapped(|ui| {
        ui.menu_button(format!("Outputs ({})", spec.outputs.len()), |ui| {
            for c in COLUMNS {
                let (name, unit) = column_label(c.name);
                let mut on = spec.outputs.iter().any(|o| o == c.name);
                if ui.checkbox(&mut on, format!("{name} [{unit}]")).changed() {
                    if on {
                        spec.outputs.push(c.name.to_string());
                    } else {
                        spec.outputs.retain(|o| o != c.name);
                    }
                }
            }
        });
        ui.checkbox(&mut spec.against_sommerfeld, "against the Sommerfeld number")
            .on_hover_text("Abscissa S = µ N L D / W (R/Cb)² of each point instead of the swept value.");
        let chart = ui
            .add_enabled(case.is_some(), egui::Button::new("Sommerfeld chart"))
            .on_hover_text("Runs a load sweep (a fifth to three times the case's load; ε from 0.1 to 0.85 for a prescribed position) and draws ε, the attitude angle, h_min/Cb and the reduced coefficients K Cb/W, C Cb Ω/W against S, with the short-bearing curves of a plain 360° bearing.");
        if let (true, Some(case)) = (chart.clicked(), case) {
            *spec = SweepSpec::sommerfeld_chart(case);
            run = true;
        }
        if spec.chart && ui.button("Back to single outputs").clicked() {
            spec.chart = false;
        }
    });
    run
}

/// The edited design: the case as TOML (`None`: invalid) and the document's revision.
pub struct Design {
    pub text: Option<String>,
    pub revision: u64,
}

impl SweepView {
    /// Whether the sweep shown belongs to the edited design, as the view last drew it (`None`: no sweep, or
    /// not drawn since it started).
    #[must_use]
    pub fn shows_edited_design(&self) -> Option<bool> {
        self.job.as_ref().and(self.checked.map(|(_, current)| current))
    }

    /// The geometry the Sommerfeld chart is normalised with: the swept design's (never the edited one's).
    #[must_use]
    pub fn chart_geometry(&self) -> Option<ChartGeometry> {
        self.job.as_ref()?.design().map(ChartGeometry::of)
    }

    /// The sweep shown belongs to the edited design (checked once per document revision).
    fn sweep_is_current(&mut self, design: &Design) -> bool {
        let Some(job) = &self.job else { return false };
        match self.checked {
            Some((r, current)) if r == design.revision => current,
            _ => {
                let current = design.text.as_deref().is_some_and(|t| job.is_for(t));
                self.checked = Some((design.revision, current));
                current
            }
        }
    }
}

/// Draws the view; `design` is the edited case the sweep starts from, `current` the shown solution.
pub fn sweep_view_ui(
    ui: &mut Ui,
    view: &mut SweepView,
    design: Design,
    current: Option<&Solution>,
) -> Option<SweepAction> {
    let text = design.text.clone();
    let run_again = view.job.is_some() && !view.sweep_is_current(&design);
    let spec = &mut view.spec;
    let key_x = |key: &str| text.as_deref().and_then(|t| key_value(t, key));
    let mut run = controls_ui(ui, spec, current.map(|s| &s.inputs));
    if run_again {
        // Never drawn as if it were this design's: said, with its own geometry, and one click from a rerun.
        ui.horizontal_wrapped(|ui| {
            let of = view.job.as_ref().map_or(0, |j| j.revision);
            ui.label(RichText::new(format!(
                "This sweep belongs to an earlier design (revision {of}; the case has changed since): its curves                  are that design's, and this case is not marked on them."
            ))
            .color(ink::WARNING.of(ui)));
            if let Some(job) = &view.job {
                if ui.add_enabled(design.text.is_some(), egui::Button::new("Run it again for this design")).clicked() {
                    *spec = job.spec.clone();
                    run = true;
                }
            }
        });
    }
    let current_x = if run_again {
        None
    } else {
        view.job.as_ref().and_then(|j| key_x(&j.spec.key)).or_else(|| key_x(&spec.key))
    };
    if run {
        match text {
            Some(text) => match SweepRun::start(text.clone(), spec, design.revision, ui.ctx()) {
                Ok(job) => {
                    view.checked = Some((design.revision, true));
                    let first = format!("{}={:?}", spec.key, spec.from);
                    let replaced = crate::model::replaced_keys(&text, &[first]).unwrap_or_default();
                    view.replaced = replaced.iter().map(ToString::to_string).collect();
                    (view.job, view.error) = (Some(job), None);
                }
                Err(e) => view.error = Some(e.to_string()),
            },
            None => view.error = Some("the case is invalid: fix it in the editor first".into()),
        }
    }
    if let Some(e) = &view.error {
        ui.label(RichText::new(format!("Cannot sweep: {e}")).color(ink::EXCEEDED.of(ui)));
    }
    for note in &view.replaced {
        ui.label(RichText::new(format!("Each point: {note}.")).weak());
    }
    let Some(job) = view.job.as_mut() else {
        ui.label(RichText::new("Choose an input, its range and the outputs, then run the sweep.").weak());
        return None;
    };
    job.poll();
    let mut action = None;
    let (done, total) = job.progress();
    ui.horizontal(|ui| {
        if job.done() {
            ui.label(format!(
                "{done} points of {} ({})",
                job.spec.key,
                if job.spec.preview { "preview fidelity" } else { "the case's fidelity" }
            ));
        } else {
            ui.spinner();
            ui.label(format!("Solving point {} of {total}…", done + 1));
            ui.ctx().request_repaint_after(std::time::Duration::from_millis(50));
        }
        if ui.add_enabled(done > 0, egui::Button::new("Export sweep CSV")).clicked() {
            action = Some(SweepAction::ExportCsv(job.table.csv()));
        }
    });
    // What is drawn of the shown solution: nothing when the sweep is of an earlier design.
    let current = if run_again { None } else { current };
    if spec.chart && job.spec.chart {
        // The chart is normalised with the geometry of the design that was swept, never the edited one's.
        if let Some(g) = job.design().map(ChartGeometry::of) {
            chart_ui(ui, &job.table, &g, current.and_then(|s| s.sommerfeld));
        }
    } else {
        plots_ui(ui, job, spec, current, current_x);
    }
    action
}

/// The Sommerfeld chart of the sweep: five plots against S (log axis) in two columns, the reference lines
/// of the geometry dashed, the case's own S marked.
fn chart_ui(ui: &mut Ui, table: &crate::scene::sweep::SweepTable, g: &ChartGeometry, current_s: Option<f64>) {
    let plots = chart(table, g);
    let reference = g.plain_360_l_over_d.map_or_else(
        || "No closed form for this geometry (reference lines exist for a plain 360° bearing).".to_string(),
        |ld| format!("Dashed: short-bearing theory (Ocvirk) of a plain 360° bearing, here L/D = {}.", sig(ld, 3)),
    );
    ui.label(RichText::new(format!("Sommerfeld chart, S = µ N L D / W (R/Cb)². {reference}")).strong());
    let rows = 3.0;
    let height = ((ui.available_height() - 20.0) / rows - 48.0).max(70.0);
    let plot_ui = |ui: &mut Ui, p: &ChartPlot| {
        ui.label(RichText::new(p.title).strong());
        let mut legend: Vec<(String, Color32)> =
            p.curves.iter().zip(PALETTE).map(|((name, _), c)| ((*name).to_string(), c)).collect();
        if !p.reference.is_empty() {
            legend.push(("short bearing (dashed)".into(), Color32::from_gray(140)));
        }
        legend_ui(ui, &legend);
        Plot::new(("sommerfeld-chart", p.title))
            .height(height)
            .width(ui.available_width())
            .x_axis_label("Sommerfeld number S [–]")
            .x_grid_spacer(log_spacer)
            .x_axis_formatter(|m, _| decade_label(m.value))
            // Labelled steps 24 points apart: two or three numbers even on a 70-point plot.
            .labelled_y(24.0)
            .allow_scroll(false)
            .show(ui, |plot| {
                let log = |pts: &[[f64; 2]]| -> Vec<[f64; 2]> { pts.iter().map(|q| [q[0].log10(), q[1]]).collect() };
                for ((name, pts), color) in p.curves.iter().zip(PALETTE) {
                    plot.line(Line::new(*name, log(pts)).color(color).width(1.8));
                    plot.points(Points::new(*name, log(pts)).color(color).radius(2.5));
                }
                if !p.reference.is_empty() {
                    plot.line(
                        Line::new("short bearing", log(&p.reference))
                            .color(Color32::from_gray(140))
                            .style(egui_plot::LineStyle::dashed_loose()),
                    );
                }
                if let Some(s) = current_s {
                    plot.vline(VLine::new("this case", s.log10()).color(Color32::from_gray(150)));
                }
            }).named(&format!("{} against the Sommerfeld number S [–]", p.title));
    };
    ui.columns(2, |cols| {
        let [left, right] = cols else { return };
        for p in plots.iter().take(3) {
            plot_ui(left, p);
        }
        for p in plots.iter().skip(3) {
            plot_ui(right, p);
        }
    });
}

/// `key_x`: the swept key's value in the edited case (absent from the file: not marked).
fn plots_ui(ui: &mut Ui, job: &SweepRun, spec: &SweepSpec, current: Option<&Solution>, key_x: Option<f64>) {
    let table = &job.table;
    let against_s = spec.against_sommerfeld;
    let x_label = if against_s {
        "Sommerfeld number S [–]".to_string()
    } else {
        format!("{} [{}]", job.spec.key, job.spec.unit())
    };
    let current_cells = current.map(crate::study::columns::outputs);
    let current_x = if against_s { current.and_then(|s| s.sommerfeld) } else { key_x };
    let n = spec.outputs.len().max(1);
    #[allow(clippy::cast_precision_loss)]
    let height = ((ui.available_height() - 40.0) / n as f32 - 24.0).max(90.0);
    egui::ScrollArea::vertical().id_salt("sweep-plots").show(ui, |ui| {
        for name in &spec.outputs {
            let Some(k) = COLUMNS.iter().position(|c| c.name == name.as_str()) else { continue };
            let (label, unit) = column_label(name);
            // Engineering notation: 3e7 N/m reads 30 MN/m.
            let largest = table.series(name, against_s).iter().fold(0.0_f64, |m, p| m.max(p[1].abs()));
            let (scale, unit) = super::compare_panel::row_unit(unit, Some(largest), None);
            let scaled = |pts: Vec<[f64; 2]>| -> Vec<[f64; 2]> { pts.into_iter().map(|p| [p[0], p[1] / scale]).collect() };
            let series = scaled(table.series(name, against_s));
            let flagged = scaled(table.series_over_limits(name, against_s));
            let (line, current, over, reference) =
                (LINE.of(ui), CURRENT.of(ui), ink::EXCEEDED.of(ui), ink::REFERENCE.of(ui));
            // The title and the legend in one row above the plot, never over the points.
            // "this case" only where it is marked: a key the case does not give (a preload sweep of a case
            // that gives the bore radius) has no point of its own on the axis.
            let mut legend = vec![(label.clone(), line)];
            if current_x.is_some() {
                legend.push(("this case".to_string(), current));
            }
            if !flagged.is_empty() {
                legend.push(("beyond a design limit".to_string(), over));
            }
            ui.horizontal(|ui| {
                ui.label(RichText::new(format!("{label} [{unit}]")).strong());
                ui.add_space(12.0);
                legend_ui(ui, &legend);
            });
            // Labelled grids on both axes, so a short plot (a small window, many outputs) keeps its numbers.
            Plot::new(("sweep-plot", name.as_str()))
                .height(height)
                .x_axis_label(x_label.clone())
                .y_axis_label(unit.clone())
                .labelled_x(60.0)
                .labelled_y(24.0)
                .allow_scroll(false)
                .show(ui, |p| {
                    p.line(Line::new(label.clone(), series.clone()).color(line).width(1.8));
                    p.points(Points::new(label.clone(), series).color(line).radius(2.5));
                    if !flagged.is_empty() {
                        p.points(
                            Points::new("beyond a design limit", flagged)
                                .color(over)
                                .shape(MarkerShape::Cross)
                                .radius(6.0),
                        );
                    }
                    if let Some(x) = current_x {
                        p.vline(VLine::new("this case", x).color(reference));
                        if let Some(y) = current_cells.as_ref().and_then(|c| c[k]) {
                            p.points(
                                Points::new("this case", vec![[x, y / scale]])
                                    .color(current)
                                    .shape(MarkerShape::Diamond)
                                    .radius(6.0),
                            );
                        }
                    }
                }).named(&format!("{label} [{unit}] against {x_label}"));
        }
        for (x, why) in table.failures() {
            let x = crate::number::sig(x, 6);
            ui.label(RichText::new(format!("No solution at {x}: {why}")).color(ink::WARNING.of(ui)));
        }
        for (x, names) in table.limit_marks() {
            let x = crate::number::sig(x, 6);
            ui.label(RichText::new(format!("At {x}: beyond the design limits {names}")).color(ink::EXCEEDED.of(ui)));
        }
    });
}
