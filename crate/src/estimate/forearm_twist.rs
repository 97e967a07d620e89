//! The forearm's twist in the check of a given file (`check.rs`): a forearm is no rigid body
//! when the wrist turns about it (pronation and supination), and a hand laid on the hip turns it
//! far. The styloids, at the forearm's far end, then lie off the prediction of the forearm's
//! other landmarks by up to the wrist's width; turned about the forearm's axis they do not.
//!
//! The pose is read from the given landmarks themselves, no fit: the elbow's bend is the angle
//! between the upper arm (the acromion → the epicondyles' midpoint as the forearm's map puts
//! it) and the forearm's axis (the map of the template's epicondyles' midpoint → its styloids'
//! midpoint). An elbow bent more than [`CheckParams::twist_min_bend_deg`] lets the forearm
//! twist: a styloid's prediction is turned about that axis to the angle of the given position
//! (the nearest point on the circle the prediction sweeps about the axis), so what is judged is
//! its place along the forearm and its distance from the axis — both kept by any twist — and a
//! swapped pair or a typo along the forearm is still found. Nor do the styloids of such a bent
//! arm ([`Forearm::bent`], by the given landmarks alone) predict the forearm's other landmarks:
//! turned, they would spoil the elbow's prediction. A given styloid more than
//! [`CheckParams::twist_max_off_axis`] times as far from the axis as its prediction is not
//! turned to (a styloid of the other side, across the body, is no twist).

use nalgebra::{Point3, Rotation3, Unit};

use super::params::CheckParams;
use crate::landmarks::CAESAR_LANDMARKS;
use crate::mesh::similarity::Similarity;

/// One forearm's landmarks (CAESAR indices).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forearm {
    pub acromion: usize,
    /// The humeral epicondyles (lateral, medial): the elbow's hinge.
    pub epicondyles: [usize; 2],
    /// The styloids (radial, ulnar): the wrist.
    pub styloids: [usize; 2],
}

impl Forearm {
    /// Both forearms, left first.
    pub fn both() -> [Forearm; 2] {
        let index = |name: String| {
            CAESAR_LANDMARKS
                .iter()
                .position(|l| l.name == name)
                .expect("a forearm's landmarks are CAESAR landmarks")
        };
        ["Lt.", "Rt."].map(|side| {
            let i = |n: &str| index(format!("{side} {n}"));
            Forearm {
                acromion: i("Acromion"),
                epicondyles: [i("Humeral Lateral Epicn"), i("Humeral Medial Epicn")],
                styloids: [i("Radial Styloid"), i("Ulnar Styloid")],
            }
        })
    }

    /// Whether the elbow bends more than [`CheckParams::twist_min_bend_deg`] by the trusted
    /// given landmarks (`at`: a landmark's position, scan units): the acromion → the
    /// epicondyles' midpoint against that → the styloids' midpoint. Then the styloids do not
    /// predict the forearm's other landmarks (`check.rs`).
    pub fn bent(&self, at: &dyn Fn(usize) -> Option<Point3<f64>>, params: &CheckParams) -> bool {
        let mid = |[a, b]: [usize; 2]| Some(Point3::from((at(a)?.coords + at(b)?.coords) / 2.0));
        let (Some(acromion), Some(elbow), Some(wrist)) =
            (at(self.acromion), mid(self.epicondyles), mid(self.styloids))
        else {
            return false;
        };
        (elbow - acromion).angle(&(wrist - elbow)).to_degrees() > params.twist_min_bend_deg
    }

    /// The forearm whose styloid is `i`, if any.
    pub fn of_styloid(i: usize) -> Option<Forearm> {
        Self::both().into_iter().find(|f| f.styloids.contains(&i))
    }
}

/// The prediction `position` of the styloid `forearm` holds, by the forearm's `map` (the
/// similarity taking the template's landmarks `landmark_rest` of the forearm's others onto their
/// given positions), turned about the forearm's axis to the angle of its `given` position when
/// the elbow, with the trusted `acromion` (scan units), bends more than the parameters allow
/// straight; else `position` as it is.
pub fn twisted(
    forearm: &Forearm,
    map: &Similarity,
    landmark_rest: &[Point3<f64>],
    acromion: Option<Point3<f64>>,
    position: Point3<f64>,
    given: Point3<f64>,
    params: &CheckParams,
) -> Point3<f64> {
    let Some(acromion) = acromion else {
        return position;
    };
    let mid = |[a, b]: [usize; 2]| {
        map.apply(&Point3::from(
            (landmark_rest[a].coords + landmark_rest[b].coords) / 2.0,
        ))
    };
    let (elbow, wrist) = (mid(forearm.epicondyles), mid(forearm.styloids));
    let (upper, axis) = (elbow - acromion, wrist - elbow);
    if upper.angle(&axis).to_degrees() <= params.twist_min_bend_deg {
        return position;
    }
    let axis = Unit::new_normalize(axis);
    let across = |p: Point3<f64>| {
        let d = p - elbow;
        d - axis.as_ref() * d.dot(&axis)
    };
    let (from, to) = (across(position), across(given));
    // A given styloid far off the forearm's axis is no turned wrist (a styloid of the other
    // side lies across the body): turned towards it, the prediction would only blur the flag.
    if from.norm() < 1e-12
        || to.norm() < 1e-12
        || to.norm() > params.twist_max_off_axis * from.norm()
    {
        return position;
    }
    let angle = from.angle(&to) * from.cross(&to).dot(&axis).signum();
    elbow + Rotation3::from_axis_angle(&axis, angle) * (position - elbow)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    #[test]
    fn a_turn_about_the_axis_is_undone_and_a_shift_along_it_kept() {
        let forearm = Forearm::both()[0];
        let mut rest = vec![Point3::origin(); CAESAR_LANDMARKS.len()];
        rest[forearm.epicondyles[0]] = Point3::new(0.03, 0.0, 0.0);
        rest[forearm.epicondyles[1]] = Point3::new(-0.03, 0.0, 0.0);
        rest[forearm.styloids[0]] = Point3::new(0.025, -0.25, 0.0);
        rest[forearm.styloids[1]] = Point3::new(-0.025, -0.25, 0.0);
        let map = Similarity::identity();
        let params = CheckParams {
            twist_min_bend_deg: 60.0,
            ..CheckParams::default()
        };
        let predicted = rest[forearm.styloids[0]];
        let turn = Rotation3::from_axis_angle(&Vector3::y_axis(), 1.2);
        let given = Point3::from(turn * predicted.coords);
        // The upper arm along the forearm's axis (straight): no twist.
        let straight = Some(Point3::new(0.0, 0.3, 0.0));
        let p = twisted(&forearm, &map, &rest, straight, predicted, given, &params);
        assert_eq!(p, predicted);
        // Bent 90°: the turn is undone, a shift along the forearm is not.
        let bent = Some(Point3::new(0.0, 0.0, 0.3));
        let p = twisted(&forearm, &map, &rest, bent, predicted, given, &params);
        assert!((p - given).norm() < 1e-12, "{p} {given}");
        let along = given + Vector3::new(0.0, 0.03, 0.0);
        let p = twisted(&forearm, &map, &rest, bent, predicted, along, &params);
        assert!(((p - along).norm() - 0.03).abs() < 1e-12);
        // Far off the axis (the other wrist): not turned to.
        let far = Point3::new(-0.3, -0.25, 0.1);
        let p = twisted(&forearm, &map, &rest, bent, predicted, far, &params);
        assert_eq!(p, predicted);
    }
}
