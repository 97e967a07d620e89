//! [`scan_without_floor`]: the scan the fit is made to, once the landmarks say which way is up —
//! a floor or turntable remnant under the feet taken off (`mesh/floor.rs`), as the landmark
//! estimate takes it off once its frame is known.

use std::borrow::Cow;

use nalgebra::Vector3;

use crate::estimate::{given_landmarks, landmark_rest};
use crate::landmarks::LandmarkSet;
use crate::mesh::floor::{remove_floor, FloorParams, FloorRemoval};
use crate::mesh::similarity::similarity;
use crate::mesh::Mesh;
use crate::template::Template;

/// At least this many CAESAR landmarks say which way is up.
const UP_FROM: usize = 4;

/// `scan` (its frame and units; `to_m`: units → metres) without its floor remnant, and what was
/// removed. Up is the template's +y carried by the similarity of its landmarks at rest onto
/// `landmarks` (the scan's frame and units); with fewer than four CAESAR landmarks the scan
/// stays as it is.
pub fn scan_without_floor<'a>(
    template: &Template,
    scan: &'a Mesh,
    landmarks: &LandmarkSet,
    to_m: f64,
    params: &FloorParams,
) -> (Cow<'a, Mesh>, Option<FloorRemoval>) {
    let placed = given_landmarks(landmarks);
    if placed.len() < UP_FROM {
        return (Cow::Borrowed(scan), None);
    }
    let rest = landmark_rest(template);
    let from: Vec<_> = placed.iter().map(|(i, _)| rest[*i]).collect();
    let to: Vec<_> = placed.iter().map(|(_, p)| *p).collect();
    let Some(frame) = similarity(&from, &to, true).filter(|t| t.scale > 0.0) else {
        return (Cow::Borrowed(scan), None);
    };
    match remove_floor(scan, &(frame.rotation * Vector3::y()), to_m, params) {
        Some((kept, removal)) => (Cow::Owned(kept), Some(removal)),
        None => (Cow::Borrowed(scan), None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::landmarks::Landmark;
    use crate::template::fixture::base_body;
    use nalgebra::Point3;

    /// The template at rest on a floor (every 1 cm, 2–12 cm beside the feet: the vertices below
    /// 3 cm), z up in millimetres, and its landmarks in that frame; the body's vertex count.
    fn on_floor() -> (Template, Mesh, LandmarkSet, usize) {
        let body = base_body();
        let lowest = body.rest.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
        let feet: Vec<[f64; 2]> = body
            .rest
            .iter()
            .filter(|p| p.y < lowest + 0.03)
            .map(|p| [p.x, p.z])
            .collect();
        let beside = |x: f64, z: f64| {
            let d = feet
                .iter()
                .map(|f| ((f[0] - x).powi(2) + (f[1] - z).powi(2)).sqrt())
                .fold(f64::INFINITY, f64::min);
            d > 0.02 && d <= 0.12
        };
        let mm = |p: &Point3<f64>| Point3::new(p.x, -p.z, p.y) * 1000.0;
        let mut positions: Vec<Point3<f64>> = body.rest.iter().map(mm).collect();
        let mut triangles = body.triangles.clone();
        let n = positions.len();
        let cells = 80;
        let mut at = vec![None; (cells + 1) * (cells + 1)];
        for j in 0..=cells {
            for i in 0..=cells {
                let (x, z) = (-0.4 + i as f64 * 0.01, -0.4 + j as f64 * 0.01);
                if beside(x, z) {
                    at[j * (cells + 1) + i] = Some(positions.len() as u32);
                    positions.push(mm(&Point3::new(x, lowest - 0.002, z)));
                }
            }
        }
        for j in 0..cells {
            for i in 0..cells {
                let q = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                    .map(|(a, b)| at[b * (cells + 1) + a]);
                if let [Some(a), Some(b), Some(c), Some(d)] = q {
                    triangles.extend([[a, b, c], [a, c, d]]);
                }
            }
        }
        let landmarks = LandmarkSet {
            landmarks: body
                .template
                .landmark_vertices()
                .iter()
                .map(|(name, v)| Landmark {
                    name: name.clone(),
                    position: mm(&body.rest[*v as usize]),
                })
                .collect(),
            ..LandmarkSet::default()
        };
        (body.template, Mesh::new(positions, triangles), landmarks, n)
    }

    #[test]
    fn the_floor_goes_with_up_from_the_landmarks_and_the_body_stays() {
        let (template, scan, landmarks, body) = on_floor();
        let params = FloorParams::default();
        let (kept, removal) = scan_without_floor(&template, &scan, &landmarks, 0.001, &params);
        let removal = removal.expect("the floor is found");
        // Every floor vertex goes; of the body's, only a few of the coarse template's sole edges
        // (farther than `clear` from any vertex 1.5 cm up), never more than 1 cm above the floor.
        let floor = &scan.positions[body..];
        assert!(kept.positions.iter().all(|p| !floor.contains(p)));
        let gone: Vec<&Point3<f64>> = scan.positions[..body]
            .iter()
            .filter(|p| !kept.positions.contains(p))
            .collect();
        assert_eq!(removal.vertices, floor.len() + gone.len());
        assert!(gone.len() <= 20, "{} body vertices removed", gone.len());
        assert!(gone.iter().all(|p| p.z < floor[0].z + 10.0), "{gone:?}");
        assert!((removal.height - floor[0].z).abs() < 2.0, "{removal:?}");
        // Three landmarks do not say which way is up: the scan stays as it is.
        let three = LandmarkSet {
            landmarks: landmarks.landmarks[..3].to_vec(),
            ..LandmarkSet::default()
        };
        let (same, none) = scan_without_floor(&template, &scan, &three, 0.001, &params);
        assert!(none.is_none() && matches!(same, Cow::Borrowed(_)));
    }
}
