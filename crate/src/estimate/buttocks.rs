//! The torso's length from the buttocks. The body's one common scale (the similarity fit's)
//! leaves the torso as long as the template's for the subject's height; real torsos are longer
//! or shorter than that, and nearest points do not see it (the trunk is close to a cylinder), so
//! the hips, the pelvic landmarks and the crotch land centimetres high or low. The crotch itself
//! is rarely scanned (the scanner does not see between the legs); the buttocks are: the height
//! at which the back of the body reaches furthest back below the waist (the gluteal prominence,
//! anthropometry's buttock height). That height on the scan against the template's own, in the
//! fit's frame, sets the torso's stretch along its axis about the neck. The stretch moves the
//! torso's own landmarks; the limbs stay attached where the unstretched torso puts their joints
//! (`segments.rs`).

use nalgebra::{Point3, Vector3};

use super::params::ButtocksParams;
use crate::template::parts::{Part, PartPose};
use crate::template::Template;

/// The height along `up` (unit) above `at` at which `points` (spread over a surface) within
/// `params.across` of the midline through `at` reach furthest against `front` (unit, the body's
/// facing), within `params.window`; `size`: the body's scale (metres per template metre). The
/// back's extent per bin (`params.bin`) smoothed over three bins; `None` when it has no peak
/// standing `params.min_prominence` out of both ends of the window, or the peak is at an end.
pub fn buttock_height(
    points: &[Point3<f64>],
    at: &Point3<f64>,
    up: &Vector3<f64>,
    front: &Vector3<f64>,
    size: f64,
    params: &ButtocksParams,
) -> Option<f64> {
    let across = up.cross(front);
    let (low, bin) = (params.window.0 * size, params.bin * size);
    let bins = ((params.window.1 - params.window.0) / params.bin).round() as usize;
    let mut back: Vec<(f64, usize)> = vec![(f64::NEG_INFINITY, 0); bins];
    for p in points {
        let d = p - at;
        if d.dot(&across).abs() > params.across * size {
            continue;
        }
        let b = ((d.dot(up) - low) / bin).floor();
        if b < 0.0 || b >= bins as f64 {
            continue;
        }
        let cell = &mut back[b as usize];
        cell.0 = cell.0.max(-d.dot(front));
        cell.1 += 1;
    }
    let extent: Vec<Option<f64>> = back
        .iter()
        .map(|&(e, n)| (n >= params.min_points).then_some(e))
        .collect();
    let smooth: Vec<Option<f64>> = (0..bins)
        .map(|i| {
            let near: Vec<f64> = (i.saturating_sub(1)..(i + 2).min(bins))
                .filter_map(|j| extent[j])
                .collect();
            (near.len() >= 2).then(|| near.iter().sum::<f64>() / near.len() as f64)
        })
        .collect();
    let (peak, top) = smooth
        .iter()
        .enumerate()
        .filter_map(|(i, e)| Some((i, (*e)?)))
        .max_by(|a, b| a.1.total_cmp(&b.1))?;
    let first = smooth.iter().find_map(|e| *e)?;
    let last = smooth.iter().rev().find_map(|e| *e)?;
    let inside = peak > 0 && peak + 1 < bins;
    (inside && top - first.max(last) >= params.min_prominence * size)
        .then_some(low + (peak as f64 + 0.5) * bin)
}

/// The midpoint of `template`'s PSIS landmark vertices at rest: where the back's profile is
/// taken from.
pub(crate) fn psis_midpoint(template: &Template) -> Option<Point3<f64>> {
    let at = |name: &str| {
        template
            .landmark_vertex(name)
            .map(|v| template.mesh().positions[v as usize])
    };
    Some(Point3::from(
        (at("Rt. PSIS")?.coords + at("Lt. PSIS")?.coords) / 2.0,
    ))
}

