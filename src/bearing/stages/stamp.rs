//! The request's title and case on a published solution.
//!
//! A stage sees its view of the case ([`super::view`]), so the solution it computes carries a blank title
//! and that view as its inputs. What the caller gets is stamped by the registry, which knows the request:
//! the solution with the request's title and its whole case (what the JSON, the pins and the views show).
//! No stage reads the title, so an edit of it reruns nothing and is published at once. The stamped copy is
//! kept while neither the output nor the case changes, so a caller that asks again gets the very same
//! solution (views compare them by pointer to skip repainting).

use std::sync::Arc;

use crate::bearing::solution::Solution;
use crate::bearing::stages::outcome::Published;
use crate::model::Case;

/// The last stamped solution of one stage: the output it was made from, the case stamped, the result.
#[derive(Default)]
pub(super) struct Stamp {
    last: Option<(Published, Case, Published)>,
}

impl Stamp {
    /// `output` as the caller sees it: a [`Solution`] with `case`'s title and case on it; any other output
    /// as it is.
    pub fn stamp(&mut self, output: Published, case: &Case) -> Published {
        let Some(solution) = output.downcast_ref::<Solution>() else { return output };
        if let Some((from, stamped_case, stamped)) = &self.last {
            if Arc::ptr_eq(from, &output) && stamped_case == case {
                return stamped.clone();
            }
        }
        let mut s = solution.clone();
        s.title.clone_from(&case.title);
        s.inputs = case.clone();
        let stamped: Published = Arc::new(s);
        self.last = Some((output, case.clone(), stamped.clone()));
        stamped
    }
}
