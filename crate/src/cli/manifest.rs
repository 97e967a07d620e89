//! What `bodyspace batch` records per subject ([`SubjectRecord`], the `batch` object of each
//! `OUT/reports/<subject>.json`), the `OUT/manifest.csv` made from those records, reading that
//! manifest back (for `build-model --exclude-flagged`), and atomic file writes.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

/// A subject's outcome.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// Fitted, no quality flag.
    Ok,
    /// Fitted, with at least one quality flag (docs/batch.md).
    Flagged,
    /// Not fitted; `reason` says why.
    Failed,
}

impl Status {
    /// Whether the subject has a fit.
    pub fn fitted(self) -> bool {
        self != Status::Failed
    }

    /// The name written in reports and manifests.
    pub fn name(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::Flagged => "flagged",
            Status::Failed => "failed",
        }
    }
}

/// One subject of a batch, as its report's `batch` object (`Flags` = `Vec<String>`, one name a
/// flag) and its manifest row ([`ManifestRow`]: `Flags` = `String`, the names separated by `;`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SubjectRecord<Flags = Vec<String>> {
    /// The scan's file name without its extensions (`scan_001.ply.gz` → `scan_001`).
    pub subject: String,
    pub status: Status,
    /// Why the subject failed, or which flags it raised; empty when ok.
    pub reason: String,
    /// Scan → template RMS (mm) of the fit.
    pub rms_mm: Option<f64>,
    /// Quality flag names (docs/batch.md).
    pub flags: Flags,
    /// Wall time of this subject (read, align, assess, write), s.
    pub seconds: f64,
    /// Template resolution of the fit ("base" or "fine").
    pub resolution: String,
    pub scan: String,
    /// The landmark file used (empty when none was found).
    pub landmarks: String,
}

/// One CSV row of the manifest: the record with its flags joined by `;`, the RMS rounded to
/// 0.1 µm and the time to 1 ms.
pub type ManifestRow = SubjectRecord<String>;

impl From<&SubjectRecord> for ManifestRow {
    fn from(r: &SubjectRecord) -> Self {
        Self {
            subject: r.subject.clone(),
            status: r.status,
            reason: r.reason.clone(),
            rms_mm: r.rms_mm.map(|x| (x * 1e4).round() / 1e4),
            flags: r.flags.join(";"),
            seconds: (r.seconds * 1e3).round() / 1e3,
            resolution: r.resolution.clone(),
            scan: r.scan.clone(),
            landmarks: r.landmarks.clone(),
        }
    }
}

/// The manifest's CSV text: a header and one row per record, in the order given.
pub fn manifest_csv(records: &[SubjectRecord]) -> Result<Vec<u8>, String> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    for r in records {
        writer
            .serialize(ManifestRow::from(r))
            .map_err(|e| format!("manifest row of {}: {e}", r.subject))?;
    }
    writer
        .into_inner()
        .map_err(|e| format!("manifest: {}", e.error()))
}

/// Reads a manifest written by [`manifest_csv`].
pub fn read_manifest(path: &Path) -> Result<Vec<ManifestRow>, String> {
    let mut reader = csv::Reader::from_path(path).map_err(|e| {
        format!(
            "{}: cannot read the batch manifest ({e}); run `bodyspace batch` to make it",
            path.display()
        )
    })?;
    reader
        .deserialize()
        .map(|row| {
            row.map_err(|e| {
                format!(
                    "{}: not a `bodyspace batch` manifest ({e}); rerun the batch to rewrite it",
                    path.display()
                )
            })
        })
        .collect()
}

/// Writes `bytes` to `path` atomically: to a temporary file in the same folder, then renamed
/// over `path`, so a killed run never leaves a half-written file under the final name.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let temp: PathBuf = path.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    std::fs::write(&temp, bytes)
        .and_then(|_| std::fs::rename(&temp, path))
        .map_err(|e| {
            let _ = std::fs::remove_file(&temp);
            format!(
                "{}: cannot write ({e}); check the folder is writable and has space",
                path.display()
            )
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(subject: &str, status: Status, reason: &str) -> SubjectRecord {
        SubjectRecord {
            subject: subject.into(),
            status,
            reason: reason.into(),
            rms_mm: status.fitted().then_some(0.95),
            flags: if status == Status::Flagged {
                vec!["high_rms".into(), "fold_overs".into()]
            } else {
                vec![]
            },
            seconds: 1.25,
            resolution: "base".into(),
            scan: format!("/scans/{subject}.ply"),
            landmarks: String::new(),
        }
    }

    #[test]
    fn a_manifest_reads_back_with_quoted_reasons() {
        let dir = std::env::temp_dir().join(format!("bodyspace-manifest-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let records = [
            record("a", Status::Ok, ""),
            record("b", Status::Flagged, "high_rms;fold_overs"),
            record(
                "c",
                Status::Failed,
                "c.ply: header, line 3: \"bad\", expected a number",
            ),
        ];
        let path = dir.join("manifest.csv");
        write_atomically(&path, &manifest_csv(&records).unwrap()).unwrap();
        let rows = read_manifest(&path).unwrap();
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[1].flags, "high_rms;fold_overs");
        assert_eq!(rows[2].status, Status::Failed);
        assert_eq!(rows[2].reason, records[2].reason);
        assert_eq!(rows[2].rms_mm, None);
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.starts_with("subject,status,reason,rms_mm,flags,seconds"));
        // No temporary file is left beside it.
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
