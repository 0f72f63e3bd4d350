//! Reduced stiffness and damping against ω/Ω or speed (from a background sweep), the case's own point
//! marked, and the full coefficient matrices as a table.

use egui::{Color32, Grid, RichText, ScrollArea, Ui};
use egui_plot::{Legend, Line, MarkerShape, Plot, Points, VLine};

use crate::scene::plots::{CoefficientPlot, MatrixTable};

const COLORS: [Color32; 4] = [
    Color32::from_rgb(86, 180, 233),
    Color32::from_rgb(230, 159, 0),
    Color32::from_rgb(0, 158, 115),
    Color32::from_rgb(204, 121, 167),
];

/// What a plot shows: its id, title, unit and abscissa.
struct PlotSpec<'a> {
    id: &'a str,
    title: &'a str,
    unit: &'a str,
    x_label: &'a str,
}

fn plot_ui(ui: &mut Ui, spec: &PlotSpec<'_>, series: &[crate::scene::plots::Series], current: Option<(f64, [f64; 4])>, height: f32) {
    let PlotSpec { id, title, unit, x_label } = *spec;
    ui.label(RichText::new(format!("{title} [{unit}]")).strong());
    Plot::new(id)
        .height(height)
        .legend(Legend::default())
        .x_axis_label(x_label)
        .y_axis_label(unit)
        .allow_scroll(false)
        .show(ui, |p| {
            for (s, color) in series.iter().zip(COLORS) {
                p.line(Line::new(s.name.clone(), s.points.clone()).color(color).width(1.8));
                p.points(Points::new(s.name.clone(), s.points.clone()).color(color).radius(2.0));
            }
            if let Some((x, values)) = current {
                p.vline(VLine::new("this case", x).color(Color32::from_gray(150)));
                for (v, color) in values.iter().zip(COLORS) {
                    p.points(Points::new("this case", vec![[x, *v]]).color(color).shape(MarkerShape::Diamond).radius(6.0));
                }
            }
        });
}

/// The two plots.
pub fn coefficient_plots_ui(ui: &mut Ui, plot: &CoefficientPlot) {
    let h = ((ui.available_height() - 300.0) / 2.0).max(150.0);
    let spec = |id, title, unit| PlotSpec { id, title, unit, x_label: plot.x_label };
    plot_ui(ui, &spec("stiffness", "Reduced stiffness K", "MN/m"), &plot.stiffness, plot.current.map(|c| (c.0, c.1)), h);
    plot_ui(ui, &spec("damping", "Reduced damping C", "kN·s/m"), &plot.damping, plot.current.map(|c| (c.0, c.2)), h);
    for (x, why) in &plot.failures {
        ui.label(RichText::new(format!("No solution at {x:.0}: {why}")).color(Color32::from_rgb(230, 120, 60)));
    }
}

/// The full matrices.
pub fn matrix_table_ui(ui: &mut Ui, table: &MatrixTable) {
    ui.label(RichText::new("Full coefficients over journal and pad coordinates (SI: force or moment per unit of the column coordinate)").strong());
    ScrollArea::both().id_salt("matrices").show(ui, |ui| {
        for (name, m) in [("K (stiffness)", &table.k), ("C (damping)", &table.c), ("M (pad inertia)", &table.m)] {
            ui.label(name);
            Grid::new(name).striped(true).show(ui, |ui| {
                ui.label("");
                for h in &table.headers {
                    ui.label(RichText::new(h).small());
                }
                ui.end_row();
                for (h, row) in table.headers.iter().zip(m) {
                    ui.label(RichText::new(h).small());
                    for v in row {
                        ui.label(RichText::new(format!("{v:.3e}")).monospace().small());
                    }
                    ui.end_row();
                }
            });
            ui.add_space(6.0);
        }
    });
}
