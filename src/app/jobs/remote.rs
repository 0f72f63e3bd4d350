//! A job's trip to another instance of the program (the web build's worker, which shares no memory with the
//! page): the messages both ends exchange, as bytes in the wire format ([`to_bytes`]: CBOR), and the worker's
//! side of the conversation, which holds no JavaScript and is therefore tested natively.
//!
//! - The page posts an [`Order`]: the job's registry name, its id and the job. The worker reads the header
//!   first ([`Header`]), finds the job type by name in [`super::registry`] and decodes the whole order as
//!   that type into its [`Slot`]; a newer order of the same name supersedes the job under way (the slot's
//!   [`Job::Keep`] — the solver stages' cache — stays). The worker's state is [`super::worker_side`].
//! - The worker steps its jobs a tick at a time and posts [`Report`]s: each output, the last progress of the
//!   tick, the end. A report that cannot be encoded reaches the page as its job's failure (never a silent
//!   hang).

use serde::{Deserialize, Serialize};

use super::job::{Event, Job};
use super::stepped::Stepped;
use crate::bearing::stages::{from_bytes, to_bytes};

/// What the page posts.
#[derive(Serialize, Deserialize)]
pub struct Order<J> {
    pub kind: String,
    pub id: u64,
    /// `None`: stop the job under way.
    pub job: Option<J>,
}

/// An order's header: enough to find the job type.
#[derive(Deserialize)]
pub struct Header {
    pub kind: String,
    pub id: u64,
}

/// What the worker posts back.
#[derive(Serialize, Deserialize)]
pub struct Report<O> {
    pub id: u64,
    pub event: Event<O>,
}

/// The bytes of the failure of job `id` (decodes as a report of any output type).
#[must_use]
pub fn failure(id: u64, why: String) -> Vec<u8> {
    // A report of nothing encodes; should even that fail, the page hears nothing (and says so on its side).
    to_bytes(&Report::<()> { id, event: Event::Failed(why) }).unwrap_or_default()
}

/// One slot of the worker: a job type's current job, with its type erased.
pub trait RemoteSlot {
    /// The job's registry name.
    fn kind(&self) -> &'static str;
    /// Decodes an order for this slot and starts it (superseding the job under way; an order without a job
    /// stops it); the id, or why not.
    ///
    /// # Errors
    /// An order that does not decode.
    fn start(&mut self, bytes: &[u8]) -> Result<u64, String>;
    /// Steps the current job for up to `budget_s`; its reports as bytes.
    fn tick(&mut self, budget_s: f64) -> Vec<Vec<u8>>;
    fn busy(&self) -> bool;
}

/// A slot of job type `J`.
pub struct Slot<J: Job> {
    id: u64,
    stepped: Stepped<J>,
}

impl<J: Job> Default for Slot<J> {
    fn default() -> Self {
        Self { id: 0, stepped: Stepped::default() }
    }
}

impl<J: Job> RemoteSlot for Slot<J> {
    fn kind(&self) -> &'static str {
        J::NAME
    }

    fn start(&mut self, bytes: &[u8]) -> Result<u64, String> {
        let order: Order<J> = from_bytes(bytes).map_err(|e| format!("a {} job does not decode: {e}", J::NAME))?;
        self.id = order.id;
        match order.job {
            Some(job) => self.stepped.start(job),
            None => self.stepped.stop(),
        }
        Ok(order.id)
    }

    fn tick(&mut self, budget_s: f64) -> Vec<Vec<u8>> {
        let id = self.id;
        self.stepped
            .run_for(budget_s)
            .into_iter()
            .map(|event| {
                to_bytes(&Report { id, event })
                    .unwrap_or_else(|e| failure(id, format!("the worker cannot send a {} result: {e}", J::NAME)))
            })
            .collect()
    }

    fn busy(&self) -> bool {
        self.stepped.busy()
    }
}

/// An order's bytes (`job` `None`: stop the slot's job).
///
/// # Errors
/// A job that cannot be encoded.
pub fn order_bytes<J: Job>(id: u64, job: Option<&J>) -> Result<Vec<u8>, String> {
    #[derive(Serialize)]
    struct OrderRef<'a, J> {
        kind: &'static str,
        id: u64,
        job: Option<&'a J>,
    }
    to_bytes(&OrderRef { kind: J::NAME, id, job }).map_err(|e| format!("a {} job cannot be sent: {e}", J::NAME))
}

/// A report's event, if it is of job `id`.
///
/// # Errors
/// A report that does not decode.
pub fn read_report<O: serde::de::DeserializeOwned>(bytes: &[u8]) -> Result<(u64, Event<O>), String> {
    let r: Report<O> =
        from_bytes(bytes).map_err(|e| format!("a report from the solver worker does not decode: {e}"))?;
    Ok((r.id, r.event))
}
