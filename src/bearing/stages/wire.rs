//! An [`Outcome`] as plain data, for handing it to another instance of the program (the web build's solver
//! runs in a web worker, which shares no memory with the page): each published output with its concrete
//! type, serialisable with serde.
//!
//! Contract: [`Outcome::to_data`] names every output a stage publishes, or says which stage's output it
//! cannot name ([`UnnamedOutput`]) — a stage that starts publishing a new type adds a variant to
//! [`OutputData`]; the round-trip test wants every publishing stage. [`Outcome::from_data`] rebuilds an
//! outcome that answers [`Outcome::get`] exactly as the original did. `Outcome` is serde through that form;
//! [`to_bytes`]/[`from_bytes`] are the wire format: CBOR (RFC 8949) with field names — self-describing, so
//! the case's tagged enums and skipped optional fields round-trip, and non-finite numbers survive.
//!
//! Why CBOR (through `ciborium`) rather than MessagePack (`rmp_serde`, used before): a serde decoder is
//! compiled once per type it reads, and `rmp_serde` routes every read through its whole "any value" decoder
//! (about 8 kB of WebAssembly per type, 2.6 MB in the web build), where `ciborium` reads each header once
//! and hands the visitor only the kind of value it asked for (docs/PERFORMANCE.md, "Web build").

use std::sync::Arc;

use serde::de::DeserializeOwned;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::bearing::frf::model::FrfModel;
use crate::bearing::solution::{PadField, PadFlex, PadSolidField, Solution};
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::{Outcome, Published};
use crate::bearing::stages::sweeps::{FrequencySweep, SpeedPoint};

/// A published output by its type.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum OutputData {
    Solution(Box<SolutionData>),
    FrequencySweep(FrequencySweep),
    SpeedSweep(Vec<SpeedPoint>),
    Frf(Box<FrfModel>),
}

/// A solution with what its JSON form leaves out: each pad's drawing data.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SolutionData {
    solution: Solution,
    pads: Vec<PadDrawing>,
}

/// The parts of a pad's result that are skipped by its serde form (large, for drawing only).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct PadDrawing {
    field: PadField,
    flex: Option<PadFlex>,
    /// The pad solid's temperatures (thermal model).
    solid: Option<PadSolidField>,
    /// The thermal growth's nodal displacements and layer radii (TEHD).
    growth: Option<(Vec<f64>, Vec<f64>)>,
}

impl From<&Solution> for SolutionData {
    fn from(s: &Solution) -> Self {
        let mut solution = s.clone();
        let pads = solution
            .pads
            .iter_mut()
            .map(|p| PadDrawing {
                field: std::mem::take(&mut p.field),
                flex: p.flex.take(),
                solid: p.thermal.as_mut().and_then(|t| t.solid.take()),
                growth: p
                    .thermal_growth
                    .as_mut()
                    .map(|g| (std::mem::take(&mut g.nodal_polar_m), std::mem::take(&mut g.radii_m))),
            })
            .collect();
        Self { solution, pads }
    }
}

impl From<SolutionData> for Solution {
    fn from(data: SolutionData) -> Self {
        let SolutionData { mut solution, pads } = data;
        for (p, d) in solution.pads.iter_mut().zip(pads) {
            p.field = d.field;
            p.flex = d.flex;
            if let Some(t) = p.thermal.as_mut() {
                t.solid = d.solid;
            }
            if let (Some(g), Some((nodal, radii))) = (p.thermal_growth.as_mut(), d.growth) {
                g.nodal_polar_m = nodal;
                g.radii_m = radii;
            }
        }
        solution
    }
}

/// A stage published an output that [`OutputData`] has no variant for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("the output of stage {0:?} has no plain-data form (add it to OutputData)")]
pub struct UnnamedOutput(pub StageId);

impl OutputData {
    fn from_published(stage: StageId, out: &Published) -> Result<Self, UnnamedOutput> {
        if let Some(s) = out.downcast_ref::<Solution>() {
            Ok(Self::Solution(Box::new(s.into())))
        } else if let Some(s) = out.downcast_ref::<FrequencySweep>() {
            Ok(Self::FrequencySweep(s.clone()))
        } else if let Some(s) = out.downcast_ref::<Vec<SpeedPoint>>() {
            Ok(Self::SpeedSweep(s.clone()))
        } else if let Some(s) = out.downcast_ref::<FrfModel>() {
            Ok(Self::Frf(Box::new(s.clone())))
        } else {
            Err(UnnamedOutput(stage))
        }
    }

    fn into_published(self) -> Published {
        match self {
            Self::Solution(s) => Arc::new(Solution::from(*s)),
            Self::FrequencySweep(s) => Arc::new(s),
            Self::SpeedSweep(s) => Arc::new(s),
            Self::Frf(s) => Arc::new(*s),
        }
    }
}

impl Outcome {
    /// The outputs as plain data (copies).
    ///
    /// # Errors
    /// A stage whose output type has no [`OutputData`] variant.
    pub fn to_data(&self) -> Result<Vec<(StageId, OutputData)>, UnnamedOutput> {
        self.outputs.iter().map(|(stage, out)| Ok((*stage, OutputData::from_published(*stage, out)?))).collect()
    }

    /// The outcome those outputs came from.
    #[must_use]
    pub fn from_data(data: Vec<(StageId, OutputData)>) -> Self {
        Self { outputs: data.into_iter().map(|(stage, d)| (stage, d.into_published())).collect() }
    }
}

