//! What the workbench remembers between sessions (eframe storage: a file on native, local storage on
//! the web) — the case being edited and the view settings. Runtime state (the worker, results,
//! textures, dialogs) lives in [`super::WorkbenchApp`] and is never persisted.

use serde::{Deserialize, Serialize};

use crate::bearing::stages::StageId;
use crate::scene::field::FieldKind;
use crate::scene::request;

/// The central view.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
pub enum View {
    #[default]
    Bearing,
    Fields,
    Coefficients,
    PadDeformation,
    Frf,
    Rotor,
    Sweep,
}

impl View {
    pub const ALL: [Self; 7] =
        [Self::Bearing, Self::Fields, Self::Coefficients, Self::PadDeformation, Self::Frf, Self::Rotor, Self::Sweep];

    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::Bearing => "Bearing",
            Self::Fields => "Pad fields",
            Self::Coefficients => "Coefficients",
            Self::PadDeformation => "Pad deformation",
            Self::Frf => "FRF",
            Self::Rotor => "Rotor",
            Self::Sweep => "Sweep",
        }
    }

    /// The stages whose results the view shows ([`crate::scene::request`]).
    #[must_use]
    pub fn needs(self, axis: CoefficientAxis) -> &'static [StageId] {
        match (self, axis) {
            (Self::Coefficients, CoefficientAxis::FrequencyRatio) => request::FREQUENCY_PLOTS,
            (Self::Coefficients, CoefficientAxis::Speed) => request::SPEED_PLOTS,
            (Self::Frf, _) => request::FRF,
            (Self::PadDeformation, _) => request::DEFORMATION,
            (Self::Bearing | Self::Fields | Self::Rotor | Self::Sweep, _) => request::SOLUTION,
        }
    }
}

/// Which pads the field view shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
pub enum PadChoice {
    #[default]
    All,
    One(usize),
}

/// Abscissa of the coefficient plots.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
pub enum CoefficientAxis {
    #[default]
    FrequencyRatio,
    Speed,
}

/// Persisted settings and the edited case.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Persisted {
    /// The case as TOML (what the user was editing), and its display name.
    pub case_toml: Option<String>,
    pub case_name: String,
    /// Where the case was last opened from or saved to (native), and whether it was unchanged since.
    pub case_path: Option<std::path::PathBuf>,
    pub case_saved: bool,
    pub view: View,
    pub field: FieldKind,
    pub pads: PadChoice,
    pub flowlines: bool,
    pub axis: CoefficientAxis,
    /// Solve at preview fidelity while a value is dragged, at the case's fidelity on release.
    pub preview_while_dragging: bool,
    pub editor_width: f32,
    /// Locked film exaggeration and pressure scale of the bearing view (`None`: chosen per picture).
    pub outline_lock: Option<crate::scene::outline::OutlineScales>,
    /// Pinned reference results (Compare in the results panel).
    pub pins: Vec<crate::scene::compare::Pin>,
    /// The pin the views overlay or show beside the live result (by name; `None`: live only).
    pub compare_with: Option<String>,
    /// How the pad field view compares with that pin.
    pub field_compare: super::views::field_view::FieldCompare,
    /// Locked colour ranges of the pad field view (one per field kind).
    pub field_locks: Vec<crate::scene::field_compare::FieldScaleLock>,
    /// The sweep view's input, range and outputs.
    pub sweep: crate::scene::sweep::SweepSpec,
    /// The editor and results side panels are shown (each can be collapsed to give the view room).
    pub editor_open: bool,
    pub results_open: bool,
}

impl Default for Persisted {
    fn default() -> Self {
        Self {
            case_toml: None,
            case_name: String::new(),
            case_path: None,
            case_saved: false,
            view: View::Bearing,
            field: FieldKind::Pressure,
            pads: PadChoice::All,
            flowlines: true,
            axis: CoefficientAxis::FrequencyRatio,
            preview_while_dragging: true,
            editor_width: 360.0,
            outline_lock: None,
            pins: Vec::new(),
            compare_with: None,
            field_compare: super::views::field_view::FieldCompare::SideBySide,
            field_locks: Vec::new(),
            sweep: crate::scene::sweep::SweepSpec::default(),
            editor_open: true,
            results_open: true,
        }
    }
}
