//! The Acromions on the scan's own shoulder. The fit reads each Acromion off the template's
//! vertex, and nearest points do not see where along the shoulder's rounded cap that vertex
//! belongs: on the development subjects the fit's Acromions slid down onto the arm's outer side
//! or in towards the neck by 2–3 cm (lateral and vertical errors of opposite sign, the same on
//! both sides of a subject) and 15–20 mm to the front or back (docs/landmarks-estimate.md).
//!
//! The standard's Acromion (CAESAR, ISO 7250-1) is the most lateral point of the acromion's
//! lateral edge; on a scan, apparel practice takes the shoulder point, where the shoulder's top
//! line turns down into the arm's outer side. Here that turn is found as the surface's furthest
//! reach, near the fit's guess, in the direction halfway between the shoulder's top (the trunk's
//! up) and the upper arm's outer side (square to the arm, in the trunk's frontal plane): on a
//! rounded corner that reach lies where the surface's normal bisects the turn, and on the cap's
//! crest front to back. The template's Acromion vertex lies at some offset from the same point
//! found on the template at rest (the same direction, in its own trunk's frame); the scan's
//! Acromion is its shoulder point plus that offset, in the fitted body's trunk frame at the
//! body's scale. (The template posed like the scan by the segment-wise fit, its parts blended at
//! the shoulder, placed them worse: 22.4 mm on the development seeds against 18.3 from the rest
//! pose.) Front to back the fit's guess is kept (the crest was no nearer). Nothing depends on
//! the scan's frame or units, nor on the generator.
//!
//! Not sure, and the fit's guess kept, where there is no turn (an upper arm raised more than
//! [`AcromionParams::max_abduction_deg`]), where the reach runs on to the window's edge, or where
//! the window holds too little surface.

use nalgebra::{Point3, Vector3};

use super::params::AcromionParams;
use crate::landmarks::CAESAR_LANDMARKS;
use crate::mesh::Mesh;

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
    CAESAR_LANDMARKS
        .iter()
        .position(|l| l.name == name)
        .expect("the shoulder's landmarks are CAESAR landmarks")
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
        let (al, au) = (self.arm.dot(&self.lateral), self.arm.dot(&self.up));
        let n = al.hypot(au);
        if n < 0.5 {
            return None;
        }
        let (al, au) = (al / n, au / n);
        if al.atan2(-au).to_degrees() > max_abduction_deg {
            return None;
        }
        let (dl, du) = (-au, 1.0 + al);
        let norm = dl.hypot(du);
        (norm > 1e-9).then(|| (dl / norm, du / norm))
    }

    /// `(lateral, up, forward)` components → a vector.
    fn vector(&self, [l, u, f]: [f64; 3]) -> Vector3<f64> {
        self.lateral * l + self.up * u + self.forward * f
    }

    /// A vector → its `(lateral, up, forward)` components.
    fn components(&self, v: &Vector3<f64>) -> [f64; 3] {
        [v.dot(&self.lateral), v.dot(&self.up), v.dot(&self.forward)]
    }
}

/// Points spread `spacing` apart over the triangles of a mesh (`positions`, `triangles`) that
/// lie within `radius` of `centre` (barycentric grids, as `profile::surface_samples`).
pub fn surface_near(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    centre: &Point3<f64>,
    radius: f64,
    spacing: f64,
) -> Vec<Point3<f64>> {
    let r2 = radius * radius;
    let near: Vec<[u32; 3]> = triangles
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|v| positions[v as usize]);
            let longest = (b - a).norm().max((c - b).norm()).max((a - c).norm());
            t.iter()
                .any(|&v| (positions[v as usize] - centre).norm() <= radius + longest)
        })
        .copied()
        .collect();
    super::profile::surface_samples(positions, &near, spacing)
        .into_iter()
        .filter(|p| (p - centre).norm_squared() <= r2)
        .collect()
}

