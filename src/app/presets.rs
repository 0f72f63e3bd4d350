//! The shipped cases (`cases/*.toml`), built into the binary so the web build has them too.

/// File name and text of every shipped case; the first is the default (the compressor bearing).
pub const PRESETS: [(&str, &str); 15] = [
    ("compressor-bearing.toml", include_str!("../../cases/compressor-bearing.toml")),
    ("test-rig.toml", include_str!("../../cases/test-rig.toml")),
    ("test-rig-pub5.toml", include_str!("../../cases/test-rig-pub5.toml")),
    ("fillon-a.toml", include_str!("../../cases/fillon-a.toml")),
    ("taniguchi-b.toml", include_str!("../../cases/taniguchi-b.toml")),
    ("someya-4pad-lbp.toml", include_str!("../../cases/someya-4pad-lbp.toml")),
    ("plain-2groove-ld05.toml", include_str!("../../cases/plain-2groove-ld05.toml")),
    ("compressor-bearing-flexible.toml", include_str!("../../cases/compressor-bearing-flexible.toml")),
    ("fillon-a-tehd.toml", include_str!("../../cases/fillon-a-tehd.toml")),
    ("compressor-overload.toml", include_str!("../../cases/compressor-overload.toml")),
    ("compressor-bearing-rocker-pivot.toml", include_str!("../../cases/compressor-bearing-rocker-pivot.toml")),
    ("fillon-a-tehd-bc3.toml", include_str!("../../cases/fillon-a-tehd-bc3.toml")),
    ("compressor-bearing-tehd.toml", include_str!("../../cases/compressor-bearing-tehd.toml")),
    ("compressor-bearing-starved.toml", include_str!("../../cases/compressor-bearing-starved.toml")),
    ("plain-360-sommerfeld.toml", include_str!("../../cases/plain-360-sommerfeld.toml")),
];

/// The default case's name and text.
#[must_use]
pub fn default_preset() -> (&'static str, &'static str) {
    PRESETS[0]
}

/// The preset a page address asks for: `?case=fillon-a` (or `fillon-a.toml`) in the query string of the
/// web build, so a link can open a given shipped case.
#[must_use]
pub fn preset_from_query(query: &str) -> Option<usize> {
    let wanted = query.trim_start_matches('?').split('&').find_map(|kv| kv.strip_prefix("case="))?;
    let wanted = wanted.strip_suffix(".toml").unwrap_or(wanted);
    PRESETS.iter().position(|(name, _)| name.strip_suffix(".toml") == Some(wanted))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_query_string_names_a_preset() {
        assert_eq!(preset_from_query("?case=fillon-a"), Some(3));
        assert_eq!(preset_from_query("?x=1&case=fillon-a.toml"), Some(3));
        assert_eq!(preset_from_query("case=compressor-bearing"), Some(0));
        assert_eq!(preset_from_query("?case=unknown"), None);
        assert_eq!(preset_from_query(""), None);
    }

    #[test]
    fn every_preset_is_a_valid_case() {
        for (name, text) in PRESETS {
            crate::model::load_case(text, &[]).unwrap_or_else(|e| panic!("{name}: {e}"));
        }
    }
}
