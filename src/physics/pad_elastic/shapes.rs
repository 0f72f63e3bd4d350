//! Element integrations shared by copies: the pad solid's cylindrical element boxes repeat along the axis
//! and around the arc, and a copy turned by R about the z axis has `K' = R K Rᵀ`, `M' = M`, `G' = R G`.

use crate::fem::solid8::{element_matrices_and_thermal, Elastic, Formulation, Matrix24};

/// Elements that are copies of one another moved along and turned about the z axis have the same stiffness,
/// mass and thermal-load operator up to that turn (`K' = R K Rᵀ`, `M' = M`, `G' = R G` with R the nodal
/// rotation; the integrals depend on the nodes' relative positions only): the pad solid's cylindrical boxes
/// repeat along the axis and around the arc, so each distinct box (layer, arc and axial spacing) is integrated
/// once. Shapes are keyed by the nodes' offsets from the first node in the frame turned by that node's angle,
/// rounded to 2⁻⁴⁰ of the element's extent (the round-off of the node coordinates, about 10⁻¹⁴ of the extent,
/// rarely separates two copies; elements that the key merges differ by less than 10⁻¹² of their size).
#[derive(Default)]
pub(super) struct ElementShapes {
    index: std::collections::HashMap<[i64; 21], usize>,
    /// Per distinct shape: stiffness, mass, thermal-load operator and the first node's angle [rad].
    pub(super) shapes: Vec<(Matrix24, Matrix24, nalgebra::SMatrix<f64, 24, 8>, f64)>,
}

impl ElementShapes {
    /// The shape of the element with nodes `x` (integrated if new) and the turn (cos, sin) from the shape to
    /// it; `None` for an inverted element.
    pub(super) fn element(
        &mut self,
        x: &[[f64; 3]; 8],
        material: &Elastic,
        form: Formulation,
    ) -> Option<(usize, [f64; 2])> {
        let angle = x[0][1].atan2(x[0][0]);
        let (s, c) = angle.sin_cos();
        let offsets: [f64; 21] = std::array::from_fn(|i| {
            let (p, axis) = (&x[1 + i / 3], i % 3);
            let d = [p[0] - x[0][0], p[1] - x[0][1], p[2] - x[0][2]];
            [c * d[0] + s * d[1], -s * d[0] + c * d[1], d[2]][axis]
        });
        let extent = offsets.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
        let scale = 2.0_f64.powi(40) / extent;
        #[allow(clippy::cast_possible_truncation)]
        let key: [i64; 21] = std::array::from_fn(|i| (offsets[i] * scale).round() as i64);
        let shape = match self.index.get(&key) {
            Some(&i) => i,
            None => {
                let (k, m, g) = element_matrices_and_thermal(x, material, form)?;
                self.shapes.push((k, m, g, angle));
                self.index.insert(key, self.shapes.len() - 1);
                self.shapes.len() - 1
            }
        };
        let turn = angle - self.shapes[shape].3;
        Some((shape, if turn == 0.0 { [1.0, 0.0] } else { [turn.cos(), turn.sin()] }))
    }

    /// Stiffness of a shape turned by (cos, sin): `R K Rᵀ`, 3 × 3 block by block.
    pub(super) fn stiffness(&self, shape: usize, turn: [f64; 2]) -> std::borrow::Cow<'_, Matrix24> {
        let k = &self.shapes[shape].0;
        if turn == [1.0, 0.0] {
            return std::borrow::Cow::Borrowed(k);
        }
        let r = nalgebra::Matrix3::new(turn[0], -turn[1], 0.0, turn[1], turn[0], 0.0, 0.0, 0.0, 1.0);
        let mut out = Matrix24::zeros();
        for a in 0..8 {
            for b in 0..8 {
                let block = r * k.fixed_view::<3, 3>(3 * a, 3 * b) * r.transpose();
                out.fixed_view_mut::<3, 3>(3 * a, 3 * b).copy_from(&block);
            }
        }
        std::borrow::Cow::Owned(out)
    }
}
