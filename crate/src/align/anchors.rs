//! Landmark anchors for fine alignment: each landmark vertex of the template (the 73 CAESAR and
//! the virtual ones) whose landmark the RBF warp used, held at its warped position — where the
//! warp's exact interpolation put it, on the scan landmark. Their weight is
//! `FineAlignParams::landmark_weight` (0 by default: the paper drops the markers after the warp).

use nalgebra::Point3;

use crate::template::Template;

/// `(vertex, target)` pairs: the landmark vertices of `template` whose names are in `used`,
/// targeted at their `warped` positions (`#V` of `template`, metres, scan frame).
pub fn landmark_anchors(
    template: &Template,
    warped: &[Point3<f64>],
    used: &[String],
) -> Vec<(u32, Point3<f64>)> {
    let mut named: Vec<(String, u32)> = template.landmark_vertices().to_vec();
    named.extend(template.virtual_landmark_vertices().unwrap_or_default());
    named
        .into_iter()
        .filter(|(name, v)| used.iter().any(|u| u == name) && (*v as usize) < warped.len())
        .map(|(_, v)| (v, warped[v as usize]))
        .collect()
}
