//! The shoulder point and the Acromion on a body's own surface: the rule the landmark estimate
//! (`crate::estimate::acromion`, on a scan) and the measurements (`crate::measure::acromion`, on
//! a body in template vertex order) share.
//!
//! The standard's Acromion (CAESAR, ISO 7250-1) is the most lateral point of the acromion's
//! lateral edge; on a surface, apparel practice takes the shoulder point, where the shoulder's
//! top line turns down into the arm's outer side. That turn is the surface's furthest reach
//! ([`shoulder_point`]) in the direction halfway between the shoulder's top (the trunk's up) and
//! the upper arm's outer side (square to the arm, in the trunk's frontal plane:
//! [`ShoulderFrame::direction`]): on a rounded corner that reach lies where the surface's normal
//! bisects the turn. The template's Acromion vertex lies at some offset from the same point found
//! on the template at rest (the same direction in its own shoulder frame); a body's Acromion is
//! its shoulder point plus that offset in the body's shoulder frame ([`acromion_at`]), so the
//! template's landmark keeps its anatomy and the body's own surface says where it is.
//!
//! A search around a guess far from the turn ends on the window's edge (the surface still rises
//! beyond it); [`climb_to_shoulder_point`] then searches again around where it ended, a given
//! number of times.

use nalgebra::{Point3, Vector3};

use super::caesar::caesar_index;
use crate::mesh::surface_points::SurfacePoint;

/// The trunk's frame at one shoulder and the upper arm's direction, unit vectors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShoulderFrame {
    /// Away from the body's midline (Lt. → Rt. Acromion for the right shoulder), square to `up`.
    pub lateral: Vector3<f64>,
    /// The ASIS' midpoint → Suprasternale.
    pub up: Vector3<f64>,
    /// Cervicale → Suprasternale, square to `up`.
    pub forward: Vector3<f64>,
    /// The Acromion → the humeral epicondyles' midpoint.
    pub arm: Vector3<f64>,
}

/// The CAESAR index of `name`.
fn index(name: &str) -> usize {
    caesar_index(name).expect("the shoulder's landmarks are CAESAR landmarks")
}

/// The CAESAR indices of the right and the left Acromion.
pub fn acromion_indices() -> [usize; 2] {
    [index("Rt. Acromion"), index("Lt. Acromion")]
}

impl ShoulderFrame {
    /// Both shoulders' frames (right, left) from a body's landmark positions (`at`: CAESAR
    /// index → position). `None` when the landmarks do not span a frame.
    pub fn both(at: &dyn Fn(usize) -> Point3<f64>) -> Option<[ShoulderFrame; 2]> {
        let p = |name: &str| at(index(name));
        let hips = nalgebra::center(&p("Rt. ASIS"), &p("Lt. ASIS"));
        let up = (p("Suprasternale") - hips).try_normalize(1e-12)?;
        let square = |v: Vector3<f64>| (v - up * v.dot(&up)).try_normalize(1e-12);
        let right = square(p("Rt. Acromion") - p("Lt. Acromion"))?;
        let forward = square(p("Suprasternale") - p("Cervicale"))?;
        let arm = |side: &str| {
            let elbow = nalgebra::center(
                &p(&format!("{side} Humeral Lateral Epicn")),
                &p(&format!("{side} Humeral Medial Epicn")),
            );
            (elbow - p(&format!("{side} Acromion"))).try_normalize(1e-12)
        };
        Some([
            ShoulderFrame {
                lateral: right,
                up,
                forward,
                arm: arm("Rt.")?,
            },
            ShoulderFrame {
                lateral: -right,
                up,
                forward,
                arm: arm("Lt.")?,
            },
        ])
    }

