//! Reduced bearing coefficients for rotordynamics codes: ROSS's bearing-element TOML and a plain CSV.
//!
//! A [`CoefficientTable`] holds the 2×2 reduced stiffness `K` [N/m] and damping `C` [N·s/m] (rows and
//! columns x, y; x horizontal, y vertical up, as in ROSS, whose rotor lies along z) at a list of
//! frequencies [rad/s]. What the frequency means is part of the table: the running speed Ω of a speed
//! sweep (each point condensed at ω = r·Ω, r the case's excitation ratio), or the excitation frequency ω
//! at one running speed (frequency-dependent coefficients).
//!
//! ROSS layout. `BearingElement.save` (ross-rotordynamics 2.3.0, `ross/bearing_seal_element.py`) writes one
//! TOML table named `BearingElement_<tag>` holding the constructor's arguments: `n` (the rotor node),
//! `kxx`, `kxy`, `kyx`, `kyy`, `cxx`, `cxy`, `cyx`, `cyy` as lists, `frequency` as a list in rad/s, `tag`,
//! `scale_factor`, `color` (and `kzz`, `czz`, `m..` terms we leave at their defaults). `Element.load`
//! (`ross/element.py`) reads the first table of the file and passes its keys to the constructor, so
//! `ross.BearingElement.load("bearing.toml")` returns the element. Found with the code search in
//! petrobras/ross (`ross/element.py`, `ross/bearing_seal_element.py`) and checked by saving an element with
//! ross-rotordynamics 2.3.0 installed from PyPI.

use std::fmt::Write as _;

use crate::bearing::solution::coefficients::reduce;
use crate::bearing::Solution;
use crate::number::csv;
use crate::study::band::Band;

/// What the frequency column of a [`CoefficientTable`] is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrequencyMeaning {
    /// Running speed Ω of a speed sweep (coefficients condensed at ω = ratio · Ω).
    RunningSpeed { excitation_ratio: f64 },
    /// Excitation frequency ω at one running speed.
    Excitation,
}

/// Reduced coefficients over frequency.
#[derive(Debug, Clone, PartialEq)]
pub struct CoefficientTable {
    pub meaning: FrequencyMeaning,
    /// Frequencies [rad/s], ascending.
    pub frequency_rad_s: Vec<f64>,
    /// Running speed at each row [rpm].
    pub speed_rpm: Vec<f64>,
    /// Excitation frequency at each row [rad/s].
    pub excitation_rad_s: Vec<f64>,
    pub k_n_per_m: Vec<[[f64; 2]; 2]>,
    pub c_ns_per_m: Vec<[[f64; 2]; 2]>,
}

const TERMS: [(&str, usize, usize); 4] = [("xx", 0, 0), ("xy", 0, 1), ("yx", 1, 0), ("yy", 1, 1)];

fn toml_list(values: impl Iterator<Item = f64>) -> String {
    // `{:?}` keeps a decimal point (TOML floats) and round-trips exactly.
    let items: Vec<String> = values.map(|v| format!("{v:?}")).collect();
    format!("[{}]", items.join(", "))
}

impl CoefficientTable {
    /// The table of a speed band's samples ([`crate::study::band`]), each condensed at `excitation_ratio`.
    #[must_use]
    pub fn of_band(band: &Band, excitation_ratio: f64) -> Self {
        let s = &band.samples;
        Self {
            meaning: FrequencyMeaning::RunningSpeed { excitation_ratio },
            frequency_rad_s: s.iter().map(|x| x.speed_rad_s).collect(),
            speed_rpm: s.iter().map(|x| x.speed_rpm).collect(),
            excitation_rad_s: s.iter().map(|x| x.excitation_rad_s).collect(),
            k_n_per_m: s.iter().map(|x| x.k_n_per_m).collect(),
            c_ns_per_m: s.iter().map(|x| x.c_ns_per_m).collect(),
        }
    }

