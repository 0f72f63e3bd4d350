//! Web entry: starts the workbench on the page's `<canvas id="tiltpad">` (see `web/index.html`).

use wasm_bindgen::JsCast as _;

/// Starts the app; errors are logged to the browser console and shown on the page.
pub fn start() {
    eframe::WebLogger::init(log::LevelFilter::Info).ok();
    wasm_bindgen_futures::spawn_local(async {
        let Some(document) = web_sys::window().and_then(|w| w.document()) else {
            log::error!("no document");
            return;
        };
        let Some(canvas) = document.get_element_by_id("tiltpad").and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok()) else {
            log::error!("no <canvas id=\"tiltpad\"> on the page");
            return;
        };
        // `?case=<shipped case>` opens that case (asking first if the restored one has unsaved changes).
        let preset = web_sys::window().and_then(|w| w.location().search().ok()).and_then(|q| super::presets::preset_from_query(&q));
        let runner = eframe::WebRunner::new();
        let started = runner
            .start(
                canvas,
                eframe::WebOptions::default(),
                Box::new(move |cc| {
                    let mut app = super::WorkbenchApp::new(cc);
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
                    loading.set_text_content(Some(&format!("The workbench failed to start: {e:?}")));
                    log::error!("failed to start: {e:?}");
                }
            }
        }
    });
}
