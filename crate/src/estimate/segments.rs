//! The segment-wise (articulated) fit: the template's own segments (head, torso, arms, legs —
//! the six of paper §4.2.1, with their blend weights) with the arms split at the elbow and the
//! legs at the knee, each moved rigidly (at the body's common scale) by iterative closest
//! points, the vertex positions blended by the weights as in linear blend skinning. It takes the
//! template from the similarity fit to the scan's pose (arms down or raised, hands on hips, feet
//! apart or together) before the stiff non-rigid fit; no skeleton and no shape model are needed.
//!
//! The head is held by its nose tip rather than by its joint: the template's nose tip
//! (`template::face`) is pulled to the scan's (`mesh::tip`, near where the head's pose puts it),
//! since nearest points slide a head's surface over the scan's head almost freely. A part other
//! than the torso with three or more given landmarks (placed by a person) is pulled by them
//! instead (`SegmentParams::given_min`, `given_share`): they fix its pose where the nose tip or
//! the nearest points went wrong.
//!
//! The thigh and the lower leg also stretch along their own axis (about the hip or the knee):
//! the body's common scale leaves them as long as the template's, whatever the subject's leg
//! proportions. Nearest points do not see where along a near-cylindrical limb the knee or the
//! elbow is, so before the last iterations each arm's elbow is placed where its upper arm's and
//! forearm's axes meet (`bent_arm.rs`) and each leg's cross-section profile places its knee
//! (`profile.rs`; an arm in line with its shoulder → elbow line is placed so too): the thigh's
//! and the upper arm's stretches are set from it and held, the lower leg's refitted, the forearm
//! kept rigid; a knee is then set by where the front of the leg steps back to the shin below the
//! patella. Before that the torso's own length (along its
//! axis down from the neck) is set from the height of the buttocks (`buttocks.rs`) and the torso
//! then held. (Fitting the arm parts' stretch by ICP, a hand
//! part of its own and pulling a thigh towards where the lower leg puts the knee were measured
//! and made the estimate worse: docs/landmarks-estimate.md.)

use std::ops::ControlFlow;

use nalgebra::{Point3, Vector3};

use super::arm_swing::swing_arms;
use super::bent_arm::place_bent_elbows;
use super::buttocks::{place_buttocks, psis_midpoint};
use super::knees::{knee_placements, legs_energy, PlacedKnee};
use super::matching::Matching;
use super::params::{ProfileParams, SegmentParams};
use super::profile::{fraction, knee_from_front, profile, reach, register, LimbLine};
use super::tick::Ticker;
use crate::mesh::normals::vertex_normals;
use crate::mesh::similarity::{similarity, Similarity};
use crate::mesh::surface_points::{surface_samples, thinned};
use crate::mesh::tip::tip;
use crate::mesh::Mesh;
use crate::template::face::nose_tip;
use crate::template::parts::{blend, dominant_parts, limb_bend, Part, PartPose};
use crate::template::Template;

/// The stretch along `part`'s axis that best explains `wanted` (template point, where it should
/// go) in the placement `transform`: the least-squares ratio of the axial distances from the
/// joint, target over template, within `range`.
fn fit_stretch(
    part: &Part,
    axis: &Vector3<f64>,
    transform: &Similarity,
    wanted: &[(Point3<f64>, Point3<f64>)],
    range: (f64, f64),
) -> Option<f64> {
    let (mut num, mut den) = (0.0, 0.0);
    for (p, q) in wanted {
        let u = (p - part.joint).dot(axis);
        num += u * (transform.apply_inverse(q) - part.joint).dot(axis);
        den += u * u;
    }
    (den > 0.0).then(|| (num / den).clamp(range.0, range.1))
}

