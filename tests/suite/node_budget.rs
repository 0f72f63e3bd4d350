//! Bounded memory: the node budget `mesh.max_nodes` is checked from the case alone, before any mesh
//! is built, and counts exactly what the solver then allocates; the orifice operators are sparse.

use crate::common;

use tiltpad::bearing::{solve_case, BearingModel, ThermalModel};
use tiltpad::model::budget::{count, DEFAULT_MAX_NODES};
use tiltpad::model::{load_case, Case, CaseError};

/// The compressor bearing with `holes` 0.2 mm orifices on each of its five pads.
fn with_orifices(holes: &[(f64, f64)]) -> String {
    let text = std::fs::read_to_string(common::case_path("compressor-bearing.toml")).unwrap();
    let tables: String = holes
        .iter()
        .map(|(pf, af)| format!("[[bearing.pads.orifice]]\nposition_frac = {pf}\naxial_frac = {af}\ndiameter_mm = 0.2\nlength_mm = 5.0\n"))
        .collect();
    text.replace("[[bearing.pads.orifice]]\nposition_frac = 0.3\ndiameter_mm = 5.0\nlength_mm = 5.0\n", &tables)
}

/// 100 holes scattered over the pad (each at its own circumferential and axial position, 0.4 mm apart
/// axially): every hole refines a column and a row of the tensor-product grid, so the grid grows as the
/// square of the hole count (the reported failure: 55 GB, then an abort).
fn hundred_scattered_orifices() -> String {
    let holes: Vec<(f64, f64)> =
        (0..100).map(|i| (0.05 + 0.9 * (f64::from(i) * 0.618_034).fract(), 0.05 + 0.9 * f64::from(i) / 99.0)).collect();
    with_orifices(&holes)
}

/// A 10 × 10 pattern of holes (ten columns and ten rows of refinement).
fn hundred_orifices_in_a_pattern() -> String {
    let holes: Vec<(f64, f64)> =
        (0..100).map(|k| (0.1 + 0.08 * f64::from(k / 10), 0.1 + 0.08 * f64::from(k % 10))).collect();
    with_orifices(&holes)
}

#[test]
fn hundred_small_orifices_are_refused_before_allocating() {
    let text = hundred_scattered_orifices();
    assert_eq!(text.matches("[[bearing.pads.orifice]]").count(), 100);
    let err = load_case(&text, &[]).unwrap_err();
    let CaseError::NodeBudget { needed, budget, film, pad_solid, orifices, .. } = err else { panic!("{err:?}") };
    assert_eq!(budget, DEFAULT_MAX_NODES);
    assert!(needed > budget && needed == film + pad_solid, "{needed} vs {budget}");
    assert_eq!(orifices, 500);
    let msg = err.to_string();
    for key in ["mesh.max_nodes", "mesh.orifice_elements", "mesh.circumferential_elements", "mesh.axial_elements"] {
        assert!(msg.contains(key), "the message names {key}: {msg}");
    }
    assert!(msg.contains(&needed.to_string()) && msg.contains(&budget.to_string()), "{msg}");
    assert_eq!(err.key(), Some("mesh.max_nodes"), "the editor flags the budget field");
}

/// The count is what the solver allocates: film nodes per pad, and the pad solids of the thermal model.
#[test]
fn the_count_is_what_the_meshes_have() {
    let hundred = hundred_orifices_in_a_pattern();
    let cases: Vec<(String, Vec<String>)> = vec![
        (
            std::fs::read_to_string(common::case_path("compressor-bearing.toml")).unwrap(),
            vec!["mesh.fidelity=\"reference\"".into()],
        ),
        (
            std::fs::read_to_string(common::case_path("fillon-a.toml")).unwrap(),
            vec!["mesh.pad_radial_elements=7".into()],
        ),
        (std::fs::read_to_string(common::case_path("test-rig-pub5.toml")).unwrap(), vec![]),
        (std::fs::read_to_string(common::case_path("plain-2groove-ld05.toml")).unwrap(), vec![]),
        (common::PLAIN_360.to_string(), vec![]),
        (
            hundred,
            vec![
                "mesh.fidelity=\"preview\"".into(),
                "mesh.orifice_elements=2".into(),
                "mesh.max_nodes=50000000".into(),
            ],
        ),
    ];
    for (text, set) in &cases {
        let (_, case) = load_case(text, set).unwrap();
        let n = count(&case);
        let model = BearingModel::new(&case).unwrap();
        let per_pad: Vec<usize> = model.pads.iter().map(|p| p.film.geom.n_nodes()).collect();
        assert_eq!(n.film_per_pad, per_pad, "{} {set:?}", case.title);
        if case.thermal.model == tiltpad::model::ThermalModelKind::Thd {
            let thermal = ThermalModel::new(&case, &model).unwrap();
            let solid: usize =
                thermal.pads.iter().filter_map(|p| p.conduction.as_ref()).map(|c| c.mesh.n_nodes()).sum();
            assert!(solid > 0);
            assert_eq!(n.pad_solid, solid, "{}", case.title);
        } else {
            assert_eq!(n.pad_solid, 0);
        }
    }
}

