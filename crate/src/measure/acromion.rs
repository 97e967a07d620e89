//! ISO 7250-1's acromia found on the measured body's own surface around its Acromion vertices
//! (shoulder breadth, acromion height, arm length), by the shoulder's rule the landmark estimate
//! places them with ([`crate::landmarks::shoulder`]): on each side the body's shoulder point — the surface's
//! furthest reach halfway between the shoulder's top and the upper arm's outer side, in the
//! body's shoulder frame — plus the template's offset of its Acromion vertex from its own
//! shoulder point at rest, found the same way; front to back the vertex's own place (the
//! breadth runs across). The search starts at the Acromion vertex and, while the reach runs to
//! the window's edge, starts again where it ended (`acromion_searches` in all), so a vertex a few
//! centimetres off the shoulder's turn names nearly the same point (an estimated Acromion farther
//! off still moves it: the measurements keep the Acromions' trust). On the template itself the
//! point is the Acromion vertex. The vertex stands where there is no turn (an upper arm raised more
//! than `acromion_max_abduction_deg`) or the search is not sure.
//!
//! Cost: the template's side (its frame, its surface near each Acromion) is prepared once; a body
//! costs two or more searches over the triangles near its shoulders.

use nalgebra::Point3;

use super::definitions::SHOULDERS;
use super::params::MeasureParams;
use crate::landmarks::shoulder::{
    acromion_at, climb_to_shoulder_point, shoulder_point, ShoulderFrame,
};
use crate::landmarks::CAESAR_LANDMARKS;
use crate::mesh::surface_points::surface_near;

/// One shoulder's template side: its Acromion at rest, the template's surface around it, and the
/// triangles a body's search may take.
#[derive(Debug, Clone)]
struct Side {
    /// The template's Acromion vertex at rest.
    rest_acromion: Point3<f64>,
    /// The template's surface points within `acromion_radius` of it, `acromion_spacing` apart.
    rest_points: Vec<Point3<f64>>,
    /// Template vertices of the triangles within reach of the search (every search's window,
    /// `acromion_searches` of them in a row, at rest) and those triangles in their indices.
    vertices: Vec<u32>,
    triangles: Vec<[u32; 3]>,
}

/// The acromia's search on the bodies of one template, prepared once.
#[derive(Debug, Clone)]
pub struct AcromionSearch {
    /// The vertices of [`SHOULDERS`], in its order.
    landmarks: Vec<u32>,
    /// The template's shoulder frames at rest (right, left); `None` when its landmarks span none.
    rest_frames: Option<[ShoulderFrame; 2]>,
    sides: [Side; 2],
}

fn point(positions: &[f32], v: u32) -> Point3<f64> {
    let i = 3 * v as usize;
    Point3::new(
        positions[i] as f64,
        positions[i + 1] as f64,
        positions[i + 2] as f64,
    )
}

/// The position of CAESAR landmark `k` on `positions`, among the vertices `landmarks` of
/// [`SHOULDERS`] (the shoulder frame asks only for those).
fn shoulder_landmark(positions: &[f32], landmarks: &[u32], k: usize) -> Point3<f64> {
    let name = CAESAR_LANDMARKS[k].name;
    let slot = SHOULDERS
        .iter()
        .position(|n| *n == name)
        .expect("the shoulder frame's landmarks are SHOULDERS");
    point(positions, landmarks[slot])
}

impl AcromionSearch {
    /// The search on bodies of the template at rest `rest` (flat `#V·3`, metres) with
    /// `triangles` (`#F`) and the vertices `landmarks` of [`SHOULDERS`] (in its order, checked
    /// against `#V` by the caller).
    pub fn new(
        rest: &[f32],
        triangles: &[[u32; 3]],
        landmarks: Vec<u32>,
        params: &MeasureParams,
    ) -> AcromionSearch {
        let p = params;
        let rest_points: Vec<Point3<f64>> = rest
            .chunks_exact(3)
            .map(|q| Point3::new(q[0] as f64, q[1] as f64, q[2] as f64))
            .collect();
        let reach = p.acromion_radius * p.acromion_searches.max(1) as f64;
        let side = |v: u32| {
            let at = rest_points[v as usize];
            let near = |t: &[u32; 3]| {
                t.iter()
                    .any(|&w| (rest_points[w as usize] - at).norm() <= reach)
            };
            let mut local = vec![u32::MAX; rest_points.len()];
            let mut vertices = Vec::new();
            let triangles: Vec<[u32; 3]> = triangles
                .iter()
                .filter(|t| near(t))
                .map(|t| {
                    t.map(|w| {
                        if local[w as usize] == u32::MAX {
                            local[w as usize] = vertices.len() as u32;
                            vertices.push(w);
                        }
                        local[w as usize]
                    })
                })
                .collect();
            let local_rest: Vec<Point3<f64>> =
                vertices.iter().map(|&w| rest_points[w as usize]).collect();
            Side {
                rest_acromion: at,
                rest_points: surface_near(
                    &local_rest,
                    &triangles,
                    &at,
                    p.acromion_radius,
                    p.acromion_spacing,
                ),
                vertices,
                triangles,
            }
        };
        // SHOULDERS: Rt. Acromion, Lt. Acromion first.
        let sides = [side(landmarks[0]), side(landmarks[1])];
        let rest_frames = ShoulderFrame::both(&|k| shoulder_landmark(rest, &landmarks, k));
        AcromionSearch {
            landmarks,
            rest_frames,
            sides,
        }
    }

    /// The acromia (right, left) of the body at flat `positions` (template vertex order,
    /// metres, upright like the template): each side's Acromion vertex where the search finds
    /// no shoulder point.
    pub fn acromia(&self, positions: &[f32], params: &MeasureParams) -> [[f64; 3]; 2] {
        let p = params;
        let guesses = [0, 1].map(|s| point(positions, self.landmarks[s]));
        let mut out = guesses;
        let frames = ShoulderFrame::both(&|k| shoulder_landmark(positions, &self.landmarks, k));
        if let (Some(rest), Some(frames)) = (self.rest_frames, frames) {
            let window = (p.acromion_radius, p.acromion_edge, p.acromion_cap);
            for (side, s) in self.sides.iter().enumerate() {
                let (frame, own) = (&frames[side], &rest[side]);
                let Some((dl, du)) = frame.direction(p.acromion_max_abduction_deg) else {
                    continue;
                };
                let Some(template_point) = shoulder_point(
                    &s.rest_points,
                    &s.rest_acromion,
                    &own.vector([dl, du, 0.0]),
                    window,
                    p.acromion_min_points,
                ) else {
                    continue;
                };
                let offset = own.components(&(s.rest_acromion - template_point));
                let local: Vec<Point3<f64>> =
                    s.vertices.iter().map(|&v| point(positions, v)).collect();
                let surface = |c: &Point3<f64>| {
                    surface_near(
                        &local,
                        &s.triangles,
                        c,
                        p.acromion_radius,
                        p.acromion_spacing,
                    )
                };
                if let Some(found) = climb_to_shoulder_point(
                    &surface,
                    &guesses[side],
                    &frame.vector([dl, du, 0.0]),
                    window,
                    p.acromion_min_points,
                    p.acromion_searches,
                ) {
                    // Front to back the vertex's own place (keep 1): the breadth runs across.
                    out[side] = acromion_at(frame, &found, offset, &guesses[side], 1.0, 1.0);
                }
            }
        }
        out.map(|a| [a.x, a.y, a.z])
    }
}
