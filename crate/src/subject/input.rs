//! What one subject is made of: the scan in its own frame and units, and the landmarks given with
//! it. [`read_subject`] reads both from file bytes with the core's readers and applies the one
//! units rule: the scan's units are detected from the body's extent unless given, and a landmark
//! file is in the units its format fixes (`.lnd`: millimetres, [`landmark_file_units`]), else in
//! the scan's.

use crate::align::AlignObserver;
use crate::estimate::{
    estimate_landmarks, EstimateInput, EstimateParams, LandmarkEstimate, Orientation,
};
use crate::io::{landmark_file_units, read_landmarks, read_scan};
use crate::landmarks::LandmarkSet;
use crate::mesh::bounding_extent;
use crate::mesh::units::{detect_units, Units};
use crate::mesh::Mesh;
use crate::template::Template;

use super::error::SubjectError;

/// Landmarks given with a scan (read from a file, or placed by a person).
#[derive(Debug, Clone, PartialEq)]
pub struct GivenLandmarks {
    /// In `units`, or in the scan's units when the format fixes none.
    pub set: LandmarkSet,
    /// The units the file's format fixes (`.lnd`: millimetres), else `None`.
    pub units: Option<Units>,
    /// The file's name (for reports and messages); empty for landmarks placed by hand.
    pub file: String,
}

/// One subject: the scan and what came with it.
#[derive(Debug, Clone)]
pub struct SubjectInput {
    /// The scan's file name (for messages).
    pub name: String,
    /// The scan, in its own frame and units.
    pub scan: Mesh,
    /// The scan's units; `None` detects them from the body's extent ([`detect_units`]).
    pub units: Option<Units>,
    /// Landmarks given with the scan, if any.
    pub given: Option<GivenLandmarks>,
}

impl SubjectInput {
    /// The scan's units (as given or detected) and whether they were detected.
    pub fn scan_units(&self) -> (Units, bool) {
        match self.units {
            Some(units) => (units, false),
            None => (detect_units(bounding_extent(&self.scan.positions)), true),
        }
    }

    /// The given landmarks in the scan's frame and units (empty when none were given).
    pub fn given_in_scan_units(&self) -> LandmarkSet {
        let Some(given) = &self.given else {
            return LandmarkSet::default();
        };
        match given.units {
            Some(units) => {
                let (scan_units, _) = self.scan_units();
                given
                    .set
                    .scaled(units.scale_to_metres() / scan_units.scale_to_metres())
            }
            None => given.set.clone(),
        }
    }

    /// The core's landmark estimate on this scan with its default parameters, keeping `given`
    /// (the scan's frame and units) as it is, in the frame a person stated (`orientation`) or
    /// else the one it finds. It reports to `observer` (a `Break` cancels).
    pub fn estimate_landmarks(
        &self,
        template: &Template,
        given: &LandmarkSet,
        orientation: Option<Orientation>,
        observer: &mut dyn AlignObserver,
    ) -> Result<LandmarkEstimate, SubjectError> {
        let input = EstimateInput {
            template,
            scan: &self.scan,
            given,
            units: Some(self.scan_units().0),
            orientation,
        };
        estimate_landmarks(&input, &EstimateParams::default(), observer).map_err(|e| {
            SubjectError::Estimate {
                scan: self.name.clone(),
                message: e.to_string(),
            }
        })
    }
}

/// Reads a subject from its files: `scan` (bytes, file name: PLY, OBJ or STL, optionally
/// gzip-compressed) and, when there is one, its landmark file (CSV, CAESAR `.lnd` or JSON).
/// `units` overrides the scan's detected units.
pub fn read_subject(
    scan: (&[u8], &str),
    landmarks: Option<(&[u8], &str)>,
    units: Option<Units>,
) -> Result<SubjectInput, SubjectError> {
    let mesh = read_scan(scan.0, scan.1)?;
    let given = landmarks
        .map(|(bytes, name)| {
            Ok::<_, SubjectError>(GivenLandmarks {
                set: read_landmarks(bytes, name)?,
                units: landmark_file_units(name),
                file: name.to_string(),
            })
        })
        .transpose()?;
    Ok(SubjectInput {
        name: scan.1.to_string(),
        scan: mesh,
        units,
        given,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::landmarks::Landmark;
    use nalgebra::Point3;

    fn body(scale: f64) -> Mesh {
        let p = |x: f64, y: f64, z: f64| Point3::new(x * scale, y * scale, z * scale);
        Mesh::new(
            vec![p(0.0, 0.0, 0.0), p(0.4, 0.0, 0.0), p(0.0, 1.7, 0.2)],
            vec![[0, 1, 2]],
        )
    }

    fn given(units: Option<Units>, value: f64) -> GivenLandmarks {
        GivenLandmarks {
            set: LandmarkSet {
                landmarks: vec![Landmark {
                    name: "Sellion".into(),
                    position: Point3::new(value, 0.0, 0.0),
                }],
                ..LandmarkSet::default()
            },
            units,
            file: "a".into(),
        }
    }

    #[test]
    fn an_lnd_beside_a_metres_scan_is_read_in_millimetres() {
        let input = SubjectInput {
            name: "s".into(),
            scan: body(1.0),
            units: None,
            given: Some(given(Some(Units::Millimetres), 1500.0)),
        };
        assert_eq!(input.scan_units(), (Units::Metres, true));
        let set = input.given_in_scan_units();
        assert!((set.landmarks[0].position.x - 1.5).abs() < 1e-12);
    }

    #[test]
    fn a_csv_follows_the_scan_whatever_its_units() {
        for (scale, units) in [(1.0, Units::Metres), (1000.0, Units::Millimetres)] {
            let input = SubjectInput {
                name: "s".into(),
                scan: body(scale),
                units: None,
                given: Some(given(None, 1.5 * scale)),
            };
            assert_eq!(input.scan_units().0, units);
            assert_eq!(
                input.given_in_scan_units().landmarks[0].position.x,
                1.5 * scale
            );
        }
    }

    #[test]
    fn units_given_override_the_detected_ones() {
        let input = SubjectInput {
            name: "s".into(),
            scan: body(100.0),
            units: Some(Units::Millimetres),
            given: Some(given(Some(Units::Millimetres), 1500.0)),
        };
        assert_eq!(input.scan_units(), (Units::Millimetres, false));
        assert_eq!(input.given_in_scan_units().landmarks[0].position.x, 1500.0);
    }
}
