//! Scene data from real solves, without any GPU or GUI: what the workbench's views draw.

use crate::common;

use tiltpad::scene::field::{common_range, FieldKind, PadMap};
use tiltpad::scene::flowlines::{orifice_sites, pad_flowlines, End, FlowlineParams, Seed};
use tiltpad::scene::outline::bearing_outline;
use tiltpad::scene::{export, plots, summary};

#[test]
fn compressor_bearing_scene() {
    let s = common::solve("compressor-bearing.toml", &["mesh.fidelity=\"preview\""]);
    // Cross-section: the loaded pad (pad 3, pivot 276°) has the smallest film, drawn k·h_min wide.
    let o = bearing_outline(&s.inputs, Some(&s));
    let (j, p, h) = o.pads[3].h_min.unwrap();
    assert!((h - s.h_min_m).abs() < 1e-15, "pad 3 carries the load: {h} vs {}", s.h_min_m);
    let drawn_gap = (p[0] - j[0]).hypot(p[1] - j[1]);
    assert!(
        (drawn_gap - o.exaggeration * h).abs() < 1e-12 * o.exaggeration * h,
        "{drawn_gap} vs {}",
        o.exaggeration * h
    );
    assert!(!o.pads[3].pressure.is_empty());
    // Journal displaced downwards, drawn exaggerated.
    assert!(
        o.journal_centre[1] < 0.0 && (o.journal_centre[1] - o.exaggeration * s.journal_position_m[1]).abs() < 1e-15
    );

    // Field maps: half model mirrored to the full length; pressure between 0 and p_max; h ≥ h_min.
    let maps = PadMap::all(&s, FieldKind::Pressure);
    assert_eq!(maps.len(), 5);
    let (lo, hi) = common_range(&maps);
    assert!(lo >= 0.0 && (hi - s.p_max_pa).abs() < 1e-9 * s.p_max_pa);
    let m = &maps[3];
    assert!((m.length_m() - s.inputs.bearing.length_m).abs() < 1e-12);
    let mid = 0.5 * m.arc_length_m();
    let (a, b) = (m.sample(mid, 0.01).unwrap(), m.sample(mid, -0.01).unwrap());
    assert!((a - b).abs() < 1e-9 * a, "mirror symmetric: {a} vs {b}");
    let h_map = PadMap::new(&s, 3, FieldKind::FilmThickness).unwrap();
    assert!((h_map.min - s.pads[3].h_min_m).abs() < 1e-12);
    // No temperature in an isothermal solve: the view offers only what exists.
    assert_eq!(FieldKind::available(&s), vec![FieldKind::Pressure, FieldKind::FilmThickness, FieldKind::Reynolds]);
    assert!(PadMap::new(&s, 0, FieldKind::FilmTemperature).is_none());

    // Injection off: the orifices drain the loaded pad (sinks). The open hole holds its surroundings at
    // ambient pressure, which the Reynolds condition counts as cavitated: the central leading-edge traces
    // end at the rim of that zone, next to the hole; the outer ones pass it and leave the pad.
    let site = orifice_sites(&s, 3)[0];
    assert!(site.flow_m3_per_s < 0.0);
    let lines = pad_flowlines(&s, 3, FlowlineParams::default());
    let drained = lines
        .iter()
        .filter(|l| l.seed == Seed::LeadingEdge && matches!(l.end, End::Orifice | End::Cavitation))
        .filter(|l| {
            let p = l.points.last().unwrap();
            (p[0] - site.s_m).hypot(p[1] - site.z_m) < 1.5 * site.radius_m
        })
        .count();
    assert!(drained >= 2, "the central leading-edge oil drains towards the hole: {drained}");
    assert!(lines
        .iter()
        .filter(|l| l.seed == Seed::LeadingEdge)
        .any(|l| l.end == End::LeftPad && l.points.last().unwrap()[0] > 0.9 * m.arc_length_m()));

    // Summary and exports.
    let sum = summary::summary(&s);
    assert_eq!(sum.pads.len(), 5);
    let row = |label: &str| sum.groups.iter().flat_map(|g| &g.rows).find(|r| r.label == label).unwrap();
    assert_eq!(row("Eccentricity ε").value, format!("{:.4}", s.eccentricity_ratio));
    // Forces, stiffnesses and damping in engineering notation: the load in kN, the stiffness matrix in one
    // prefix (chosen by its largest term).
    let load = row("Load");
    assert_eq!((load.value.as_str(), load.unit.as_str()), (summary::sig4(s.load_magnitude_n / 1e3).as_str(), "kN"));
    let (kxx, kyy) = (row("Kxx, Kxy"), row("Kyx, Kyy"));
    let k = s.reduced.k_n_per_m;
    let largest = k.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    let (scale, prefix) = tiltpad::number::eng_prefix(largest);
    assert_eq!(kxx.value, format!("{}, {}", summary::sig4(k[0][0] / scale), summary::sig4(k[0][1] / scale)));
    assert_eq!(kyy.value, format!("{}, {}", summary::sig4(k[1][0] / scale), summary::sig4(k[1][1] / scale)));
    assert_eq!((kxx.unit.clone(), kyy.unit.clone()), (format!("{prefix}N/m"), format!("{prefix}N/m")));
    let csv = export::fields_csv(&s);
    let nodes: usize = s.pads.iter().map(|p| p.field.pressure_pa.len()).sum();
    assert_eq!(csv.lines().count(), 1 + nodes);
    let json: serde_json::Value = serde_json::from_str(&export::results_json(&s, &[])).unwrap();
    assert!((json["eccentricity_ratio"].as_f64().unwrap() - s.eccentricity_ratio).abs() < 1e-15);
    let t = plots::matrix_table(&s.full);
    assert_eq!(t.headers[2], "pad 0 tilt [rad]");
}

