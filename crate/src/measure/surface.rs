//! A body point found on the surface around a landmark's guess rather than taken from the
//! landmark's vertex, so that a landmark a few centimetres off names the same point: the
//! **prominence** of a part along a direction, and with it the hip level ([`buttock_level`])
//! and the bust level ([`bust_level`]); the neck's narrowest level ([`narrowest_neck`]), the
//! neck's own axis there ([`squarest_neck`]) and the head's widest ([`fullest_head`]).
//! Parameters: [`MeasureParams`].
//!
//! Of the candidate vertices pᵢ and a unit direction d, the prominence's extent is
//! s* = maxᵢ d·pᵢ, and its point the centroid c of the cap {pᵢ : d·pᵢ ≥ s* − δ} weighted by
//! wᵢ = d·pᵢ − (s* − δ), moved along d onto the supporting plane: c + (s* − d·c)·d. The extent moves only to second order when the surface is sampled
//! differently; the cap's centroid, unlike the single highest vertex, moves continuously with the
//! surface instead of jumping from vertex to vertex (δ, the cap depth, spans several vertices).

use super::params::MeasureParams;
use super::section::{plane_section, Plane};
use super::tape::{tape, LoopChoice};
use super::vec3::{cross, dot, scale, sub, unit};
use std::ops::RangeInclusive;

/// The prominence of a set of vertices along a direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prominence {
    /// s* = max d·p over the candidates (metres along d).
    pub extent: f64,
    /// The cap's weighted centroid moved along d onto the plane d·p = s* (metres).
    pub point: [f64; 3],
}

fn vertex(positions: &[f32], v: u32) -> [f64; 3] {
    let i = 3 * v as usize;
    [
        positions[i] as f64,
        positions[i + 1] as f64,
        positions[i + 2] as f64,
    ]
}

/// The prominence along unit `direction` of `candidates` (vertex indices into flat `#V·3`
/// `positions`), with cap depth `depth` (metres, > 0). `None` when there is no candidate.
pub fn prominence(
    positions: &[f32],
    candidates: impl IntoIterator<Item = u32>,
    direction: [f64; 3],
    depth: f64,
) -> Option<Prominence> {
    let scored: Vec<([f64; 3], f64)> = candidates
        .into_iter()
        .filter_map(|v| {
            let i = 3 * v as usize;
            let p = positions.get(i..i + 3)?;
            let p = [p[0] as f64, p[1] as f64, p[2] as f64];
            Some((p, dot(p, direction)))
        })
        .collect();
    let extent = scored
        .iter()
        .map(|&(_, s)| s)
        .fold(f64::NEG_INFINITY, f64::max);
    if !extent.is_finite() {
        return None;
    }
    let floor = extent - depth.max(f64::MIN_POSITIVE);
    let (mut sum, mut weight) = ([0.0; 3], 0.0);
    for (p, s) in scored {
        let w = s - floor;
        if w > 0.0 {
            for k in 0..3 {
                sum[k] += w * p[k];
            }
            weight += w;
        }
    }
    let centroid = sum.map(|x| x / weight);
    let lift = extent - dot(centroid, direction);
    Some(Prominence {
        extent,
        point: [0, 1, 2].map(|k| centroid[k] + lift * direction[k]),
    })
}

/// `direction` made horizontal (its `up` component dropped) and unit; `None` when that leaves
/// nothing.
fn horizontal(direction: [f64; 3], up: usize) -> Option<[f64; 3]> {
    let mut d = direction;
    d[up] = 0.0;
    unit(d)
}

/// ISO 8559-1 5.3.13's hip level: the height (along `params.up_axis`) of the prominence along
/// `backward` made horizontal (Suprasternale → Cervicale) of the vertices `trunk` (the torso's and
/// legs': never a hand on the hip) whose height is in `band`. `None` when none is.
pub fn buttock_level(
    positions: &[f32],
    trunk: &[u32],
    backward: [f64; 3],
    band: RangeInclusive<f64>,
    params: &MeasureParams,
) -> Option<f64> {
    let up = params.up_axis;
    let backward = horizontal(backward, up)?;
    let in_band = trunk
        .iter()
        .copied()
        .filter(|&v| band.contains(&vertex(positions, v)[up]));
    prominence(positions, in_band, backward, params.prominence_depth).map(|b| b.point[up])
}

