//! Fuzzes the case reader: arbitrary bytes as a case file, plus the same text with an override derived
//! from it. The reader must return a case or an error, never panic or loop.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let _ = tiltpad::model::load_case(text, &[]);
        if let Some((a, b)) = text.split_once('\n') {
            let _ = tiltpad::model::load_case(b, &[a.to_string()]);
        }
    }
});
