//! Editor group for the controllable bearing's hydraulics (`[hydraulics]`): supply, servovalve, one block
//! per injection line (port), and the test rig. Shown when the case has the section; the ports' pad lists
//! and valve ports are shown, and edited in the case file (a list editor would hide which pad is which).

use egui::{RichText, Ui};

use super::widgets::{label_ui, number_ui, optional_ui, EditOutput, Num};
use crate::app::document::Document;
use crate::model::hydraulics::{HydraulicsFile, PortFile, RigFile, ValvePort};
use crate::model::CaseFile;

fn h(f: &CaseFile) -> Option<&HydraulicsFile> {
    f.hydraulics.as_ref()
}

fn h_mut(f: &mut CaseFile) -> Option<&mut HydraulicsFile> {
    f.hydraulics.as_mut()
}

fn rig_mut(f: &mut CaseFile) -> Option<&mut RigFile> {
    h_mut(f).and_then(|h| h.rig.as_mut())
}

fn port(f: &CaseFile, i: usize) -> Option<&PortFile> {
    h(f).and_then(|h| h.port.get(i))
}

fn rig(f: &CaseFile) -> Option<&RigFile> {
    h(f).and_then(|h| h.rig.as_ref())
}

fn port_mut(f: &mut CaseFile, i: usize) -> Option<&mut PortFile> {
    h_mut(f).and_then(|h| h.port.get_mut(i))
}

/// A required number of `[hydraulics]`.
struct Required {
    num: Num<'static>,
    get: fn(&HydraulicsFile) -> f64,
    set: fn(&mut HydraulicsFile, f64),
}

/// An optional number of `[hydraulics]` with the default the model uses when it is absent.
struct Optional {
    num: Num<'static>,
    default: f64,
    get: fn(&HydraulicsFile) -> Option<f64>,
    set: fn(&mut HydraulicsFile, Option<f64>),
}

const REQUIRED: [Required; 5] = [
    Required {
        num: Num { key: "hydraulics.supply_pressure_bar", label: "Supply pressure", decimals: 1 },
        get: |h| h.supply_pressure_bar,
        set: |h, v| h.supply_pressure_bar = v,
    },
    Required {
        num: Num { key: "hydraulics.valve.natural_frequency_hz", label: "Valve ω_V/2π", decimals: 1 },
        get: |h| h.valve.natural_frequency_hz,
        set: |h, v| h.valve.natural_frequency_hz = v,
    },
    Required {
        num: Num { key: "hydraulics.valve.damping_ratio", label: "Valve damping ξ_V", decimals: 2 },
        get: |h| h.valve.damping_ratio,
        set: |h, v| h.valve.damping_ratio = v,
    },
    Required {
        num: Num { key: "hydraulics.valve.rated_flow_l_per_min", label: "Valve rated flow", decimals: 2 },
        get: |h| h.valve.rated_flow_l_per_min,
        set: |h, v| h.valve.rated_flow_l_per_min = v,
    },
    Required {
        num: Num { key: "hydraulics.valve.rated_drop_bar", label: "Valve rated drop", decimals: 1 },
        get: |h| h.valve.rated_drop_bar,
        set: |h, v| h.valve.rated_drop_bar = v,
    },
];

const OPTIONAL: [Optional; 4] = [
    Optional {
        num: Num { key: "hydraulics.return_pressure_bar", label: "Return pressure", decimals: 1 },
        default: 0.0,
        get: |h| h.return_pressure_bar,
        set: |h, v| h.return_pressure_bar = v,
    },
    Optional {
        num: Num { key: "hydraulics.valve.full_scale_v", label: "Valve full-scale signal", decimals: 1 },
        default: 10.0,
        get: |h| h.valve.full_scale_v,
        set: |h, v| h.valve.full_scale_v = v,
    },
    Optional {
        num: Num {
            key: "hydraulics.valve.flow_pressure_coefficient_l_per_min_bar",
            label: "Valve flow–pressure K_c",
            decimals: 4,
        },
        default: 0.0,
        get: |h| h.valve.flow_pressure_coefficient_l_per_min_bar,
        set: |h, v| h.valve.flow_pressure_coefficient_l_per_min_bar = v,
    },
    Optional {
        num: Num { key: "hydraulics.valve.leakage_l_per_min", label: "Valve leakage", decimals: 3 },
        default: 0.0,
        get: |h| h.valve.leakage_l_per_min,
        set: |h, v| h.valve.leakage_l_per_min = v,
    },
];

/// A number of each `[[hydraulics.port]]`: key suffix, label, decimals, the default when it is optional.
struct PortRow {
    name: &'static str,
    label: &'static str,
    decimals: usize,
    default: Option<f64>,
    get: fn(&PortFile) -> Option<f64>,
    set: fn(&mut PortFile, Option<f64>),
}

