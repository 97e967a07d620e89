//! The scan's orientation as a person states it: which scan axis points up (from the feet to the
//! head) and, optionally, which way the body faces. A person sees at once that a body stands on
//! its head; the estimate then tries only the frames that agree ([`orientation_candidates`]).

use nalgebra::{Matrix3, Point3, Vector3};
use serde::{Deserialize, Serialize};

use super::frame::{body_centre, extent_along, frame_candidates, FrameCandidate};

/// A scan direction named by its coordinate axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Axis {
    #[serde(rename = "+x")]
    PlusX,
    #[serde(rename = "-x")]
    MinusX,
    #[serde(rename = "+y")]
    PlusY,
    #[serde(rename = "-y")]
    MinusY,
    #[serde(rename = "+z")]
    PlusZ,
    #[serde(rename = "-z")]
    MinusZ,
}

impl Axis {
    /// The six axes, in the order the app lists them.
    pub const ALL: [Axis; 6] = [
        Axis::PlusX,
        Axis::MinusX,
        Axis::PlusY,
        Axis::MinusY,
        Axis::PlusZ,
        Axis::MinusZ,
    ];

    /// `"+x"`, `"-y"`, … (as `FrameReport::up_axis` writes it).
    pub fn name(self) -> &'static str {
        ["+x", "-x", "+y", "-y", "+z", "-z"][self as usize]
    }

    /// The axis called `name` (`"+x"`, `"-z"`, …; `"x"` is `"+x"`).
    pub fn from_name(name: &str) -> Option<Self> {
        let name = if name.len() == 1 {
            format!("+{name}")
        } else {
            name.to_string()
        };
        Self::ALL.into_iter().find(|a| a.name() == name)
    }

    /// The unit vector.
    pub fn vector(self) -> Vector3<f64> {
        let k = self as usize / 2;
        let sign = if self as usize % 2 == 0 { 1.0 } else { -1.0 };
        Vector3::ith(k, sign)
    }
}

/// Which way is up on the scan and, when known, which way the body faces.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Orientation {
    pub up: Axis,
    /// `None`: the estimate tries both facings across the body's width.
    pub facing: Option<Axis>,
}

impl Orientation {
    /// A check of the person's words: the facing must be across the up axis.
    pub fn validate(&self) -> Result<(), String> {
        match self.facing {
            Some(f) if f.vector().dot(&self.up.vector()).abs() > 0.5 => Err(format!(
                "the facing {} is along the up axis {}; choose an axis across it",
                f.name(),
                self.up.name()
            )),
            _ => Ok(()),
        }
    }
}

/// The frame candidates that agree with `orientation`: template up (+y) along the stated up,
/// facing (+z) along the stated facing, or — without one — along ± the axis across up of the
/// scan's smaller extent (a standing body is wider than it is deep). Scale and translation as
/// [`frame_candidates`] makes them, from the extent along up and the body's centre. `None` when the scan has
/// no extent.
pub fn orientation_candidates(
    template: &[Point3<f64>],
    scan: &[Point3<f64>],
    orientation: &Orientation,
) -> Option<Vec<FrameCandidate>> {
    let up = orientation.up.vector();
    let facings: Vec<Vector3<f64>> = match orientation.facing {
        Some(f) => vec![f.vector()],
        None => {
            // Of the two coordinate axes across up, the one of smaller extent is the depth.
            let across: Vec<Vector3<f64>> = Axis::ALL
                .iter()
                .map(|a| a.vector())
                .filter(|v| v.dot(&up).abs() < 0.5 && v.sum() > 0.0)
                .collect();
            let depth = across
                .iter()
                .min_by(|a, b| extent_along(scan, a).total_cmp(&extent_along(scan, b)))
                .copied()?;
            vec![depth, -depth]
        }
    };
    let template_height = extent_along(template, &Vector3::y());
    let scan_height = extent_along(scan, &up);
    if !(template_height > 0.0 && scan_height > 0.0) {
        return None;
    }
    let scale = scan_height / template_height;
    let template_mid = body_centre(template, &Matrix3::identity(), 0);
    let candidates = facings
        .into_iter()
        .map(|facing| {
            let rotation = Matrix3::from_columns(&[up.cross(&facing), up, facing]);
            let translation = body_centre(scan, &rotation, 0) - scale * (rotation * template_mid);
            FrameCandidate {
                start: crate::mesh::similarity::Similarity {
                    scale,
                    rotation,
                    translation,
                },
            }
        })
        .collect();
    Some(candidates)
}

/// The frame candidates of a scan: from the person's `orientation` when given, else from the
/// principal axes ([`frame_candidates`]).
pub fn candidates_for(
    template: &[Point3<f64>],
    scan: &[Point3<f64>],
    orientation: Option<&Orientation>,
) -> Option<Vec<FrameCandidate>> {
    match orientation {
        Some(o) => orientation_candidates(template, scan, o),
        None => frame_candidates(template, scan),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A box "body": 1.8 tall along `up`, 0.5 wide, 0.25 deep along `depth`.
    fn body(up: Vector3<f64>, depth: Vector3<f64>) -> Vec<Point3<f64>> {
        let side = up.cross(&depth);
        let mut out = Vec::new();
        for i in 0..=10 {
            for j in 0..=36 {
                for k in 0..=5 {
                    let p = side * (i as f64 * 0.05 - 0.25)
                        + up * (j as f64 * 0.05)
                        + depth * (k as f64 * 0.05 - 0.125);
                    out.push(Point3::from(p + Vector3::new(3.0, 4.0, 5.0)));
                }
            }
        }
        out
    }

    #[test]
    fn axes_read_and_name_themselves() {
        for a in Axis::ALL {
            assert_eq!(Axis::from_name(a.name()), Some(a));
            assert!((a.vector().norm() - 1.0).abs() < 1e-12);
        }
        assert_eq!(Axis::from_name("z"), Some(Axis::PlusZ));
        assert_eq!(Axis::from_name("up"), None);
        let along = Orientation {
            up: Axis::PlusZ,
            facing: Some(Axis::MinusZ),
        };
        assert!(along.validate().is_err());
    }

    #[test]
    fn the_stated_up_is_the_templates_up_and_both_facings_are_tried() {
        let template = body(Vector3::y(), Vector3::z());
        let scan: Vec<_> = body(Vector3::z(), -Vector3::x())
            .iter()
            .map(|p| Point3::from(p.coords * 1000.0))
            .collect();
        let orientation = Orientation {
            up: Axis::PlusZ,
            facing: None,
        };
        let candidates = orientation_candidates(&template, &scan, &orientation).unwrap();
        assert_eq!(candidates.len(), 2);
        for c in &candidates {
            let t = c.start;
            assert!((t.rotation * Vector3::y() - Vector3::z()).norm() < 1e-12);
            assert!((t.rotation * Vector3::z()).x.abs() > 0.999);
            assert!((t.rotation.determinant() - 1.0).abs() < 1e-12);
            assert!((t.scale - 1000.0).abs() < 1e-9, "{}", t.scale);
            // The template's top (its box sits at (3, 4, 5) + y·[0, 1.8]) lands on the scan's.
            let top = t.apply(&Point3::new(3.0, 5.8, 5.0));
            assert!((top.z - (5000.0 + 1800.0)).abs() < 1e-6, "{top}");
        }
        let facing = Orientation {
            up: Axis::PlusZ,
            facing: Some(Axis::MinusX),
        };
        let one = orientation_candidates(&template, &scan, &facing).unwrap();
        assert_eq!(one.len(), 1);
        assert!((one[0].start.rotation * Vector3::z() + Vector3::x()).norm() < 1e-12);
    }
}