fn with_budget(case_file: &str, set: &[&str], budget: usize) -> Result<Case, CaseError> {
    let text = std::fs::read_to_string(common::case_path(case_file)).unwrap();
    let mut set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
    set.push(format!("mesh.max_nodes={budget}"));
    load_case(&text, &set).map(|(_, c)| c)
}

/// A case exactly at its budget solves; one node less is refused.
#[test]
fn a_case_at_its_budget_solves() {
    for (file, set) in [
        ("compressor-bearing.toml", vec!["mesh.fidelity=\"preview\""]),
        ("fillon-a.toml", vec!["mesh.fidelity=\"preview\""]),
    ] {
        let needed = count(&common::case(file, &set)).total();
        let case = with_budget(file, &set, needed).unwrap_or_else(|e| panic!("{file}: {e}"));
        let s = solve_case(&case).unwrap_or_else(|e| panic!("{file} at its budget: {e}"));
        assert!(s.report.residual < 1e-9, "{file}: {}", s.report.residual);
        assert_eq!(s.derived.film_nodes, count(&case).film());
        match with_budget(file, &set, needed - 1) {
            Err(CaseError::NodeBudget { needed: n, budget, .. }) => assert_eq!((n, budget), (needed, needed - 1)),
            other => panic!("{file}: one node over the budget must be refused, got {other:?}"),
        }
    }
}

/// Every shipped case, at every fidelity, fits the default budget with a wide margin (twice its nodes: the
/// largest, `compressor-bearing-tehd.toml` at the reference fidelity, has 230 100 — 23 010 film nodes and the
/// five pad solids of 8 layers that its thermal growth and pad conduction need).
#[test]
fn shipped_cases_fit_the_default_budget() {
    for entry in std::fs::read_dir(common::case_path("")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let name = path.file_name().unwrap().to_str().unwrap().to_string();
        for fidelity in ["preview", "standard", "reference"] {
            let case = common::case(&name, &[&format!("mesh.fidelity=\"{fidelity}\"")]);
            let n = count(&case).total();
            assert!(n < DEFAULT_MAX_NODES / 2, "{name} {fidelity}: {n} nodes");
        }
    }
}

/// The orifice operators hold only the nodes of the elements each hole touches, however many holes a pad has.
#[test]
fn orifice_operators_are_sparse() {
    let (_, case) = load_case(
        &hundred_orifices_in_a_pattern(),
        &["mesh.fidelity=\"preview\"".into(), "mesh.orifice_elements=2".into(), "mesh.max_nodes=50000000".into()],
    )
    .unwrap();
    let model = BearingModel::new(&case).unwrap();
    let geom = &model.pads[0].film.geom;
    assert_eq!(geom.orifices.len(), 100);
    for (k, op) in geom.orifices.iter().enumerate() {
        let o = op.orifice;
        let touched = geom.rects.iter().filter(|r| o.touches(r.s0, r.s0 + r.ds, r.z0, r.z0 + r.dz)).count();
        assert!(touched > 0, "orifice {k}");
        assert!(
            op.vector.len() <= 4 * touched && op.matrix.len() <= 10 * touched,
            "orifice {k}: {} / {} entries for {touched} elements",
            op.vector.len(),
            op.matrix.len()
        );
        // ∫ 3 g / l0 dA = 3 π d⁴ / (32 l0) (full model here).
        let exact = 3.0 * std::f64::consts::PI * o.diameter.powi(4) / (32.0 * o.length);
        // Sub-cell quadrature on the rim: measured up to 2.5e-4 over these holes (two elements across each).
        assert!((op.total / exact - 1.0).abs() < 5e-4, "orifice {k}: {} vs {exact}", op.total);
    }
}
