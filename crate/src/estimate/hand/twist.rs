//! A hand's turn about the forearm carried down the forearm (pronation and supination turn the
//! wrist with the hand, the elbow not at all).

use nalgebra::{Point3, Rotation3, UnitQuaternion, Vector3};

use crate::template::hand::Hand;

/// The angle (radians, right-handed about `axis`) of the part of `rotation` about the unit
/// `axis`: the twist of its swing–twist decomposition.
pub(super) fn twist_about(rotation: &UnitQuaternion<f64>, axis: &Vector3<f64>) -> f64 {
    let along = rotation.imag().dot(axis);
    let angle = 2.0 * along.atan2(rotation.w);
    // The shorter way round.
    (angle + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
}

/// Carries a hand's turn `twist` (radians) about the forearm's `axis` down the forearm: the
/// forearm turns with the hand about its own axis (pronation and supination turn the radius
/// about the ulna: the wrist turns with the hand, the elbow not at all), each vertex by its
/// fraction of the way from the elbow to the wrist, less what it already turned with the hand
/// (`Hand::twist`).
pub(super) fn twist_forearm(
    hand: &Hand,
    positions: &mut [Point3<f64>],
    wrist: Point3<f64>,
    axis: Vector3<f64>,
    twist: f64,
) {
    for (v, share) in &hand.twist {
        let p = &mut positions[*v as usize];
        let turn = Rotation3::from_scaled_axis(axis * (twist * share));
        *p = wrist + turn * (*p - wrist);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_twist_is_the_turn_about_the_axis() {
        let axis = Vector3::new(1.0, 2.0, -0.5).normalize();
        let across = axis.cross(&Vector3::z()).normalize();
        for deg in [-150.0, -60.0, 0.0, 35.0, 170.0] {
            let twist = UnitQuaternion::from_scaled_axis(axis * f64::to_radians(deg));
            let swing = UnitQuaternion::from_scaled_axis(across * 0.4);
            let found = twist_about(&(swing * twist), &axis).to_degrees();
            assert!((found - deg).abs() < 1e-9, "{deg}: {found}");
        }
    }
}
