//! A free hand's length from its fingertip on the scan ([`stretch_to_fingertip`]).
//!
//! The segment-wise fit gives the hand the body's one scale: a hand long or short for its body
//! keeps the template's proportions. On a free hand the scan's farthest point beyond the wrist, in
//! the direction of the template hand's own farthest vertex (its middle fingertip), is the
//! fingertip: the hand is stretched along that direction, each vertex by its share of the hand,
//! until its farthest vertex lies as far out. Where that point is far from the template's — a
//! hand beside the thigh, whose skin lies beyond the fingertips; fingers curled or cut off — the
//! hand is left as it is.

use nalgebra::Point3;

use crate::estimate::params::HandParams;
use crate::template::hand::{mid, Hand};

/// Stretches `hand` in `positions` (metres) along the direction from its wrist (the styloids'
/// midpoint) to its farthest own vertex, so that vertex lies as far along it as the farthest of
/// the `scan` points (metres) within `params.fingertip_search` of it. Left as it is, and `None`,
/// where no scan point lies there or the scan's reach differs from the template's by
/// `params.fingertip_gate` or more. Returns the stretch (the scan's reach over the template's).
pub fn stretch_to_fingertip(
    hand: &Hand,
    positions: &mut [Point3<f64>],
    scan: &[Point3<f64>],
    params: &HandParams,
) -> Option<f64> {
    let wrist = mid(positions, hand.styloids);
    let tip = hand
        .own
        .iter()
        .map(|&v| positions[v as usize])
        .max_by(|a, b| (a - wrist).norm().total_cmp(&(b - wrist).norm()))?;
    let reach = (tip - wrist).norm();
    if reach <= 0.0 {
        return None;
    }
    let along = (tip - wrist) / reach;
    let scan_reach = scan
        .iter()
        .filter(|p| (*p - tip).norm() < params.fingertip_search)
        .map(|p| (p - wrist).dot(&along))
        .fold(f64::NEG_INFINITY, f64::max);
    if !scan_reach.is_finite() || (scan_reach - reach).abs() >= params.fingertip_gate {
        return None;
    }
    let stretch = scan_reach / reach;
    for (v, share) in &hand.share {
        let p = &mut positions[*v as usize];
        let out = (*p - wrist).dot(&along).max(0.0);
        *p += along * (out * (stretch - 1.0) * share);
    }
    Some(stretch)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimate::hand::P;
    use crate::template::fixture::{base_body, BaseBody};

    /// The template hand's Dactylion vertex.
    fn dactylion(template: &crate::template::Template, hand: &Hand) -> usize {
        template
            .landmark_vertex(&format!("{} Dactylion", hand.side))
            .unwrap() as usize
    }

    #[test]
    fn a_hand_is_stretched_to_the_scans_fingertip() {
        let BaseBody {
            template,
            rest,
            hands,
            ..
        } = base_body();
        for hand in &hands {
            // The scan: the template with this hand 7 % longer (stretched as the rule does).
            let wrist = mid(&rest, hand.styloids);
            let longer = {
                let mut scan = rest.clone();
                let tip = hand.own.iter().map(|&v| rest[v as usize]);
                let tip = tip.max_by(|a, b| (a - wrist).norm().total_cmp(&(b - wrist).norm()));
                let along = (tip.unwrap() - wrist).normalize();
                for (v, share) in &hand.share {
                    let p = &mut scan[*v as usize];
                    *p += along * ((*p - wrist).dot(&along).max(0.0) * 0.07 * share);
                }
                scan
            };
            let d = dactylion(&template, hand);
            assert!((longer[d] - rest[d]).norm() > 0.01, "the fingertip moved");
            let mut positions = rest.clone();
            let stretch = stretch_to_fingertip(hand, &mut positions, &longer, &P).unwrap();
            assert!((stretch - 1.07).abs() < 1e-9, "{stretch}");
            // The hand's landmarks are where the scan's are; the body elsewhere stays.
            for name in ["Dactylion", "Metacarpal Phal. II", "Metacarpal Phal. V"] {
                let v = template
                    .landmark_vertex(&format!("{} {name}", hand.side))
                    .unwrap() as usize;
                assert!((positions[v] - longer[v]).norm() < 1e-9, "{name}");
            }
            let elbow = mid(&rest, hand.epicondyles);
            let moved = |v: usize| (positions[v] - rest[v]).norm();
            let far: Vec<usize> = (0..rest.len())
                .filter(|&v| (rest[v] - elbow).norm() > 0.5)
                .collect();
            assert!(far.iter().all(|&v| moved(v) == 0.0));
        }
    }

    #[test]
    fn a_fingertip_far_from_the_templates_or_none_leaves_the_hand() {
        let BaseBody {
            template,
            rest,
            hands,
            ..
        } = base_body();
        let hand = &hands[0];
        let d = dactylion(&template, hand);
        let wrist = mid(&rest, hand.styloids);
        let along = (rest[d] - wrist).normalize();
        // The thigh beside the hand: skin 4 cm beyond the fingertip, within reach of it.
        let mut beside = rest.clone();
        beside.push(rest[d] + along * 0.04);
        // The hand cut off by the scanner: nothing within reach of the fingertip.
        let cut: Vec<Point3<f64>> = rest
            .iter()
            .filter(|p| (*p - rest[d]).norm() > P.fingertip_search)
            .copied()
            .collect();
        for scan in [beside, cut] {
            let mut positions = rest.clone();
            assert_eq!(stretch_to_fingertip(hand, &mut positions, &scan, &P), None);
            assert_eq!(positions, rest);
        }
    }
}
