//! The CAESAR landmarks as points in CAESAR order, on both sides of the estimate and the checks:
//! the template's landmark vertices at rest, and the given ones of a landmark set.

use nalgebra::Point3;

use crate::landmarks::{LandmarkSet, CAESAR_LANDMARKS};
use crate::template::Template;

/// The template's landmark vertices at rest, CAESAR order: what [`super::steps::flag_given`]
/// and [`super::check`] predict the given landmarks from (`template` at base resolution, as the
/// estimate fits it).
pub fn landmark_rest(template: &Template) -> Vec<Point3<f64>> {
    let rest = &template.mesh().positions;
    template
        .landmark_vertices()
        .iter()
        .map(|(_, v)| rest[*v as usize])
        .collect()
}

/// The given landmarks that are CAESAR landmarks, as (CAESAR index, position), first of each
/// name; positions that are not finite are left out.
pub fn given_landmarks(set: &LandmarkSet) -> Vec<(usize, Point3<f64>)> {
    let mut out: Vec<(usize, Point3<f64>)> = Vec::new();
    for l in &set.landmarks {
        let Some(i) = CAESAR_LANDMARKS.iter().position(|c| c.name == l.name) else {
            continue;
        };
        if l.position.coords.iter().all(|c| c.is_finite()) && !out.iter().any(|(j, _)| *j == i) {
            out.push((i, l.position));
        }
    }
    out
}