/// Fits every part (rigid at `start`'s scale, a leg part stretched along its axis) by ICP from
/// `start`: each iteration blends the template, matches `vertices` to the scan, then fits each
/// part, parents first, to the matches of the vertices it dominates plus its joint held where
/// its (already moved) parent puts it — first the stretch in the part's last placement, then
/// the rigid motion of the stretched part. After `params.swing.after` iterations each arm is tried
/// at several turns about its shoulder (`arm_swing.rs`): nearest points alone leave an arm
/// held down along the body out at the template's A-pose. Then each elbow of an arm bent more
/// than `params.bent_arm.min_bend_deg` goes where its upper arm's and forearm's axes meet
/// (`bent_arm.rs`). Before the last `params.profile_iterations` the knees (and any straighter
/// arm's elbow) are moved along the limbs to where the limbs' cross-section profiles put them
/// (`profile.rs`, [`place_joints`]) and the torso's length is set by the buttocks
/// (`buttocks.rs`), the torso then held, both profiles taken from points spread over the surfaces
/// (`scan`, metres, is the mesh `matching` indexes): a coarse mesh's vertices alone lie in rings
/// too far apart. Knees far apart along their legs are each tried at the other's distance too,
/// and the placement whose legs then lie nearest the scan is kept (`knees.rs`). Returns the
/// blended positions, or `None` when the caller cancelled. `given` (template vertex, where it
/// goes on the scan, metres): landmarks a person placed, each pulling its part's rigid fit (as
/// `params.given_share` of the part's matches, split among them): three on the face re-pose a
/// head the nearest points and the nose tip turned.
#[allow(clippy::too_many_arguments)]
pub fn fit_segments(
    template: &Template,
    parts: &[Part],
    scan: &Mesh,
    start: Similarity,
    vertices: &[u32],
    matching: &Matching<'_>,
    given: &[(u32, Point3<f64>)],
    iterations: usize,
    params: &SegmentParams,
    profile: &ProfileParams,
    ticker: &mut Ticker<'_>,
) -> Option<Vec<Point3<f64>>> {
    let rest = &template.mesh().positions;
    let mut poses = vec![
        PartPose {
            transform: start,
            stretch: 1.0,
        };
        parts.len()
    ];
    let after_profile = params.profile_iterations.min(iterations / 2);
    let mut held = vec![false; parts.len()];
    let surface = surface_samples(rest, &template.mesh().triangles, params.surface_spacing);
    let scan_surface = surface_samples(&scan.positions, &scan.triangles, params.surface_spacing);
    let face = parts
        .iter()
        .position(|p| p.name == "head")
        .zip(nose_tip(template))
        .filter(|_| params.face.share > 0.0)
        .map(|(head, nose)| {
            // Only the scan's surface near where the start puts the nose is ever looked at, no
            // denser than the samples' spacing (a dense scan gives one sample per triangle).
            let start_nose = start.apply(&rest[nose as usize]);
            let reach = params.face.reach;
            Face {
                head,
                nose,
                scan: thinned(
                    scan_surface
                        .iter()
                        .filter(|p| (*p - start_nose).norm_squared() <= reach * reach),
                    params.surface_spacing,
                ),
            }
        });
    let dominant = dominant_parts(parts, rest.len());
    let given = given
        .iter()
        .filter_map(|&(v, at)| Some((dominant[v as usize]?, rest[v as usize], at)))
        .collect();
    let fit = Fit {
        template,
        parts,
        vertices,
        matching,
        dominant,
        params,
        face,
        given,
    };
    let before_swing = params.swing.after.min(iterations - after_profile);
    fit.iterate(&mut poses, &held, before_swing, ticker)?;
    swing_arms(
        parts,
        &mut poses,
        rest,
        &template.mesh().triangles,
        vertices,
        &fit.dominant,
        matching,
        &params.swing,
        |run| fit.iterate(run, &held, params.swing.iterations, ticker),
    )?;
    fit.iterate(
        &mut poses,
        &held,
        iterations - after_profile - before_swing,
        ticker,
    )?;
    // An arm's stretch is never fitted by the ICP: nothing to hold.
    place_bent_elbows(
        template,
        parts,
        &mut poses,
        vertices,
        &fit.dominant,
        matching,
        params,
    );
    if let Some(psis) = psis_midpoint(template) {
        place_buttocks(
            parts,
            &mut poses,
            &surface,
            &scan_surface,
            &psis,
            &params.buttocks,
        );
        held[0] = true;
    }
    let knees = place_joints(parts, &mut poses, &surface, &scan_surface, params, profile);
    for k in knees.held {
        held[k] = true;
    }
    let placements = knee_placements(&knees.legs, &poses, &params.knees, params.stretch_range);
    let compare = placements.len() > 1;
    // (the legs' energy, the blended positions) of the placement kept; one placement is not
    // compared.
    let mut best: Option<(f64, Vec<Point3<f64>>)> = None;
    for mut placed in placements {
        fit.iterate(&mut placed, &held, after_profile, ticker)?;
        let positions = blend(parts, &placed, rest);
        let energy = if compare {
            legs_energy(
                &positions,
                &template.mesh().triangles,
                vertices,
                &fit.dominant,
                &knees.legs,
                matching,
            )
        } else {
            0.0
        };
        if best.as_ref().is_none_or(|(e, _)| energy < *e) {
            best = Some((energy, positions));
        }
    }
    best.map(|(_, positions)| positions)
}

