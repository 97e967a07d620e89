//! Body measurements on a mesh in template vertex order: stature, chest/waist/hip girths by
//! horizontal plane sections, arm length and inseam from landmark vertices.
//!
//! Girth, like a tape measure: the mesh (restricted to the caller's triangles, normally the
//! torso and leg segments of [`girth_triangles`] so arms are not crossed) is cut by the plane
//! "up = h"; the cut segments are chained into loops through the mesh edges they cross; the loop
//! enclosing the largest area is the body's, and its girth is the perimeter of its convex hull in
//! the plane (a tape spans concavities such as the cleft between the breasts). The raw loop
//! length is reported too.

use super::error::PcaError;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// Template vertices that define the measurement levels and paths (CAESAR landmark vertices of
/// the template, chosen by the template module).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct MeasureLandmarks {
    /// The chest plane passes through the mean height of these (e.g. both Thelions).
    pub chest: Vec<u32>,
    /// Waist plane (e.g. both 10th Ribs, or "Waist, Preferred, Post.").
    pub waist: Vec<u32>,
    /// Hip plane (e.g. both Trochanterions), raised to at least
    /// [`MeasureParams::hip_above_crotch`] above the crotch so it surrounds both legs.
    pub hip: Vec<u32>,
    /// Arm path, summed segment by segment (e.g. Acromion → Radiale → Radial Styloid).
    pub arm: Vec<u32>,
    /// Crotch vertex: inseam is its height above the floor (lowest vertex).
    pub crotch: u32,
}

impl MeasureLandmarks {
    /// From the template's (canonical CAESAR name, vertex) list: chest at both
    /// Thelion/Bustpoints, waist at both 10th Ribs, hip at both Trochanterions, right arm
    /// Acromion → Radiale → Radial Styloid, Crotch. Names a missing landmark on failure.
    pub fn from_named(landmarks: &[(String, u32)]) -> Result<Self, PcaError> {
        let find = |name: &str| {
            landmarks
                .iter()
                .find(|(n, _)| n == name)
                .map(|(_, v)| *v)
                .ok_or_else(|| PcaError::Measurement {
                    what: "landmarks".into(),
                    reason: format!("the template has no landmark {name}"),
                })
        };
        Ok(Self {
            chest: vec![
                find("Rt. Thelion/Bustpoint")?,
                find("Lt. Thelion/Bustpoint")?,
            ],
            waist: vec![find("Rt. 10th Rib")?, find("Lt. 10th Rib")?],
            hip: vec![find("Rt. Trochanterion")?, find("Lt. Trochanterion")?],
            arm: vec![
                find("Rt. Acromion")?,
                find("Rt. Radiale")?,
                find("Rt. Radial Styloid")?,
            ],
            crotch: find("Crotch")?,
        })
    }
}

/// Parameters of [`measure`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MeasureParams {
    /// Index of the up axis (0 = x, 1 = y, 2 = z); default 1 (y up, as in three.js and MakeHuman).
    pub up_axis: usize,
    /// Least height of the hip plane above the crotch vertex (the template's Trochanterions sit
    /// within millimetres of the crotch, where a plane may pass between the legs); default 0.02 m.
    pub hip_above_crotch: f64,
}

impl Default for MeasureParams {
    fn default() -> Self {
        Self {
            up_axis: 1,
            hip_above_crotch: 0.02,
        }
    }
}

/// One plane section: convex-hull perimeter (the girth) and the loop's own length.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Girth {
    pub girth: f64,
    pub loop_length: f64,
    pub height: f64,
}

/// All measurements, in model units (metres).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Measurements {
    pub stature: f64,
    pub chest: Option<Girth>,
    pub waist: Option<Girth>,
    pub hip: Option<Girth>,
    pub arm_length: f64,
    pub inseam: f64,
}