/// ISO 8559-1's bust level, the height (along `params.up_axis`) of the bust points, each the
/// most prominent point of its breast: the mean height of two prominences along `forward` made
/// horizontal (Cervicale → Suprasternale), each of the vertices `trunk` whose height is in `band`
/// and that lie on one Thelion's side of the vertical plane through the two `thelia`' midpoint
/// across them (the Rt. → Lt. Thelion direction made horizontal). `None` when a side has none.
pub fn bust_level(
    positions: &[f32],
    trunk: &[u32],
    thelia: [[f64; 3]; 2],
    forward: [f64; 3],
    band: RangeInclusive<f64>,
    params: &MeasureParams,
) -> Option<f64> {
    let up = params.up_axis;
    let forward = horizontal(forward, up)?;
    let mut across = sub(thelia[0], thelia[1]);
    across[up] = 0.0;
    let mid = [0, 1, 2].map(|k| (thelia[0][k] + thelia[1][k]) / 2.0);
    let side = |v: u32| dot(sub(vertex(positions, v), mid), across);
    let mut sum = 0.0;
    for sign in [1.0, -1.0] {
        let candidates = trunk
            .iter()
            .copied()
            .filter(|&v| band.contains(&vertex(positions, v)[up]) && sign * side(v) > 0.0);
        sum += prominence(positions, candidates, forward, params.prominence_depth)?.point[up];
    }
    Some(sum / 2.0)
}

/// Whether `q` lies inside (or on) the counter-clockwise convex polygon `hull`.
fn hull_contains(hull: &[[f64; 2]], q: [f64; 2]) -> bool {
    let n = hull.len();
    n >= 3
        && (0..n).all(|i| {
            let (a, b) = (hull[i], hull[(i + 1) % n]);
            (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]) >= 0.0
        })
}

/// Girths of a tape perpendicular to an axis: at fraction f, the plane through base + f·axis
/// perpendicular to `axis`, cut from the triangles of a region that straddle the searched stretch
/// of the axis, around the outermost loop that encloses the axis (not the chin, an ear or a
/// shoulder beside a tilted axis). Shared by the neck's and the head's searches; the neck's
/// triangles also give the neck girth's tape and the neck base girth's section
/// ([`GirthsAlong::reaching`]).
pub(super) struct GirthsAlong<'a> {
    positions: &'a [f32],
    triangles: &'a [[u32; 3]],
    /// The region's triangles that reach into fractions `first..=last` of the axis, each with the
    /// span of fractions it covers, `(lo, hi, triangle)`.
    near: Vec<(f64, f64, u32)>,
    base: [f64; 3],
    axis: [f64; 3],
    first: f64,
    last: f64,
}

/// The margin (in fractions of the axis) by which a triangle's span is taken to hold a fraction:
/// the spans and the plane round differently; the plane decides.
const MARGIN: f64 = 1e-9;

impl<'a> GirthsAlong<'a> {
    /// `None` when the axis has no length.
    pub(super) fn new(
        positions: &'a [f32],
        triangles: &'a [[u32; 3]],
        region: &[u32],
        base: [f64; 3],
        axis: [f64; 3],
        (first, last): (f64, f64),
    ) -> Option<Self> {
        let length2 = dot(axis, axis);
        if length2 <= 0.0 {
            return None;
        }
        let along = |v: u32| dot(sub(vertex(positions, v), base), axis) / length2;
        let near: Vec<(f64, f64, u32)> = region
            .iter()
            .map(|&t| {
                let [a, b, c] = triangles[t as usize];
                let s = [along(a), along(b), along(c)];
                (s[0].min(s[1]).min(s[2]), s[0].max(s[1]).max(s[2]), t)
            })
            .filter(|&(lo, hi, _)| hi >= first && lo <= last)
            .collect();
        Some(GirthsAlong {
            positions,
            triangles,
            near,
            base,
            axis,
            first,
            last,
        })
    }

    /// The fraction of the axis at point `p`: (p − base)·axis / |axis|².
    pub(super) fn fraction(&self, p: [f64; 3]) -> f64 {
        dot(sub(p, self.base), self.axis) / dot(self.axis, self.axis)
    }

    /// The triangles whose span holds fraction `f` (in the region's order): when `f` lies inside
    /// the searched stretch by more than the margin, every triangle of the region that a plane
    /// perpendicular to the axis at `f` cuts; `None` when it does not.
    pub(super) fn reaching(&self, f: f64) -> Option<Vec<u32>> {
        (f - MARGIN >= self.first && f + MARGIN <= self.last).then(|| self.holding(f))
    }

