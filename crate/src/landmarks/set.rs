//! A set of named landmark positions as read from a file or placed on a template.

use nalgebra::Point3;

/// One named landmark position.
#[derive(Debug, Clone, PartialEq)]
pub struct Landmark {
    /// Canonical CAESAR name where the name was recognised, else the name as given.
    pub name: String,
    /// Position in the file's (or mesh's) units.
    pub position: Point3<f64>,
}

/// Landmarks in file order. Missing landmarks (CAESAR's −999) are not in `landmarks`; their
/// canonical names are listed in `missing`. Names the reader could not map to a CAESAR name are
/// kept in `landmarks` under their own name and listed in `unknown`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LandmarkSet {
    pub landmarks: Vec<Landmark>,
    /// Canonical names of landmarks the file marks as missing.
    pub missing: Vec<String>,
    /// Names found in the file that are not CAESAR landmarks.
    pub unknown: Vec<String>,
}

impl LandmarkSet {
    /// The position of the landmark called `name`, if present.
    pub fn get(&self, name: &str) -> Option<Point3<f64>> {
        self.landmarks
            .iter()
            .find(|l| l.name == name)
            .map(|l| l.position)
    }

    /// The set with every position multiplied by `factor` (e.g. `Units::scale_to_metres()`).
    pub fn scaled(&self, factor: f64) -> LandmarkSet {
        LandmarkSet {
            landmarks: self
                .landmarks
                .iter()
                .map(|l| Landmark {
                    name: l.name.clone(),
                    position: l.position * factor,
                })
                .collect(),
            missing: self.missing.clone(),
            unknown: self.unknown.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scaled_multiplies_positions_only() {
        let set = LandmarkSet {
            landmarks: vec![Landmark {
                name: "Sellion".into(),
                position: Point3::new(100.0, 1700.0, -20.0),
            }],
            missing: vec!["Crotch".into()],
            unknown: vec![],
        };
        let m = set.scaled(1e-3);
        assert_eq!(m.get("Sellion"), Some(Point3::new(0.1, 1.7, -0.02)));
        assert_eq!(m.missing, set.missing);
    }
}
