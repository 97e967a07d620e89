//! The body frame of a fit, as its report records it. A fit is made in its scan's frame and units
//! (CAESAR: z up, millimetres, any origin); models, measurements and percentiles work in the
//! template's frame — upright, y up, metres, facing +z. The map between the two is the shape
//! model's own rule ([`template_frame_in`]: the units' factor, then the rigid fit onto the
//! template at rest); [`ToTemplate`] records it with every fit.

use nalgebra::{Point3, Vector3};
use serde::Serialize;

use crate::mesh::units::Units;
use crate::pca::template_frame::{template_frame_in, TemplateFrame};

/// x_template = R·(s·x_scan) + t: the scan's units to metres (`scale_to_metres` s), then the
/// rigid motion (R, t) that puts the fitted body on the template at rest. No other scale: the
/// body keeps its size.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ToTemplate {
    pub scale_to_metres: f64,
    /// R, three rows.
    pub rotation: [[f64; 3]; 3],
    /// t, metres.
    pub translation: [f64; 3],
}

impl ToTemplate {
    /// The frame of a fit: `fitted` (`#V` positions in the scan's frame and `units`, template
    /// order; the first `rest.len()` are used) onto `rest` (the template's base vertices at rest).
    pub fn of_fit(fitted: &[Point3<f64>], rest: &[Point3<f64>], units: Units) -> Self {
        let n = rest.len().min(fitted.len());
        Self::from(template_frame_in(&fitted[..n], &rest[..n], units))
    }

    /// A point of the scan (its frame and units) in the template's frame (metres).
    pub fn to_template(&self, p: &Point3<f64>) -> Point3<f64> {
        let r = nalgebra::Matrix3::from_fn(|i, j| self.rotation[i][j]);
        r * (p * self.scale_to_metres) + Vector3::from(self.translation)
    }
}

impl From<TemplateFrame> for ToTemplate {
    fn from(frame: TemplateFrame) -> Self {
        let (r, t) = (frame.transform.rotation, frame.transform.translation);
        Self {
            scale_to_metres: frame.transform.scale,
            rotation: [0, 1, 2].map(|i| [r[(i, 0)], r[(i, 1)], r[(i, 2)]]),
            translation: [t.x, t.y, t.z],
        }
    }
}
