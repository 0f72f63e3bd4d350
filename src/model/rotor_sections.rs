//! Adding and removing a rotor file's shaft sections, with every node-carrying entry renumbered.
//!
//! Nodes are counted from 0 at the first section's left end; section i spans nodes a_i … b_i with
//! b_i = Σ_{j≤i} elements_j and a_i = b_i − elements_i. Disks, unbalances, bearing positions and linear
//! supports name a node, so every change of the sections maps their nodes:
//! - **split** section i in two: with n ≥ 2 elements the halves keep the element length (⌈n/2⌉ and ⌊n/2⌋
//!   elements, the length shared in that ratio), so the mesh and every node are unchanged; with one element
//!   the halves are one element each of half the length, which inserts node a_i + 1 (nodes > a_i shift by 1);
//! - **append** at either end: a section with the end section's diameters, [`APPENDED_LENGTH_MM`] long, in
//!   elements about as long as the end section's (appending at the start shifts every node);
//! - **remove** section i (not the last one left): the section shrinks to a point, its nodes a_i … b_i
//!   collapse onto one, nodes above b_i shift down by its elements. Entries on the removed nodes move to that
//!   point — the nearest remaining node, where the shaft's neighbours now join (or its new end) — and each
//!   move is returned, named, so the caller shows it. This is what shortening a shaft does on the drawing
//!   board: a coupling hub on a removed stub stays at the shaft end, a bearing on a removed span sits at the
//!   joint; refusing would force the user to move each one first, and dropping one would lose their work.
//!   Entries on an end node that a remaining section shares stay where they are on that section.

use super::rotor::RotorTable;

/// Length of a section appended at an end [mm].
pub const APPENDED_LENGTH_MM: f64 = 100.0;

/// Which end of the shaft.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShaftEnd {
    Start,
    End,
}

/// An entry moved to another node because its node was removed: its key (`rotor.disk[0]`) and the nodes
/// before and after (after: in the new numbering).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Moved {
    pub key: String,
    pub from: usize,
    pub to: usize,
}

impl std::fmt::Display for Moved {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} (on removed node {}) now at node {}", self.key, self.from, self.to)
    }
}

/// Why a section change was refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SectionEditError {
    #[error("rotor.section[{index}]: no such section (the rotor has {count})")]
    NoSuchSection { index: usize, count: usize },
    #[error("rotor.section[0] is the only shaft section; a rotor needs at least one")]
    LastSection,
}

/// The first node of section `i`.
fn first_node(r: &RotorTable, i: usize) -> usize {
    r.section.iter().take(i).map(|s| s.elements).sum()
}

fn check_index(r: &RotorTable, i: usize) -> Result<(), SectionEditError> {
    if i < r.section.len() {
        Ok(())
    } else {
        Err(SectionEditError::NoSuchSection { index: i, count: r.section.len() })
    }
}

/// Every node-carrying entry: its key and its node.
fn nodes_mut(r: &mut RotorTable) -> impl Iterator<Item = (String, &mut usize)> {
    let disks = r.disk.iter_mut().enumerate().map(|(i, d)| (format!("rotor.disk[{i}]"), &mut d.node));
    let unbalances = r.unbalance.iter_mut().enumerate().map(|(i, u)| (format!("rotor.unbalance[{i}]"), &mut u.node));
    let bearings = r.bearing.iter_mut().enumerate().map(|(i, b)| (format!("rotor.bearing[{i}]"), &mut b.node));
    let supports = r.support.iter_mut().enumerate().map(|(i, s)| (format!("rotor.support[{i}]"), &mut s.node));
    disks.chain(unbalances).chain(bearings).chain(supports)
}

/// Splits section `i` in two (see the module header); returns the index of the second half.
///
/// # Errors
/// [`SectionEditError::NoSuchSection`].
pub fn split_section(r: &mut RotorTable, i: usize) -> Result<usize, SectionEditError> {
    check_index(r, i)?;
    let a = first_node(r, i);
    let s = r.section[i].clone();
    let (mut left, mut right) = (s.clone(), s.clone());
    if s.elements >= 2 {
        left.elements = s.elements.div_ceil(2);
        right.elements = s.elements - left.elements;
        #[allow(clippy::cast_precision_loss)]
        let share = left.elements as f64 / s.elements as f64;
        left.length_mm = s.length_mm * share;
        right.length_mm = s.length_mm - left.length_mm;
    } else {
        left.length_mm = s.length_mm / 2.0;
        right.length_mm = s.length_mm - left.length_mm;
        for (_, n) in nodes_mut(r) {
            if *n > a {
                *n += 1;
            }
        }
    }
    r.section[i] = left;
    r.section.insert(i + 1, right);
    Ok(i + 1)
}

