//! A design-space table: one design per row, any case keys as columns, on top of a base case; and the
//! shard of it one job runs.
//!
//! The table is CSV with a header of dotted case keys (`bearing.pads.preload,operating.speed_rpm`). Cells
//! are case values as `--set` takes them (numbers, words, per-pad lists in quotes: `"[0,0,0,20,0]"`); an
//! empty cell keeps the base case's value. Lines starting with `#` are comments. Designs are numbered from
//! 0 in file order; that number is the first column of every output row.
//!
//! `--shard I/N` (1 ≤ I ≤ N) takes the I-th of N contiguous, nearly equal blocks of designs, so the
//! outputs of shards 1…N concatenated in order are the unsharded output.

use super::StudyError;

/// The designs of a table.
#[derive(Debug, Clone, PartialEq)]
pub struct Designs {
    /// Case keys, one per column.
    pub keys: Vec<String>,
    /// Per design: its `(key, value)` overrides (empty cells left out).
    pub rows: Vec<Vec<(String, String)>>,
}

impl Designs {
    /// Reads a designs table.
    ///
    /// # Errors
    /// A missing or empty header, a duplicated key, or a row with the wrong number of cells.
    pub fn parse(text: &str) -> Result<Self, StudyError> {
        let mut reader = csv::ReaderBuilder::new()
            .comment(Some(b'#'))
            .trim(csv::Trim::All)
            .flexible(false)
            .from_reader(text.as_bytes());
        let bad = |line: usize, message: String| StudyError::BadDesigns { line, message };
        let headers = reader.headers().map_err(|e| bad(1, e.to_string()))?.clone();
        let keys: Vec<String> = headers.iter().map(str::to_string).collect();
        if keys.is_empty() || keys.iter().any(String::is_empty) {
            return Err(bad(1, "the header must name a case key in every column".into()));
        }
        for (i, k) in keys.iter().enumerate() {
            if keys[..i].contains(k) {
                return Err(bad(1, format!("`{k}` appears twice in the header")));
            }
        }
        let mut rows = Vec::new();
        for record in reader.records() {
            let record = record.map_err(|e| {
                let line = e.position().map_or(0, |p| usize::try_from(p.line()).unwrap_or(0));
                bad(line, e.to_string())
            })?;
            rows.push(
                keys.iter()
                    .zip(record.iter())
                    .filter(|(_, v)| !v.is_empty())
                    .map(|(k, v)| (k.clone(), v.to_string()))
                    .collect(),
            );
        }
        Ok(Self { keys, rows })
    }
}

/// The part of a batch one job runs: block `index` (1-based) of `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

impl Shard {
    /// The whole batch.
    pub const ALL: Self = Self { index: 1, count: 1 };

    /// Parses `I/N`.
    ///
    /// # Errors
    /// Not two whole numbers with 1 ≤ I ≤ N.
    pub fn parse(spec: &str) -> Result<Self, StudyError> {
        let bad = |message: &str| StudyError::BadShard { spec: spec.to_string(), message: message.to_string() };
        let (i, n) = spec.split_once('/').ok_or_else(|| bad("expected I/N, e.g. 2/8"))?;
        let (i, n) = (i.trim().parse::<usize>(), n.trim().parse::<usize>());
        match (i, n) {
            (Ok(i), Ok(n)) if n >= 1 && (1..=n).contains(&i) => Ok(Self { index: i, count: n }),
            _ => Err(bad("I and N must be whole numbers with 1 ≤ I ≤ N")),
        }
    }

    /// The design numbers of this shard out of `total`.
    #[must_use]
    pub fn range(self, total: usize) -> std::ops::Range<usize> {
        let at = |k: usize| k * total / self.count;
        at(self.index - 1)..at(self.index)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn designs_read_keys_values_comments_and_quoted_lists() {
        let text =
            "# preload study\nbearing.pads.preload, operating.injection_pressure_bar\n0.2,\"[0,0,0,20,0]\"\n0.3,\n";
        let d = Designs::parse(text).unwrap();
        assert_eq!(d.keys, ["bearing.pads.preload", "operating.injection_pressure_bar"]);
        assert_eq!(d.rows.len(), 2);
        assert_eq!(d.rows[0][1].1, "[0,0,0,20,0]");
        assert_eq!(d.rows[1], vec![("bearing.pads.preload".to_string(), "0.3".to_string())]);
        let e = Designs::parse("a,b\n1,2,3\n").unwrap_err().to_string();
        assert!(e.contains("line 2"), "{e}");
        assert!(Designs::parse("a,a\n1,2\n").unwrap_err().to_string().contains("twice"));
    }

    #[test]
    fn shards_cover_every_design_once_in_order() {
        for total in [0, 1, 2, 7, 10, 11] {
            for n in 1..=5 {
                let ranges: Vec<_> = (1..=n).map(|i| Shard { index: i, count: n }.range(total)).collect();
                let all: Vec<usize> = ranges.iter().flat_map(Clone::clone).collect();
                assert_eq!(all, (0..total).collect::<Vec<_>>(), "{total} designs in {n} shards");
                let sizes: Vec<usize> = ranges.iter().map(ExactSizeIterator::len).collect();
                assert!(sizes.iter().max().unwrap() - sizes.iter().min().unwrap() <= 1, "{sizes:?}");
            }
        }
        assert_eq!(Shard::parse("2/3").unwrap(), Shard { index: 2, count: 3 });
        for bad in ["0/3", "4/3", "3", "a/b", "1/0"] {
            assert!(Shard::parse(bad).unwrap_err().to_string().contains(bad));
        }
    }
}
