//! Levels where a horizontal section's loops part, found on the surface rather than taken from
//! the landmarks' heights: the armpits' apex (ISO 8559-1's chest girth, "under the armpits", the
//! torso alone) and the crotch (ISO 7250-1's crotch height; the thigh girth's level below it).
//!
//! A horizontal section of the torso and both arms is one loop above the armpits (the shoulders
//! join the arms to the torso) and three below them: the torso's and one per arm. A section of
//! the torso and both legs is one loop above the crotch and two below it, one per leg. On a
//! triangle mesh the loops part exactly at a saddle vertex (the armpit's vault, the crotch).
//! [`parting_level`] finds the highest level at which a section's loops have parted, by bisection
//! between a level where they have not and one where they have. It depends on the mesh's
//! connectivity alone: an arm hanging against the torso, or thighs pressed together (touching or
//! passing into each other), are still loops of their own.
//! Parameters: [`MeasureParams`].

use super::params::MeasureParams;
use super::section::{plane_section, Plane, SectionLoop};
use super::tape::{contains, polygon_area};

fn centroid(points: &[[f64; 2]]) -> [f64; 2] {
    let n = points.len().max(1) as f64;
    points
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n])
}

/// Whether of `loops` one's centroid c lies on each side of `centre` along `lateral`:
/// (c − centre)·`lateral` > 0 for one, < 0 for another. In-plane coordinates.
fn both_sides<'l>(
    loops: impl Iterator<Item = &'l SectionLoop>,
    centre: [f64; 2],
    lateral: [f64; 2],
) -> bool {
    let (mut right, mut left) = (false, false);
    for l in loops {
        let c = centroid(&l.points);
        let side = (c[0] - centre[0]) * lateral[0] + (c[1] - centre[1]) * lateral[1];
        right |= side > 0.0;
        left |= side < 0.0;
    }
    right && left
}

/// Whether the torso's loop of a section stands alone: of the closed `loops`, the largest one
/// containing `centre` (the torso's), with another closed loop — neither inside it nor around
/// `centre` — whose centroid lies on each side of `centre` along `lateral` (the two arms).
/// In-plane coordinates.
pub fn torso_alone(loops: &[SectionLoop], centre: [f64; 2], lateral: [f64; 2]) -> bool {
    let closed: Vec<&SectionLoop> = loops.iter().filter(|l| l.closed).collect();
    let Some(torso) = closed
        .iter()
        .filter(|l| contains(&l.points, centre))
        .max_by(|a, b| polygon_area(&a.points).total_cmp(&polygon_area(&b.points)))
    else {
        return false;
    };
    let arms = closed.iter().copied().filter(|l| {
        !std::ptr::eq(*l, *torso)
            && !contains(&l.points, centre)
            && !contains(&torso.points, centroid(&l.points))
    });
    both_sides(arms, centre, lateral)
}

/// Whether the legs stand apart: the centroids of two closed loops of the section lie on either
/// side of `centre` (the point between the legs) along `lateral`, one per leg. Above the crotch
/// the one loop around the pelvis has its centroid on one side only; thighs pressed into each
/// other are still two loops. In-plane coordinates.
pub fn legs_apart(loops: &[SectionLoop], centre: [f64; 2], lateral: [f64; 2]) -> bool {
    both_sides(loops.iter().filter(|l| l.closed), centre, lateral)
}

/// Where a parting is sought: the section's triangles, the point between the parting pieces, the
/// side direction, and the guess of its level with the band around it.
pub struct PartingSearch<'a> {
    /// Indices into the triangles: the region whose horizontal sections are taken.
    pub region: &'a [u32],
    /// The point the loops part around (the axillae's centre, the crotch).
    pub centre: [f64; 3],
    /// A side direction: from the left pieces to the right ones.
    pub lateral: [f64; 3],
    /// The landmarks' guess of the level (along `MeasureParams::up_axis`).
    pub guess: f64,
    /// The band sought: from `guess + above` (not yet parted) down to `guess − below` (parted).
    pub above: f64,
    pub below: f64,
}

/// The highest level h (along `params.up_axis`) under which the horizontal section of
/// `search.region` has parted (`parted(loops, centre, lateral)`, in-plane coordinates): sought
/// from the band's top (where it must not have) down to its bottom (where it must have), by
/// bisection until the bracket is narrower than `params.parting_resolution`; its midpoint is
/// returned. `None` when the band does not bracket the level (never parted in it, or already
/// parted at its top).
pub fn parting_level(
    positions: &[f32],
    triangles: &[[u32; 3]],
    search: &PartingSearch,
    parted: impl Fn(&[SectionLoop], [f64; 2], [f64; 2]) -> bool,
    params: &MeasureParams,
) -> Option<f64> {
    let up = params.up_axis;
    let mut joined = search.guess + search.above;
    let mut apart = search.guess - search.below;
    // Only the triangles that straddle the bracket can be cut: (triangle, lowest, highest
    // corner), narrowed with the bracket, so each halving sections about half as many.
    let mut near: Vec<(u32, f64, f64)> = search
        .region
        .iter()
        .map(|&t| {
            let height = |v: u32| positions[3 * v as usize + up] as f64;
            let [a, b, c] = triangles[t as usize];
            let h = [height(a), height(b), height(c)];
            (t, h[0].min(h[1]).min(h[2]), h[0].max(h[1]).max(h[2]))
        })
        .filter(|&(_, lo, hi)| hi >= apart && lo <= joined)
        .collect();
    let has_parted = |near: &[(u32, f64, f64)], h: f64| {
        let plane = Plane::horizontal(up, h);
        let cut: Vec<u32> = near
            .iter()
            .filter(|&&(_, lo, hi)| lo <= h && hi >= h)
            .map(|&(t, _, _)| t)
            .collect();
        let loops = plane_section(positions, triangles, &cut, &plane);
        let c = plane.to_plane(search.centre);
        let side = plane.to_plane([0, 1, 2].map(|k| search.centre[k] + search.lateral[k]));
        parted(&loops, c, [side[0] - c[0], side[1] - c[1]])
    };
    if has_parted(&near, joined) || !has_parted(&near, apart) {
        return None;
    }
    while joined - apart > params.parting_resolution {
        let mid = (joined + apart) / 2.0;
        if has_parted(&near, mid) {
            apart = mid;
        } else {
            joined = mid;
        }
        near.retain(|&(_, lo, hi)| hi >= apart && lo <= joined);
    }
    Some((joined + apart) / 2.0)
}