/// What the iterations of [`fit_segments`] share.
struct Fit<'a> {
    template: &'a Template,
    parts: &'a [Part],
    vertices: &'a [u32],
    matching: &'a Matching<'a>,
    dominant: Vec<Option<usize>>,
    params: &'a SegmentParams,
    face: Option<Face>,
    /// Given landmarks: (their part, the template's point at rest, where it goes on the scan).
    given: Vec<(usize, Point3<f64>, Point3<f64>)>,
}

/// The head's part, the template's nose tip and the scan's surface it is found on.
struct Face {
    head: usize,
    nose: u32,
    scan: Vec<Point3<f64>>,
}

impl Fit<'_> {
    /// The template's nose tip (at rest) and the scan's nose tip near where the head's `pose`
    /// puts it, seen from the front of the torso (`torso`'s pose): the point farthest along the
    /// head's own front turned the head back further each iteration, its face 11 cm off on
    /// held-out 2727/004 (head flexed 12°; 7 cm off along the torso's front), hence the tip that
    /// stands out from its surroundings. `None` when no scan point lies near.
    fn nose_tip(
        &self,
        face: &Face,
        head: &Part,
        pose: &PartPose,
        torso: &PartPose,
    ) -> Option<(Point3<f64>, Point3<f64>)> {
        let nose = self.template.mesh().positions[face.nose as usize];
        let forward = torso.transform.rotation * Vector3::z();
        let near = head.apply(pose, &nose);
        let params = &self.params.face;
        tip(
            &face.scan,
            &near,
            params.radius,
            &forward,
            params.surroundings,
        )
        .map(|at| (nose, at))
    }

    /// `iterations` of the fit from `poses`; a part whose `held` is set keeps its stretch, the
    /// torso (part 0) its whole pose: its length is set by the buttocks (`buttocks.rs`), and
    /// fitted rigidly again it moves up or down to where the template's length fitted best
    /// (head and neck 14.7 → 15.5 mm on the development subjects). `None` when the caller
    /// cancelled.
    fn iterate(
        &self,
        poses: &mut [PartPose],
        held: &[bool],
        iterations: usize,
        ticker: &mut Ticker<'_>,
    ) -> Option<()> {
        let rest = &self.template.mesh().positions;
        let triangles = &self.template.mesh().triangles;
        let scale = poses[0].transform.scale;
        for _ in 0..iterations {
            let positions = blend(self.parts, poses, rest);
            let normals = vertex_normals(&positions, triangles);
            let pairs = self.matching.pairs(self.vertices, &positions, &normals);
            if ticker.tick(Matching::rms(&pairs), pairs.len()) == ControlFlow::Break(()) {
                return None;
            }
            for (k, part) in self.parts.iter().enumerate() {
                let mut wanted: Vec<(Point3<f64>, Point3<f64>)> = pairs
                    .iter()
                    .filter(|p| self.dominant[p.vertex as usize] == Some(k))
                    .map(|p| (rest[p.vertex as usize], p.target))
                    .collect();
                if wanted.len() < 10 || (k == 0 && held[k]) {
                    continue;
                }
                let given: Vec<(Point3<f64>, Point3<f64>)> = self
                    .given
                    .iter()
                    .filter(|(part, _, _)| *part == k)
                    .map(|&(_, p, q)| (p, q))
                    .collect();
                // Not the torso: its pose is the frame, which four given landmarks already set,
                // and its thousands of matches place it better than three landmarks on a trunk
                // that is no rigid body.
                let anchored =
                    k != 0 && given.len() >= self.params.given_min && self.params.given_share > 0.0;
                if anchored {
                    let copies = ((wanted.len() as f64 * self.params.given_share)
                        / given.len() as f64) as usize;
                    for pair in given {
                        wanted.extend(std::iter::repeat_n(pair, copies.max(1)));
                    }
                }
                // The head's nose tip is pulled to the scan's, and then its joint is not held:
                // nearest points alone slid the head's surface down over the scan's head, its
                // joint holding it at the template's neck (docs/landmarks-estimate.md).
                let nose = self
                    .face
                    .as_ref()
                    .filter(|f| f.head == k && !anchored)
                    .and_then(|f| self.nose_tip(f, part, &poses[k], &poses[0]));
                if let Some(pair) = nose {
                    let copies = ((wanted.len() as f64 * self.params.face.share) as usize).max(3);
                    wanted.extend(std::iter::repeat_n(pair, copies));
                } else if let Some(parent) = part.parent {
                    // The joint stays attached: as many copies as a fifth of the part's matches,
                    // where the torso puts it before its stretch (the buttocks' length moves the
                    // torso's landmarks; legs following it left the knees and ankles worse,
                    // 9.7 → 12.1 and 9.3 → 10.9 mm on the development subjects).
                    let parent_pose = if parent == 0 {
                        PartPose {
                            stretch: 1.0,
                            ..poses[0]
                        }
                    } else {
                        poses[parent]
                    };
                    let at = self.parts[parent].apply(&parent_pose, &part.joint);
                    let copies = (wanted.len() / 5).max(3);
                    wanted.extend(std::iter::repeat_n((part.joint, at), copies));
                }
                let stretch = part
                    .axis
                    .filter(|_| part.stretches && !held[k])
                    .and_then(|a| {
                        fit_stretch(
                            part,
                            &a,
                            &poses[k].transform,
                            &wanted,
                            self.params.stretch_range,
                        )
                    })
                    .unwrap_or(poses[k].stretch);
                let from: Vec<_> = wanted
                    .iter()
                    .map(|(p, _)| part.stretched(p, stretch) * scale)
                    .collect();
                let to: Vec<_> = wanted.iter().map(|(_, q)| *q).collect();
                if let Some(rigid) = similarity(&from, &to, false) {
                    poses[k] = PartPose {
                        transform: Similarity {
                            scale,
                            rotation: rigid.rotation,
                            translation: rigid.translation,
                        },
                        stretch,
                    };
                }
            }
            unfold(self.parts, poses, self.params.max_fold_deg);
        }
        Some(())
    }
}

