//! The runners, checked: the native thread and the web worker's side of the conversation (run here
//! without JavaScript) give the same events for the same jobs, only the latest job of a slot reports,
//! and a job that cannot be read fails by name.

use super::job::{Event, Job};
use super::remote::{order_bytes, read_report};
use super::solve::{stage_of, SolveJob};
use super::worker_side::WorkerSide;
use super::Runner;
use crate::bearing::stages::{Outcome, Request, StageId};
use crate::model::load_case;

fn request(speed_rpm: f64, sweep: bool) -> Request {
    let set = [format!("operating.speed_rpm={speed_rpm}"), "mesh.fidelity=\"preview\"".to_string()];
    let case = load_case(include_str!("../../../cases/compressor-bearing.toml"), &set).unwrap().1;
    let mut wanted = vec![StageId::Reduction, StageId::FrequencySweep];
    wanted.extend(sweep.then_some(StageId::SpeedSweep));
    Request {
        frequency_ratios: vec![0.5, 1.0],
        speeds_rad_s: if sweep { [8000.0, 9000.0].map(|n| crate::units::RPM.to_si(n)).to_vec() } else { Vec::new() },
        ..Request::of(case, &wanted)
    }
}

/// Polls until the slot's latest job ends; every event seen.
fn run_until_done<J: Job>(r: &mut Runner<J>) -> Vec<Event<J::Output>> {
    let start = web_time::Instant::now();
    let mut seen = Vec::new();
    while r.busy() {
        assert!(start.elapsed().as_secs() < 300, "the job did not finish");
        seen.extend(r.poll(0.01));
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    seen
}

/// (is the last, has the speed sweep) of each output.
fn outputs(events: &[Event<Outcome>]) -> Vec<(bool, bool)> {
    events
        .iter()
        .filter_map(|e| match e {
            Event::Partial(o) => Some((false, o.speed_sweep().is_some())),
            Event::Done(o) => Some((true, o.speed_sweep().is_some())),
            _ => None,
        })
        .collect()
}

#[test]
fn a_solve_reports_progress_then_its_solution_then_the_speed_sweep() {
    let mut r = Runner::new(&egui::Context::default());
    r.submit(SolveJob::new(request(9000.0, true)));
    let events = run_until_done(&mut r);
    assert!(events.iter().any(|e| matches!(e, Event::Progress(p) if stage_of(p) == Some(StageId::Equilibrium))));
    // First the solution without the sweep, then the complete outcome with it.
    assert_eq!(outputs(&events), vec![(false, false), (true, true)]);
}

#[test]
fn a_newer_job_supersedes_the_running_one() {
    let mut r = Runner::new(&egui::Context::default());
    r.submit(SolveJob::new(request(9000.0, true)));
    // The first job runs a while and sends events the owner has not taken yet.
    std::thread::sleep(std::time::Duration::from_millis(400));
    r.submit(SolveJob::new(request(7000.0, false)));
    let events = run_until_done(&mut r);
    // Only the newest job's events reach the owner: one output, at its speed, without the sweep.
    assert_eq!(outputs(&events), vec![(true, false)]);
    let speed = events.iter().find_map(|e| match e {
        Event::Done(o) => o.solution().map(|s| s.derived.speed_rpm),
        _ => None,
    });
    assert!((speed.unwrap() - 7000.0).abs() < 1e-9);
    // A stopped slot reports nothing more and is idle at once.
    r.submit(SolveJob::new(request(8000.0, false)));
    r.stop();
    assert!(!r.busy() && r.poll(0.0).is_empty());
}

/// The worker's side, fed the page's orders as bytes: the same outputs as the native thread, each tagged
/// with its job's id; a newer order supersedes, keeping the slot's stages (the second solve re-uses the films).
#[test]
fn the_web_workers_side_gives_the_native_outputs_and_supersedes_by_id() {
    let mut w = WorkerSide::default();
    assert!(w.receive(&order_bytes(1, Some(&SolveJob::new(request(9000.0, true)))).unwrap()).is_empty());
    let mut remote: Vec<(u64, Event<Outcome>)> = Vec::new();
    let mut ticks = 0;
    while w.busy() {
        remote.extend(w.tick(0.0).iter().map(|b| read_report(b).unwrap()));
        ticks += 1;
        assert!(ticks < 100_000);
    }
    assert!(remote.iter().all(|(id, _)| *id == 1));
    let events: Vec<Event<Outcome>> = remote.into_iter().map(|(_, e)| e).collect();
    assert_eq!(outputs(&events), vec![(false, false), (true, true)]);
    let mut native = Runner::new(&egui::Context::default());
    native.submit(SolveJob::new(request(9000.0, true)));
    let native_events = run_until_done(&mut native);
    let eps = |events: &[Event<Outcome>]| {
        events.iter().find_map(|e| match e {
            Event::Done(o) => o.solution().map(|s| s.eccentricity_ratio),
            _ => None,
        })
    };
    assert_eq!(eps(&events), eps(&native_events));

    // Superseded: job 2 starts, job 3 replaces it before its first tick; only job 3 reports.
    w.receive(&order_bytes(2, Some(&SolveJob::new(request(7000.0, false)))).unwrap());
    w.receive(&order_bytes(3, Some(&SolveJob::new(request(8000.0, false)))).unwrap());
    let mut ids = std::collections::BTreeSet::new();
    while w.busy() {
        for b in w.tick(1.0) {
            ids.insert(read_report::<Outcome>(&b).unwrap().0);
        }
    }
    assert_eq!(ids.into_iter().collect::<Vec<_>>(), vec![3]);
}

#[test]
fn an_order_the_worker_cannot_read_fails_its_job_by_name() {
    let mut w = WorkerSide::default();
    #[derive(serde::Serialize)]
    struct Unknown {
        kind: &'static str,
        id: u64,
        job: Option<u8>,
    }
    let bytes = crate::bearing::stages::to_bytes(&Unknown { kind: "no-such-job", id: 7, job: Some(1) }).unwrap();
    let reports = w.receive(&bytes);
    let (id, e) = read_report::<Outcome>(&reports[0]).unwrap();
    assert_eq!(id, 7);
    assert!(matches!(&e, Event::Failed(why) if why.contains("no-such-job")), "{e:?}");
    // A known name whose job does not decode.
    let bytes = crate::bearing::stages::to_bytes(&Unknown { kind: "solve", id: 8, job: Some(1) }).unwrap();
    let (id, e) = read_report::<Outcome>(&w.receive(&bytes)[0]).unwrap();
    assert_eq!(id, 8);
    assert!(matches!(&e, Event::Failed(why) if why.contains("solve job does not decode")), "{e:?}");
    assert!(!w.busy());
}
