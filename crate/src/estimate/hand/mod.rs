//! The hand's pose about the wrist (the template's hands: `template::hand`). After the segment-wise fit the hand has moved rigidly with
//! the forearm (which keeps the template's length and moves with the elbow): a wrist that sits
//! higher or lower along the arm than the template's, or a hand turned at the wrist, is not
//! followed — nearest-point matching of a whole forearm part barely sees the hand. Here:
//!
//! 1. the wrist slides along the forearm (the forearm stretched, the hand carried along) to
//!    where the forearm's width profile puts it (`wrist_from_profile`: the forearm narrowing to
//!    the wrist and widening into the hand, on the scan against the posed template). A hand is
//!    wider than the wrist whatever it hangs beside or rests on. (The hand's centroid, taken
//!    before, slid the wrist the wrong way where the scan's hand was short of fingertips or
//!    merged with the thigh: free hands 8.4–12.9 mm on held-out seeds, 6.6–11.8 mm by the
//!    profile.)
//! 2. a free hand turns about the wrist, from the scan's surface beyond the wrist (within the
//!    hand's reach, on the far side of the plane across the forearm at the wrist) against the
//!    posed template's hand surface there: the shortest rotation of the template hand's axis
//!    (wrist → centroid) onto the scan's, then about that axis the turn that brings the widest
//!    direction across the hand (the flat side) onto the scan's. The rotation is blended to
//!    nothing at the wrist. It is kept only when the hand's own vertices then match the scan
//!    better (nearest compatible points): the moments also see
//!    whatever else lies in the region, so a hand hanging beside the thigh was turned 55–58°
//!    away from where it hung (held-out seed 2468).
//! 3. a free hand is stretched along itself to the scan's fingertip (`stretch_to_fingertip`),
//!    where that lies near the template hand's.
//!
//! A hand that is not free (against the thigh) or not seen (a hole) shows there as much more or
//! much less surface than a hand: it is not turned. The hand of an arm bent more than the limbs'
//! profiles take (`SegmentParams::max_bend_deg`, hands on hips), or bent less with its forearm coming down
//! onto the body, is laid on the body, its surface merged with the hip's (`laid_hand`): its wrist
//! placed where the forearm levels out onto the hand, it is turned about the wrist so that its
//! palm lies against the body's plane there and its fingers along the most raised strip of the
//! scan on that plane (the hand lying on it), tilted as that strip's top slopes. The part of its
//! turn about the forearm is then carried down the forearm, as pronation and supination turn the
//! wrist with the hand.
//!
//! * [`pose`] — [`pose_hands`]: the slide, then the turn of a free hand kept when it matches
//!   better, or the hand laid on the body.
//! * [`moments`] — the surfaces beyond the wrist as area-weighted points: whether the scan's is
//!   hand-like ([`moments::hand_like`]) and the turn onto it ([`moments::hand_rotation`]).
//! * [`wrist_profile`] — the wrist's slide from the forearm's width profile.
//! * [`laid`] — a hand laid on the body: the raised strip the hand makes on the body's plane
//!   ([`body_plane`]), the palm across the knuckles' line; [`laid_wrist`] — its wrist where the
//!   forearm levels out.
//! * [`twist`] — a hand's turn about the forearm carried down the forearm.
//! * [`length`] — a free hand stretched to its fingertip on the scan.

pub mod body_plane;
pub mod laid;
pub mod laid_wrist;
pub mod length;
pub mod moments;
pub mod pose;
pub mod twist;
pub mod wrist_profile;

pub use pose::pose_hands;

use nalgebra::{Point3, Rotation3, Vector3};

use crate::template::hand::Hand;

/// Where a hand was moved: the wrist's slide along the forearm (m), the turn about it and the
/// stretch to its fingertip.
#[derive(Debug, Clone, Copy)]
pub struct HandPose {
    pub slide: f64,
    pub rotation: Option<Rotation3<f64>>,
    pub stretch: Option<f64>,
}

/// Slides the wrist `by` (m) along the forearm's unit `axis`: the forearm stretched from the
/// elbow, the hand carried along.
fn slide_wrist(hand: &Hand, positions: &mut [Point3<f64>], axis: Vector3<f64>, by: f64) {
    for (v, u) in &hand.slide {
        positions[*v as usize] += axis * (by * u);
    }
}

/// The hands' default parameters, for tests.
#[cfg(test)]
static P: std::sync::LazyLock<crate::estimate::params::HandParams> =
    std::sync::LazyLock::new(Default::default);
