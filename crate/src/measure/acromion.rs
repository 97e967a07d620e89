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
//! than `acromion_max_abduction_deg`), the search is not sure, or the point found is not on the
//! shoulder's turn: the surface rises more than `acromion_turn_rise` above it along the search's
//! direction within `acromion_turn_reach` towards the neck or the arm ([`turn_rises`]; an arm
//! out 55° under a shoulder rising to the neck, where the search's direction lies nearly square to
//! that slope and the reach stops on a bump of it).
//!
//! Cost: the template's side (its frame, its surface near each Acromion) is prepared once; a body
//! costs two or more searches over the triangles near its shoulders and one profile per side.

use nalgebra::{Point3, Vector3};

use super::definitions::SHOULDERS;
use super::params::MeasureParams;
use crate::landmarks::shoulder::{
    acromion_at, climb_to_shoulder_point, shoulder_point, Cap, ShoulderFrame,
};
use crate::landmarks::CAESAR_LANDMARKS;
use crate::mesh::surface_points::{grid_steps, SurfacePoint, SurfaceWindows};

/// One shoulder's template side: its Acromion at rest, the template's surface around it, and the
/// triangles a body's search may take.
#[derive(Debug, Clone)]
struct Side {
    /// The template's Acromion vertex at rest.
    rest_acromion: Point3<f64>,
    /// The template's surface points within `acromion_radius` of it, `acromion_spacing` apart,
    /// each with the area it stands for.
    rest_points: Vec<SurfacePoint>,
    /// Template vertices of the triangles within reach of the search (every search's window,
    /// `acromion_searches` of them in a row, at rest) and those triangles in their indices.
    vertices: Vec<u32>,
    triangles: Vec<[u32; 3]>,
    /// Those triangles' sampling grids, laid at rest and held on every body (`grid_steps`).
    steps: Vec<u32>,
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
            let steps = grid_steps(&local_rest, &triangles, p.acromion_spacing);
            let windows = SurfaceWindows::held(&local_rest, &triangles, &steps);
            let rest_points = windows.near_with_areas(&at, p.acromion_radius, p.acromion_spacing);
            Side {
                rest_acromion: at,
                rest_points,
                steps,
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
    /// metres, upright like the template), each with how it was found ([`Acromion`]): the
    /// Acromion vertex where the search finds no shoulder point or the point it finds is not on
    /// the shoulder's turn ([`turn_rises`]).
    pub fn acromia(&self, positions: &[f32], params: &MeasureParams) -> [Acromion; 2] {
        let p = params;
        let guesses = [0, 1].map(|s| point(positions, self.landmarks[s]));
        let mut out = guesses.map(|g| Acromion {
            point: [g.x, g.y, g.z],
            vertex: [g.x, g.y, g.z],
            on_surface: false,
            shoulder_point: None,
            rises: None,
        });
        let frames = ShoulderFrame::both(&|k| shoulder_landmark(positions, &self.landmarks, k));
        let (Some(rest), Some(frames)) = (self.rest_frames, frames) else {
            return out;
        };
        let cap = Cap {
            depth: p.acromion_cap,
            taper: p.acromion_cap_taper,
        };
        let window = (p.acromion_radius, p.acromion_edge, cap);
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
            let local: Vec<Point3<f64>> = s.vertices.iter().map(|&v| point(positions, v)).collect();
            let windows = SurfaceWindows::held(&local, &s.triangles, &s.steps);
            let surface =
                |c: &Point3<f64>| windows.near_with_areas(c, p.acromion_radius, p.acromion_spacing);
            let direction = frame.vector([dl, du, 0.0]);
            let Some(found) = climb_to_shoulder_point(
                &surface,
                &guesses[side],
                &direction,
                window,
                p.acromion_min_points,
                p.acromion_searches,
            ) else {
                continue;
            };
            let o = &mut out[side];
            o.shoulder_point = Some([found.x, found.y, found.z]);
            let medial = frame.vector([-du, dl, 0.0]);
            let near: Vec<Point3<f64>> = surface(&found).into_iter().map(|(q, _)| q).collect();
            o.rises = turn_rises(
                &near,
                &found,
                &direction,
                &medial,
                &frame.forward,
                (p.acromion_turn_reach, p.acromion_turn_band),
            );
            if o.rises
                .is_some_and(|r| r.iter().all(|&x| x <= p.acromion_turn_rise))
            {
                // Front to back the vertex's own place (keep 1): the breadth runs across.
                let a = acromion_at(frame, &found, offset, &guesses[side], 1.0, 1.0);
                o.point = [a.x, a.y, a.z];
                o.on_surface = true;
            }
        }
        out
    }
}

/// One acromion of a body and how it was found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Acromion {
    /// The acromion the measurements take: found on the surface, or the Acromion vertex.
    pub point: [f64; 3],
    /// The body's Acromion vertex (the search's guess).
    pub vertex: [f64; 3],
    /// Found on the surface: the shoulder point was sure and on the shoulder's turn. Otherwise
    /// `point` is `vertex`.
    pub on_surface: bool,
    /// The shoulder point the search found, sure or not on the turn (`None`: no search, or not
    /// sure).
    pub shoulder_point: Option<[f64; 3]>,
    /// [`turn_rises`] at the shoulder point (m, towards the neck and towards the arm).
    pub rises: Option<[f64; 2]>,
}