/// The shoulder point among `points` (on a surface, within `radius` of `centre`): the centroid
/// of those within `cap` of the furthest reach along `direction` (unit). `None` with fewer than
/// `min_points` points, or when the point lies farther than `radius − edge` from `centre` (the
/// surface reaches on beyond the window).
pub fn shoulder_point(
    points: &[Point3<f64>],
    centre: &Point3<f64>,
    direction: &Vector3<f64>,
    (radius, edge, cap): (f64, f64, f64),
    min_points: usize,
) -> Option<Point3<f64>> {
    if points.len() < min_points {
        return None;
    }
    let reach = |p: &Point3<f64>| (p - centre).dot(direction);
    let top = points.iter().map(reach).fold(f64::NEG_INFINITY, f64::max);
    let (sum, n) = points
        .iter()
        .filter(|p| reach(p) >= top - cap)
        .fold((Vector3::zeros(), 0usize), |(s, n), p| {
            (s + p.coords, n + 1)
        });
    let found = Point3::from(sum / n as f64);
    ((found - centre).norm() <= radius - edge).then_some(found)
}

/// The template at rest: its positions (`#V`, template metres), triangles and landmark
/// vertices (CAESAR order).
#[derive(Debug, Clone, Copy)]
pub struct RestTemplate<'a> {
    pub positions: &'a [Point3<f64>],
    pub triangles: &'a [[u32; 3]],
    pub landmark_vertices: &'a [u32],
}

