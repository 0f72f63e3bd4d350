//! Files: open and save case TOML, export the current view (PNG), the fields (CSV) and the results
//! (JSON), through native dialogs or the browser.
//!
//! Dialogs never block the UI: on native they run on a short-lived thread (rfd's blocking dialog), on the
//! web in a future (rfd's async dialog; saving becomes a download). Their outcome comes back as a
//! [`FileEvent`] over a channel. Writes on native are safe ([`crate::io::safe_write`]): the bytes go to
//! an exclusively created temporary file beside the target, which is synced and renamed over it; a
//! symlink is written through, never replaced. A case is saved as the text it was opened from with the
//! edited values written in ([`super::document::Document::text`]), so its comments survive.

use std::sync::mpsc::{channel, Receiver, Sender};

pub use super::file_event::{display_name, FileEvent};
use super::file_event::{OpenKind, PendingSave};

/// Dialog runner and its event channel.
pub struct Files {
    tx: Sender<FileEvent>,
    rx: Receiver<FileEvent>,
    repaint: egui::Context,
    /// Open and save through the system's dialogs (false: the workbench's own path dialogs).
    pub native_dialogs: bool,
}

impl Files {
    #[must_use]
    pub fn new(repaint: egui::Context) -> Self {
        let (tx, rx) = channel();
        Self { tx, rx, repaint, native_dialogs: dialogs_available() }
    }

    /// Events since the last call.
    pub fn poll(&self) -> Vec<FileEvent> {
        self.rx.try_iter().collect()
    }

    /// Reads a file dropped on the window (asynchronously on the web).
    pub fn read_dropped(&self, file: egui::DroppedFileHandle) {
        let name = display_name(file.path());
        #[cfg(not(target_arch = "wasm32"))]
        {
            let event = match file.bytes().map(String::from_utf8) {
                Ok(Ok(text)) => FileEvent::Opened { name, path: Some(file.path().to_path_buf()), text },
                Ok(Err(_)) => FileEvent::Error(format!("{name} is not UTF-8 text")),
                Err(e) => FileEvent::Error(format!("cannot read {name}: {e}")),
            };
            let _ = self.tx.send(event);
        }
        #[cfg(target_arch = "wasm32")]
        {
            let (tx, repaint) = (self.tx.clone(), self.repaint.clone());
            spawn(async move {
                let event = match file.bytes_async().await.map(String::from_utf8) {
                    Ok(Ok(text)) => FileEvent::Opened { name, path: None, text },
                    Ok(Err(_)) => FileEvent::Error(format!("{name} is not UTF-8 text")),
                    Err(e) => FileEvent::Error(format!("cannot read {name}: {e}")),
                };
                let _ = tx.send(event);
                repaint.request_repaint();
            });
        }
    }

    /// Asks for a case file to open.
    pub fn open_case(&self) {
        if !self.native_dialogs {
            let _ = self.tx.send(FileEvent::PathNeeded(OpenKind::Case));
            // The event is taken at the start of a frame: ask for one, or the dialog waits for the next
            // input (it did after "Discard changes", whose frame asks for no other).
            self.repaint.request_repaint();
            return;
        }
        let (tx, repaint) = (self.tx.clone(), self.repaint.clone());
        spawn(async move {
            let picked = rfd::AsyncFileDialog::new()
                .add_filter("Case (TOML)", &["toml"])
                .set_title("Open a case")
                .pick_file()
                .await;
            if let Some(handle) = picked {
                let bytes = handle.read().await;
                let event = match String::from_utf8(bytes) {
                    Ok(text) => FileEvent::Opened { name: handle.file_name(), path: handle_path(&handle), text },
                    Err(_) => FileEvent::Error(format!("{} is not UTF-8 text", handle.file_name())),
                };
                let _ = tx.send(event);
                repaint.request_repaint();
            }
        });
    }

    /// Asks for a rotor file to open (native only: its bearing cases are read from beside it; the web keeps
    /// the shipped rotors).
    #[cfg(not(target_arch = "wasm32"))]
    pub fn open_rotor(&self) {
        if !self.native_dialogs {
            let _ = self.tx.send(FileEvent::PathNeeded(OpenKind::Rotor));
            // The event is taken at the start of a frame: ask for one, or the dialog waits for the next
            // input (it did after "Discard changes", whose frame asks for no other).
            self.repaint.request_repaint();
            return;
        }
        let (tx, repaint) = (self.tx.clone(), self.repaint.clone());
        spawn(async move {
            let picked = rfd::AsyncFileDialog::new()
                .add_filter("Rotor (TOML)", &["toml"])
                .set_title("Open a rotor")
                .pick_file()
                .await;
            if let Some(handle) = picked {
                let path = handle.path().to_path_buf();
                let event = match std::fs::read_to_string(&path) {
                    Ok(text) => FileEvent::OpenedRotor { name: handle.file_name(), path, text },
                    Err(e) => FileEvent::Error(format!("cannot read {}: {e}", path.display())),
                };
                let _ = tx.send(event);
                repaint.request_repaint();
            }
        });
    }

