//! The web worker's state: a slot per job type it has been sent ([`super::remote::Slot`], made by name from
//! [`super::registry`]), fed the page's orders and stepped a tick at a time. No JavaScript here (that is
//! [`super::web_worker`]), so the worker's side is tested natively.

use super::remote::{failure, Header, RemoteSlot};
use crate::bearing::stages::from_bytes;

/// The worker's state: a slot per job type it has been sent.
#[derive(Default)]
pub struct WorkerSide {
    slots: Vec<Box<dyn RemoteSlot>>,
}

impl WorkerSide {
    /// Takes an order; the reports to post at once (an order that cannot be read fails its job).
    pub fn receive(&mut self, bytes: &[u8]) -> Vec<Vec<u8>> {
        let header: Header = match from_bytes(bytes) {
            Ok(h) => h,
            Err(e) => {
                log::error!("solver worker: an order does not decode: {e}");
                return Vec::new();
            }
        };
        let i = match self.slots.iter().position(|s| s.kind() == header.kind) {
            Some(i) => i,
            None => match super::registry::slot(&header.kind) {
                Some(slot) => {
                    self.slots.push(slot);
                    self.slots.len() - 1
                }
                None => return vec![failure(header.id, format!("the worker knows no job '{}'", header.kind))],
            },
        };
        match self.slots[i].start(bytes) {
            Ok(_) => Vec::new(),
            Err(e) => vec![failure(header.id, e)],
        }
    }

    /// Steps every busy slot, `budget_s` shared between them; their reports.
    pub fn tick(&mut self, budget_s: f64) -> Vec<Vec<u8>> {
        let busy = self.slots.iter().filter(|s| s.busy()).count().max(1);
        #[allow(clippy::cast_precision_loss)]
        let share = budget_s / busy as f64;
        self.slots.iter_mut().filter(|s| s.busy()).flat_map(|s| s.tick(share)).collect()
    }

    #[must_use]
    pub fn busy(&self) -> bool {
        self.slots.iter().any(|s| s.busy())
    }
}