/// The Acromions (right, left) on `scan` (metres) from the fine fit `fitted` (`#V` positions on
/// the scan, metres) at the body's scale `size` (metres per template metre): for each side, the
/// scan's shoulder point within `params.radius · size` of the fit's Acromion, plus the offset
/// (times `size`) of the template's Acromion vertex from its own shoulder point at rest (found
/// the same way, in the same direction of its own shoulder frame), in the fitted body's
/// shoulder frame; front to back `params.keep_forward` of the fit's guess stays. `None` for a
/// side where either search is not sure (the fit's guess stands).
pub fn place_acromions(
    template: &RestTemplate<'_>,
    fitted: &[Point3<f64>],
    scan: &Mesh,
    size: f64,
    params: &AcromionParams,
) -> [Option<Point3<f64>>; 2] {
    let vertex = |k: usize| template.landmark_vertices[k] as usize;
    let (Some(body), Some(rest)) = (
        ShoulderFrame::both(&|k| fitted[vertex(k)]),
        ShoulderFrame::both(&|k| template.positions[vertex(k)]),
    ) else {
        return [None, None];
    };
    let search =
        |positions: &[Point3<f64>], triangles: &[[u32; 3]], at: &Point3<f64>, s: f64, d| {
            let points = surface_near(
                positions,
                triangles,
                at,
                params.radius * s,
                params.spacing * s,
            );
            let window = (params.radius * s, params.edge * s, params.cap * s);
            shoulder_point(&points, at, &d, window, params.min_points)
        };
    let mut out = [None, None];
    for (side, k) in acromion_indices().into_iter().enumerate() {
        let (frame, own) = (&body[side], &rest[side]);
        let Some((dl, du)) = frame.direction(params.max_abduction_deg) else {
            continue;
        };
        let at_rest = template.positions[vertex(k)];
        let Some(template_point) = search(
            template.positions,
            template.triangles,
            &at_rest,
            1.0,
            own.vector([dl, du, 0.0]),
        ) else {
            continue;
        };
        let offset = own.components(&(at_rest - template_point));
        let guess = fitted[vertex(k)];
        out[side] = search(
            &scan.positions,
            &scan.triangles,
            &guess,
            size,
            frame.vector([dl, du, 0.0]),
        )
        .map(|p| {
            let found = p + frame.vector(offset) * size;
            // Front to back the fit's guess stands: the cap's crest was no nearer the truth.
            found + frame.forward * (guess - found).dot(&frame.forward) * params.keep_forward
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    use nalgebra::{Rotation3, Unit};

    use crate::mesh::similarity::Similarity;
    use crate::template::fixture::{base_body, BaseBody};
    use crate::template::parts::PartPose;

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
        let found = shoulder_point(&near, &guess, &d, (0.05, 0.01, 0.002), 50).unwrap();
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
            &moved,
            &motion.apply(&guess),
            &(motion.rotation * d),
            (0.1, 0.02, 0.004),
            50,
        )
        .unwrap();
        assert!((again - motion.apply(&found)).norm() < 1e-9);
        // A window that holds only the rising slope: the reach runs on to its edge.
        assert!(shoulder_point(&near, &guess, &d, (0.012, 0.01, 0.002), 5).is_none());
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

    /// The template with both arms (upper arm and forearm) turned about the shoulder's joint in
    /// the frontal plane to hang `deg` from straight down.
    fn arms_hanging(body: &BaseBody, deg: f64) -> Vec<PartPose> {
        let mut poses = vec![PartPose::identity(); body.parts.len()];
        for side in ["left", "right"] {
            let upper = body
                .parts
                .iter()
                .position(|p| p.name == format!("{side} upper arm"))
                .unwrap();
            let part = &body.parts[upper];
            let axis = part.axis.unwrap();
            let out = axis.x.signum();
            let now = (axis.x.abs()).atan2(-axis.y);
            let turn = -out * (now - deg.to_radians());
            let rotation = *Rotation3::from_axis_angle(&Vector3::z_axis(), turn).matrix();
            let pose = PartPose {
                transform: Similarity {
                    scale: 1.0,
                    rotation,
                    translation: part.joint.coords - rotation * part.joint.coords,
                },
                stretch: 1.0,
            };
            for (k, p) in body.parts.iter().enumerate() {
                if p.name.starts_with(side) && p.name.contains("arm") {
                    poses[k] = pose;
                }
            }
        }
        poses
    }

    #[test]
    fn the_acromions_of_the_template_are_found_from_guesses_off_the_shoulder() {
        // The template itself as the scan: its Acromion vertices are the known answer. (A body
        // with its arms turned down rigidly is none: blending the parts flattens the shoulder.)
        let body = base_body();
        let scan = Mesh::new(body.rest.clone(), body.triangles.clone());
        let landmark_vertices: Vec<u32> = body
            .template
            .landmark_vertices()
            .iter()
            .map(|(_, v)| *v)
            .collect();
        let template = RestTemplate {
            positions: &body.rest,
            triangles: &body.triangles,
            landmark_vertices: &landmark_vertices,
        };
        // The template's arms are out in its A-pose.
        let params = AcromionParams {
            max_abduction_deg: 60.0,
            ..AcromionParams::default()
        };
        let [rt, lt] = acromion_indices().map(|k| landmark_vertices[k] as usize);
        let truth = [scan.positions[rt], scan.positions[lt]];
        // The fit's guesses slid 10 mm down onto the arm's outer side and 10 mm out.
        let frames =
            ShoulderFrame::both(&|k| scan.positions[landmark_vertices[k] as usize]).unwrap();
        let mut fitted = scan.positions.clone();
        for (side, v) in [rt, lt].into_iter().enumerate() {
            let f = &frames[side];
            fitted[v] += (f.lateral - f.up) * 0.01;
        }
        let found = place_acromions(&template, &fitted, &scan, 1.0, &params);
        for side in 0..2 {
            let p = found[side].expect("the shoulder point is found");
            let (error, guess) = (
                (p - truth[side]).norm(),
                (fitted[[rt, lt][side]] - truth[side]).norm(),
            );
            assert!(
                error < 0.006 && error < guess / 3.0,
                "side {side}: {error} (guess {guess})"
            );
        }
        // The same in another frame and units: turned, moved, in millimetres.
        let motion = Similarity {
            scale: 1000.0,
            rotation: *Rotation3::from_euler_angles(1.2, -0.4, 2.5).matrix(),
            translation: Vector3::new(300.0, -20.0, 1500.0),
        };
        let moved_scan = Mesh::new(motion.apply_all(&scan.positions), scan.triangles.clone());
        let moved = place_acromions(
            &template,
            &motion.apply_all(&fitted),
            &moved_scan,
            1000.0,
            &params,
        );
        for side in 0..2 {
            let (a, b) = (moved[side].unwrap(), motion.apply(&found[side].unwrap()));
            assert!((a - b).norm() < 1e-6, "side {side}: {a} against {b}");
        }
        // Arms raised to the side (here by turning the arms' parts): not sure, the fit's guesses
        // stand.
        let raised = body.posed(&arms_hanging(&body, 80.0));
        let found = place_acromions(
            &template,
            &raised.positions,
            &raised,
            1.0,
            &AcromionParams::default(),
        );
        assert_eq!(found, [None, None]);
    }
}