/// Publication 4, Fig. 6: at 17 bar on the lower pad the film flow reverses upstream of the orifice.
#[test]
fn injection_reverses_the_flow_upstream_of_the_orifice() {
    let s =
        common::solve("test-rig.toml", &["operating.injection_pressure_bar=[17.0, 0.0]", "mesh.fidelity=\"preview\""]);
    let site = orifice_sites(&s, 0)[0];
    assert!(site.flow_m3_per_s > 0.0, "the lower pad injects");
    let lines = pad_flowlines(&s, 0, FlowlineParams::default());
    let from_hole: Vec<_> = lines.iter().filter(|l| l.seed == Seed::Orifice(0)).collect();
    assert_eq!(from_hole.len(), FlowlineParams::default().orifice_seeds);
    // Lines from the hole run against the rotation, past the orifice's upstream edge by more than a
    // diameter: the reversal. (With 17 bar on its soft pivot the lower pad lifts the journal ~0.44 Cb; the
    // load curve is monotonic, so this equilibrium is the only one. Counts are the same on the preview,
    // standard and reference meshes: 6 of 16 lines pass one radius upstream, 4 two, 2 three.)
    let upstream =
        |k: f64| from_hole.iter().filter(|l| l.points.iter().any(|p| p[0] < site.s_m - k * site.radius_m)).count();
    assert!(upstream(3.0) >= 1 && upstream(1.0) >= 4, "{} {}", upstream(3.0), upstream(1.0));
    // Without injection the same orifice is a sink and no line runs upstream from it.
    let s0 =
        common::solve("test-rig.toml", &["operating.injection_pressure_bar=[0.0, 0.0]", "mesh.fidelity=\"preview\""]);
    assert!(orifice_sites(&s0, 0)[0].flow_m3_per_s < 0.0);
    let lines0 = pad_flowlines(&s0, 0, FlowlineParams::default());
    for l in lines0.iter().filter(|l| l.seed == Seed::Orifice(0)) {
        let last = *l.points.last().unwrap();
        assert!((last[0] - site.s_m).hypot(last[1] - site.z_m) < 1.1 * site.radius_m, "sink traces end at the hole");
        assert!(l.points.windows(2).all(|w| w[1][0] >= w[0][0] - 1e-9), "no reversal without injection");
    }
}
