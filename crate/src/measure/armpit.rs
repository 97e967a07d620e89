//! The armpits' apex found on the surface: the level of ISO 8559-1's chest girth ("under the
//! armpits", the torso alone) without trusting the axilla landmarks' height.
//!
//! A horizontal section of the torso and both arms is one loop above the armpits (the shoulders
//! join the arms to the torso) and three below them: the torso's and one per arm. On a triangle
//! mesh the loops part exactly at the armpit's vault, a saddle vertex. [`armpit_level`] finds the
//! highest level where the torso's loop (the closed loop around the axillae's centre) stands apart
//! from both arms (another closed loop on each side of it), by bisection between a level where it
//! does not and one where it does. It depends on the mesh's connectivity alone: an arm hanging
//! against the torso (touching or passing into it) is still its own loop.
//! Parameters: [`MeasureParams`].

use super::params::MeasureParams;
use super::section::{plane_section, Plane, SectionLoop};
use super::tape::{contains, polygon_area};

fn vertex(positions: &[f32], v: u32) -> [f64; 3] {
    let i = 3 * v as usize;
    [0, 1, 2].map(|k| positions[i + k] as f64)
}

fn centroid(points: &[[f64; 2]]) -> [f64; 2] {
    let n = points.len().max(1) as f64;
    points
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n])
}

/// Whether the torso's loop of a section stands alone: of the closed `loops`, the largest one
/// containing `centre` (the torso's), with another closed loop — neither inside it nor around
/// `centre` — whose centroid c lies on each side, (c − centre)·`lateral` > 0 and < 0 (the two
/// arms). In-plane coordinates.
pub fn torso_alone(loops: &[SectionLoop], centre: [f64; 2], lateral: [f64; 2]) -> bool {
    let closed: Vec<&SectionLoop> = loops.iter().filter(|l| l.closed).collect();
    let Some(torso) = closed
        .iter()
        .filter(|l| contains(&l.points, centre))
        .max_by(|a, b| polygon_area(&a.points).total_cmp(&polygon_area(&b.points)))
    else {
        return false;
    };
    let (mut right, mut left) = (false, false);
    for l in &closed {
        if std::ptr::eq(*l, *torso) || contains(&l.points, centre) {
            continue;
        }
        let c = centroid(&l.points);
        if contains(&torso.points, c) {
            continue;
        }
        let side = (c[0] - centre[0]) * lateral[0] + (c[1] - centre[1]) * lateral[1];
        right |= side > 0.0;
        left |= side < 0.0;
    }
    right && left
}

/// The armpits' apex: the height h (along `params.up_axis`) under which the horizontal section
/// of `region` (indices into `triangles`: the torso's and both arms' triangles) has the torso's
/// loop apart from both arms ([`torso_alone`], with `centre` the axillae's centre and `lateral`
/// the direction from the left axillae to the right ones). Sought from `guess +
/// armpit_band_above` (where the loop must still join an arm) down to `guess −
/// armpit_band_below` (where it must stand alone), by bisection until the bracket is narrower
/// than `armpit_resolution`; its midpoint is returned. `None` when the band does not bracket
/// the apex (the torso never stands alone in it, or already does at its top).
pub fn armpit_level(
    positions: &[f32],
    triangles: &[[u32; 3]],
    region: &[u32],
    centre: [f64; 3],
    lateral: [f64; 3],
    guess: f64,
    params: &MeasureParams,
) -> Option<f64> {
    let up = params.up_axis;
    let mut joined = guess + params.armpit_band_above;
    let mut alone = guess - params.armpit_band_below;
    // Only the triangles that straddle the bracket can be cut: (triangle, lowest, highest
    // corner), narrowed with the bracket, so each halving sections about half as many.
    let mut near: Vec<(u32, f64, f64)> = region
        .iter()
        .map(|&t| {
            let h = triangles[t as usize].map(|v| vertex(positions, v)[up]);
            (t, h[0].min(h[1]).min(h[2]), h[0].max(h[1]).max(h[2]))
        })
        .filter(|&(_, lo, hi)| hi >= alone && lo <= joined)
        .collect();
    let stands_alone = |near: &[(u32, f64, f64)], h: f64| {
        let plane = Plane::horizontal(up, h);
        let cut: Vec<u32> = near
            .iter()
            .filter(|&&(_, lo, hi)| lo <= h && hi >= h)
            .map(|&(t, _, _)| t)
            .collect();
        let loops = plane_section(positions, triangles, &cut, &plane);
        let c = plane.to_plane(centre);
        let side = plane.to_plane([0, 1, 2].map(|k| centre[k] + lateral[k]));
        torso_alone(&loops, c, [side[0] - c[0], side[1] - c[1]])
    };
    if stands_alone(&near, joined) || !stands_alone(&near, alone) {
        return None;
    }
    while joined - alone > params.armpit_resolution {
        let mid = (joined + alone) / 2.0;
        if stands_alone(&near, mid) {
            alone = mid;
        } else {
            joined = mid;
        }
        near.retain(|&(_, lo, hi)| hi >= alone && lo <= joined);
    }
    Some((joined + alone) / 2.0)
}
