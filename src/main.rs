//! tiltpad entry point.
//!
//! Native: without arguments the workbench opens on the default case; `tiltpad solve …` and
//! `tiltpad sweep …` run the command-line batch jobs. Web (`wasm32`): the workbench starts on the page's
//! canvas (see `web/`).

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    use clap::Parser;

    let cli = tiltpad::cli::Cli::parse();
    let Some(command) = cli.command else {
        #[cfg(feature = "gui")]
        std::process::exit(i32::from(run_workbench().is_err()));
        #[cfg(not(feature = "gui"))]
        {
            eprintln!("usage: tiltpad solve CASE [--set key=value]... [--json OUT]\n       tiltpad sweep CASE --param KEY --from A --to B --steps N --csv OUT");
            std::process::exit(2);
        }
    };
    if let Err(e) = tiltpad::cli::run(command) {
        if e.downcast_ref::<tiltpad::cli::interrupt::Interrupted>().is_some() {
            eprintln!("{e:#}");
            std::process::exit(tiltpad::cli::interrupt::EXIT_STATUS);
        }
        eprintln!("error: {e:#}");
        std::process::exit(1);
    }
}

/// Opens the workbench window; returns when it is closed.
#[cfg(all(not(target_arch = "wasm32"), feature = "gui"))]
fn run_workbench() -> Result<(), ()> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("tiltpad — tilting-pad bearing workbench")
            .with_inner_size([1400.0, 860.0]),
        ..Default::default()
    };
    eframe::run_native("tiltpad", options, Box::new(|cc| Ok(Box::new(tiltpad::app::WorkbenchApp::new(cc))))).map_err(|e| {
        eprintln!("error: cannot open the workbench window: {e}\n(the command line works without a display: tiltpad solve CASE, tiltpad sweep …)");
    })
}

#[cfg(target_arch = "wasm32")]
fn main() {
    // On the page the workbench starts; in the solver's web worker (no window, `web/worker.js`) the program
    // only answers jobs through `tiltpad_worker_receive`.
    #[cfg(feature = "gui")]
    if web_sys::window().is_some() {
        tiltpad::app::web::start();
    } else {
        tiltpad::app::jobs::web_worker::init_worker();
    }
}

/// Web worker entry: one job from the page, as bytes (`web/worker.js` calls it for each message).
#[cfg(all(target_arch = "wasm32", feature = "gui"))]
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn tiltpad_worker_receive(bytes: &[u8]) {
    tiltpad::app::jobs::web_worker::receive(bytes);
}
