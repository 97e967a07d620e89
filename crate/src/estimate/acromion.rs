//! The Acromions on the scan's own shoulder. The fit reads each Acromion off the template's
//! vertex, and nearest points do not see where along the shoulder's rounded cap that vertex
//! belongs: on the development subjects the fit's Acromions slid down onto the arm's outer side
//! or in towards the neck by 2–3 cm (lateral and vertical errors of opposite sign, the same on
//! both sides of a subject) and 15–20 mm to the front or back (docs/landmarks-estimate.md).
//!
//! Each is placed by the shoulder's rule ([`crate::landmarks::shoulder`], which the
//! measurements share): the scan's shoulder point near the fit's guess, the surface's furthest
//! reach halfway between the shoulder's top and the upper arm's outer side, plus the template's
//! offset of its Acromion vertex from its own shoulder point at rest, in the fitted body's trunk
//! frame at the body's scale. (The template posed like the scan by the segment-wise fit, its
//! parts blended at the shoulder, placed them worse: 22.4 mm on the development seeds against
//! 18.3 from the rest pose.) Front to back the fit's guess is kept (the cap's crest was no
//! nearer). Nothing depends on the scan's frame or units, nor on the generator. One search
//! around the guess (the measurements climb further, `MeasureParams::acromion_searches`).
//!
//! Not sure, and the fit's guess kept, where there is no turn (an upper arm raised more than
//! [`AcromionParams::max_abduction_deg`]), where the reach runs on to the window's edge, or where
//! the window holds too little surface.

use nalgebra::Point3;

use super::params::AcromionParams;
use crate::landmarks::shoulder::{
    acromion_at, acromion_indices, shoulder_point, Cap, ShoulderFrame,
};
use crate::mesh::surface_points::surface_near;
use crate::mesh::Mesh;

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
            let window = (
                params.radius * s,
                params.edge * s,
                Cap::even(params.cap * s),
            );
            // The scan's points alike: its grids are laid anew on every scan anyway.
            let points: Vec<_> = points.into_iter().map(|p| (p, 1.0)).collect();
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
        // Front to back the fit's guess stands: the cap's crest was no nearer the truth.
        .map(|p| acromion_at(frame, &p, offset, &guess, size, params.keep_forward));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    use nalgebra::{Rotation3, Vector3};

    use crate::mesh::similarity::Similarity;
    use crate::template::fixture::{base_body, BaseBody};
    use crate::template::parts::PartPose;

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
