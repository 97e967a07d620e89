//! ISO 8559-1's neck base girth: the tape laid round the base of the neck over the Cervicale,
//! the side neck points and the front neck point (the Suprasternale, at the jugular notch).
//!
//! The Cervicale and the front neck point are bony landmarks; the side neck points, where the
//! neck's side meets the shoulder's top, are not on the template and are found on the surface.
//! The Cervicale sits at the neck's base at the back, the front neck point well below it (on the
//! template 8.6 cm), and the side neck points above the plane through both (that plane runs over
//! the trapezius and the clavicles at the sides, docs/measurements.md): the standard's tape is not
//! planar. It is taken in two parts:
//!
//! * behind, the section of the body by the plane through the Cervicale c perpendicular to the
//!   neck's axis a (from m = (c + s)/2 to the Tragions' midpoint), around the loop that encloses
//!   the axis — the neck at its base, as the neck girth is taken higher up —: its convex hull
//!   (the tape over the Cervicale's bump) from one side neck point through the back to the other;
//!   the side neck points are the hull's corners farthest out along the lateral axis
//!   ℓ = e_up × (c − s) on either side;
//! * in front, straight from each side neck point down to the front neck point s, as a tape held
//!   at the sides and drawn into the notch spans the front of the neck.
//!
//! girth = (length of the hull from one side neck point round the back to the other)
//!       + |l − s| + |r − s|.

use super::section::{plane_section, Plane};
use super::tape::{tape, LoopChoice};
use super::vec3::{cross, distance, dot, sub};

/// The neck base tape: its length (m) and its path, a closed 3-D polyline (the back's hull
/// corners from one side neck point to the other, then the front neck point).
#[derive(Debug, Clone, PartialEq)]
pub struct NeckBaseTape {
    pub girth: f64,
    pub path: Vec<[f64; 3]>,
}

/// The neck base tape (module doc) of the body at flat `#V·3` `positions`, cut from the triangles
/// `region` (indices into `triangles`), over `cervicale` and `front` (the front neck point), with
/// `ears` (the Tragions' midpoint) the neck axis's top; `up_axis` 0, 1 or 2. `None` when the
/// neck axis or the back–front line has no length, or the plane finds no loop.
pub fn neck_base_tape(
    positions: &[f32],
    triangles: &[[u32; 3]],
    region: &[u32],
    cervicale: [f64; 3],
    front: [f64; 3],
    ears: [f64; 3],
    up_axis: usize,
) -> Option<NeckBaseTape> {
    let m = [0, 1, 2].map(|k| (cervicale[k] + front[k]) / 2.0);
    let axis = sub(ears, m);
    let plane = Plane::new(cervicale, axis)?;
    // The axis's point in the plane: m + t·a with (m + t·a − c)·a = 0.
    let t = dot(sub(cervicale, m), axis) / dot(axis, axis);
    let centre = [0, 1, 2].map(|k| m[k] + t * axis[k]);
    let loops = plane_section(positions, triangles, region, &plane);
    let hull = tape(&loops, LoopChoice::Around(plane.to_plane(centre)))?.hull;
    let backward = sub(cervicale, front);
    let mut up = [0.0; 3];
    up[up_axis] = 1.0;
    // ℓ = e_up × (c − s).
    let lateral = cross(up, backward);
    if dot(lateral, lateral) <= 0.0 {
        return None;
    }
    let corners: Vec<[f64; 3]> = hull.iter().map(|&q| plane.from_plane(q)).collect();
    let along = |p: [f64; 3]| dot(sub(p, m), lateral);
    let n = corners.len();
    let by_along = |a: &usize, b: &usize| along(corners[*a]).total_cmp(&along(corners[*b]));
    let first = (0..n).min_by(by_along)?;
    let last = (0..n).max_by(by_along)?;
    if first == last {
        return None;
    }
    // The hull's two chains between the side neck points; the back one holds the corner nearest
    // the Cervicale.
    let chain = |from: usize, to: usize| {
        let mut c = vec![from];
        let mut i = from;
        while i != to {
            i = (i + 1) % n;
            c.push(i);
        }
        c
    };
    let nearest = (0..n).min_by(|&a, &b| {
        distance(corners[a], cervicale).total_cmp(&distance(corners[b], cervicale))
    })?;
    let (one, other) = (chain(first, last), chain(last, first));
    let back = if other[1..other.len() - 1].contains(&nearest) {
        other
    } else {
        one
    };
    let mut path: Vec<[f64; 3]> = back.iter().map(|&i| corners[i]).collect();
    let length: f64 = path.windows(2).map(|w| distance(w[0], w[1])).sum();
    let girth = length + distance(path[0], front) + distance(path[path.len() - 1], front);
    path.push(front);
    Some(NeckBaseTape { girth, path })
}
