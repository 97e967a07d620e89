//! Which files make one subject of a batch: a scan file names its subject (`a.ply.gz` → `a`),
//! and the subject's landmark file has the same base name (`a.lnd`, `a.csv`, `a.json`, and for
//! `scan_ID` also `landmarks_ID.*`, the synthetic population's names). Pure functions of file
//! names, shared by `bodyspace batch` (files of folders) and the app (files dropped at once).

use std::collections::BTreeMap;

use serde::Serialize;

/// Scan file extensions (each also with `.gz`).
pub const SCAN_EXTENSIONS: [&str; 3] = ["ply", "obj", "stl"];
/// Landmark file extensions, in the order they are looked for.
pub const LANDMARK_EXTENSIONS: [&str; 3] = ["lnd", "csv", "json"];

/// The subject name of a scan file name (`scan_001.ply.gz` → `scan_001`, case of the extension
/// ignored), or `None` when it is not a scan file (or a hidden one).
pub fn subject_name(file_name: &str) -> Option<&str> {
    let lower = file_name.to_ascii_lowercase();
    let stem_len = SCAN_EXTENSIONS.iter().find_map(|ext| {
        [format!(".{ext}"), format!(".{ext}.gz")]
            .iter()
            .find(|suffix| lower.ends_with(suffix.as_str()))
            .map(|suffix| file_name.len() - suffix.len())
    })?;
    (stem_len > 0 && !file_name.starts_with('.')).then(|| &file_name[..stem_len])
}

/// The landmark file names of `subject`, in the order they are looked for: `<subject>.lnd`,
/// `.csv`, `.json`, then for `scan_ID` the same names of `landmarks_ID`.
pub fn landmark_file_names(subject: &str) -> Vec<String> {
    let mut stems = vec![subject.to_string()];
    if let Some(id) = subject.strip_prefix("scan_") {
        stems.push(format!("landmarks_{id}"));
    }
    stems
        .iter()
        .flat_map(|stem| {
            LANDMARK_EXTENSIONS
                .iter()
                .map(move |ext| format!("{stem}.{ext}"))
        })
        .collect()
}

/// One subject among files given together.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct SubjectFiles {
    pub subject: String,
    /// Index of its scan in the names given.
    pub scan: usize,
    /// Index of its landmark file, when one was given.
    pub landmarks: Option<usize>,
}

/// The subjects among `file_names` (files given together, e.g. dropped at once or a folder's),
/// sorted by subject name, each with its landmark file by [`landmark_file_names`]. A second scan
/// of the same subject is returned in the second list (by index), not paired: its fit would
/// replace the first's.
pub fn pair_subject_files<S: AsRef<str>>(file_names: &[S]) -> (Vec<SubjectFiles>, Vec<usize>) {
    let index: BTreeMap<&str, usize> = file_names
        .iter()
        .enumerate()
        .rev()
        .map(|(i, name)| (name.as_ref(), i))
        .collect();
    let mut subjects: BTreeMap<&str, usize> = BTreeMap::new();
    let mut duplicates = Vec::new();
    for (i, name) in file_names.iter().enumerate() {
        let Some(subject) = subject_name(name.as_ref()) else {
            continue;
        };
        if subjects.contains_key(subject) {
            duplicates.push(i);
        } else {
            subjects.insert(subject, i);
        }
    }
    let paired = subjects
        .into_iter()
        .map(|(subject, scan)| SubjectFiles {
            subject: subject.to_string(),
            scan,
            landmarks: landmark_file_names(subject)
                .iter()
                .find_map(|name| index.get(name.as_str()).copied()),
        })
        .collect();
    (paired, duplicates)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subject_names_drop_scan_extensions_only() {
        assert_eq!(subject_name("scan_001.ply"), Some("scan_001"));
        assert_eq!(subject_name("A.B.PLY.gz"), Some("A.B"));
        assert_eq!(subject_name("x.stl"), Some("x"));
        assert_eq!(subject_name("x.lnd"), None);
        assert_eq!(subject_name("x.ply.tmp"), None);
        assert_eq!(subject_name(".x.ply"), None);
        assert_eq!(subject_name(".ply"), None);
    }

    #[test]
    fn scans_pair_with_landmarks_of_the_same_base_name() {
        let names = [
            "b.obj",
            "landmarks_001.csv",
            "b.json",
            "scan_001.ply.gz",
            "b.lnd",
            "c.stl",
            "notes.txt",
            "c.ply",
        ];
        let (paired, duplicates) = pair_subject_files(&names);
        let got: Vec<_> = paired
            .iter()
            .map(|s| (s.subject.as_str(), s.scan, s.landmarks))
            .collect();
        // `.lnd` is looked for before `.json`; c has no landmark file; the second c is a duplicate.
        assert_eq!(
            got,
            [("b", 0, Some(4)), ("c", 5, None), ("scan_001", 3, Some(1))]
        );
        assert_eq!(duplicates, [7]);
    }
}