    /// The search's direction as (lateral, up) components: the bisector of the shoulder's top
    /// (normal `up`) and the upper arm's outer side (normal n = (−a_u, a_l), the arm's
    /// direction (a_l, a_u) in the frontal plane turned a quarter up and out), d ∝ n + up. `None`
    /// when the arm lies mostly along `forward` or is raised more than `max_abduction_deg`
    /// from hanging down.
    pub fn direction(&self, max_abduction_deg: f64) -> Option<(f64, f64)> {
        if self.abduction_deg()? > max_abduction_deg {
            return None;
        }
        let (al, au) = (self.arm.dot(&self.lateral), self.arm.dot(&self.up));
        let n = al.hypot(au);
        let (al, au) = (al / n, au / n);
        let (dl, du) = (-au, 1.0 + al);
        let norm = dl.hypot(du);
        (norm > 1e-9).then(|| (dl / norm, du / norm))
    }

    /// How far (degrees) the upper arm is raised from hanging down, in the trunk's frontal plane:
    /// 0 down along the body, 90 held out level, 180 straight up. `None` when the arm lies mostly
    /// along `forward`.
    pub fn abduction_deg(&self) -> Option<f64> {
        let (al, au) = (self.arm.dot(&self.lateral), self.arm.dot(&self.up));
        (al.hypot(au) >= 0.5).then(|| al.atan2(-au).to_degrees())
    }

    /// `(lateral, up, forward)` components → a vector.
    pub fn vector(&self, [l, u, f]: [f64; 3]) -> Vector3<f64> {
        self.lateral * l + self.up * u + self.forward * f
    }

    /// A vector → its `(lateral, up, forward)` components.
    pub fn components(&self, v: &Vector3<f64>) -> [f64; 3] {
        [v.dot(&self.lateral), v.dot(&self.up), v.dot(&self.forward)]
    }
}

/// How far into the furthest reach the shoulder point's centroid takes the points (m below the
/// reach along the search's direction): every point within `depth` alike when `taper` is 0, or,
/// with `taper` > 0, each weighted 1 down to `depth − taper/2` and 0 from `depth + taper/2`,
/// linearly between, so that the centroid moves continuously as the points move.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cap {
    pub depth: f64,
    pub taper: f64,
}

impl Cap {
    /// Every point within `depth` alike.
    pub fn even(depth: f64) -> Cap {
        Cap { depth, taper: 0.0 }
    }

    /// A point's weight `below` (m) the furthest reach.
    fn weight(&self, below: f64) -> f64 {
        if self.taper <= 0.0 {
            return if below <= self.depth { 1.0 } else { 0.0 };
        }
        ((self.depth + 0.5 * self.taper - below) / self.taper).clamp(0.0, 1.0)
    }
}

/// The centroid of the `points` in the `cap` of their furthest reach along `direction` (unit)
/// from `centre`, each weighted by its [`Cap`] weight times the area it stands for; `None`
/// without points.
pub fn furthest_reach(
    points: &[SurfacePoint],
    centre: &Point3<f64>,
    direction: &Vector3<f64>,
    cap: Cap,
) -> Option<Point3<f64>> {
    let reach = |p: &Point3<f64>| (p - centre).dot(direction);
    let top = points
        .iter()
        .map(|(p, _)| reach(p))
        .fold(f64::NEG_INFINITY, f64::max);
    let (sum, total) = points
        .iter()
        .map(|(p, area)| (p, area * cap.weight(top - reach(p))))
        .filter(|(_, w)| *w > 0.0)
        .fold((Vector3::zeros(), 0.0), |(s, t), (p, w)| {
            (s + p.coords * w, t + w)
        });
    (total > 0.0).then(|| Point3::from(sum / total))
}

/// The shoulder point among `points` (on a surface, within `radius` of `centre`, each with the
/// area it stands for): the [`furthest_reach`] along `direction` (unit) with cap `cap`. `None`
/// with fewer than `min_points` points, or when the point lies farther than `radius − edge` from
/// `centre` (the surface reaches on beyond the window).
pub fn shoulder_point(
    points: &[SurfacePoint],
    centre: &Point3<f64>,
    direction: &Vector3<f64>,
    (radius, edge, cap): (f64, f64, Cap),
    min_points: usize,
) -> Option<Point3<f64>> {
    if points.len() < min_points {
        return None;
    }
    let found = furthest_reach(points, centre, direction, cap)?;
    ((found - centre).norm() <= radius - edge).then_some(found)
}

