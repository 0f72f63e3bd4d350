//! Views whose results the solver does not produce yet. Each says what it will show and what it needs,
//! so a user (and the next engineer) knows where the workbench is going.

use egui::{RichText, Ui};

use crate::app::state::View;

/// What a future view will show.
#[must_use]
pub fn placeholder_text(view: View) -> Option<(&'static str, &'static str)> {
    match view {
        View::PadDeformation => Some((
            "Pad deformation — needs the pad flexibility model",
            "Will show each pad's elastic and thermal deformation: the retained bending modes and the thermal \
             growth of the film-side surface (exaggerated, with the rigid pad as reference), and how they change \
             the film thickness. Computed from a 3-D finite-element pad model reduced to a few pseudo-modes \
             (model.md §5).",
        )),
        View::Frf => Some((
            "Frequency response — needs the hydraulics model",
            "Will show Bode plots of the controllable bearing as an actuator: servovalve, injection pipeline \
             (acoustic modes) and film, G = F/u = G1·G2·G3, magnitude and phase against frequency (model.md §8), \
             with the measured extra phase lag the model does not contain stated beside it.",
        )),
        View::Rotor => Some((
            "Rotor — needs the rotor–bearing model",
            "Will show the rotor–bearing system: Campbell diagram and stability map (eigenvalues against speed, \
             logarithmic decrement, onset of instability) and the unbalance response with the API 617 limit, \
             using the full or the reduced bearing coefficients (model.md §10).",
        )),
        View::Bearing | View::Fields | View::Coefficients | View::Sweep => None,
    }
}

pub fn placeholder_ui(ui: &mut Ui, view: View) {
    if let Some((title, text)) = placeholder_text(view) {
        ui.add_space(24.0);
        ui.label(RichText::new(title).heading());
        ui.add_space(8.0);
        ui.label(text);
        ui.add_space(8.0);
        ui.label(RichText::new("Not computed yet: this view is filled by a later version of the workbench.").italics().weak());
    }
}
