//! The sweep view's job: the points of a [`SweepSpec`] solved one after another by the study runner
//! ([`crate::study::Runner`], warm-started from the previous point), each kept as a row of a
//! [`SweepTable`].
//!
//! Where it runs: on native a named thread solves the points and sends each row over a channel (the UI
//! thread takes them in [`SweepJob::poll`] and asks for a repaint); on the web a web worker of its own solves
//! them ([`super::web_solver::SweepLink`]; where no worker runs, `poll` steps the points within the frame's
//! solve budget, [`super::sweep_steps`]). Dropping the job (a new sweep, closing the app) stops it after the
//! point under way (native) or at once (web: the worker is terminated).

#[cfg(not(target_arch = "wasm32"))]
use crate::scene::sweep::point_override;
use crate::scene::sweep::{SweepSpec, SweepSpecError, SweepTable};
#[cfg(not(target_arch = "wasm32"))]
use crate::study::Runner;

/// A sweep under way or finished.
pub struct SweepJob {
    pub spec: SweepSpec,
    pub table: SweepTable,
    total: usize,
    #[cfg(not(target_arch = "wasm32"))]
    rows: std::sync::mpsc::Receiver<(f64, crate::study::Row)>,
    #[cfg(not(target_arch = "wasm32"))]
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    #[cfg(target_arch = "wasm32")]
    points: super::web_solver::SweepLink,
}

fn base_overrides(spec: &SweepSpec) -> Vec<String> {
    if spec.preview {
        vec!["mesh.fidelity=\"preview\"".into()]
    } else {
        Vec::new()
    }
}

impl SweepJob {
    /// Starts sweeping the case `text` (TOML) as `spec` says.
    ///
    /// # Errors
    /// A spec that names no numeric key, an empty range or a bad count.
    pub fn start(text: String, spec: &SweepSpec, repaint: &egui::Context) -> Result<Self, SweepSpecError> {
        let values = spec.values()?;
        let total = values.len();
        let table = SweepTable::new(&spec.key);
        #[cfg(not(target_arch = "wasm32"))]
        {
            use std::sync::atomic::{AtomicBool, Ordering};
            let (tx, rows) = std::sync::mpsc::channel();
            let stop = std::sync::Arc::new(AtomicBool::new(false));
            let (flag, key, ctx) = (stop.clone(), spec.key.clone(), repaint.clone());
            let mut runner = Runner::new(text, base_overrides(spec), true);
            let spawned = std::thread::Builder::new().name("tiltpad-sweep".into()).spawn(move || {
                for (i, x) in values.into_iter().enumerate() {
                    if flag.load(Ordering::Relaxed) {
                        return;
                    }
                    let (row, _) = runner.row(i, &point_override(&key, x));
                    if tx.send((x, row)).is_err() {
                        return;
                    }
                    ctx.request_repaint();
                }
            });
            if let Err(e) = spawned {
                log::error!("cannot start the sweep thread: {e}");
            }
            Ok(Self { spec: spec.clone(), table, total, rows, stop })
        }
        #[cfg(target_arch = "wasm32")]
        {
            let order =
                super::web_solver::SweepOrder { text, overrides: base_overrides(spec), key: spec.key.clone(), values };
            let points = super::web_solver::SweepLink::start(order, repaint);
            Ok(Self { spec: spec.clone(), table, total, points })
        }
    }

    /// Takes the rows solved since the last call (web: works on the points for the frame's budget).
    pub fn poll(&mut self) {
        #[cfg(not(target_arch = "wasm32"))]
        self.table.points.extend(self.rows.try_iter());
        #[cfg(target_arch = "wasm32")]
        self.table.points.extend(self.points.poll(super::WEB_SOLVE_BUDGET_S));
    }

    /// Points solved and points in all.
    #[must_use]
    pub fn progress(&self) -> (usize, usize) {
        (self.table.points.len(), self.total)
    }

    #[must_use]
    pub fn done(&self) -> bool {
        self.table.points.len() >= self.total
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl Drop for SweepJob {
    fn drop(&mut self) {
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
    }
}