/// Straightens each limb folded past `max_fold_deg` (degrees) at the elbow or knee: its lower part takes
/// its parent's rotation, its joint kept where the parent puts it, and the ICP goes on from the
/// straight limb. Nearest points can fold a forearm held in front of the body back up along the
/// upper arm (the hand at the shoulder), which no elbow does. The fold is the angle between the
/// lower part's joint → end direction as posed and as its parent's rotation would carry it (a
/// turn about the limb's own axis is no fold).
fn unfold(parts: &[Part], poses: &mut [PartPose], max_fold_deg: f64) {
    for (k, part) in parts.iter().enumerate() {
        let (Some(parent), Some(end)) = (part.parent, part.end) else {
            continue;
        };
        let along = end - part.joint;
        let rotation = poses[parent].transform.rotation;
        if (rotation * along).angle(&(poses[k].transform.rotation * along))
            <= max_fold_deg.to_radians()
        {
            continue;
        }
        let bend = parts[parent].apply(&poses[parent], &part.joint);
        let scale = poses[parent].transform.scale;
        poses[k].transform = Similarity {
            scale,
            rotation,
            translation: bend.coords - rotation * part.joint.coords * scale,
        };
    }
}

/// Moves each knee (and the elbow of an arm bent no more than `bent_arm.min_bend_deg`, whose
/// axes do not meet surely) along its limb to where the limb's cross-section profile on `scan`
/// puts it (the template's profile from `surface`, points on its surface at rest, registered to
/// the one from `scan`, points on the scan's surface, `profile.rs`): the upper part's stretch scaled so that the joint's fraction of the
/// root → end line (hip → ankle, shoulder → wrist) is the profile's; a leg's knee is then moved to
/// where the front of the knee puts it (`knee_from_front`, the reach away from the part's
/// `back`: knees 25.6 → 9.7 mm on the development subjects). A leg's lower part is
/// stretched to keep the ankle where it was, as a start for its own stretch fit; the forearm
/// stays rigid and moves with the elbow (stretching it to keep the wrist made the hands worse,
/// 39 → 48 mm on the development subjects). Returns the upper parts, whose stretch is then held
/// (holding a lower leg's too left the ankles and feet ≈ 1 mm worse), and the knees as placed
/// (compared side against side by the caller, `knees.rs`).
fn place_joints(
    parts: &[Part],
    poses: &mut [PartPose],
    surface: &[Point3<f64>],
    scan: &[Point3<f64>],
    params: &SegmentParams,
    profile_params: &ProfileParams,
) -> PlacedJoints {
    // Each limb: (upper part, lower part, its end), its line at rest and where the fit put it.
    let limbs: Vec<(usize, usize, Point3<f64>)> = parts
        .iter()
        .enumerate()
        .filter_map(|(k, p)| Some((p.parent?, k, p.end?)))
        .collect();
    let line = |(upper, lower, end): (usize, usize, Point3<f64>), posed: bool| {
        let place = |k: usize, p: &Point3<f64>| {
            if posed {
                parts[k].apply(&poses[k], p)
            } else {
                *p
            }
        };
        let root = place(upper, &parts[upper].joint);
        let bend = place(lower, &parts[lower].joint);
        let end = place(lower, &end);
        let reach = if parts[lower].stretches {
            0.0
        } else {
            params.hand_reach
        };
        LimbLine {
            root,
            end: end + (end - bend) * reach,
        }
    };
    let at_rest: Vec<LimbLine> = limbs.iter().map(|l| line(*l, false)).collect();
    let posed: Vec<LimbLine> = limbs.iter().map(|l| line(*l, true)).collect();
    let mut placed = PlacedJoints {
        held: Vec::new(),
        legs: Vec::new(),
    };
    for (i, &(upper, lower, end)) in limbs.iter().enumerate() {
        if parts[lower].axis.is_none() || parts[upper].axis.is_none() {
            continue;
        }
        let arm = !parts[lower].stretches;
        // A bent arm's elbow is where its axes meet (`bent_arm.rs`).
        let max_bend = if arm {
            params.bent_arm.min_bend_deg
        } else {
            params.max_bend_deg
        };
        if limb_bend(parts, poses, upper, lower, &end) > max_bend.to_radians() {
            continue;
        }
        let bend = parts[lower].apply(&poses[lower], &parts[lower].joint);
        let joint = fraction(&at_rest[i], &parts[lower].joint);
        let now = fraction(&posed[i], &bend);
        let radius = if arm {
            params.arm_radius
        } else {
            params.leg_radius
        };
        let template_profile = profile(surface, &at_rest, i, radius, profile_params);
        let scan_profile = profile(scan, &posed, i, radius, profile_params);
        let Some(mut f) = register(&template_profile, &scan_profile, joint, now, profile_params)
        else {
            continue;
        };
        if let Some(back) = parts[lower].back {
            let posed_back = poses[lower].transform.rotation * back;
            let template_front = reach(surface, &at_rest, i, radius, &-back, profile_params);
            let scan_front = reach(scan, &posed, i, radius, &-posed_back, profile_params);
            f = knee_from_front(&template_front, &scan_front, joint, f, profile_params)
                .unwrap_or(f);
        }
        let range = params.stretch_range;
        if arm {
            poses[upper].stretch = (poses[upper].stretch * f / now).clamp(range.0, range.1);
        } else {
            let mut knee = PlacedKnee {
                upper,
                lower,
                before: now,
                placed: f,
                length: (posed[i].end - posed[i].root).norm(),
                stretches: (poses[upper].stretch, poses[lower].stretch),
            };
            knee.placed = knee.place(poses, f, range);
            placed.legs.push(knee);
        }
        placed.held.push(upper);
    }
    placed
}

