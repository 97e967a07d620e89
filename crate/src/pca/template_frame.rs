//! A training shape brought into the template's frame (y up, metres, facing +z) before GPA, so a
//! model is built there whatever the frames and units of its fits.
//!
//! Fits come in their scans' frames: CAESAR's z up in millimetres, a y-up scan in metres, a
//! turned one in centimetres. GPA alone aligns every subject to the first one, so a model of
//! z-up fits would lie on its face and one of millimetre fits would be a thousand times too
//! large. Each shape x (#V points, template vertex order) is mapped by
//!
//!   x ↦ R·(u·x) + t
//!
//! where u is its units' factor to metres ([`detect_units`] on its bounding box, the rule every
//! reader uses: never a free scale, which would remove the subject's size) and (R, t) the rigid
//! least-squares fit of u·x onto the template's rest shape (Umeyama, all vertices in
//! correspondence). R is global (SVD), so any orientation is found: y up, z up, −x up, turned
//! about the vertical.

use nalgebra::Point3;

use crate::mesh::bounds::bounding_extent;
use crate::mesh::similarity::Similarity;
use crate::mesh::units::{detect_units, Units};

use super::procrustes_gpa::rigid_align;

/// The map of a shape into the template's frame and the units it was found in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TemplateFrame {
    /// x ↦ s·R·x + t with s = `units.scale_to_metres()`.
    pub transform: Similarity,
    pub units: Units,
}

/// The units of `shape` (its largest bounding-box side by [`detect_units`]) and the rigid fit of
/// the shape in metres onto `rest` (the template's rest shape). Shapes: `shape`, `rest` both #V
/// points in template vertex order; the identity map in metres when they differ in length.
pub fn template_frame(shape: &[Point3<f64>], rest: &[Point3<f64>]) -> TemplateFrame {
    template_frame_in(shape, rest, detect_units(bounding_extent(shape)))
}

/// [`template_frame`] for a shape whose units are known (a fit of a scan whose units were given
/// or detected on the scan itself).
pub fn template_frame_in(
    shape: &[Point3<f64>],
    rest: &[Point3<f64>],
    units: Units,
) -> TemplateFrame {
    let u = units.scale_to_metres();
    let metres: Vec<Point3<f64>> = shape.iter().map(|p| Point3::from(p.coords * u)).collect();
    let rigid = rigid_align(&metres, rest, false);
    TemplateFrame {
        transform: Similarity {
            scale: u,
            rotation: rigid.rotation,
            translation: rigid.translation,
        },
        units,
    }
}

/// `shape` in the template's frame ([`template_frame`]).
pub fn into_template_frame(shape: &[Point3<f64>], rest: &[Point3<f64>]) -> Vec<Point3<f64>> {
    let frame = template_frame(shape, rest);
    frame.transform.apply_all(shape)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::test_points::stick_body;
    use nalgebra::{Rotation3, Vector3};

    #[test]
    fn z_up_millimetres_and_turned_centimetres_come_back_upright_in_metres() {
        let rest = stick_body();
        let turn = Rotation3::from_axis_angle(&Vector3::y_axis(), 2.0);
        for (shape, units) in [
            // (x, y, z) ↦ 1000·(x, −z, y) + t: `bodyspace synth`'s CAESAR frame.
            (
                rest.iter()
                    .map(|p| Point3::new(1e3 * p.x + 40.0, -1e3 * p.z - 7.0, 1e3 * p.y))
                    .collect::<Vec<_>>(),
                Units::Millimetres,
            ),
            (
                rest.iter()
                    .map(|p| Point3::from(100.0 * (turn * p.coords) + Vector3::new(3.0, 1.0, 2.0)))
                    .collect(),
                Units::Centimetres,
            ),
            // −x up, metres.
            (
                rest.iter().map(|p| Point3::new(-p.y, p.x, p.z)).collect(),
                Units::Metres,
            ),
        ] {
            let frame = template_frame(&shape, &rest);
            assert_eq!(frame.units, units);
            for (p, q) in into_template_frame(&shape, &rest).iter().zip(&rest) {
                assert!((p - q).norm() < 1e-9, "{p} vs {q}");
            }
        }
    }
}