fn vertex(positions: &[f32], v: u32) -> Option<[f64; 3]> {
    let i = 3 * v as usize;
    positions
        .get(i..i + 3)
        .map(|p| [p[0] as f64, p[1] as f64, p[2] as f64])
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// The loops where the plane up = `height` cuts `section_triangles` (indices into
/// `triangles`), each as points in the plane's two horizontal coordinates, and whether closed.
pub fn plane_section(
    positions: &[f32],
    triangles: &[[u32; 3]],
    section_triangles: &[u32],
    up_axis: usize,
    height: f64,
) -> Vec<(Vec<[f64; 2]>, bool)> {
    let (ua, ub) = ((up_axis + 1) % 3, (up_axis + 2) % 3);
    let mut points: HashMap<(u32, u32), [f64; 2]> = HashMap::new();
    let mut links: HashMap<(u32, u32), Vec<(u32, u32)>> = HashMap::new();
    for &t in section_triangles {
        let Some(tri) = triangles.get(t as usize) else {
            continue;
        };
        let (Some(p0), Some(p1), Some(p2)) = (
            vertex(positions, tri[0]),
            vertex(positions, tri[1]),
            vertex(positions, tri[2]),
        ) else {
            continue;
        };
        let p = [p0, p1, p2];
        // A vertex exactly on the plane counts as above it, so every crossing is a proper edge cut.
        let d = p.map(|q| q[up_axis] - height);
        let above = d.map(|x| x >= 0.0);
        // Most triangles lie wholly above or below: nothing to allocate for them.
        if above[0] == above[1] && above[1] == above[2] {
            continue;
        }
        let mut cut = Vec::with_capacity(2);
        for (a, b) in [(0, 1), (1, 2), (2, 0)] {
            if above[a] != above[b] {
                let f = d[a] / (d[a] - d[b]);
                let key = (tri[a].min(tri[b]), tri[a].max(tri[b]));
                let at = |k: usize| p[a][k] + f * (p[b][k] - p[a][k]);
                points.insert(key, [at(ua), at(ub)]);
                cut.push(key);
            }
        }
        if let [a, b] = cut[..] {
            links.entry(a).or_default().push(b);
            links.entry(b).or_default().push(a);
        }
    }
    let mut visited: HashMap<(u32, u32), bool> = HashMap::new();
    let mut starts: Vec<(u32, u32)> = links.keys().copied().collect();
    // Open chains must be walked from an end; sorting keeps the result deterministic.
    starts.sort_by_key(|k| (links[k].len() != 1, *k));
    let mut loops = Vec::new();
    for start in starts {
        if visited.contains_key(&start) {
            continue;
        }
        let mut chain = vec![points[&start]];
        visited.insert(start, true);
        let mut current = start;
        let closed;
        loop {
            let next = links[&current]
                .iter()
                .find(|k| !visited.contains_key(k))
                .copied();
            match next {
                Some(k) => {
                    visited.insert(k, true);
                    chain.push(points[&k]);
                    current = k;
                }
                None => {
                    closed = chain.len() > 2 && links[&current].contains(&start);
                    break;
                }
            }
        }
        loops.push((chain, closed));
    }
    loops
}

fn polygon_area(points: &[[f64; 2]]) -> f64 {
    let n = points.len();
    (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
        .abs()
        / 2.0
}

fn perimeter(points: &[[f64; 2]], closed: bool) -> f64 {
    let n = points.len();
    let edges = if closed { n } else { n.saturating_sub(1) };
    (0..edges)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
        })
        .sum()
}

/// Convex hull (Andrew's monotone chain), counter-clockwise.
pub fn convex_hull(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut p = points.to_vec();
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut hull: Vec<[f64; 2]> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &[f64; 2]>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    hull
}

/// Girth at `height`: the closed section loop enclosing the largest area.
pub fn girth_at(
    positions: &[f32],
    triangles: &[[u32; 3]],
    section_triangles: &[u32],
    up_axis: usize,
    height: f64,
) -> Option<Girth> {
    plane_section(positions, triangles, section_triangles, up_axis, height)
        .into_iter()
        .filter(|(_, closed)| *closed)
        .max_by(|a, b| polygon_area(&a.0).total_cmp(&polygon_area(&b.0)))
        .map(|(points, _)| Girth {
            girth: perimeter(&convex_hull(&points), true),
            loop_length: perimeter(&points, true),
            height,
        })
}

