//! Which end of a standing body is the head, from the scan's shape alone: the head is narrower
//! than the shoulders below it, while the feet (with the floor or a turntable a scanner may leave
//! under them) are as wide as the legs above them or wider. It holds on raw scans whatever the
//! nearest points say: cut crowns, bodies delivered in parts, floor remnants, stray points.
//!
//! Along the up axis `u` (the principal axis of largest extent) the body spans the robust extent
//! `[t_lo, t_hi]` (the `EXTENT_PERCENTILE` and `1 − EXTENT_PERCENTILE` quantiles of `p·u` over the
//! vertices of the scan's triangles: lone stray points and small strays do not move it). At each
//! end, over the slabs `END_SLAB` (the end) and `BELOW_SLAB` (below the end), as fractions of the
//! extent from that end, the width is the larger of two: across the body (the second principal
//! axis `s`) twice the narrower side's reach from the body's centre line `c` (the median of `p·s`
//! over all points), `2·max(0, min(c − q_lo, q_hi − c))`, and front to back (the third) the range
//! `q_hi − q_lo`, with `q_lo`, `q_hi` the slab's `WIDTH_PERCENTILE` and `1 − WIDTH_PERCENTILE`
//! quantiles; `ratio = width(end) / width(below)`. The head's end is the one with the smaller
//! ratio, when it is below `decisive` times the other's; otherwise the shape does not say. A
//! body is much the same on its two sides, so the narrower side is the body's; one arm raised
//! beside or above the head widens one side only (a raised hand in the head's slab had made the
//! head's end 1.7 times as wide as the shoulders, wider than the feet's: upside down). Both arms
//! raised above the head would still widen the head's end.

use nalgebra::{Matrix3, Point3, Vector3};

use crate::mesh::principal_axes::principal_axes;

/// Robust extent along the up axis: these quantiles of the heights.
pub(super) const EXTENT_PERCENTILE: f64 = 0.002;
/// The slab at an end and the slab below it, fractions of the extent from that end.
const END_SLAB: (f64, f64) = (0.0, 0.08);
const BELOW_SLAB: (f64, f64) = (0.15, 0.25);
/// A slab's width: the range between these quantiles.
const WIDTH_PERCENTILE: f64 = 0.05;

/// The shape's verdict on which way is up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeadEnd {
    /// The scan direction from the feet to the head (±the first principal axis).
    pub up: Vector3<f64>,
    /// `width(end) / width(below)` at the head's end and at the feet's.
    pub head_ratio: f64,
    pub feet_ratio: f64,
}

/// The head's end of the body in `positions` (the vertices of `triangles` only), when the
/// head's ratio is below `decisive` times the feet's; `None` when the shape does not say.
pub fn head_end(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    decisive: f64,
) -> Option<HeadEnd> {
    let points = triangulated(positions, triangles);
    let axes = principal_axes(&points)?;
    let up = axes.column(0).into_owned();
    let heights: Vec<f64> = points.iter().map(|p| p.coords.dot(&up)).collect();
    let lo = quantile(&heights, EXTENT_PERCENTILE)?;
    let hi = quantile(&heights, 1.0 - EXTENT_PERCENTILE)?;
    let extent = hi - lo;
    if extent.is_nan() || extent <= 0.0 {
        return None;
    }
    let across = axes.column(1).into_owned();
    let centre = quantile(
        &points
            .iter()
            .map(|p| p.coords.dot(&across))
            .collect::<Vec<_>>(),
        0.5,
    )?;
    // Ratio at the end where the height from the end is `from_end(t)`.
    let ratio = |from_end: &dyn Fn(f64) -> f64| {
        let end = slab_width(&points, &heights, &axes, centre, |t| {
            in_slab(from_end(t) / extent, END_SLAB)
        })?;
        let below = slab_width(&points, &heights, &axes, centre, |t| {
            in_slab(from_end(t) / extent, BELOW_SLAB)
        })?;
        (below > 0.0).then_some(end / below)
    };
    let top = ratio(&|t| hi - t)?;
    let bottom = ratio(&|t| t - lo)?;
    let (up, head_ratio, feet_ratio) = if top <= bottom {
        (up, top, bottom)
    } else {
        (-up, bottom, top)
    };
    (head_ratio < decisive * feet_ratio).then_some(HeadEnd {
        up,
        head_ratio,
        feet_ratio,
    })
}

/// The vertices of `positions` that `triangles` use (lone stray points left out), in order.
pub(super) fn triangulated(positions: &[Point3<f64>], triangles: &[[u32; 3]]) -> Vec<Point3<f64>> {
    let mut used = vec![false; positions.len()];
    for t in triangles {
        for &v in t {
            used[v as usize] = true;
        }
    }
    positions
        .iter()
        .zip(&used)
        .filter(|(_, u)| **u)
        .map(|(p, _)| *p)
        .collect()
}

fn in_slab(f: f64, (a, b): (f64, f64)) -> bool {
    f >= a && f <= b
}