/// The shoulder point on a surface (`surface(c)`: its points within `radius` of c, each with
/// the area it stands for) found from `guess`: [`shoulder_point`] around the guess and, while it
/// is not sure because the reach ran to the window's edge, around where that search ended, at
/// most `searches` searches in all.
/// With one search, [`shoulder_point`] around the guess. `None` when the last is not sure too.
pub fn climb_to_shoulder_point(
    surface: &dyn Fn(&Point3<f64>) -> Vec<SurfacePoint>,
    guess: &Point3<f64>,
    direction: &Vector3<f64>,
    (radius, edge, cap): (f64, f64, Cap),
    min_points: usize,
    searches: usize,
) -> Option<Point3<f64>> {
    let mut centre = *guess;
    for _ in 0..searches {
        let points = surface(&centre);
        if points.len() < min_points {
            return None;
        }
        let found = furthest_reach(&points, &centre, direction, cap)?;
        if (found - centre).norm() <= radius - edge {
            return Some(found);
        }
        centre = found;
    }
    None
}

/// A body's Acromion from its `shoulder_point` found in `frame` (the body's shoulder frame):
/// the shoulder point plus `offset` (the template's Acromion vertex minus its own shoulder point,
/// as `(lateral, up, forward)` components of the template's shoulder frame at rest) times
/// `size` (the body's scale against the template), with `keep_forward` (0–1) of the `guess`'s
/// position front to back kept: a + k·(f·(g − a))·f, a = s + size·F·offset.
pub fn acromion_at(
    frame: &ShoulderFrame,
    shoulder_point: &Point3<f64>,
    offset: [f64; 3],
    guess: &Point3<f64>,
    size: f64,
    keep_forward: f64,
) -> Point3<f64> {
    let found = shoulder_point + frame.vector(offset) * size;
    found + frame.forward * (guess - found).dot(&frame.forward) * keep_forward
}

#[cfg(test)]
mod tests {
    use super::*;

    use nalgebra::{Rotation3, Unit};

    use crate::mesh::similarity::Similarity;

    /// Points on the ellipsoid with semi-axes `axes` about the origin, ≈ 1.5 mm apart.
    fn ellipsoid(axes: Vector3<f64>) -> Vec<Point3<f64>> {
        let mut out = Vec::new();
        for i in 0..=200 {
            let theta = std::f64::consts::PI * i as f64 / 200.0;
            for j in 0..400 {
                let phi = 2.0 * std::f64::consts::PI * j as f64 / 400.0;
                let unit = Vector3::new(
                    theta.sin() * phi.cos(),
                    theta.cos(),
                    theta.sin() * phi.sin(),
                );
                out.push(Point3::from(unit.component_mul(&axes)));
            }
        }
        out
    }

