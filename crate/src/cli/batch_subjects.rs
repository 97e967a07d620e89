//! Which scans `bodyspace batch` aligns: the subjects of a scans folder with their landmark
//! files ([`list_subjects`]), and the K-th of N disjoint shares of them ([`Shard`]).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use crate::io::subject_files;

/// The K-th (1-based) of N shares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub k: usize,
    pub n: usize,
}

impl FromStr for Shard {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let bad = || format!("--shard {s}: expected K/N with 1 ≤ K ≤ N, e.g. 2/8");
        let (k, n) = s.split_once('/').ok_or_else(bad)?;
        let (k, n) = (
            k.trim().parse::<usize>().map_err(|_| bad())?,
            n.trim().parse::<usize>().map_err(|_| bad())?,
        );
        if k == 0 || k > n {
            return Err(bad());
        }
        Ok(Self { k, n })
    }
}

impl Shard {
    /// Whether the subject at `index` of the sorted list belongs to this share.
    pub fn takes(&self, index: usize) -> bool {
        index % self.n == self.k - 1
    }
}

/// One scan to align.
#[derive(Debug, Clone, PartialEq)]
pub struct Subject {
    pub name: String,
    pub scan: PathBuf,
    /// Its landmark file, when one was found.
    pub landmarks: Option<PathBuf>,
}

/// The subject name of a scan file path, or `None` when it is not a scan file.
fn subject_name(path: &Path) -> Option<String> {
    subject_files::subject_name(path.file_name()?.to_str()?).map(str::to_string)
}

/// The landmark file of `subject` in `folders`, by [`subject_files::landmark_file_names`]: each
/// base name in all folders (in order) before the next base name.
fn find_landmark_file(subject: &str, folders: &[&Path]) -> Option<PathBuf> {
    let names = subject_files::landmark_file_names(subject);
    names
        .chunks(subject_files::LANDMARK_EXTENSIONS.len())
        .find_map(|same_stem| {
            folders.iter().find_map(|dir| {
                same_stem
                    .iter()
                    .map(|name| dir.join(name))
                    .find(|p| p.is_file())
            })
        })
}

/// Every scan in `scans` with its landmark file, sorted by subject name. Two scans with the same
/// subject name are an error (their fits would overwrite each other). Meshes that are not scans
/// of a body ([`subject_files::is_not_a_scan`], the pairing rule the app uses too) are left out,
/// and a line on standard error says how many.
pub fn list_subjects(scans: &Path, landmarks: Option<&Path>) -> Result<Vec<Subject>, String> {
    let entries = std::fs::read_dir(scans).map_err(|e| {
        format!(
            "{}: cannot list the scans folder ({e}); --scans takes a folder of scan files",
            scans.display()
        )
    })?;
    let mut by_name: BTreeMap<String, PathBuf> = BTreeMap::new();
    let mut not_scans = 0;
    for entry in entries.flatten() {
        let path = entry.path();
        let file_name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if path.is_file() && subject_files::is_not_a_scan(file_name) {
            not_scans += 1;
            continue;
        }
        let Some(name) = subject_name(&path).filter(|_| path.is_file()) else {
            continue;
        };
        if let Some(other) = by_name.insert(name.clone(), path.clone()) {
            return Err(format!(
                "{} and {}: two scans of subject {name}; rename one (a subject's fit is fits/{name}.ply)",
                other.display(),
                path.display()
            ));
        }
    }
    if not_scans > 0 {
        eprintln!(
            "{}: left out {not_scans} meshes that are not scans of a body ({})",
            scans.display(),
            subject_files::NOT_SCAN_PREFIXES
                .map(|p| format!("{p}*"))
                .join(", ")
        );
    }
    let folders: Vec<&Path> = landmarks.into_iter().chain([scans]).collect();
    Ok(by_name
        .into_iter()
        .map(|(name, scan)| Subject {
            landmarks: find_landmark_file(&name, &folders),
            name,
            scan,
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_synth_folder_lists_its_scans_only() {
        let dir =
            std::env::temp_dir().join(format!("bodyspace-batch-subjects-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for name in [
            "scan_001.ply",
            "surface_001.ply",
            "truth_001.ply",
            "landmarks_001.lnd",
            "scan_002.ply",
        ] {
            std::fs::write(dir.join(name), b"").unwrap();
        }
        let listed = list_subjects(&dir, None).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let names: Vec<_> = listed.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["scan_001", "scan_002"]);
        assert_eq!(
            listed[0]
                .landmarks
                .as_ref()
                .and_then(|p| p.file_name())
                .and_then(|n| n.to_str()),
            Some("landmarks_001.lnd")
        );
    }

    #[test]
    fn shards_split_the_sorted_list_disjointly() {
        let shards: Vec<Shard> = ["1/3", "2/3", "3/3"]
            .iter()
            .map(|s| s.parse().unwrap())
            .collect();
        for i in 0..10 {
            assert_eq!(shards.iter().filter(|s| s.takes(i)).count(), 1, "{i}");
        }
        assert!(shards[1].takes(4));
        for bad in ["0/3", "4/3", "3", "a/b", "1/0"] {
            assert!(bad.parse::<Shard>().is_err(), "{bad}");
        }
    }
}