    /// Saves the case `text` (of `file`): straight to `path` when known (native), else through a save dialog.
    pub fn save_case(
        &self,
        text: Result<String, crate::model::CaseError>,
        file: &crate::model::CaseFile,
        name: &str,
        path: Option<&std::path::Path>,
    ) {
        let text = match text {
            Ok(t) => t,
            Err(e) => {
                let _ = self.tx.send(FileEvent::Error(format!("cannot write the case as TOML: {e}")));
                return;
            }
        };
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(p) = path {
            let event = match crate::io::write_file(p, text.as_bytes()) {
                Ok(()) => FileEvent::SavedCase {
                    name: display_name(p),
                    path: Some(p.to_path_buf()),
                    saved: Box::new(file.clone()),
                    text,
                },
                Err(e) => FileEvent::Error(e.to_string()),
            };
            let _ = self.tx.send(event);
            return;
        }
        let _ = path;
        let saved = Box::new(file.clone());
        let bytes = text.clone().into_bytes();
        self.save_bytes(name, "Case (TOML)", "toml", bytes, move |name, path| FileEvent::SavedCase {
            name,
            path,
            saved,
            text,
        });
    }

    /// Exports bytes under a suggested name.
    pub fn export(&self, name: &str, filter: &str, extension: &str, bytes: Vec<u8>) {
        self.save_bytes(name, filter, extension, bytes, |name, path| FileEvent::Exported { name, path });
    }

    fn save_bytes(
        &self,
        name: &str,
        filter: &str,
        extension: &str,
        bytes: Vec<u8>,
        done: impl FnOnce(String, Option<std::path::PathBuf>) -> FileEvent + Send + 'static,
    ) {
        if !self.native_dialogs {
            // Without a dialog, the workbench asks for a name: nothing is written under a name not typed.
            let pending = PendingSave {
                suggested: name.to_string(),
                extension: extension.to_string(),
                bytes,
                done: Box::new(done),
            };
            let _ = self.tx.send(FileEvent::NameNeeded(Box::new(pending)));
            // The event is taken at the start of a frame: ask for one, or the dialog waits for the next
            // input (it did after "Discard changes", whose frame asks for no other).
            self.repaint.request_repaint();
            return;
        }
        let (tx, repaint) = (self.tx.clone(), self.repaint.clone());
        let dialog = rfd::AsyncFileDialog::new().add_filter(filter, &[extension]).set_file_name(name);
        spawn(async move {
            if let Some(handle) = dialog.save_file().await {
                let event = write_handle(&handle, &bytes)
                    .await
                    .map_or_else(FileEvent::Error, |()| done(handle.file_name(), handle_path(&handle)));
                let _ = tx.send(event);
                repaint.request_repaint();
            }
        });
    }
}

/// Native dialogs go through the XDG desktop portal, which needs a session bus; the browser always has one.
fn dialogs_available() -> bool {
    cfg!(target_arch = "wasm32") || std::env::var_os("DBUS_SESSION_BUS_ADDRESS").is_some()
}

/// Writes through a dialog's handle: atomically on native, as a download on the web.
async fn write_handle(handle: &rfd::FileHandle, bytes: &[u8]) -> Result<(), String> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        crate::io::write_file(handle.path(), bytes).map_err(|e| e.to_string())
    }
    #[cfg(target_arch = "wasm32")]
    {
        handle.write(bytes).await.map_err(|e| e.to_string())
    }
}

#[cfg(not(target_arch = "wasm32"))]
#[allow(clippy::unnecessary_wraps)]
fn handle_path(handle: &rfd::FileHandle) -> Option<std::path::PathBuf> {
    Some(handle.path().to_path_buf())
}

#[cfg(target_arch = "wasm32")]
fn handle_path(_: &rfd::FileHandle) -> Option<std::path::PathBuf> {
    None
}

/// Runs a dialog future without blocking the UI.
#[cfg(not(target_arch = "wasm32"))]
fn spawn(fut: impl std::future::Future<Output = ()> + Send + 'static) {
    let spawned = std::thread::Builder::new().name("tiltpad-file-dialog".into()).spawn(move || pollster_block_on(fut));
    if let Err(e) = spawned {
        log::error!("cannot start a file dialog thread: {e}");
    }
}

