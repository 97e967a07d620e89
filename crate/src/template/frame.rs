//! The template frame: metres, y up, feet on y = 0, subject facing +z.

use nalgebra::{Point3, Vector3};

/// Maps MakeHuman model coordinates (decimetres, y up, facing +z, origin near the hips) into the
/// template frame: `p' = scale · p + translation`, with `scale = 0.1` (dm → m) and a translation
/// that only lifts the body so that its lowest skin vertex sits on y = 0. No rotation is needed:
/// MakeHuman already has y up and the subject facing +z, so the subject's right side is x < 0.
///
/// Offsets (morph-target deltas, displacements) transform with the scale only: see
/// [`FrameTransform::apply_offset`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameTransform {
    /// Uniform scale (0.1: decimetres to metres).
    pub scale: f64,
    /// Translation applied after scaling, in metres.
    pub translation: Vector3<f64>,
}

/// MakeHuman's JSON models are in decimetres.
pub const MAKEHUMAN_TO_METRES: f64 = 0.1;

impl FrameTransform {
    /// The transform that scales to metres and lifts the point set so its minimum y is 0.
    pub fn feet_on_floor(points_model: &[Point3<f64>]) -> Self {
        let min_y = points_model
            .iter()
            .map(|p| p.y)
            .fold(f64::INFINITY, f64::min);
        let min_y = if min_y.is_finite() { min_y } else { 0.0 };
        Self {
            scale: MAKEHUMAN_TO_METRES,
            translation: Vector3::new(0.0, -min_y * MAKEHUMAN_TO_METRES, 0.0),
        }
    }

    /// A model-space point into the template frame.
    pub fn apply_point(&self, p: &Point3<f64>) -> Point3<f64> {
        Point3::from(p.coords * self.scale + self.translation)
    }

    /// A model-space offset (e.g. a morph-target delta) into the template frame: scale only.
    pub fn apply_offset(&self, d: &Vector3<f64>) -> Vector3<f64> {
        d * self.scale
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lifts_to_floor_and_scales() {
        let pts = [Point3::new(1.0, -8.0, 0.0), Point3::new(0.0, 8.0, 2.0)];
        let f = FrameTransform::feet_on_floor(&pts);
        let a = f.apply_point(&pts[0]);
        assert!((a.y).abs() < 1e-12 && (a.x - 0.1).abs() < 1e-12);
        let b = f.apply_point(&pts[1]);
        assert!((b.y - 1.6).abs() < 1e-12 && (b.z - 0.2).abs() < 1e-12);
        let d = f.apply_offset(&Vector3::new(0.0, 10.0, 0.0));
        assert!((d.y - 1.0).abs() < 1e-12);
    }
}
