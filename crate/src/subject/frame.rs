//! The body frame: where bodies are compared. A fit is made in its scan's frame and units (CAESAR:
//! z up, millimetres, any origin); models, measurements and percentiles work in the template's
//! frame — upright, y up, metres, facing +z. [`TemplateFrame`] is the motion between the two,
//! recorded with every fit.

use nalgebra::{Matrix3, Point3, Vector3};
use serde::Serialize;

use crate::mesh::similarity::similarity;

/// x_template = R·(s·x_scan) + t: the scan's units to metres (`scale_to_metres` s), then the
/// rigid motion (R, t) that puts the fitted body on the template at rest. No other scale: the
/// body keeps its size.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TemplateFrame {
    pub scale_to_metres: f64,
    /// R, three rows.
    pub rotation: [[f64; 3]; 3],
    /// t, metres.
    pub translation: [f64; 3],
}

impl TemplateFrame {
    /// The frame of a fit: `fitted` (`#V` positions, metres, the scan's frame, template order; at
    /// least the first `rest.len()` are used) moved rigidly onto `rest` (the template's base
    /// vertices at rest) by least squares. `None` when the fit fails (too few vertices, NaN).
    pub fn of_fit(
        fitted: &[Point3<f64>],
        rest: &[Point3<f64>],
        scale_to_metres: f64,
    ) -> Option<Self> {
        let n = rest.len().min(fitted.len());
        let rigid = similarity(&fitted[..n], &rest[..n], false)?;
        let r = rigid.rotation;
        let ok = r.iter().chain(rigid.translation.iter()).all(|v| v.is_finite());
        ok.then(|| Self {
            scale_to_metres,
            rotation: [0, 1, 2].map(|i| [r[(i, 0)], r[(i, 1)], r[(i, 2)]]),
            translation: [rigid.translation.x, rigid.translation.y, rigid.translation.z],
        })
    }

    fn matrix(&self) -> Matrix3<f64> {
        Matrix3::from_fn(|i, j| self.rotation[i][j])
    }

    /// A point of the scan (its frame and units) in the template's frame (metres).
    pub fn to_template(&self, p: &Point3<f64>) -> Point3<f64> {
        self.matrix() * (p * self.scale_to_metres) + Vector3::from(self.translation)
    }

    /// A point in the template's frame (metres) in the scan's frame and units.
    pub fn to_scan(&self, p: &Point3<f64>) -> Point3<f64> {
        let q = self.matrix().transpose() * (p - Vector3::from(self.translation));
        q / self.scale_to_metres
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Rotation3;

    #[test]
    fn a_z_up_millimetre_body_comes_back_upright_in_metres() {
        let rest = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(0.0, 1.7, 0.0),
            Point3::new(0.3, 1.4, 0.0),
            Point3::new(0.0, 1.0, 0.1),
        ];
        // y up → z up (x, y, z) ↦ (x, −z, y), then millimetres and an origin on the floor.
        let turn = Rotation3::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_2);
        let scan_m: Vec<Point3<f64>> = rest
            .iter()
            .map(|p| turn * p + Vector3::new(0.2, -0.4, 0.05))
            .collect();
        let scan_mm: Vec<Point3<f64>> = scan_m.iter().map(|p| p * 1000.0).collect();
        let frame = TemplateFrame::of_fit(&scan_m, &rest, 1e-3).unwrap();
        for (p, r) in scan_mm.iter().zip(&rest) {
            assert!((frame.to_template(p) - r).norm() < 1e-9);
            assert!((frame.to_scan(r) - p).norm() < 1e-6);
        }
    }
}
