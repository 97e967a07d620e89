//! The elbow of an arm bent at it. Nearest points do not see where along a near-cylindrical arm
//! the elbow is, and the limbs' profiles (`profile.rs`) placed it 16 mm off on the development
//! subjects; a bent arm kept the template's upper-arm length (× the body's scale), its forearm
//! held at that elbow, and nearest points then pulled the forearm and the hand towards the elbow
//! and into the hip. An arm shows its elbow in its shape: the corner where the upper arm's axis
//! (from the shoulder joint, inside the shoulder) meets the forearm's. So here, for every arm
//! bent more than `BentArmParams::min_bend_deg` (the template's straight arm is bent ≈ 39° so),
//! the forearm (with the hand) is fitted on its own, rigid and not held at the elbow, from its
//! surface beyond the elbow's blend; the upper arm is stretched along its axis to the point
//! nearest the forearm's axis, and the forearm, turned as its own fit turned it, is held at that
//! elbow. An arm bent more than `SegmentParams::max_bend_deg` (hands on hips) then has its upper
//! arm turned about its own axis until the elbow's hinge lies across the plane of the two axes,
//! as a real elbow's does (`roll_to_hinge`; the segment-wise fit had left it 47–90° off: the
//! elbows' landmarks 23.8 mm off on held-out seed 7531, 18.8 mm turned); a straighter arm is
//! not turned (the turn moved its shoulder's blend and the Acromions 20–24 → 25–30 mm on the
//! development subjects). The segment-wise fit then goes on from there.

use nalgebra::{Point3, Rotation3, Vector3};

use super::arm_swing::arms;
use super::matching::Matching;
use super::params::SegmentParams;
use super::profile::{fraction, LimbLine};
use crate::mesh::similarity::{similarity, Similarity};
use crate::template::parts::{limb_bend, Part, PartPose};
use crate::template::Template;

/// The parameter along the line `a + s·u` of its point nearest the line `b + t·v` (unit
/// directions), `None` when the lines are near parallel.
fn nearest_on(a: &Point3<f64>, u: &Vector3<f64>, b: &Point3<f64>, v: &Vector3<f64>) -> Option<f64> {
    let w = a - b;
    let c = u.dot(v);
    let den = 1.0 - c * c;
    (den > 1e-6).then(|| (c * v.dot(&w) - u.dot(&w)) / den)
}

/// The upper part's stretch that puts the elbow (the lower part's joint) where the upper arm's
/// axis passes nearest the forearm's axis in `forearm` (the forearm's own placement), within
/// the stretch `range`; `None` when the axes are near parallel.
fn elbow_stretch(
    upper: &Part,
    upper_pose: &PartPose,
    lower: &Part,
    forearm: &Similarity,
    range: (f64, f64),
) -> Option<f64> {
    let (axis, lower_axis) = (upper.axis?, lower.axis?);
    let t = upper_pose.transform;
    let root = t.apply(&upper.joint);
    let u = t.rotation * axis;
    let along = nearest_on(
        &root,
        &u,
        &forearm.apply(&lower.joint),
        &(forearm.rotation * lower_axis),
    )?;
    let length = (lower.joint - upper.joint).dot(&axis) * t.scale;
    (length > 0.0).then(|| (along / length).clamp(range.0, range.1))
}

/// The template's elbow hinge of the arm whose upper part is `upper` (unit, template frame): from
/// the lateral to the medial humeral epicondyle.
fn hinge(template: &Template, upper: &Part) -> Option<Vector3<f64>> {
    let side = if upper.name.starts_with("left") {
        "Lt."
    } else {
        "Rt."
    };
    let at = |name: &str| {
        let v = template.landmark_vertex(&format!("{side} Humeral {name} Epicn"))?;
        Some(template.mesh().positions[v as usize])
    };
    (at("Medial")? - at("Lateral")?).try_normalize(1e-9)
}

/// A real elbow bends about one hinge, across the plane of the upper arm and the forearm. The
/// upper arm (`upper_pose`) is turned about its own axis (through the shoulder) until the
/// template's `hinge` lies across the plane of its axis and the forearm's (`forearm`'s own fit),
/// on the side the template's elbow flexes to; the forearm then takes the upper arm's rotation,
/// flexed about that hinge onto its own axis. Its own turn about its axis (pronation,
/// supination) is left to the hand (`hand.rs`): nearest points do not see it on a forearm.
fn roll_to_hinge(
    upper: &Part,
    upper_pose: &mut PartPose,
    lower: &Part,
    forearm: &mut Similarity,
    hinge: Vector3<f64>,
) -> Option<()> {
    let (upper_axis, lower_axis) = (upper.axis?, lower.axis?);
    let flexes = upper_axis.cross(&lower_axis).dot(&hinge).signum();
    let t = &mut upper_pose.transform;
    let u = (t.rotation * upper_axis).normalize();
    let f = (forearm.rotation * lower_axis).normalize();
    let target = u.cross(&f).try_normalize(1e-9)? * flexes;
    let across = |v: Vector3<f64>| (v - u * v.dot(&u)).try_normalize(1e-9);
    let (from, to) = (across(t.rotation * hinge)?, across(target)?);
    let roll = from.cross(&to).dot(&u).atan2(from.dot(&to));
    let shoulder = t.apply(&upper.joint);
    t.rotation = Rotation3::from_scaled_axis(u * roll).matrix() * t.rotation;
    t.translation = shoulder.coords - t.scale * (t.rotation * upper.joint.coords);
    let carried = (t.rotation * lower_axis).normalize();
    let flex = Rotation3::rotation_between(&carried, &f)?;
    forearm.rotation = flex.matrix() * t.rotation;
    Some(())
}

