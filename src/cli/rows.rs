//! Where study rows go: a CSV and/or a JSON-lines output, each row written and flushed as it completes.
//!
//! Files are written safely ([`SafeFile`]): rows go to the target's `.partial` temporary file (named on
//! standard error when the study starts, so an interrupted run keeps every finished row there) and the
//! file takes the target's name when the study ends. `-` streams to standard output.

use std::io::Write as _;
use std::path::Path;

use anyhow::{Context, Result};

use crate::io::SafeFile;
use crate::study::Row;

/// The outputs of one study.
pub struct RowSink {
    csv: Option<csv::Writer<SafeFile>>,
    jsonl: Option<SafeFile>,
    index_name: &'static str,
}

fn open(path: &Path) -> Result<SafeFile> {
    let f = SafeFile::create(path)?;
    if let Some(p) = f.partial_path() {
        eprintln!("rows go to {} as they complete; it becomes {} at the end", p.display(), path.display());
    }
    Ok(f)
}

impl RowSink {
    /// Opens the outputs and writes the CSV header (`index_name`, input keys, output columns).
    ///
    /// # Errors
    /// A target that cannot be written.
    pub fn open(
        csv_path: Option<&Path>,
        jsonl_path: Option<&Path>,
        index_name: &'static str,
        input_keys: &[String],
    ) -> Result<Self> {
        let csv = match csv_path {
            Some(p) => {
                let mut w = csv::WriterBuilder::new().flexible(false).from_writer(open(p)?);
                w.write_record(Row::header(index_name, input_keys))
                    .with_context(|| format!("cannot write {}", p.display()))?;
                w.flush().with_context(|| format!("cannot write {}", p.display()))?;
                Some(w)
            }
            None => None,
        };
        let jsonl = jsonl_path.map(open).transpose()?;
        Ok(Self { csv, jsonl, index_name })
    }

    /// Writes one row to every output and flushes.
    ///
    /// # Errors
    /// A failed write (the message names the file).
    pub fn write(&mut self, row: &Row) -> Result<()> {
        if let Some(w) = &mut self.csv {
            let name = w.get_ref().path().display().to_string();
            w.write_record(row.record()).with_context(|| format!("cannot write {name}"))?;
            w.flush().with_context(|| format!("cannot write {name}"))?;
        }
        if let Some(f) = &mut self.jsonl {
            let mut line = serde_json::to_string(&row.json(self.index_name))?;
            line.push('\n');
            f.put(line.as_bytes())?;
            f.flush().map_err(|e| f.error(e))?;
        }
        Ok(())
    }

    /// Puts the files in place.
    ///
    /// # Errors
    /// A failed flush, sync or rename.
    pub fn finish(self) -> Result<()> {
        if let Some(w) = self.csv {
            let f = w.into_inner().map_err(|e| anyhow::anyhow!("cannot write a CSV output: {}", e.error()))?;
            let path = f.path().to_path_buf();
            f.commit()?;
            announce(&path);
        }
        if let Some(f) = self.jsonl {
            let path = f.path().to_path_buf();
            f.commit()?;
            announce(&path);
        }
        Ok(())
    }
}

/// Tells where a file went (on standard error, so standard output stays machine-readable).
pub fn announce(path: &Path) {
    if path.as_os_str() != "-" {
        eprintln!("wrote {}", path.display());
    }
}
