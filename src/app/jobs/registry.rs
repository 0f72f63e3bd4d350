//! Every job type, listed once: the web worker rebuilds a job from its bytes by the name the page sent
//! ([`super::remote`]). Adding a job: its file in this folder, and its line here.

use super::job::Job;
use super::remote::{RemoteSlot, Slot};

/// Lists the job types and makes [`slot`] and [`NAMES`] from them.
macro_rules! jobs {
    ($($ty:ty,)*) => {
        /// The registered jobs' names.
        pub const NAMES: &[&str] = &[$(<$ty as Job>::NAME),*];

        /// An empty worker slot for the job named `name` (`None`: no such job).
        #[must_use]
        pub fn slot(name: &str) -> Option<Box<dyn RemoteSlot>> {
            $(if name == <$ty as Job>::NAME {
                return Some(Box::new(Slot::<$ty>::default()));
            })*
            None
        }
    };
}

jobs! {
    super::solve::SolveJob,
    super::sweep::SweepJob,
    super::rotor::RotorJob,
    super::control::Build,
    super::control::Tune,
    super::rig::RigJob,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_job_has_its_own_name_and_a_slot() {
        let unique: std::collections::BTreeSet<&&str> = NAMES.iter().collect();
        assert_eq!(unique.len(), NAMES.len(), "{NAMES:?}");
        for name in NAMES {
            assert_eq!(slot(name).map(|s| s.kind()), Some(*name));
        }
        assert!(slot("no-such-job").is_none());
    }
}