const PORT_ROWS: [PortRow; 5] = [
    PortRow {
        name: "line_length_mm",
        label: "length",
        decimals: 0,
        default: None,
        get: |p| Some(p.line_length_mm),
        set: |p, v| p.line_length_mm = v.unwrap_or(p.line_length_mm),
    },
    PortRow {
        name: "line_diameter_mm",
        label: "inner diameter",
        decimals: 2,
        default: None,
        get: |p| Some(p.line_diameter_mm),
        set: |p, v| p.line_diameter_mm = v.unwrap_or(p.line_diameter_mm),
    },
    PortRow {
        name: "air_fraction",
        label: "air fraction",
        decimals: 4,
        default: Some(0.0),
        get: |p| p.air_fraction,
        set: |p, v| p.air_fraction = v,
    },
    PortRow {
        name: "bulk_modulus_gpa",
        label: "oil bulk modulus",
        decimals: 2,
        default: Some(1.5),
        get: |p| p.bulk_modulus_gpa,
        set: |p, v| p.bulk_modulus_gpa = v,
    },
    PortRow {
        name: "wall_compliance_per_gpa",
        label: "wall compliance",
        decimals: 3,
        default: Some(0.0),
        get: |p| p.wall_compliance_per_gpa,
        set: |p, v| p.wall_compliance_per_gpa = v,
    },
];

pub fn hydraulics_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = EditOutput::default();
    let Some(file) = doc.file().hydraulics.clone() else {
        ui.label(
            RichText::new(
                "No [hydraulics] section: a passive bearing. The shipped \"Test rig, Publ. 5\" case has one.",
            )
            .weak(),
        );
        ui.end_row();
        return out;
    };
    for r in &REQUIRED {
        out.merge(number_ui(
            ui,
            doc,
            &r.num,
            |f| h(f).map_or(0.0, r.get),
            |f, v| {
                if let Some(h) = h_mut(f) {
                    (r.set)(h, v);
                }
            },
        ));
    }
    for r in &OPTIONAL {
        out.merge(optional_ui(
            ui,
            doc,
            &r.num,
            r.default,
            |f| h(f).and_then(r.get),
            |f, v| {
                if let Some(h) = h_mut(f) {
                    (r.set)(h, v);
                }
            },
        ));
    }
    for (i, p) in file.port.iter().enumerate() {
        let pads: Vec<String> = p.pads.iter().map(ToString::to_string).collect();
        let side = match p.valve_port {
            ValvePort::A => "A",
            ValvePort::B => "B",
        };
        let tip = format!(
            "{}\n\nEdit the port's pads and valve port in the case file.",
            super::widgets::key_tooltip("hydraulics.port[].pads")
        );
        let label = label_ui(ui, &format!("Line {i}"), &tip);
        ui.label(RichText::new(format!("valve port {side}, feeds pads {}", pads.join(", "))).strong())
            .labelled_by(label.id);
        ui.label("");
        ui.end_row();
        for row in &PORT_ROWS {
            let key = format!("hydraulics.port[{i}].{}", row.name);
            let label = format!("Line {i} {}", row.label);
            let num = Num { key: &key, label: &label, decimals: row.decimals };
            out.merge(match row.default {
                None => number_ui(
                    ui,
                    doc,
                    &num,
                    |f| port(f, i).and_then(row.get).unwrap_or(0.0),
                    |f, v| {
                        if let Some(p) = port_mut(f, i) {
                            (row.set)(p, Some(v));
                        }
                    },
                ),
                Some(d) => optional_ui(
                    ui,
                    doc,
                    &num,
                    d,
                    |f| port(f, i).and_then(row.get),
                    |f, v| {
                        if let Some(p) = port_mut(f, i) {
                            (row.set)(p, v);
                        }
                    },
                ),
            });
        }
    }
    if file.rig.is_some() {
        out.merge(number_ui(
            ui,
            doc,
            &Num { key: "hydraulics.rig.mass_kg", label: "Rig mass", decimals: 1 },
            |f| rig(f).map_or(0.0, |r| r.mass_kg),
            |f, v| {
                if let Some(r) = rig_mut(f) {
                    r.mass_kg = v;
                }
            },
        ));
        out.merge(number_ui(
            ui,
            doc,
            &Num { key: "hydraulics.rig.support_stiffness_n_per_m", label: "Rig support stiffness", decimals: 0 },
            |f| rig(f).map_or(0.0, |r| r.support_stiffness_n_per_m),
            |f, v| {
                if let Some(r) = rig_mut(f) {
                    r.support_stiffness_n_per_m = v;
                }
            },
        ));
        out.merge(optional_ui(
            ui,
            doc,
            &Num { key: "hydraulics.rig.support_damping_ns_per_m", label: "Rig support damping", decimals: 0 },
            0.0,
            |f| rig(f).and_then(|r| r.support_damping_ns_per_m),
            |f, v| {
                if let Some(r) = rig_mut(f) {
                    r.support_damping_ns_per_m = v;
                }
            },
        ));
    }
    out
}