    /// The triangles whose span holds `f`, with the margin.
    fn holding(&self, f: f64) -> Vec<u32> {
        self.near
            .iter()
            .filter(|n| n.0 <= f + MARGIN && n.1 >= f - MARGIN)
            .map(|n| n.2)
            .collect()
    }

    /// The girth at fraction `f`; `None` when no loop there encloses the axis.
    fn at(&self, f: f64) -> Option<f64> {
        let cut = self.holding(f);
        let at = [0, 1, 2].map(|k| self.base[k] + f * self.axis[k]);
        let plane = Plane::new(at, self.axis)?;
        let loops = plane_section(self.positions, self.triangles, &cut, &plane);
        tape(&loops, LoopChoice::Around(plane.to_plane(at)))
            .filter(|t| hull_contains(&t.hull, [0.0, 0.0]))
            .map(|t| t.girth)
    }
}

/// The vertex of the parabola through three girths a step apart (`l`, `c`, `r`), as a shift of
/// the middle one in steps (within ±½); 0 when they do not bend the way sought (`least`: up).
fn parabola_shift(l: f64, c: f64, r: f64, least: bool) -> f64 {
    let curvature = l - 2.0 * c + r;
    if (least && curvature > 0.0) || (!least && curvature < 0.0) {
        (0.5 * (l - r) / curvature).clamp(-0.5, 0.5)
    } else {
        0.0
    }
}

/// The neck search's samples: `n + 1` fractions of the neck's axis `neck_step` apart, centred on
/// `neck_fraction` and spanning about `neck_fraction ± neck_band`, as `(n, first, last)`.
fn neck_samples(params: &MeasureParams) -> (usize, f64, f64) {
    let p = params;
    let n = (2.0 * p.neck_band / p.neck_step).round().max(0.0) as usize;
    let first = p.neck_fraction - p.neck_step * n as f64 / 2.0;
    (n, first, first + p.neck_step * n as f64)
}

/// The triangles of `region` (indices into `triangles`) along the neck's `axis` from `base`,
/// over the stretch [`narrowest_neck`] samples; `None` when the axis has no length.
pub(super) fn neck_girths<'a>(
    positions: &'a [f32],
    triangles: &'a [[u32; 3]],
    region: &[u32],
    base: [f64; 3],
    axis: [f64; 3],
    params: &MeasureParams,
) -> Option<GirthsAlong<'a>> {
    let (_, first, last) = neck_samples(params);
    GirthsAlong::new(positions, triangles, region, base, axis, (first, last))
}

/// ISO 8559-1 5.3.2's level of the neck girth, where the neck is narrowest: the fraction f of
/// the neck's axis (the point base + f·axis) where the tape perpendicular to the axis around the
/// outermost loop that encloses the axis, cut from the triangles `girths_along` holds
/// ([`neck_girths`]: the head's and torso's), is least, over `neck_fraction ± neck_band` every
/// `neck_step` (every other step first, then downhill beside the least), refined by the parabola
/// through the least sample and its neighbours. `neck_fraction` when the axis has no length or no
/// sample has such a loop.
pub(super) fn narrowest_neck(girths_along: Option<&GirthsAlong>, params: &MeasureParams) -> f64 {
    let p = params;
    let (n, first, _) = neck_samples(p);
    let Some(girths_along) = girths_along else {
        return p.neck_fraction;
    };
    let girth_at = |i: usize| {
        girths_along
            .at(first + p.neck_step * i as f64)
            .unwrap_or(f64::INFINITY)
    };
    // Every other sample first (and the last), then downhill through the skipped samples beside
    // the least: the same least sample as taking them all where the girth has one valley near
    // its least, in about two thirds of the sections. NaN: not yet taken.
    let mut girths = vec![f64::NAN; n + 1];
    for i in (0..=n).step_by(2).chain(std::iter::once(n)) {
        girths[i] = girth_at(i);
    }
    let Some(mut i) = (0..=n)
        .filter(|&i| girths[i].is_finite())
        .min_by(|&x, &y| girths[x].total_cmp(&girths[y]))
    else {
        return p.neck_fraction;
    };
    loop {
        let beside = [i.checked_sub(1), (i < n).then_some(i + 1)];
        for j in beside.into_iter().flatten() {
            if girths[j].is_nan() {
                girths[j] = girth_at(j);
            }
        }
        let lower = beside
            .into_iter()
            .flatten()
            .filter(|&j| girths[j] < girths[i])
            .min_by(|&x, &y| girths[x].total_cmp(&girths[y]));
        match lower {
            Some(j) => i = j,
            None => break,
        }
    }
    let mut f = first + p.neck_step * i as f64;
    if i > 0 && i < n && girths[i - 1].is_finite() && girths[i + 1].is_finite() {
        f += p.neck_step * parabola_shift(girths[i - 1], girths[i], girths[i + 1], true);
    }
    f
}

