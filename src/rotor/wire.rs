//! An [`AnalysisResult`] as plain data, for the web build's solver worker ([`crate::bearing::stages::to_bytes`]
//! is the wire format): the result's serde form leaves out the mode shapes (large, for drawing only), so
//! they travel beside it and are put back.
//!
//! Contract: `AnalysisResult::from(AnalysisData::from(&r)) == r`.

use nalgebra::Complex;
use serde::{Deserialize, Serialize};

use super::analysis::AnalysisResult;

/// A result with the mode shapes its serde form skips.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AnalysisData {
    result: AnalysisResult,
    /// Per speed, per mode: the shape.
    shapes: Vec<Vec<Vec<[Complex<f64>; 2]>>>,
}

impl From<&AnalysisResult> for AnalysisData {
    fn from(r: &AnalysisResult) -> Self {
        let mut result = r.clone();
        let shapes = result
            .speeds
            .iter_mut()
            .map(|s| s.point.modes.modes.iter_mut().map(|m| std::mem::take(&mut m.shape)).collect())
            .collect();
        Self { result, shapes }
    }
}

impl From<AnalysisData> for AnalysisResult {
    fn from(data: AnalysisData) -> Self {
        let AnalysisData { mut result, shapes } = data;
        for (s, shapes) in result.speeds.iter_mut().zip(shapes) {
            for (m, shape) in s.point.modes.modes.iter_mut().zip(shapes) {
                m.shape = shape;
            }
        }
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::stages::{from_bytes, to_bytes};
    use crate::model::rotor::{parse_rotor_file, Rotor};
    use crate::rotor::analysis::{run, AnalysisParams};

    /// The compressor rotor on its bearing cases (preview fidelity), at two speeds, round-trips with its
    /// mode shapes; the rotor itself (with its bearing cases) round-trips too.
    #[test]
    fn a_rotor_analysis_round_trips_with_its_mode_shapes() {
        let text = include_str!("../../cases/rotors/compressor-rotor.toml");
        let bearing = include_str!("../../cases/compressor-bearing.toml")
            .replace("fidelity = \"standard\"", "fidelity = \"preview\"");
        let rotor: Rotor = parse_rotor_file(text).unwrap().resolve(&|_| Ok(bearing.clone())).unwrap();
        let result = run(&rotor, AnalysisParams::new(vec![800.0, 1000.0])).unwrap();
        assert!(result.speeds.iter().all(|s| s.point.modes.modes.iter().all(|m| !m.shape.is_empty())));
        let back: AnalysisData = from_bytes(&to_bytes(&AnalysisData::from(&result)).unwrap()).unwrap();
        assert_eq!(AnalysisResult::from(back), result);
        assert_eq!(from_bytes::<Rotor>(&to_bytes(&rotor).unwrap()).unwrap(), rotor);
    }
}
