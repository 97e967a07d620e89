//! Which CAESAR landmarks a set holds, lacks, and which names it holds that are not CAESAR's.

use serde::Serialize;

use super::caesar::CAESAR_LANDMARKS;
use super::set::LandmarkSet;

/// The landmark coverage of a set.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct LandmarkReport {
    /// Canonical names present, in CAESAR `.lnd` order.
    pub found: Vec<String>,
    /// The other CAESAR landmarks (marked missing in the file or simply absent), in CAESAR order.
    pub missing: Vec<String>,
    /// Names in the file that are not CAESAR landmarks, in file order.
    pub unknown: Vec<String>,
}

/// The report of `set` against the 73 CAESAR landmarks.
pub fn report(set: &LandmarkSet) -> LandmarkReport {
    let (found, missing): (Vec<_>, Vec<_>) = CAESAR_LANDMARKS
        .iter()
        .map(|l| l.name)
        .partition(|name| set.get(name).is_some());
    LandmarkReport {
        found: found.into_iter().map(String::from).collect(),
        missing: missing.into_iter().map(String::from).collect(),
        unknown: set.unknown.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::landmarks::Landmark;
    use nalgebra::Point3;

    #[test]
    fn splits_found_missing_unknown_in_caesar_order() {
        let at = |name: &str| Landmark {
            name: name.to_string(),
            position: Point3::origin(),
        };
        let set = LandmarkSet {
            landmarks: vec![at("Crotch"), at("Nose tip"), at("Sellion")],
            missing: vec!["Rt. Acromion".to_string()],
            unknown: vec!["Nose tip".to_string()],
        };
        let r = report(&set);
        assert_eq!(r.found, ["Sellion", "Crotch"]);
        assert_eq!(r.missing.len(), 71);
        assert_eq!(r.missing[0], "Rt. Infraorbitale");
        assert_eq!(r.unknown, ["Nose tip"]);
    }
}