/// What [`place_joints`] placed: the upper parts whose stretch is then held, and the knees.
struct PlacedJoints {
    held: Vec<usize>,
    legs: Vec<PlacedKnee>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::template::fixture::base_body;

    const RANGE: (f64, f64) = (0.75, 1.33);

    #[test]
    fn a_stretched_part_is_fitted_back() {
        let part = Part {
            name: "thigh",
            weights: Vec::new(),
            parent: None,
            joint: Point3::new(0.0, 0.0, 1.0),
            axis: Some(-Vector3::z()),
            end: None,
            stretches: true,
            back: None,
        };
        // The part 1.2 times as long along its axis, turned by the transform.
        let transform = Similarity {
            scale: 1.0,
            rotation: *nalgebra::Rotation3::from_axis_angle(&Vector3::x_axis(), 0.3).matrix(),
            translation: Vector3::new(0.1, 0.2, 0.3),
        };
        let pose = PartPose {
            transform,
            stretch: 1.2,
        };
        let wanted: Vec<_> = (0..20)
            .map(|i| {
                let p = Point3::new(0.05 * (i % 3) as f64, 0.02, 1.0 - 0.02 * i as f64);
                (p, part.apply(&pose, &p))
            })
            .collect();
        let s = fit_stretch(&part, &part.axis.unwrap(), &transform, &wanted, RANGE).unwrap();
        assert!((s - 1.2).abs() < 1e-12, "{s}");
        // Beyond the range it is clamped.
        let far = PartPose {
            stretch: 2.0,
            ..pose
        };
        let wanted: Vec<_> = wanted
            .iter()
            .map(|(p, _)| (*p, part.apply(&far, p)))
            .collect();
        let s = fit_stretch(&part, &part.axis.unwrap(), &transform, &wanted, RANGE).unwrap();
        assert_eq!(s, RANGE.1);
    }

