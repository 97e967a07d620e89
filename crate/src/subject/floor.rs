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