    /// The table of one solution's full coefficients condensed at each excitation frequency ω = ratio · Ω
    /// (frequency-dependent coefficients at the solution's speed).
    #[must_use]
    pub fn of_excitation(s: &Solution, ratios: &[f64]) -> Self {
        let omegas: Vec<f64> = ratios.iter().map(|r| r * s.derived.speed_rad_s).collect();
        let reduced: Vec<_> = omegas.iter().map(|&w| reduce(&s.full, w)).collect();
        Self {
            meaning: FrequencyMeaning::Excitation,
            frequency_rad_s: omegas.clone(),
            speed_rpm: vec![s.derived.speed_rpm; omegas.len()],
            excitation_rad_s: omegas,
            k_n_per_m: reduced.iter().map(|r| r.k_n_per_m).collect(),
            c_ns_per_m: reduced.iter().map(|r| r.c_ns_per_m).collect(),
        }
    }

    /// The file ROSS's `BearingElement.load` reads, for rotor node `node`, with a `#` comment header.
    #[must_use]
    pub fn ross_toml(&self, node: usize, tag: &str, source: &str) -> String {
        self.ross_toml_elements(&[(node, tag.to_string())], source)
    }

    /// One bearing element per `(node, tag)`, each with this table, in one file: a table per element named as
    /// ROSS's `Element.save` names it (`BearingElement_<tag>`), so `BearingElement.load` reads the first and
    /// `[ross.BearingElement.read_toml_data(d) for d in toml.load(f).values()]` all of them.
    #[must_use]
    pub fn ross_toml_elements(&self, elements: &[(usize, String)], source: &str) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "# Reduced coefficients of {source}, written by tiltpad for ROSS:");
        if elements.len() > 1 {
            let _ = writeln!(s, "#   import ross, toml");
            let _ = writeln!(
                s,
                "#   bearings = [ross.BearingElement.read_toml_data(d) for d in toml.load(\"THIS_FILE.toml\").values()]"
            );
        } else {
            let _ = writeln!(s, "#   import ross; bearing = ross.BearingElement.load(\"THIS_FILE.toml\")");
        }
        let _ = writeln!(s, "# SI units: k [N/m], c [N*s/m], frequency [rad/s]; x horizontal, y vertical up.");
        match self.meaning {
            FrequencyMeaning::RunningSpeed { excitation_ratio } => {
                let _ = writeln!(
                    s,
                    "# frequency = running speed; each point condensed at excitation ratio {excitation_ratio}."
                );
            }
            FrequencyMeaning::Excitation => {
                let _ = writeln!(
                    s,
                    "# frequency = excitation frequency at {:.1} rpm.",
                    self.speed_rpm.first().copied().unwrap_or(0.0)
                );
            }
        }
        for (node, tag) in elements {
            self.ross_element(&mut s, *node, tag);
        }
        s
    }

    fn ross_element(&self, s: &mut String, node: usize, tag: &str) {
        let tag = tag.replace(['"', '\\'], "_");
        // A bare TOML key when the tag allows it (as ROSS writes it), else a quoted one.
        let name = format!("BearingElement_{tag}");
        if name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') {
            let _ = writeln!(s, "[{name}]");
        } else {
            let _ = writeln!(s, "[\"{name}\"]");
        }
        let _ = writeln!(s, "n = {node}");
        let _ = writeln!(s, "tag = \"{tag}\"");
        let _ = writeln!(s, "scale_factor = 1");
        let _ = writeln!(s, "color = \"#355d7a\"");
        let _ = writeln!(s, "frequency = {}", toml_list(self.frequency_rad_s.iter().copied()));
        for (name, i, j) in TERMS {
            let _ = writeln!(s, "k{name} = {}", toml_list(self.k_n_per_m.iter().map(|k| k[i][j])));
        }
        for (name, i, j) in TERMS {
            let _ = writeln!(s, "c{name} = {}", toml_list(self.c_ns_per_m.iter().map(|c| c[i][j])));
        }
    }

    /// A CSV with units in the header: one row per frequency.
    #[must_use]
    pub fn csv(&self) -> String {
        let mut s = String::from("frequency_rad_s,speed_rpm,excitation_rad_s");
        for (name, _, _) in TERMS {
            let _ = write!(s, ",k{name}_n_per_m");
        }
        for (name, _, _) in TERMS {
            let _ = write!(s, ",c{name}_ns_per_m");
        }
        s.push('\n');
        for r in 0..self.frequency_rad_s.len() {
            // The speed in rpm comes from arithmetic on the swept range and is written without its round-off;
            // the rest keeps every digit (the same numbers as the ROSS file).
            let _ =
                write!(s, "{:?},{},{:?}", self.frequency_rad_s[r], csv(self.speed_rpm[r]), self.excitation_rad_s[r]);
            for (_, i, j) in TERMS {
                let _ = write!(s, ",{:?}", self.k_n_per_m[r][i][j]);
            }
            for (_, i, j) in TERMS {
                let _ = write!(s, ",{:?}", self.c_ns_per_m[r][i][j]);
            }
            s.push('\n');
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table() -> CoefficientTable {
        CoefficientTable {
            meaning: FrequencyMeaning::RunningSpeed { excitation_ratio: 1.0 },
            frequency_rad_s: vec![628.3185307179587, 942.4777960769379],
            speed_rpm: vec![6000.0, 9000.0],
            excitation_rad_s: vec![628.3185307179587, 942.4777960769379],
            k_n_per_m: vec![[[1.5e8, -2.0e6], [3.0e6, 2.5e8]], [[1.7e8, 1.0], [2.0, 2.7e8]]],
            c_ns_per_m: vec![[[2.0e5, 0.0], [0.0, 3.0e5]], [[1.9e5, 0.5], [0.25, 2.9e5]]],
        }
    }

    #[test]
    fn ross_file_has_the_bearing_element_layout() {
        let text = table().ross_toml(12, "de bearing", "a test");
        let doc: toml::Table = text.parse().unwrap();
        // One table, named as ROSS names it, so `Element.load` takes it as the first table.
        assert_eq!(doc.len(), 1);
        let (name, t) = doc.iter().next().unwrap();
        assert_eq!(name, "BearingElement_de bearing");
        let t = t.as_table().unwrap();
        // Exactly the constructor arguments ROSS's BearingElement accepts (no unknown keyword).
        let mut keys: Vec<&str> = t.keys().map(String::as_str).collect();
        keys.sort_unstable();
        assert_eq!(
            keys,
            ["color", "cxx", "cxy", "cyx", "cyy", "frequency", "kxx", "kxy", "kyx", "kyy", "n", "scale_factor", "tag"]
        );
        assert_eq!(t["n"].as_integer(), Some(12));
        assert_eq!(t["tag"].as_str(), Some("de bearing"));
        let list = |k: &str| -> Vec<f64> { t[k].as_array().unwrap().iter().map(|v| v.as_float().unwrap()).collect() };
        assert_eq!(list("frequency"), vec![628.3185307179587, 942.4777960769379]);
        assert_eq!(list("kxy"), vec![-2.0e6, 1.0]);
        assert_eq!(list("kyx"), vec![3.0e6, 2.0]);
        assert_eq!(list("cyx"), vec![0.0, 0.25]);
        assert_eq!(list("cyy"), vec![3.0e5, 2.9e5]);
        for k in ["kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy"] {
            assert_eq!(list(k).len(), 2, "{k}: one value per frequency");
        }
    }

    #[test]
    fn csv_names_units_and_round_trips_values() {
        let csv = table().csv();
        let mut lines = csv.lines();
        assert_eq!(
            lines.next().unwrap(),
            "frequency_rad_s,speed_rpm,excitation_rad_s,kxx_n_per_m,kxy_n_per_m,kyx_n_per_m,kyy_n_per_m,cxx_ns_per_m,cxy_ns_per_m,cyx_ns_per_m,cyy_ns_per_m"
        );
        let row: Vec<f64> = lines.next().unwrap().split(',').map(|v| v.parse().unwrap()).collect();
        assert_eq!(
            row,
            vec![628.3185307179587, 6000.0, 628.3185307179587, 1.5e8, -2.0e6, 3.0e6, 2.5e8, 2.0e5, 0.0, 0.0, 3.0e5]
        );
        assert_eq!(lines.count(), 1);
    }
}