/// Appends a section at `end` (see the module header); returns its index.
///
/// # Panics
/// Never: a rotor file without sections gets a 50 mm diameter one.
pub fn append_section(r: &mut RotorTable, end: ShaftEnd) -> usize {
    let neighbour = match end {
        ShaftEnd::Start => r.section.first(),
        ShaftEnd::End => r.section.last(),
    };
    let mut s = neighbour.cloned().unwrap_or(super::rotor::SectionTable {
        length_mm: 1.0,
        outer_diameter_mm: 50.0,
        inner_diameter_mm: 0.0,
        elements: 1,
    });
    #[allow(clippy::cast_precision_loss)]
    let element_mm = s.length_mm / s.elements.max(1) as f64;
    // As many elements as keep the neighbour's element length, within the allowed counts.
    let (lo, hi) = match const { super::rotor_schema::rotor_row("rotor.section[].elements") }.allowed {
        super::schema::Allowed::Integer { lo, hi } => (lo, hi),
        _ => (1, 1),
    };
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let elements = if element_mm > 0.0 && element_mm.is_finite() {
        ((APPENDED_LENGTH_MM / element_mm).round().max(0.0) as usize).clamp(lo, hi)
    } else {
        lo
    };
    s.length_mm = APPENDED_LENGTH_MM;
    s.elements = elements;
    match end {
        ShaftEnd::Start => {
            for (_, n) in nodes_mut(r) {
                *n += elements;
            }
            r.section.insert(0, s);
            0
        }
        ShaftEnd::End => {
            r.section.push(s);
            r.section.len() - 1
        }
    }
}