    #[test]
    fn the_shoulder_point_is_the_furthest_reach_of_a_rounded_shoulder() {
        // A shoulder as an ellipsoid 20 cm across, 10 cm high, 8 cm deep; its furthest reach
        // towards d is A²d / √(dᵀA²d), here (a², b², 0) / √(a² + b²).
        let axes = Vector3::new(0.2, 0.1, 0.08);
        let points = ellipsoid(axes);
        let d = Vector3::new(1.0, 1.0, 0.0).normalize();
        let truth = Point3::new(0.04, 0.01, 0.0) / 0.05f64.sqrt();
        let guess = truth + Vector3::new(0.015, -0.015, 0.01);
        let near: Vec<_> = points
            .iter()
            .filter(|p| (*p - guess).norm() <= 0.05)
            .copied()
            .collect();
        let even = |points: &[Point3<f64>]| points.iter().map(|p| (*p, 1.0)).collect::<Vec<_>>();
        let found =
            shoulder_point(&even(&near), &guess, &d, (0.05, 0.01, Cap::even(0.002)), 50).unwrap();
        assert!((found - truth).norm() < 0.003, "{found} against {truth}");
        // Turned, moved and twice the size: the same point, turned, moved and doubled.
        let motion = Similarity {
            scale: 2.0,
            rotation: *Rotation3::from_axis_angle(
                &Unit::new_normalize(Vector3::new(0.3, -1.0, 0.5)),
                2.0,
            )
            .matrix(),
            translation: Vector3::new(1.0, -3.0, 0.5),
        };
        let moved = motion.apply_all(&near);
        let again = shoulder_point(
            &even(&moved),
            &motion.apply(&guess),
            &(motion.rotation * d),
            (0.1, 0.02, Cap::even(0.004)),
            50,
        )
        .unwrap();
        assert!((again - motion.apply(&found)).norm() < 1e-9);
        // A window that holds only the rising slope: the reach runs on to its edge.
        assert!(
            shoulder_point(&even(&near), &guess, &d, (0.012, 0.01, Cap::even(0.002)), 5).is_none()
        );
    }

    #[test]
    fn a_tapered_cap_takes_a_point_in_gradually() {
        // The reach's top at height 0 and one more point sinking from 3 to 5 mm below it, at
        // x = 1: an even cap of 4 mm drops it at once; one tapered over 2 mm lets it go evenly.
        let centroid_x = |cap: Cap, below: f64| {
            let points = [
                (Point3::new(0.0, 0.0, 0.0), 1.0),
                (Point3::new(1.0, -below, 0.0), 1.0),
            ];
            furthest_reach(&points, &Point3::origin(), &Vector3::y(), cap)
                .unwrap()
                .x
        };
        let tapered = Cap {
            depth: 0.004,
            taper: 0.002,
        };
        assert_eq!(centroid_x(Cap::even(0.004), 0.00399), 0.5);
        assert_eq!(centroid_x(Cap::even(0.004), 0.00401), 0.0);
        assert!((centroid_x(tapered, 0.004) - 1.0 / 3.0).abs() < 1e-12);
        assert_eq!(centroid_x(tapered, 0.003), 0.5);
        assert_eq!(centroid_x(tapered, 0.005), 0.0);
        assert!((centroid_x(tapered, 0.00399) - centroid_x(tapered, 0.00401)).abs() < 0.01);
    }

    #[test]
    fn the_search_bisects_the_turn_and_a_raised_arm_has_none() {
        let frame = |arm: Vector3<f64>| ShoulderFrame {
            lateral: Vector3::x(),
            up: Vector3::y(),
            forward: Vector3::z(),
            arm: arm.normalize(),
        };
        // Hanging down: halfway between up and out.
        let (l, u) = frame(-Vector3::y()).direction(30.0).unwrap();
        assert!((l - u).abs() < 1e-12 && (l - 0.5f64.sqrt()).abs() < 1e-12);
        // Out 20°: the outer side's normal turned up 20°, the bisector with it.
        let a = 20f64.to_radians();
        let (l, u) = frame(Vector3::new(a.sin(), -a.cos(), 0.0))
            .direction(30.0)
            .unwrap();
        let expected = (45.0 + 10.0f64).to_radians();
        assert!((u.atan2(l) - expected).abs() < 1e-9, "{}", u.atan2(l));
        // Raised 40° or pointing forward: no turn to find.
        let a = 40f64.to_radians();
        assert!(frame(Vector3::new(a.sin(), -a.cos(), 0.0))
            .direction(30.0)
            .is_none());
        assert!(frame(Vector3::new(0.1, -0.2, 1.0))
            .direction(30.0)
            .is_none());
    }
}