/// How far the surface rises above the shoulder point `at` along the search's `direction` d
/// (unit) within `reach` of it to either side in the frontal plane: towards the neck (`medial`,
/// the unit tangent square to d in the frontal plane that points in and up) and towards the arm
/// (−`medial`). The profile R(s) = max (p − at)·d over the `points` (surface samples around
/// `at`) within `band` of `at` front to back and within ½·`band` of the tangent offset s,
/// s = k·`band`; the rises are max R(s) − R(0) over 0 < s ≤ `reach` and over −`reach` ≤ s < 0
/// (≤ 0 where the point is its profile's furthest reach). On a shoulder's turn both are about 0
/// (the cap's top and the arm's side fall away from it); where an arm is raised until the cap's
/// top and the arm's upper side make nearly one slope, d lies nearly square to that slope and the
/// point found is a bump on the way up to the neck: the rise towards the neck is centimetres.
/// `None` when no point lies at s = 0.
pub fn turn_rises(
    points: &[Point3<f64>],
    at: &Point3<f64>,
    direction: &Vector3<f64>,
    medial: &Vector3<f64>,
    forward: &Vector3<f64>,
    (reach, band): (f64, f64),
) -> Option<[f64; 2]> {
    let bins = (reach / band).round().max(1.0) as i64;
    let mut profile = vec![f64::NEG_INFINITY; 2 * bins as usize + 1];
    for p in points {
        let v = p - at;
        let k = (v.dot(medial) / band).round();
        if v.dot(forward).abs() <= band && k.abs() <= bins as f64 {
            let r = &mut profile[(k as i64 + bins) as usize];
            *r = r.max(v.dot(direction));
        }
    }
    let top = profile[bins as usize];
    if top == f64::NEG_INFINITY {
        return None;
    }
    let rise = |side: &[f64]| side.iter().fold(f64::NEG_INFINITY, |m, &r| m.max(r - top));
    let (arm, neck) = (&profile[..bins as usize], &profile[bins as usize + 1..]);
    Some([rise(neck), rise(arm)])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A profile in the frontal plane (x out, y up; points `step` apart along each piece)
    /// drawn front to back from −6 to 6 mm: the surface a shoulder's turn is sought on.
    fn extruded(pieces: &[(Point3<f64>, Vector3<f64>, f64)], step: f64) -> Vec<Point3<f64>> {
        let mut out = Vec::new();
        for (start, along, length) in pieces {
            let n = (length / step).round() as usize;
            for i in 0..=n {
                for k in -6..=6 {
                    let p = start + along * (i as f64 * step);
                    out.push(Point3::new(p.x, p.y, k as f64 * 0.001));
                }
            }
        }
        out
    }

    fn unit(deg: f64) -> Vector3<f64> {
        let a = deg.to_radians();
        Vector3::new(a.cos(), a.sin(), 0.0)
    }

    /// The rises (towards the neck, towards the arm) around the origin, looking along the
    /// direction `deg` above the outward horizontal, with the defaults' reach and band.
    fn rises(points: &[Point3<f64>], deg: f64) -> [f64; 2] {
        let p = MeasureParams::default();
        let medial = unit(deg + 90.0);
        let window = (p.acromion_turn_reach, p.acromion_turn_band);
        turn_rises(
            points,
            &Point3::origin(),
            &unit(deg),
            &medial,
            &Vector3::z(),
            window,
        )
        .unwrap()
    }

    #[test]
    fn a_turn_falls_away_on_both_sides_and_a_bump_under_a_rising_slope_does_not() {
        let o = Point3::origin();
        // A right-angled shoulder, d halfway: the surface falls away by the tangent offset, so
        // the nearest bins (±1.5 mm off the point) lie 1.5 mm under it.
        let corner = extruded(&[(o, unit(180.0), 0.06), (o, unit(-90.0), 0.06)], 0.0002);
        let [neck, arm] = rises(&corner, 45.0);
        assert!(
            (neck + 0.0015).abs() < 2e-4 && (arm + 0.0015).abs() < 2e-4,
            "{neck} {arm}"
        );
        // An arm out 55° (its upper side 35° under the horizontal, d 72.5° up) and the
        // shoulder's top flat for 12 mm, then rising 35° to the neck: along d the slope rises by
        // (sin 35° sin 72.5° − cos 35° cos 72.5°) = 0.3007 per unit of its length v, from
        // −12·cos 72.5° = −3.61 mm at its foot; tangent offset s = 11.44 mm + 0.9537·v, so the
        // last bin (s ≤ 40.5 mm) holds v = 30.47 mm and a rise of 5.55 mm.
        let foot = Point3::new(-0.012, 0.0, 0.0);
        let slope = extruded(
            &[
                (o, unit(-35.0), 0.06),
                (o, unit(180.0), 0.012),
                (foot, unit(145.0), 0.06),
            ],
            0.0002,
        );
        let [neck, arm] = rises(&slope, 72.5);
        assert!((neck - 0.00555).abs() < 2e-4, "{neck}");
        assert!(neck > MeasureParams::default().acromion_turn_rise);
        assert!(arm <= 0.0, "{arm}");
    }
}
