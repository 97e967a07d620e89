//! Which scans `bodyspace batch` aligns: the subjects of a scans folder with their landmark
//! files ([`list_subjects`]), and the K-th of N disjoint shares of them ([`Shard`]).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::str::FromStr;

/// Scan file extensions (each also with `.gz`).
pub const SCAN_EXTENSIONS: [&str; 3] = ["ply", "obj", "stl"];
/// Landmark file extensions, in the order they are looked for.
pub const LANDMARK_EXTENSIONS: [&str; 3] = ["lnd", "csv", "json"];

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

/// The subject name of a scan file (`a.ply.gz` → `a`), or `None` when it is not a scan file.
fn subject_name(path: &Path) -> Option<String> {
    let name = path.file_name()?.to_str()?;
    let lower = name.to_ascii_lowercase();
    let stem_len = SCAN_EXTENSIONS.iter().find_map(|ext| {
        [format!(".{ext}"), format!(".{ext}.gz")]
            .iter()
            .find(|suffix| lower.ends_with(suffix.as_str()))
            .map(|suffix| name.len() - suffix.len())
    })?;
    (stem_len > 0 && !name.starts_with('.')).then(|| name[..stem_len].to_string())
}

/// The landmark file of `subject` in `folders` (searched in order): `<subject>.lnd`, `.csv`,
/// `.json`, then for `scan_ID` the same names of `landmarks_ID`.
fn find_landmark_file(subject: &str, folders: &[&Path]) -> Option<PathBuf> {
    let mut stems = vec![subject.to_string()];
    if let Some(id) = subject.strip_prefix("scan_") {
        stems.push(format!("landmarks_{id}"));
    }
    stems.iter().find_map(|stem| {
        folders.iter().find_map(|dir| {
            LANDMARK_EXTENSIONS
                .iter()
                .map(|ext| dir.join(format!("{stem}.{ext}")))
                .find(|p| p.is_file())
        })
    })
}

/// Every scan in `scans` with its landmark file, sorted by subject name. Two scans with the same
/// subject name are an error (their fits would overwrite each other).
pub fn list_subjects(scans: &Path, landmarks: Option<&Path>) -> Result<Vec<Subject>, String> {
    let entries = std::fs::read_dir(scans).map_err(|e| {
        format!(
            "{}: cannot list the scans folder ({e}); --scans takes a folder of scan files",
            scans.display()
        )
    })?;
    let mut by_name: BTreeMap<String, PathBuf> = BTreeMap::new();
    for entry in entries.flatten() {
        let path = entry.path();
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

    #[test]
    fn subject_names_drop_scan_extensions_only() {
        let name = |s: &str| subject_name(Path::new(s));
        assert_eq!(name("dir/scan_001.ply").as_deref(), Some("scan_001"));
        assert_eq!(name("A.B.PLY.gz").as_deref(), Some("A.B"));
        assert_eq!(name("x.stl").as_deref(), Some("x"));
        assert_eq!(name("x.lnd"), None);
        assert_eq!(name("x.ply.tmp"), None);
        assert_eq!(name(".x.ply"), None);
        assert_eq!(name(".ply"), None);
    }
}