/// For each arm bent more than `params.bent_arm.min_bend_deg` in `poses` (of `parts`, of
/// `template` at the resolution fitted): its forearm fitted on its own for
/// `params.bent_arm.forearm_iterations` (those of `vertices` whose `dominant` part is the
/// forearm, from `params.bent_arm.forearm_start` of the way to the wrist on, matched by
/// `matching`), the upper arm's stretch set by [`elbow_stretch`], its hinge turned across the
/// axes' plane when it is bent more than `params.max_bend_deg` ([`roll_to_hinge`]), and the
/// forearm held there in its own turn. Returns the upper parts placed.
pub fn place_bent_elbows(
    template: &Template,
    parts: &[Part],
    poses: &mut [PartPose],
    vertices: &[u32],
    dominant: &[Option<usize>],
    matching: &Matching<'_>,
    params: &SegmentParams,
) -> Vec<usize> {
    let rest = &template.mesh().positions;
    let rest_normals = template.mesh().vertex_normals();
    let mut placed = Vec::new();
    for arm in arms(parts) {
        let (upper, lower) = (&parts[arm.upper], &parts[arm.lower]);
        let Some(end) = lower.end else { continue };
        let bend = limb_bend(parts, poses, arm.upper, arm.lower, &end);
        if bend <= params.bent_arm.min_bend_deg.to_radians() {
            continue;
        }
        let line = LimbLine {
            root: lower.joint,
            end,
        };
        let own: Vec<u32> = vertices
            .iter()
            .copied()
            .filter(|&v| dominant[v as usize] == Some(arm.lower))
            .filter(|&v| fraction(&line, &rest[v as usize]) >= params.bent_arm.forearm_start)
            .collect();
        let mut forearm = poses[arm.lower];
        let scale = forearm.transform.scale;
        let mut positions = rest.to_vec();
        let mut normals = rest_normals.to_vec();
        for _ in 0..params.bent_arm.forearm_iterations {
            for &v in &own {
                positions[v as usize] = lower.apply(&forearm, &rest[v as usize]);
                normals[v as usize] = forearm.transform.rotation * rest_normals[v as usize];
            }
            let pairs = matching.pairs(&own, &positions, &normals);
            if pairs.len() < 10 {
                break;
            }
            let from: Vec<_> = pairs
                .iter()
                .map(|p| lower.stretched(&rest[p.vertex as usize], forearm.stretch) * scale)
                .collect();
            let to: Vec<_> = pairs.iter().map(|p| p.target).collect();
            let Some(rigid) = similarity(&from, &to, false) else {
                break;
            };
            forearm.transform = Similarity {
                scale,
                rotation: rigid.rotation,
                translation: rigid.translation,
            };
        }
        let Some(stretch) = elbow_stretch(
            upper,
            &poses[arm.upper],
            lower,
            &forearm.transform,
            params.stretch_range,
        ) else {
            continue;
        };
        poses[arm.upper].stretch = stretch;
        let hinge = hinge(template, upper).filter(|_| bend > params.max_bend_deg.to_radians());
        if let Some(hinge) = hinge {
            roll_to_hinge(
                upper,
                &mut poses[arm.upper],
                lower,
                &mut forearm.transform,
                hinge,
            );
        }
        // The forearm held at the new elbow.
        let elbow = upper.apply(&poses[arm.upper], &lower.joint);
        forearm.transform.translation += elbow - lower.apply(&forearm, &lower.joint);
        poses[arm.lower] = forearm;
        placed.push(arm.upper);
    }
    placed
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::align::SurfaceIndex;
    use crate::estimate::params::EstimateParams;
    use crate::template::fixture::base_body;
    use crate::template::parts::dominant_parts;
    use nalgebra::{Rotation3, Unit};

    #[test]
    fn a_bent_arms_elbow_is_placed_where_its_axes_meet() {
        let body = base_body();
        let (template, rest, parts) = (&body.template, &body.rest, &body.parts);
        let identity = PartPose::identity();
        // The "scan": the template with each upper arm 15% longer and its forearm bent 90° at
        // the elbow; the start: the same bend at the template's elbow.
        let arms = arms(parts);
        assert_eq!(arms.len(), 2);
        let mut scan_poses = vec![identity; parts.len()];
        let mut start = scan_poses.clone();
        for arm in &arms {
            let (upper, lower) = (&parts[arm.upper], &parts[arm.lower]);
            let across = upper.axis.unwrap().cross(&Vector3::y());
            let r = Rotation3::from_axis_angle(&Unit::new_normalize(across), 90f64.to_radians());
            let bent_at = |elbow: Point3<f64>| Similarity {
                scale: 1.0,
                rotation: *r.matrix(),
                translation: elbow.coords - r * lower.joint.coords,
            };
            scan_poses[arm.upper].stretch = 1.15;
            let elbow = upper.apply(&scan_poses[arm.upper], &lower.joint);
            scan_poses[arm.lower].transform = bent_at(elbow);
            start[arm.lower].transform = bent_at(lower.joint);
        }
        let vertices: Vec<u32> = (0..rest.len() as u32).step_by(2).collect();
        let dominant = dominant_parts(parts, rest.len());
        // The elbows placed from `poses` on the template posed as `scan_poses`.
        let place_on = |scan_poses: &[PartPose], poses: &mut [PartPose]| {
            let scan = body.posed(scan_poses);
            let index = SurfaceIndex::new(&scan).unwrap();
            let matching = Matching::new(&index, &EstimateParams::default());
            place_bent_elbows(
                template,
                parts,
                poses,
                &vertices,
                &dominant,
                &matching,
                &SegmentParams::default(),
            )
        };
        let mut poses = start.clone();
        let placed = place_on(&scan_poses, &mut poses);
        assert_eq!(placed, arms.iter().map(|a| a.upper).collect::<Vec<_>>());
        for arm in &arms {
            let stretch = poses[arm.upper].stretch;
            assert!((stretch - 1.15).abs() < 0.02, "{stretch}");
            // The wrist lands on the scan's.
            let end = parts[arm.lower].end.unwrap();
            let wrist = parts[arm.lower].apply(&poses[arm.lower], &end);
            let want = parts[arm.lower].apply(&scan_poses[arm.lower], &end);
            assert!((wrist - want).norm() < 0.005, "{}", (wrist - want).norm());
            // The elbow's hinge (across the upper arm) lies along the normal of the plane of the
            // upper arm and the forearm.
            let t = &poses[arm.upper].transform;
            let u = (t.rotation * parts[arm.upper].axis.unwrap()).normalize();
            let hinge = t.rotation * hinge(template, &parts[arm.upper]).unwrap();
            let across = hinge - u * hinge.dot(&u);
            let normal =
                u.cross(&(poses[arm.lower].transform.rotation * parts[arm.lower].axis.unwrap()));
            let off = across.angle(&normal).to_degrees();
            assert!(off.min(180.0 - off) < 1.0, "{off}°");
        }
        // An arm bent as the template's own (≈ 39° at the elbow: its shoulder joint sits inside
        // the shoulder) on a scan whose upper arms are 15% longer: its elbow is found there too,
        // and its upper arm is not turned about its own axis.
        let mut long_arms = vec![identity; parts.len()];
        for arm in &arms {
            long_arms[arm.upper].stretch = 1.15;
            let elbow = parts[arm.upper].apply(&long_arms[arm.upper], &parts[arm.lower].joint);
            long_arms[arm.lower].transform.translation = elbow - parts[arm.lower].joint;
        }
        let mut poses = vec![identity; parts.len()];
        assert_eq!(place_on(&long_arms, &mut poses).len(), 2);
        for arm in &arms {
            let stretch = poses[arm.upper].stretch;
            assert!((stretch - 1.15).abs() < 0.02, "{stretch}");
            assert_eq!(
                poses[arm.upper].transform.rotation,
                identity.transform.rotation
            );
        }
        // An arm whose forearm runs on in line with its shoulder → elbow line is left alone.
        let mut straight = vec![identity; parts.len()];
        for arm in &arms {
            let (upper, lower) = (&parts[arm.upper], &parts[arm.lower]);
            let r =
                Rotation3::rotation_between(&lower.axis.unwrap(), &upper.axis.unwrap()).unwrap();
            straight[arm.lower].transform = Similarity {
                scale: 1.0,
                rotation: *r.matrix(),
                translation: lower.joint.coords - r * lower.joint.coords,
            };
        }
        assert!(place_on(&long_arms, &mut straight).is_empty());
        assert!(straight.iter().all(|p| p.stretch == 1.0));
    }

    #[test]
    fn the_nearest_point_of_two_lines() {
        // The x axis and a line along y through (2, 5, 1): nearest at x = 2.
        let s = nearest_on(
            &Point3::origin(),
            &Vector3::x(),
            &Point3::new(2.0, 5.0, 1.0),
            &Vector3::y(),
        );
        assert!((s.unwrap() - 2.0).abs() < 1e-12);
        // Parallel lines have none.
        let p = nearest_on(
            &Point3::origin(),
            &Vector3::x(),
            &Point3::new(0.0, 1.0, 0.0),
            &Vector3::x(),
        );
        assert!(p.is_none());
    }
}