/// ISO 8559-1 5.3.2's "perpendicular to the neck's axis", the axis found on the body: the unit
/// normal of the least tape through `at` (the narrowest level [`narrowest_neck`] found on the
/// landmarks' `axis`) around the loop that encloses `at`, cut from the triangles of `region` with
/// a corner within `neck_tilt_radius` of it, over planes tilted from square to `axis` by up to
/// `neck_tilt_max_deg` in steps of `neck_tilt_step_deg` ([`least_tilt`]: downhill from square,
/// then the parabola): first towards `forward` (Cervicale → Suprasternale, the neck's lean),
/// then across at the best lean. The least section of a tube through a point is
/// the one square to the tube there, so the Cervicale's and the Tragions' guesses, which set the
/// landmarks' axis, no longer tilt the tape: estimated a centimetre off they leaned it 5–15° and
/// lengthened it by 3–18 mm. Returns the normal and those triangles; `None` when the axis has no
/// length or no plane has such a loop (the tape is then taken square to `axis`).
pub(super) fn squarest_neck(
    positions: &[f32],
    triangles: &[[u32; 3]],
    region: &[u32],
    at: [f64; 3],
    axis: [f64; 3],
    forward: [f64; 3],
    params: &MeasureParams,
) -> Option<([f64; 3], Vec<u32>)> {
    let p = params;
    let n0 = unit(axis)?;
    let lean = unit(sub(forward, scale(n0, dot(forward, n0))))?;
    let across = cross(n0, lean);
    // A plane through `at` tilted at most θ from square to n0 stays within r·tan θ of `at`
    // along n0 at distance r from it: only triangles with a corner in that slab of the ball can
    // hold the loop.
    let r = p.neck_tilt_radius;
    let slab = r * p.neck_tilt_max_deg.to_radians().tan() + 1e-9;
    let near: Vec<u32> = region
        .iter()
        .copied()
        .filter(|&t| {
            let c = triangles[t as usize].map(|v| sub(vertex(positions, v), at));
            let along = c.map(|d| dot(d, n0));
            along.iter().any(|&a| a <= slab)
                && along.iter().any(|&a| a >= -slab)
                && c.iter().any(|d| dot(*d, *d) <= r * r)
        })
        .collect();
    let normal = |lean_deg: f64, across_deg: f64| {
        let (a, b) = (lean_deg.to_radians(), across_deg.to_radians());
        [0, 1, 2]
            .map(|k| n0[k] * a.cos() * b.cos() + lean[k] * a.sin() * b.cos() + across[k] * b.sin())
    };
    let girth = |n: [f64; 3]| -> f64 {
        let Some(plane) = Plane::new(at, n) else {
            return f64::INFINITY;
        };
        let loops = plane_section(positions, triangles, &near, &plane);
        tape(&loops, LoopChoice::Around([0.0, 0.0]))
            .filter(|t| hull_contains(&t.hull, [0.0, 0.0]))
            .map_or(f64::INFINITY, |t| t.girth)
    };
    let steps = (p.neck_tilt_max_deg / p.neck_tilt_step_deg).floor() as i64;
    let step = p.neck_tilt_step_deg;
    let best_lean = least_tilt(&|i| girth(normal(i as f64 * step, 0.0)), steps)? * step;
    let best_across = least_tilt(&|i| girth(normal(best_lean, i as f64 * step)), steps)? * step;
    Some((normal(best_lean, best_across), near))
}

/// The tilt (in steps, −`steps`..=`steps`) of the least `girth_at` (in whole steps): from 0
/// downhill to the first sample that both its neighbours exceed (the girth of a tube against the
/// tilt of its cut has one valley), refined by the parabola through it and its neighbours;
/// `None` when no sample on the way is finite.
fn least_tilt(girth_at: &dyn Fn(i64) -> f64, steps: i64) -> Option<f64> {
    // Samples taken so far, at tilts −steps..=steps (index tilt + steps); NaN: not yet taken.
    let mut taken = vec![f64::NAN; 2 * steps as usize + 1];
    let mut at = |i: i64| -> f64 {
        let k = (i + steps) as usize;
        if taken[k].is_nan() {
            taken[k] = girth_at(i);
        }
        taken[k]
    };
    let (mut i, mut g): (i64, f64) = (0, at(0));
    loop {
        let mut next = None;
        for j in [i - 1, i + 1] {
            if j.abs() <= steps {
                let gj = at(j);
                let lower = gj < g || (!g.is_finite() && gj.is_finite());
                if lower && next.is_none_or(|(_, gn): (i64, f64)| gj < gn) {
                    next = Some((j, gj));
                }
            }
        }
        match next {
            Some(n) => (i, g) = n,
            None => break,
        }
    }
    if !g.is_finite() {
        return None;
    }
    let shift = if i.abs() < steps {
        let (l, r) = (at(i - 1), at(i + 1));
        if l.is_finite() && r.is_finite() {
            parabola_shift(l, g, r, true)
        } else {
            0.0
        }
    } else {
        0.0
    };
    Some(i as f64 + shift)
}