    #[test]
    fn a_limb_folded_back_is_straightened_and_a_bent_one_kept() {
        let parts = base_body().parts;
        let identity = PartPose::identity();
        let (k, lower) = parts
            .iter()
            .enumerate()
            .find(|(_, p)| !p.stretches && p.end.is_some())
            .unwrap();
        let upper = &parts[lower.parent.unwrap()];
        let bend_at = |poses: &[PartPose]| {
            let root = upper.apply(&poses[lower.parent.unwrap()], &upper.joint);
            let tip = lower.apply(&poses[k], &lower.end.unwrap());
            (
                (lower.joint - root)
                    .angle(&(tip - lower.joint))
                    .to_degrees(),
                tip,
            )
        };
        // The forearm turned about the elbow, across the arm, by `deg`.
        let folded = |deg: f64| {
            let across = (lower.end.unwrap() - lower.joint)
                .cross(&Vector3::y())
                .normalize();
            let r = nalgebra::Rotation3::from_axis_angle(
                &nalgebra::Unit::new_normalize(across),
                deg.to_radians(),
            );
            let mut poses = vec![identity; parts.len()];
            poses[k].transform = Similarity {
                scale: 1.0,
                rotation: *r.matrix(),
                translation: lower.joint.coords - r * lower.joint.coords,
            };
            poses
        };
        let (rest, rest_tip) = bend_at(&vec![identity; parts.len()]);
        // Bent by 120°: an elbow can, it stays.
        let mut poses = folded(120.0);
        let before = bend_at(&poses);
        unfold(&parts, &mut poses, 145.0);
        assert_eq!(bend_at(&poses), before);
        assert!((before.1 - rest_tip).norm() > 0.2);
        // Folded back up along the upper arm: straightened to the rest, the elbow in place.
        let mut poses = folded(170.0);
        unfold(&parts, &mut poses, 145.0);
        let (now, tip) = bend_at(&poses);
        assert!((now - rest).abs() < 1e-9, "{now} {rest}");
        assert!((tip - rest_tip).norm() < 1e-9);
        assert!((lower.apply(&poses[k], &lower.joint) - lower.joint).norm() < 1e-12);
    }
}
