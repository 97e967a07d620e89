//! A body in any frame brought into the template's, where "up" and the floor of the
//! measurements are defined: fits are written in their scan's frame (CAESAR: z up, millimetres).

use crate::mesh::similarity::similarity;
use nalgebra::Point3;

/// Flat `#V·3` f32 positions of `body` moved rigidly (rotation + translation, no scale: lengths
/// are kept) onto `template` by least squares over all corresponding vertices (Umeyama). Both in
/// template vertex order with the same `#V` and in metres. `None` when the counts differ or the
/// fit fails.
pub fn upright(body: &[Point3<f64>], template: &[Point3<f64>]) -> Option<Vec<f32>> {
    let rigid = similarity(body, template, false)?;
    Some(
        body.iter()
            .flat_map(|p| {
                let q = rigid.apply(p);
                [q.x as f32, q.y as f32, q.z as f32]
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::test_points::stick_body;

    #[test]
    fn a_z_up_body_stands_up() {
        let template = stick_body();
        // (x, y, z) ↦ (x, −z, y) + t, as bodyspace synth writes CAESAR-like scans.
        let body: Vec<Point3<f64>> = template
            .iter()
            .map(|p| Point3::new(p.x + 5.0, -p.z + 1.0, p.y))
            .collect();
        let up = upright(&body, &template).unwrap();
        for (i, p) in template.iter().enumerate() {
            for k in 0..3 {
                assert!((up[3 * i + k] as f64 - p[k]).abs() < 1e-5);
            }
        }
        assert!(upright(&body[..2], &template).is_none());
    }
}