/// ISO 7250-1's head circumference, the greatest girth of the head above the eyebrow ridges, taken
/// horizontally: the height (along `params.up_axis`) of the cranium's widest horizontal section.
/// From `head_search_above` over `sellion` (the Sellion's height) down every `head_step`, the tape
/// around the loop that encloses the vertical through `centre` (the Tragions' midpoint), cut from
/// `region`, grows until the dome's widest level; the first sample the next one below does not
/// exceed is that level (lower down, where the ears or the brow join the section, the girth can
/// grow again: not the cranium's), refined by the parabola through it and its neighbours; never
/// below `head_search_below` under the Sellion. `None` when no sample has such a loop.
pub fn fullest_head(
    positions: &[f32],
    triangles: &[[u32; 3]],
    region: &[u32],
    centre: [f64; 3],
    sellion: f64,
    params: &MeasureParams,
) -> Option<f64> {
    let p = params;
    let up = p.up_axis;
    let mut base = centre;
    base[up] = sellion;
    let mut axis = [0.0; 3];
    axis[up] = 1.0;
    let (top, bottom) = (p.head_search_above, -p.head_search_below);
    let girths_along = GirthsAlong::new(positions, triangles, region, base, axis, (bottom, top))?;
    let steps = ((top - bottom) / p.head_step).floor() as usize;
    let level = |i: usize| top - p.head_step * i as f64;
    // The samples taken, (index, girth), from the first with the head's loop on.
    let mut taken: Vec<(usize, f64)> = Vec::with_capacity(steps + 1);
    for i in 0..=steps {
        let Some(g) = girths_along.at(level(i)) else {
            if taken.is_empty() {
                continue; // above the crown
            }
            break;
        };
        if let Some(&(c, widest)) = taken.last() {
            if g <= widest {
                let shift = match taken.len() {
                    1 => 0.0,
                    n => parabola_shift(taken[n - 2].1, widest, g, false),
                };
                // Levels fall as the index grows: a shift towards the lower sample is down.
                return Some(sellion + level(c) - p.head_step * shift);
            }
        }
        taken.push((i, g));
    }
    taken.last().map(|&(c, _)| sellion + level(c))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sphere of radius r sampled on a latitude–longitude grid, centred at `c`.
    fn sphere(c: [f64; 3], r: f64, offset: f64) -> Vec<f32> {
        let mut p = Vec::new();
        for i in 1..40 {
            let phi = std::f64::consts::PI * i as f64 / 40.0;
            for j in 0..80 {
                let t = std::f64::consts::TAU * (j as f64 + offset) / 80.0;
                let q = [
                    c[0] + r * phi.sin() * t.cos(),
                    c[1] + r * phi.cos(),
                    c[2] + r * phi.sin() * t.sin(),
                ];
                p.extend(q.map(|x| x as f32));
            }
        }
        p
    }

    #[test]
    fn the_prominence_of_a_sphere_is_its_pole_whatever_the_sampling() {
        let d = [0.6, 0.0, 0.8];
        for offset in [0.0, 0.25, 0.5] {
            let p = sphere([0.1, 1.0, -0.2], 0.1, offset);
            let all = 0..(p.len() / 3) as u32;
            let got = prominence(&p, all, d, 0.01).unwrap();
            // The pole c + r·d, the extent d·c + r (to the grid's sampling).
            let want = [0.1 + 0.06, 1.0, -0.2 + 0.08];
            for (k, w) in want.iter().enumerate() {
                assert!((got.point[k] - w).abs() < 2e-3, "{got:?}");
            }
            assert!((got.extent - (0.06 - 0.16 + 0.1)).abs() < 1e-3, "{got:?}");
        }
        assert!(prominence(&[], [], d, 0.01).is_none());
    }
}
