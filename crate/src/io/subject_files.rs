//! Which files make one subject of a batch: a scan file names its subject (`a.ply.gz` → `a`),
//! and the subject's landmark file has the same base name (`a.lnd`, `a.csv`, `a.json`, and for
//! `scan_ID` also `landmarks_ID.*`, the synthetic population's names). Meshes that are not scans
//! of a body (the synthetic population's ground truths `surface_ID` and `truth_ID`) make no
//! subject. Pure functions of file names, shared by `bodyspace batch` (files of folders) and the
//! app (files dropped at once).

use std::collections::BTreeMap;

use serde::Serialize;

/// Scan file extensions (each also with `.gz`).
pub const SCAN_EXTENSIONS: [&str; 3] = ["ply", "obj", "stl"];
/// Landmark file extensions, in the order they are looked for.
pub const LANDMARK_EXTENSIONS: [&str; 3] = ["lnd", "csv", "json"];

/// The subject name of a scan file name (`scan_001.ply.gz` → `scan_001`, case of the extension
/// ignored), or `None` when it is not a scan file (or a hidden one, or a mesh that is not a scan
/// by [`is_not_a_scan`]).
pub fn subject_name(file_name: &str) -> Option<&str> {
    let stem_len = mesh_stem_len(file_name)?;
    (stem_len > 0 && !file_name.starts_with('.') && !is_not_a_scan(file_name))
        .then(|| &file_name[..stem_len])
}

/// The length of `file_name` without its mesh extension (by [`SCAN_EXTENSIONS`], each also with
/// `.gz`), or `None` when it has none.
fn mesh_stem_len(file_name: &str) -> Option<usize> {
    let lower = file_name.to_ascii_lowercase();
    SCAN_EXTENSIONS.iter().find_map(|ext| {
        [format!(".{ext}"), format!(".{ext}.gz")]
            .iter()
            .find(|suffix| lower.ends_with(suffix.as_str()))
            .map(|suffix| file_name.len() - suffix.len())
    })
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

/// Name prefixes of meshes that are not scans of a body: the synthetic population's ground
/// truths (`bodyspace synth` writes `surface_ID.ply`, the noiseless body, and `truth_ID.ply`, the
/// template's vertices on it, beside `scan_ID.ply`).
pub const NOT_SCAN_PREFIXES: [&str; 2] = ["surface_", "truth_"];

/// Whether `file_name` is a mesh file (by [`SCAN_EXTENSIONS`]) that is not a scan of a body, by
/// [`NOT_SCAN_PREFIXES`] (case ignored).
pub fn is_not_a_scan(file_name: &str) -> bool {
    let lower = file_name.to_ascii_lowercase();
    mesh_stem_len(file_name).is_some() && NOT_SCAN_PREFIXES.iter().any(|p| lower.starts_with(p))
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

/// A second scan of a subject already listed, left out (its fit would replace the first's).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct DuplicateScan {
    /// Index of the scan left out.
    pub file: usize,
    /// Index of the scan of the same subject that was kept.
    pub kept: usize,
}

/// How files given together make subjects; every index is into the names given, and each index
/// is in at most one of the lists.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct SubjectPairing {
    /// The subjects, sorted by name, each with its scan and landmark file.
    pub subjects: Vec<SubjectFiles>,
    /// Further scans of a listed subject, left out.
    pub duplicates: Vec<DuplicateScan>,
    /// Meshes that are not scans of a body ([`is_not_a_scan`]), left out.
    pub not_scans: Vec<usize>,
    /// Files that belong to no subject: neither a scan nor a landmark file name of one (by
    /// [`landmark_file_names`]). A second landmark file of a listed subject (`a.csv` beside the
    /// `a.lnd` taken) is not in it.
    pub unpaired: Vec<usize>,
}

