//! Sweep axes: one case key and its values; several axes make a grid (the first axis varies slowest).
//!
//! An axis is written `KEY=FROM:TO:STEPS` (STEPS evenly spaced numbers, ends included),
//! `KEY=v1,v2,v3` (a list) or, for values that contain commas themselves (per-pad lists),
//! `KEY=[0,0,20];[0,0,40]`. Values are case-file values as `--set` takes them: numbers, quoted or bare
//! words (`thermal.model=isothermal,thd`), lists.

use super::StudyError;

/// One swept key and its values (as `--set` text).
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    pub key: String,
    pub values: Vec<String>,
}

/// Most points a grid may have (a guard against a typo such as `:100000`).
pub const MAX_POINTS: usize = 1_000_000;

impl Axis {
    /// Parses `KEY=FROM:TO:STEPS`, `KEY=a,b,c` or `KEY=a;b;c`.
    ///
    /// # Errors
    /// A missing `=`, an empty key or value list, or a range that is not three numbers with STEPS ≥ 1.
    pub fn parse(spec: &str) -> Result<Self, StudyError> {
        let bad = |message: &str| StudyError::BadAxis { spec: spec.to_string(), message: message.to_string() };
        let (key, list) = spec.split_once('=').ok_or_else(|| bad("expected KEY=FROM:TO:STEPS or KEY=v1,v2,…"))?;
        let key = key.trim();
        if key.is_empty() {
            return Err(bad("empty key"));
        }
        let list = list.trim();
        let values: Vec<String> = if list.contains(';') {
            list.split(';').map(|v| v.trim().to_string()).collect()
        } else if let Some(range) = parse_range(list) {
            let (from, to, steps) = range.map_err(|m| bad(&m))?;
            Self::linspace(key, from, to, steps).values
        } else {
            list.split(',').map(|v| v.trim().to_string()).collect()
        };
        if values.is_empty() || values.iter().any(String::is_empty) {
            return Err(bad("empty value in the list"));
        }
        Ok(Self { key: key.to_string(), values })
    }

    /// `steps` evenly spaced numbers from `from` to `to` (one step: `from`).
    #[must_use]
    pub fn linspace(key: &str, from: f64, to: f64, steps: usize) -> Self {
        #[allow(clippy::cast_precision_loss)]
        let values = (0..steps)
            .map(|i| if steps == 1 { from } else { from + (to - from) * i as f64 / (steps - 1) as f64 })
            .map(crate::number::csv)
            .collect();
        Self { key: key.to_string(), values }
    }
}

/// `FROM:TO:STEPS` → numbers; `None` when the text is not of that shape at all.
fn parse_range(text: &str) -> Option<Result<(f64, f64, usize), String>> {
    let parts: Vec<&str> = text.split(':').collect();
    if parts.len() != 3 {
        return None;
    }
    let num = |s: &str| s.trim().parse::<f64>().ok().filter(|v| v.is_finite());
    Some(match (num(parts[0]), num(parts[1]), parts[2].trim().parse::<usize>()) {
        (Some(a), Some(b), Ok(n)) if (1..=MAX_POINTS).contains(&n) => Ok((a, b, n)),
        (Some(_), Some(_), _) => Err(format!("STEPS must be a whole number in [1, {MAX_POINTS}]")),
        _ => Err("FROM and TO must be finite numbers".into()),
    })
}

/// Every point of the grid spanned by `axes`, as `(key, value)` overrides; the first axis varies slowest.
///
/// # Errors
/// More than [`MAX_POINTS`] points.
pub fn points(axes: &[Axis]) -> Result<Vec<Vec<(String, String)>>, StudyError> {
    let total = axes.iter().try_fold(1usize, |n, a| n.checked_mul(a.values.len())).filter(|&n| n <= MAX_POINTS);
    let Some(total) = total else {
        let spec = axes.iter().map(|a| a.key.as_str()).collect::<Vec<_>>().join(" × ");
        return Err(StudyError::BadAxis { spec, message: format!("the grid has more than {MAX_POINTS} points") });
    };
    let mut out = Vec::with_capacity(total);
    for mut flat in 0..total {
        let mut point = vec![(String::new(), String::new()); axes.len()];
        for (k, axis) in axes.iter().enumerate().rev() {
            let n = axis.values.len();
            point[k] = (axis.key.clone(), axis.values[flat % n].clone());
            flat /= n;
        }
        out.push(point);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axes_parse_ranges_lists_and_per_pad_lists() {
        let a = Axis::parse("operating.speed_rpm=6000:10000:3").unwrap();
        assert_eq!(a.key, "operating.speed_rpm");
        assert_eq!(a.values, ["6000", "8000", "10000"]);
        // Values from arithmetic are written without round-off digits (0.2 + 0.4 = 0.6000000000000001).
        assert_eq!(Axis::parse("bearing.pads.preload=0.2:1.0:5").unwrap().values, ["0.2", "0.4", "0.6", "0.8", "1"]);
        let b = Axis::parse("thermal.model=isothermal, thd").unwrap();
        assert_eq!(b.values, ["isothermal", "thd"]);
        let c = Axis::parse("operating.injection_pressure_bar=[0,0,0,20,0];[0,0,0,40,0]").unwrap();
        assert_eq!(c.values, ["[0,0,0,20,0]", "[0,0,0,40,0]"]);
        assert_eq!(Axis::parse("bearing.pads.preload=0.2").unwrap().values, ["0.2"]);
        for bad in
            ["speed", "=1,2", "operating.speed_rpm=1:2:0", "operating.speed_rpm=a:2:3", "operating.speed_rpm=1,,2"]
        {
            let e = Axis::parse(bad).unwrap_err().to_string();
            assert!(e.contains(bad), "{e}");
        }
    }

    #[test]
    fn the_grid_varies_the_first_axis_slowest() {
        let axes = [Axis::parse("a=1,2").unwrap(), Axis::parse("b=x,y,z").unwrap()];
        let p = points(&axes).unwrap();
        let flat: Vec<String> = p.iter().map(|pt| format!("{}{}", pt[0].1, pt[1].1)).collect();
        assert_eq!(flat, ["1x", "1y", "1z", "2x", "2y", "2z"]);
        assert!(points(&[Axis::linspace("a", 0.0, 1.0, 1001), Axis::linspace("b", 0.0, 1.0, 1001)]).is_err());
    }
}