#[cfg(target_arch = "wasm32")]
fn spawn(fut: impl std::future::Future<Output = ()> + 'static) {
    wasm_bindgen_futures::spawn_local(fut);
}

/// A minimal executor for one dialog future on its own thread (the portal dialog is async).
#[cfg(not(target_arch = "wasm32"))]
fn pollster_block_on<F: std::future::Future>(fut: F) -> F::Output {
    use std::sync::Arc;
    use std::task::{Context, Poll, Wake, Waker};

    struct ThreadWaker(std::thread::Thread);
    impl Wake for ThreadWaker {
        fn wake(self: Arc<Self>) {
            self.0.unpark();
        }
    }
    let waker = Waker::from(Arc::new(ThreadWaker(std::thread::current())));
    let mut cx = Context::from_waker(&waker);
    let mut fut = std::pin::pin!(fut);
    loop {
        match fut.as_mut().poll(&mut cx) {
            Poll::Ready(v) => return v,
            Poll::Pending => std::thread::park(),
        }
    }
}

/// Encodes RGBA pixels as PNG.
///
/// # Errors
/// If the encoder fails (it does not for valid sizes).
pub fn encode_png(width: usize, height: usize, rgba: &[u8]) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    let (w, h) = (u32::try_from(width).map_err(|e| e.to_string())?, u32::try_from(height).map_err(|e| e.to_string())?);
    let mut enc = png::Encoder::new(&mut out, w, h);
    enc.set_color(png::ColorType::Rgba);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().map_err(|e| e.to_string())?;
    writer.write_image_data(rgba).map_err(|e| e.to_string())?;
    writer.finish().map_err(|e| e.to_string())?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::document::Document;
    use crate::model::parse_case_file;

    #[test]
    fn saving_an_edited_case_changes_only_the_edited_line() {
        let dir = std::env::temp_dir().join(format!("tiltpad-save-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("case.toml");
        let original = include_str!("../../cases/test-rig.toml");
        std::fs::write(&path, original).unwrap();
        let file = parse_case_file(original, &[]).unwrap();
        let mut doc = Document::new(file, "case.toml", true).with_source(original);
        doc.edit("operating.load_n", false, |f| f.operating.load_n = Some(1234.0));
        let files = Files::new(egui::Context::default());
        files.save_case(doc.text(), doc.file(), "case.toml", Some(&path));
        match files.poll().as_slice() {
            [FileEvent::SavedCase { name, path: Some(p), saved, text }] => {
                assert_eq!(name, "case.toml");
                assert_eq!(p, &path);
                assert_eq!(**saved, *doc.file());
                assert_eq!(text, &std::fs::read_to_string(&path).unwrap());
            }
            other => panic!("{other:?}"),
        }
        let written = std::fs::read_to_string(&path).unwrap();
        let changed: Vec<(&str, &str)> = original.lines().zip(written.lines()).filter(|(a, b)| a != b).collect();
        assert_eq!(original.lines().count(), written.lines().count());
        assert_eq!(changed.len(), 1, "{changed:?}");
        assert!(changed[0].0.starts_with("load_n") && changed[0].1.starts_with("load_n = 1234"), "{changed:?}");
        assert_eq!(parse_case_file(&written, &[]).unwrap(), *doc.file());
        // Only the target is left: the temporary file was renamed over it.
        let names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("case.toml")]);
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_failed_save_names_the_path_and_keeps_the_file() {
        let dir = std::env::temp_dir().join(format!("tiltpad-save-dir-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("case.toml")).unwrap();
        let file = parse_case_file(include_str!("../../cases/test-rig.toml"), &[]).unwrap();
        let files = Files::new(egui::Context::default());
        files.save_case(file.to_toml(), &file, "case.toml", Some(&dir.join("case.toml")));
        match files.poll().as_slice() {
            [FileEvent::Error(e)] => assert!(e.contains("case.toml") && e.contains("directory"), "{e}"),
            other => panic!("{other:?}"),
        }
        assert!(dir.join("case.toml").is_dir());
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn png_encoding_round_trips() {
        let rgba: Vec<u8> = (0..2 * 3 * 4).map(|i| u8::try_from(i * 10).unwrap()).collect();
        let bytes = encode_png(2, 3, &rgba).unwrap();
        let mut reader = png::Decoder::new(std::io::Cursor::new(bytes)).read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        assert_eq!((info.width, info.height), (2, 3));
        assert_eq!(&buf[..info.buffer_size()], &rgba[..]);
    }
}