/// The subjects among `file_names` (files given together, e.g. dropped at once or a folder's),
/// sorted by subject name, each with its landmark file by [`landmark_file_names`] (the first
/// given of a name). Meshes that are not scans ([`is_not_a_scan`]) make no subject.
pub fn pair_subject_files<S: AsRef<str>>(file_names: &[S]) -> SubjectPairing {
    let index: BTreeMap<&str, usize> = file_names
        .iter()
        .enumerate()
        .rev()
        .map(|(i, name)| (name.as_ref(), i))
        .collect();
    let mut subjects: BTreeMap<&str, usize> = BTreeMap::new();
    let mut duplicates = Vec::new();
    let mut not_scans = Vec::new();
    for (i, name) in file_names.iter().enumerate() {
        let name = name.as_ref();
        if is_not_a_scan(name) {
            not_scans.push(i);
            continue;
        }
        let Some(subject) = subject_name(name) else {
            continue;
        };
        match subjects.get(subject) {
            Some(&kept) => duplicates.push(DuplicateScan { file: i, kept }),
            None => {
                subjects.insert(subject, i);
            }
        }
    }
    let mut landmark_names = std::collections::BTreeSet::new();
    let paired: Vec<SubjectFiles> = subjects
        .into_iter()
        .map(|(subject, scan)| {
            let names = landmark_file_names(subject);
            let landmarks = names
                .iter()
                .find_map(|name| index.get(name.as_str()).copied());
            landmark_names.extend(names);
            SubjectFiles {
                subject: subject.to_string(),
                scan,
                landmarks,
            }
        })
        .collect();
    let unpaired = file_names
        .iter()
        .enumerate()
        .filter(|(i, name)| {
            let name = name.as_ref();
            subject_name(name).is_none() && !not_scans.contains(i) && !landmark_names.contains(name)
        })
        .map(|(i, _)| i)
        .collect();
    SubjectPairing {
        subjects: paired,
        duplicates,
        not_scans,
        unpaired,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `(subject, scan, landmarks)` of each subject.
    fn subjects_of(pairing: &SubjectPairing) -> Vec<(&str, usize, Option<usize>)> {
        pairing
            .subjects
            .iter()
            .map(|s| (s.subject.as_str(), s.scan, s.landmarks))
            .collect()
    }

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
        let pairing = pair_subject_files(&names);
        let got = subjects_of(&pairing);
        // `.lnd` is looked for before `.json`; c has no landmark file; the second c is a duplicate.
        assert_eq!(
            got,
            [("b", 0, Some(4)), ("c", 5, None), ("scan_001", 3, Some(1))]
        );
        assert_eq!(pairing.duplicates, [DuplicateScan { file: 7, kept: 5 }]);
        assert_eq!(pairing.unpaired, [6]);
        assert!(pairing.not_scans.is_empty());
    }

    #[test]
    fn ground_truth_meshes_are_not_scans() {
        // A folder `bodyspace synth` wrote: two subjects, not six.
        let names = [
            "landmarks_001.csv",
            "landmarks_001.lnd",
            "scan_001.ply",
            "surface_001.ply",
            "truth_001.ply",
            "scan_002.ply.gz",
            "Surface_002.PLY.gz",
            "truth_002.ply.gz",
            "landmarks_002.lnd",
            "population.json",
        ];
        let pairing = pair_subject_files(&names);
        let got = subjects_of(&pairing);
        assert_eq!(got, [("scan_001", 2, Some(1)), ("scan_002", 5, Some(8))]);
        assert_eq!(pairing.not_scans, [3, 4, 6, 7]);
        // The subject's second landmark file is not unpaired; the population file is.
        assert_eq!(pairing.unpaired, [9]);
        assert!(pairing.duplicates.is_empty());
        assert!(is_not_a_scan("truth_7.obj") && !is_not_a_scan("truth_7.lnd"));
        assert_eq!(subject_name("surface_001.ply"), None);
    }

    #[test]
    fn a_landmark_file_of_a_kept_scan_is_paired_not_unpaired() {
        // The same subject from two folders: one scan kept, and its landmark file with it.
        let names = ["a.ply", "a.lnd", "a.ply", "a.lnd"];
        let pairing = pair_subject_files(&names);
        assert_eq!(pairing.subjects[0].landmarks, Some(1));
        assert_eq!(pairing.duplicates, [DuplicateScan { file: 2, kept: 0 }]);
        assert!(pairing.unpaired.is_empty());
    }
}