/// Stretches the torso (part 0 of `parts`, its axis down from the neck) so that the template's
/// buttocks (`surface`, points on its surface at rest, about `psis`, the midpoint of its PSIS
/// landmarks at rest) land at the scan's (`scan`, points on its surface, metres), both found by
/// [`buttock_height`] in the frame of the torso's pose. Left as it is when either is not found
/// or the stretch would leave `params.stretch_range`.
pub fn place_buttocks(
    parts: &[Part],
    poses: &mut [PartPose],
    surface: &[Point3<f64>],
    scan: &[Point3<f64>],
    psis: &Point3<f64>,
    params: &ButtocksParams,
) {
    let torso = &parts[0];
    let Some(axis) = torso.axis else { return };
    let pose = poses[0];
    let size = pose.transform.scale;
    let (up, front) = (Vector3::y(), Vector3::z());
    let Some(template) = buttock_height(surface, psis, &up, &front, 1.0, params) else {
        return;
    };
    let at = torso.apply(&pose, psis);
    let rotation = pose.transform.rotation;
    let Some(found) = buttock_height(
        scan,
        &at,
        &(rotation * up),
        &(rotation * front),
        size,
        params,
    ) else {
        return;
    };
    // How far (template metres) the buttocks move up, and their distance down the axis.
    let lift = (found - template * size) / size;
    let depth = (psis + up * template - torso.joint).dot(&axis);
    if depth <= 0.0 {
        return;
    }
    let stretch = pose.stretch - lift / depth;
    if (params.stretch_range.0..=params.stretch_range.1).contains(&stretch) {
        poses[0].stretch = stretch;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::mesh::surface_points::surface_samples;
    use crate::template::fixture::base_body;

    /// Points on the back of a body (facing +z, y up) whose back reaches furthest at `peak`
    /// (m above the origin): a bump of `depth` over a flat back.
    fn back(peak: f64, depth: f64) -> Vec<Point3<f64>> {
        let mut out = Vec::new();
        for i in 0..400 {
            let y = -0.3 + i as f64 * 0.001;
            let z = -0.1 - depth * (-((y - peak) / 0.05).powi(2)).exp();
            for x in [-0.03, -0.01, 0.01, 0.03, 0.08] {
                out.push(Point3::new(x, y, z));
            }
        }
        out
    }

    #[test]
    fn the_buttocks_are_where_the_back_reaches_furthest() {
        let (up, front) = (Vector3::y(), Vector3::z());
        let params = ButtocksParams::default();
        let height = |points: &[Point3<f64>], scale: f64| {
            buttock_height(points, &Point3::origin(), &up, &front, scale, &params)
        };
        let h = height(&back(-0.08, 0.03), 1.0).unwrap();
        assert!((h + 0.08).abs() <= params.bin, "{h}");
        // At twice the size, twice the height.
        let big: Vec<_> = back(-0.08, 0.03).iter().map(|p| p * 2.0).collect();
        let h = height(&big, 2.0).unwrap();
        assert!((h + 0.16).abs() <= 2.0 * params.bin, "{h}");
        // A flat back, or a peak outside the window, gives none.
        assert!(height(&back(-0.08, 0.0), 1.0).is_none());
        assert!(height(&back(0.2, 0.03), 1.0).is_none());
    }

    #[test]
    fn a_shorter_torso_is_found_from_its_buttocks() {
        let body = base_body();
        let surface = surface_samples(&body.rest, &body.triangles, 0.004);
        let psis = psis_midpoint(&body.template).unwrap();
        let parts = body.parts;
        // The template itself: the torso keeps its length.
        let mut poses = vec![PartPose::identity(); parts.len()];
        place_buttocks(
            &parts,
            &mut poses,
            &surface,
            &surface,
            &psis,
            &ButtocksParams::default(),
        );
        assert_eq!(poses[0].stretch, 1.0);
        // A scan whose body below the neck is 6 % shorter.
        let torso = &parts[0];
        let scan: Vec<_> = surface.iter().map(|p| torso.stretched(p, 0.94)).collect();
        place_buttocks(
            &parts,
            &mut poses,
            &surface,
            &scan,
            &psis,
            &ButtocksParams::default(),
        );
        assert!(
            (poses[0].stretch - 0.94).abs() < 0.015,
            "{}",
            poses[0].stretch
        );
    }
}
