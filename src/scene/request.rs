//! The request the open views need: each view declares the stages whose results it shows (`View::needs` in
//! the view's file under `app/views/`), and [`request`] joins them into one [`Request`] with the grids its
//! sweeps run over. Adding a view that needs a new stage: list the stage in the view's needs; the stage
//! runs (with every stage it reads) while the view is open.

use crate::bearing::stages::{Request, StageId, Start};
use crate::model::Case;

use super::plots::{frequency_ratios, sweep_speeds};

/// Frequency ratios ω/Ω of the frequency sweep: from, to, points.
pub const RATIOS: (f64, f64, usize) = (0.0, 3.0, 31);
/// Points of the speed sweep (from half to one and a half times the case's speed).
pub const SPEED_POINTS: usize = 11;

/// The request for `case` that gives every open view what it shows (`needs`: the views' needs).
#[must_use]
pub fn request<'a>(case: Case, needs: impl IntoIterator<Item = &'a [StageId]>) -> Request {
    let mut wanted: Vec<StageId> = needs.into_iter().flatten().copied().collect();
    wanted.sort_unstable();
    wanted.dedup();
    let frequency_ratios = if wanted.contains(&StageId::FrequencySweep) {
        frequency_ratios(RATIOS.0, RATIOS.1, RATIOS.2)
    } else {
        Vec::new()
    };
    let speeds_rad_s = if wanted.contains(&StageId::SpeedSweep) {
        sweep_speeds(case.operating.speed_rad_s, SPEED_POINTS)
    } else {
        Vec::new()
    };
    Request { case, wanted, frequency_ratios, speeds_rad_s, start: Start::Warm }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::load_case;

    #[test]
    fn the_request_joins_the_views_needs_with_their_grids() {
        let case = load_case(include_str!("../../cases/fillon-a.toml"), &[]).unwrap().1;
        let solution: &[StageId] = &[StageId::Reduction];
        let r = request(case.clone(), [solution]);
        assert_eq!(r.wanted, vec![StageId::Reduction]);
        assert!(r.frequency_ratios.is_empty() && r.speeds_rad_s.is_empty());
        let frequency: &[StageId] = &[StageId::Reduction, StageId::FrequencySweep];
        let speed: &[StageId] = &[StageId::SpeedSweep, StageId::Reduction];
        let r = request(case.clone(), [solution, frequency, speed]);
        assert_eq!(r.wanted, vec![StageId::Reduction, StageId::FrequencySweep, StageId::SpeedSweep]);
        assert_eq!(r.frequency_ratios.len(), RATIOS.2);
        assert_eq!(r.speeds_rad_s.len(), SPEED_POINTS);
        // 4000 rpm: from 2000 to 6000 rpm.
        let rpm: Vec<f64> = r.speeds_rad_s.iter().map(|&w| crate::units::RPM.from_si(w)).collect();
        assert!((rpm[0] - 2000.0).abs() < 1e-9 && (rpm[SPEED_POINTS - 1] - 6000.0).abs() < 1e-9, "{rpm:?}");
    }
}