/// The slab's width (see the module documentation): the slab's points' reach from `centre`
/// along the second axis (across the body) on its narrower side `r`, and the width is the larger
/// of `2r` and the quantile range along the third axis (front to back) of the slab's points
/// within `r` of `centre` across: a raised hand beside the head is out of both.
fn slab_width(
    points: &[Point3<f64>],
    heights: &[f64],
    axes: &Matrix3<f64>,
    centre: f64,
    in_slab: impl Fn(f64) -> bool,
) -> Option<f64> {
    let (across, depth) = (axes.column(1).into_owned(), axes.column(2).into_owned());
    let slab: Vec<(f64, f64)> = points
        .iter()
        .zip(heights)
        .filter(|(_, t)| in_slab(**t))
        .map(|(p, _)| (p.coords.dot(&across) - centre, p.coords.dot(&depth)))
        .collect();
    let sideways: Vec<f64> = slab.iter().map(|s| s.0).collect();
    let r = quantile(&sideways, 1.0 - WIDTH_PERCENTILE)?
        .min(-quantile(&sideways, WIDTH_PERCENTILE)?)
        .max(0.0);
    let near: Vec<f64> = slab
        .iter()
        .filter(|s| s.0.abs() <= r)
        .map(|s| s.1)
        .collect();
    let depth = match (
        quantile(&near, WIDTH_PERCENTILE),
        quantile(&near, 1.0 - WIDTH_PERCENTILE),
    ) {
        (Some(lo), Some(hi)) => hi - lo,
        _ => 0.0,
    };
    Some((2.0 * r).max(depth))
}

/// The `q` quantile of `values` (nearest rank); `None` when empty.
pub(super) fn quantile(values: &[f64], q: f64) -> Option<f64> {
    if values.is_empty() {
        return None;
    }
    let mut v = values.to_vec();
    let k = ((q * (v.len() - 1) as f64).round() as usize).min(v.len() - 1);
    let (_, x, _) = v.select_nth_unstable_by(k, |a, b| a.total_cmp(b));
    Some(*x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stick figure's surface points along y (m): a head 0.18 wide on top of 0.45 shoulders,
    /// a 0.35 wide trunk and two legs 0.3 apart on 0.25 long feet, and with `raised` one arm
    /// raised from the shoulder 30° from the vertical, its hand 0.2 m above the head; one
    /// triangle over all.
    fn figure(flip: bool, raised: bool) -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
        let mut points = Vec::new();
        let mut ring = |y: f64, cx: f64, rx: f64, rz: f64| {
            for k in 0..24 {
                let a = std::f64::consts::TAU * k as f64 / 24.0;
                let y = if flip { 1.75 - y } else { y };
                points.push(Point3::new(cx + rx * a.cos(), y, rz * a.sin()));
            }
        };
        for i in 0..176 {
            let y = i as f64 * 0.01;
            match y {
                y if y < 0.08 => {
                    ring(y, -0.15, 0.05, 0.13);
                    ring(y, 0.15, 0.05, 0.13);
                }
                y if y < 0.85 => {
                    ring(y, -0.12, 0.07, 0.07);
                    ring(y, 0.12, 0.07, 0.07);
                }
                y if y < 1.45 => ring(y, 0.0, 0.2, 0.12),
                y if y < 1.55 => ring(y, 0.0, 0.06, 0.06),
                _ => ring(y, 0.0, 0.09, 0.1),
            }
        }
        for i in 0..=60 {
            let t = i as f64 / 60.0;
            if raised {
                ring(1.45 + 0.5 * t, 0.22 + 0.29 * t, 0.045, 0.045);
            }
        }
        let n = points.len() as u32;
        let triangles = (0..n / 3).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect();
        (points, triangles)
    }

    #[test]
    fn the_head_is_the_narrow_end_either_way_up() {
        for flip in [false, true] {
            let (points, triangles) = figure(flip, false);
            let end = head_end(&points, &triangles, 0.75).expect("decisive");
            let want = if flip { -1.0 } else { 1.0 };
            assert!(end.up.y * want > 0.99, "{flip}: {:?}", end);
            assert!(end.head_ratio < 0.6 && end.feet_ratio > 0.9, "{end:?}");
            // One arm raised above the head widens one side of the head's end only.
            let (points, triangles) = figure(flip, true);
            let end = head_end(&points, &triangles, 0.75).expect("decisive, one arm raised");
            // (The arm tilts the first principal axis by ≈ 10°.)
            assert!(end.up.y * want > 0.95, "{flip}, raised: {:?}", end);
            assert!(end.head_ratio < 0.6 * end.feet_ratio, "{end:?}");
        }
        // A featureless column says nothing.
        let column: Vec<Point3<f64>> = (0..2000)
            .map(|i| {
                let a = i as f64 * 0.7;
                Point3::new(0.1 * a.cos(), i as f64 * 0.001, 0.1 * a.sin())
            })
            .collect();
        let triangles: Vec<[u32; 3]> = (0..666).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect();
        assert!(head_end(&column, &triangles, 0.75).is_none());
    }
}