/// Removes section `i` (see the module header); returns the entries moved off its nodes.
///
/// # Errors
/// [`SectionEditError::NoSuchSection`], or [`SectionEditError::LastSection`] for the only section.
pub fn remove_section(r: &mut RotorTable, i: usize) -> Result<Vec<Moved>, SectionEditError> {
    check_index(r, i)?;
    if r.section.len() == 1 {
        return Err(SectionEditError::LastSection);
    }
    let a = first_node(r, i);
    let n = r.section[i].elements;
    let b = a + n;
    let last = first_node(r, r.section.len());
    // The removed nodes: the interior, and the free end of an end section.
    let removed = |node: usize| (node > a && node < b) || (node == a && a == 0) || (node == b && b == last);
    let mut moved = Vec::new();
    for (key, node) in nodes_mut(r) {
        let old = *node;
        *node = match old {
            _ if old < a => old,
            _ if old <= b => a,
            _ => old - n,
        };
        if removed(old) {
            moved.push(Moved { key, from: old, to: *node });
        }
    }
    r.section.remove(i);
    Ok(moved)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::rotor::{parse_rotor_file, RotorFile};

    /// Sections of 2, 3 and 1 elements (nodes 0–6), an entry of each kind.
    const ROTOR: &str = "[rotor]\n\
        [[rotor.section]]\nlength_mm = 200.0\nouter_diameter_mm = 50.0\nelements = 2\n\
        [[rotor.section]]\nlength_mm = 300.0\nouter_diameter_mm = 60.0\nelements = 3\n\
        [[rotor.section]]\nlength_mm = 100.0\nouter_diameter_mm = 50.0\nelements = 1\n\
        [[rotor.disk]]\nnode = 0\nmass_kg = 5.0\n[[rotor.disk]]\nnode = 3\nmass_kg = 10.0\n\
        [[rotor.unbalance]]\nnode = 4\namount_g_mm = 10.0\n\
        [[rotor.bearing]]\nnode = 2\nk_n_per_m = [[1e7, 0.0, 0.0, 1e7]]\nc_ns_per_m = [[1e3, 0.0, 0.0, 1e3]]\n\
        [[rotor.bearing]]\nnode = 6\nk_n_per_m = [[1e7, 0.0, 0.0, 1e7]]\nc_ns_per_m = [[1e3, 0.0, 0.0, 1e3]]\n\
        [[rotor.support]]\nnode = 5\nstiffness_n_per_m = 1e6\n";

    fn file() -> RotorFile {
        parse_rotor_file(ROTOR).unwrap()
    }

    fn nodes(f: &RotorFile) -> Vec<usize> {
        let r = &f.rotor;
        r.disk
            .iter()
            .map(|d| d.node)
            .chain(r.unbalance.iter().map(|u| u.node))
            .chain(r.bearing.iter().map(|b| b.node))
            .chain(r.support.iter().map(|s| s.node))
            .collect()
    }

    fn resolve(f: &RotorFile) -> crate::model::rotor::Rotor {
        f.resolve(&|n| Err(n.to_string())).unwrap()
    }

    #[test]
    fn splitting_a_section_of_several_elements_keeps_the_mesh() {
        let mut f = file();
        let before = resolve(&f);
        assert_eq!(split_section(&mut f.rotor, 1), Ok(2));
        let lengths: Vec<(f64, usize)> = f.rotor.section.iter().map(|s| (s.length_mm, s.elements)).collect();
        assert_eq!(lengths, vec![(200.0, 2), (200.0, 2), (100.0, 1), (100.0, 1)]);
        assert_eq!(nodes(&f), vec![0, 3, 4, 2, 6, 5]);
        // The same element lengths (to rounding: 200/2 against 300/3 mm).
        let after = resolve(&f);
        for (a, b) in after.node_positions().iter().zip(before.node_positions()) {
            assert!((a - b).abs() < 1e-15, "{a} vs {b} m");
        }
        assert_eq!(after.n_nodes(), before.n_nodes());
        assert!((after.mass() - before.mass()).abs() < 1e-14 * before.mass());
    }

    #[test]
    fn splitting_a_one_element_section_inserts_a_node() {
        let mut f = file();
        let mass = resolve(&f).mass();
        split_section(&mut f.rotor, 2).unwrap();
        assert_eq!(
            f.rotor.section[2..].iter().map(|s| (s.length_mm, s.elements)).collect::<Vec<_>>(),
            vec![(50.0, 1), (50.0, 1)]
        );
        // Section 2 starts at node 5: the bearing at the shaft end (6) becomes 7, node 5 stays.
        assert_eq!(nodes(&f), vec![0, 3, 4, 2, 7, 5]);
        assert!((resolve(&f).mass() - mass).abs() < 1e-12 * mass);
    }

    #[test]
    fn appending_at_the_start_shifts_every_node_and_adds_its_mass() {
        let mut f = file();
        let mass = resolve(&f).mass();
        assert_eq!(append_section(&mut f.rotor, ShaftEnd::Start), 0);
        assert_eq!(
            (f.rotor.section[0].length_mm, f.rotor.section[0].outer_diameter_mm, f.rotor.section[0].elements),
            (100.0, 50.0, 1)
        );
        assert_eq!(nodes(&f), vec![1, 4, 5, 3, 7, 6]);
        let added = 7850.0 * std::f64::consts::PI / 4.0 * 0.05_f64.powi(2) * 0.1;
        assert!((resolve(&f).mass() - mass - added).abs() < 1e-12 * mass);
        assert_eq!(append_section(&mut f.rotor, ShaftEnd::End), 4);
        assert_eq!(nodes(&f), vec![1, 4, 5, 3, 7, 6], "appending at the end renumbers nothing");
    }

    #[test]
    fn removing_a_section_moves_the_entries_on_its_nodes_and_names_them() {
        // The middle section (nodes 2–5): the disk at 3 and the unbalance at 4 move to the joint (node 2);
        // the bearing at 2 and the support at 5 sit on nodes the neighbours keep.
        let mut f = file();
        let moved = remove_section(&mut f.rotor, 1).unwrap();
        let shown: Vec<String> = moved.iter().map(ToString::to_string).collect();
        assert_eq!(
            shown,
            vec![
                "rotor.disk[1] (on removed node 3) now at node 2",
                "rotor.unbalance[0] (on removed node 4) now at node 2"
            ]
        );
        assert_eq!(nodes(&f), vec![0, 2, 2, 2, 3, 2]);
        assert_eq!(resolve(&f).n_nodes(), 4);
        // The last section (now nodes 2–3): the bearing at its free end moves to the new end, node 2.
        let moved = remove_section(&mut f.rotor, 1).unwrap();
        assert_eq!(moved, vec![Moved { key: "rotor.bearing[1]".into(), from: 3, to: 2 }]);
        // The first section of a fresh rotor: the coupling disk at the free end moves to the new start.
        let mut f = file();
        let moved = remove_section(&mut f.rotor, 0).unwrap();
        assert_eq!(moved, vec![Moved { key: "rotor.disk[0]".into(), from: 0, to: 0 }]);
        assert_eq!(nodes(&f), vec![0, 1, 2, 0, 4, 3]);
    }

    #[test]
    fn the_only_section_and_a_missing_one_are_refused() {
        let mut f = file();
        assert_eq!(remove_section(&mut f.rotor, 3), Err(SectionEditError::NoSuchSection { index: 3, count: 3 }));
        remove_section(&mut f.rotor, 0).unwrap();
        remove_section(&mut f.rotor, 0).unwrap();
        let before = f.clone();
        let e = remove_section(&mut f.rotor, 0).unwrap_err();
        assert_eq!(e.to_string(), "rotor.section[0] is the only shaft section; a rotor needs at least one");
        assert_eq!(f, before, "nothing changed");
    }
}