/// Triangles whose three vertices each belong to one of `segments` (weight > 0). For girths:
/// torso + both legs, so arms hanging beside the body are never crossed while the hip section
/// (which runs through the torso/leg overlap band) stays closed.
pub fn triangles_in_segments(
    triangles: &[[u32; 3]],
    weights: &[[f32; 6]],
    segments: &[usize],
) -> Vec<u32> {
    let inside = |v: u32| {
        weights
            .get(v as usize)
            .is_some_and(|w| segments.iter().any(|&s| w.get(s).is_some_and(|x| *x > 0.0)))
    };
    triangles
        .iter()
        .enumerate()
        .filter(|(_, t)| t.iter().all(|&v| inside(v)))
        .map(|(i, _)| i as u32)
        .collect()
}

/// The triangles girths are sectioned on: torso and both legs (see [`triangles_in_segments`]).
pub fn girth_triangles(triangles: &[[u32; 3]], weights: &[[f32; 6]]) -> Vec<u32> {
    use crate::template::Segment;
    triangles_in_segments(
        triangles,
        weights,
        &[
            Segment::Torso.index(),
            Segment::LeftLeg.index(),
            Segment::RightLeg.index(),
        ],
    )
}

/// Measures a body given as flat positions (3V), its triangles, the triangles to section for
/// girths (normally [`triangles_in_segments`] of torso and legs) and the landmark vertices.
pub fn measure(
    positions: &[f32],
    triangles: &[[u32; 3]],
    section_triangles: &[u32],
    landmarks: &MeasureLandmarks,
    params: &MeasureParams,
) -> Result<Measurements, PcaError> {
    let up = params.up_axis;
    let fail = |what: &str, reason: String| PcaError::Measurement {
        what: what.into(),
        reason,
    };
    if up > 2 || positions.len() < 3 {
        return Err(fail("stature", format!("up axis {up} or an empty mesh")));
    }
    let heights = positions.chunks_exact(3).map(|p| p[up] as f64);
    let floor = heights.clone().fold(f64::INFINITY, f64::min);
    let top = heights.fold(f64::NEG_INFINITY, f64::max);
    let at = |what: &str, v: u32| {
        vertex(positions, v)
            .ok_or_else(|| fail(what, format!("landmark vertex {v} is beyond the mesh")))
    };
    let crotch = at("inseam", landmarks.crotch)?[up];
    let level = |what: &str, vs: &[u32], least: f64| -> Result<Option<Girth>, PcaError> {
        if vs.is_empty() {
            return Ok(None);
        }
        let mut h = 0.0;
        for &v in vs {
            h += at(what, v)?[up] / vs.len() as f64;
        }
        Ok(girth_at(
            positions,
            triangles,
            section_triangles,
            up,
            h.max(least),
        ))
    };
    let mut arm_length = 0.0;
    for pair in landmarks.arm.windows(2) {
        arm_length += distance(at("arm length", pair[0])?, at("arm length", pair[1])?);
    }
    Ok(Measurements {
        stature: top - floor,
        chest: level("chest girth", &landmarks.chest, f64::NEG_INFINITY)?,
        waist: level("waist girth", &landmarks.waist, f64::NEG_INFINITY)?,
        hip: level(
            "hip girth",
            &landmarks.hip,
            crotch + params.hip_above_crotch,
        )?,
        arm_length,
        inseam: crotch - floor,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hull_of_a_square_with_an_inner_point() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.5]];
        let hull = convex_hull(&pts);
        assert_eq!(hull.len(), 4);
        assert!((perimeter(&hull, true) - 4.0).abs() < 1e-12);
    }
}
