//! The shipped cases (`cases/*.toml`), built into the binary so the web build has them too.

/// File name and text of every shipped case; the first is the default (the compressor bearing).
pub const PRESETS: [(&str, &str); 7] = [
    ("compressor-bearing.toml", include_str!("../../cases/compressor-bearing.toml")),
    ("test-rig.toml", include_str!("../../cases/test-rig.toml")),
    ("test-rig-pub5.toml", include_str!("../../cases/test-rig-pub5.toml")),
    ("fillon-a.toml", include_str!("../../cases/fillon-a.toml")),
    ("taniguchi-b.toml", include_str!("../../cases/taniguchi-b.toml")),
    ("someya-4pad-lbp.toml", include_str!("../../cases/someya-4pad-lbp.toml")),
    ("plain-2groove-ld05.toml", include_str!("../../cases/plain-2groove-ld05.toml")),
];

/// The default case's name and text.
#[must_use]
pub fn default_preset() -> (&'static str, &'static str) {
    PRESETS[0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_is_a_valid_case() {
        for (name, text) in PRESETS {
            crate::model::load_case(text, &[]).unwrap_or_else(|e| panic!("{name}: {e}"));
        }
    }
}
