//! Web entry: starts the workbench on the page's `<canvas id="tiltpad">` (see `web/index.html`).
//!
//! On the web the workbench draws through eframe's glow renderer, on WebGL2 or else WebGL1. Before starting, a
//! scratch canvas (not the page's, whose context type a probe would fix) is asked for either; a browser that
//! offers neither gets a plain message saying what the page needs and what to try, instead of an error text.

use wasm_bindgen::JsCast as _;

/// Starts the app; errors are logged to the browser console and shown on the page.
pub fn start() {
    eframe::WebLogger::init(log::LevelFilter::Info).ok();
    wasm_bindgen_futures::spawn_local(async {
        let Some(document) = web_sys::window().and_then(|w| w.document()) else {
            log::error!("no document");
            return;
        };
        let Some(canvas) =
            document.get_element_by_id("tiltpad").and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok())
        else {
            log::error!("no <canvas id=\"tiltpad\"> on the page");
            return;
        };
        if let Some(missing) = missing_graphics(&document) {
            show_message(&document, &missing);
            log::error!("{missing}");
            return;
        }
        // `?case=<shipped case>` opens that case (asking first if the restored one has unsaved changes).
        // `?probe` logs frame times to the console ([`super::frame_probe`]).
        let query = web_sys::window().and_then(|w| w.location().search().ok()).unwrap_or_default();
        let preset = super::presets::preset_from_query(&query);
        let probe = super::frame_probe::FrameProbe::from_query(&query);
        let runner = eframe::WebRunner::new();
        let started = runner
            .start(
                canvas,
                eframe::WebOptions::default(),
                Box::new(move |cc| {
                    let mut app = super::WorkbenchApp::new(cc);
                    // `?probe&sweep`: the sweep view opens and runs its sweep at once (measures frames while sweeping).
                    if probe.is_some() && query.trim_start_matches('?').split('&').any(|kv| kv == "sweep") {
                        app.open::<super::views::sweep_view::SweepView>();
                        let text = app.doc.text().ok();
                        let revision = app.doc.revision();
                        if let (Some(text), Some(sweep)) = (text, app.view_mut::<super::views::sweep_view::SweepView>())
                        {
                            sweep.job =
                                super::sweep_run::SweepRun::start(text, &sweep.spec, revision, &cc.egui_ctx).ok();
                        }
                    }
                    // `?probe&rotor`: the rotor view opens (its analysis starts at once).
                    if probe.is_some() && query.trim_start_matches('?').split('&').any(|kv| kv == "rotor") {
                        app.open::<super::views::rotor_view::RotorView>();
                    }
                    app.probe = probe;
                    if let Some(k) = preset {
                        app.request(super::Pending::Preset(k));
                    }
                    Ok(Box::new(app))
                }),
            )
            .await;
        if let Some(loading) = document.get_element_by_id("loading") {
            match started {
                Ok(()) => loading.remove(),
                Err(e) => {
                    let why = e
                        .as_string()
                        .or_else(|| js_sys::Reflect::get(&e, &"message".into()).ok().and_then(|m| m.as_string()));
                    let text = format!(
                        "The workbench failed to start{}. {NEEDS}",
                        why.map_or_else(String::new, |w| format!(" ({w})"))
                    );
                    loading.set_text_content(Some(&text));
                    log::error!("failed to start: {e:?}");
                }
            }
        }
    });
}

/// What the page needs, said wherever the workbench cannot start.
const NEEDS: &str = "The workbench draws with WebGL (2, or else 1): use a current Chrome, Edge, Firefox or Safari \
    with hardware acceleration on (Chrome and Edge: Settings → System → Use graphics acceleration; Firefox: \
    about:support shows WebGL). Without it, the native app and the command line (tiltpad solve, sweep) \
    compute the same results.";

/// `None` when the browser offers WebGL2 or WebGL1; else the message to show.
fn missing_graphics(document: &web_sys::Document) -> Option<String> {
    let offers = |context: &str| {
        document
            .create_element("canvas")
            .ok()
            .and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok())
            .and_then(|c| c.get_context(context).ok().flatten())
            .is_some()
    };
    (!offers("webgl2") && !offers("webgl")).then(|| format!("This browser offers no WebGL. {NEEDS}"))
}

/// Replaces the page's loading line with `text` (the canvas stays empty).
fn show_message(document: &web_sys::Document, text: &str) {
    if let Some(loading) = document.get_element_by_id("loading") {
        loading.set_text_content(Some(text));
    }
}