impl Serialize for Outcome {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.to_data().map_err(serde::ser::Error::custom)?.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Outcome {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        Ok(Self::from_data(Vec::deserialize(deserializer)?))
    }
}

/// A failed encoding or decoding on the wire.
#[derive(Debug, thiserror::Error)]
pub enum WireError {
    #[error("cannot encode: {0}")]
    Encode(#[from] ciborium::ser::Error<std::io::Error>),
    #[error("cannot decode: {0}")]
    Decode(#[from] ciborium::de::Error<std::io::Error>),
}

/// A value in the wire format.
///
/// # Errors
/// A value serde cannot write (an outcome with an output [`OutputData`] cannot name).
pub fn to_bytes<T: Serialize>(value: &T) -> Result<Vec<u8>, WireError> {
    let mut bytes = Vec::new();
    ciborium::into_writer(value, &mut bytes)?;
    Ok(bytes)
}

/// A value from the wire format.
///
/// # Errors
/// Bytes that are not a `T` in the wire format.
pub fn from_bytes<T: DeserializeOwned>(bytes: &[u8]) -> Result<T, WireError> {
    Ok(ciborium::from_reader(bytes)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::report::progress::NoCancel;
    use crate::bearing::stages::{Request, Stages};
    use crate::model::{load_case, Case};

    fn case(text: &str, set: &[&str]) -> Case {
        let set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
        load_case(text, &set).unwrap().1
    }

    /// Runs the request, sends the outcome through the wire and checks every output comes back equal.
    fn round_trip(req: &Request) -> Outcome {
        let outcome = Stages::new().run(req, &NoCancel).unwrap();
        let back: Outcome = from_bytes(&to_bytes(&outcome).unwrap()).unwrap();
        assert_eq!(back.to_data().unwrap(), outcome.to_data().unwrap());
        let req_back: Request = from_bytes(&to_bytes(req).unwrap()).unwrap();
        assert_eq!(&req_back, req);
        back
    }

    /// A flexible-pad TEHD solution keeps what its JSON form skips: fields, modes, pad temperatures and
    /// growth; the frequency and speed sweeps come back too.
    #[test]
    fn a_tehd_outcome_round_trips_with_its_drawing_data() {
        let c = case(
            include_str!("../../../cases/compressor-bearing-flexible.toml"),
            &[
                "mesh.fidelity=\"preview\"",
                "thermal.model=\"thd\"",
                "thermal.pad_expansion_ppm_per_k=12",
                "thermal.journal_expansion_ppm_per_k=11",
                "thermal.reference_temperature_c=20",
            ],
        );
        let req = Request {
            frequency_ratios: vec![0.5, 1.0],
            speeds_rad_s: vec![crate::units::RPM.to_si(8000.0)],
            ..Request::of(c, &[StageId::Reduction, StageId::FrequencySweep, StageId::SpeedSweep])
        };
        let back = round_trip(&req);
        let s = back.solution().unwrap();
        let pad = &s.pads[0];
        assert!(!pad.field.pressure_pa.is_empty() && pad.flex.is_some());
        assert!(pad
            .thermal
            .as_ref()
            .and_then(|t| t.solid.as_ref())
            .is_some_and(|solid| !solid.temperature_c.is_empty()));
        assert!(pad.thermal_growth.as_ref().is_some_and(|g| !g.nodal_polar_m.is_empty() && !g.radii_m.is_empty()));
        assert_eq!(back.frequency_sweep().unwrap().len(), 2);
        assert_eq!(back.speed_sweep().unwrap().len(), 1);
    }

    /// The bytes are CBOR maps keyed by field name (a decoder of the standard reads them without our types),
    /// non-finite numbers come back as they went, a text longer than the decoder's scratch buffer (a case's
    /// TOML) comes back whole, and truncated bytes are an error, not a value.
    #[test]
    fn the_wire_is_named_cbor_and_keeps_non_finite_numbers_and_long_texts() {
        #[derive(Debug, PartialEq, Serialize, Deserialize)]
        struct Probe {
            name: String,
            values: Vec<f64>,
            absent: Option<f64>,
        }
        let long = "x = 1.0\n".repeat(2000);
        let probe = Probe { name: long, values: vec![1.5, f64::INFINITY, f64::NEG_INFINITY], absent: None };
        let bytes = to_bytes(&probe).unwrap();
        let plain: ciborium::Value = ciborium::from_reader(bytes.as_slice()).unwrap();
        let keys: Vec<_> = plain.as_map().unwrap().iter().filter_map(|(k, _)| k.as_text()).collect();
        assert_eq!(keys, ["name", "values", "absent"]);
        assert_eq!(from_bytes::<Probe>(&bytes).unwrap(), probe);
        let nan: Vec<f64> = from_bytes(&to_bytes(&vec![f64::NAN]).unwrap()).unwrap();
        assert!(nan[0].is_nan());
        assert!(from_bytes::<Probe>(&bytes[..bytes.len() - 3]).is_err_and(|e| matches!(e, WireError::Decode(_))));
    }

    /// The FRF stage's linearised model (matrices) round-trips.
    #[test]
    fn an_frf_outcome_round_trips() {
        let c = case(include_str!("../../../cases/test-rig-pub5.toml"), &["mesh.fidelity=\"preview\""]);
        let req = Request::of(c, &[StageId::Reduction, StageId::Frf]);
        let back = round_trip(&req);
        assert!(back.get::<FrfModel>(StageId::Frf).is_some_and(|m| m.dynamics.k.norm() > 0.0));
    }
}
