//! Where a knee (elbow) sits along the limb, from the limb's cross-section profile: its width at
//! each height from the hip to the ankle (the shoulder to the wrist). Real legs narrow from the
//! thigh to the knee and bulge at the calf below it, forearms bulge below the elbow; nearest-point
//! matching does not see that (a limb is close to a cylinder), a profile does. The template's own
//! profile is registered to the scan's with a stretch above and below the joint; the joint lands
//! where the template's maps. A leg's knee is then set by a sharper feature of the same kind:
//! the front of the knee stepping back to the shin below the patella and the tibial tuberosity
//! (the steepest fall of how far forward the leg reaches), taken where the template's sits below
//! its knee. The wrist of a bent forearm (`hand/wrist_profile.rs`) is placed by the same kind of profile, the
//! template's shifted along the scan's over the forearm's narrowing and the hand's widening.

use nalgebra::{Point3, Vector3};

use super::params::ProfileParams;

/// A limb as a line: root (hip) to end (ankle).
#[derive(Debug, Clone, Copy)]
pub struct LimbLine {
    pub root: Point3<f64>,
    pub end: Point3<f64>,
}

impl LimbLine {
    /// Fraction along the line and distance from the segment of `p`.
    fn locate(&self, p: &Point3<f64>) -> (f64, f64) {
        let d = self.end - self.root;
        let u = (p - self.root).dot(&d) / d.norm_squared();
        let on = self.root + d * u.clamp(0.0, 1.0);
        (u, (p - on).norm())
    }
}

/// The points of limb `k` of `limbs` at each of `params.bins` heights, as vectors across its axis
/// from its line: the `points` nearer to limb `k`'s line than to every other line of `limbs` and
/// within `radius` (m) of it.
fn bins(
    points: &[Point3<f64>],
    limbs: &[LimbLine],
    k: usize,
    radius: f64,
    params: &ProfileParams,
) -> Vec<Vec<Vector3<f64>>> {
    let line = limbs[k];
    let axis: Vector3<f64> = (line.end - line.root).normalize();
    let mut bins: Vec<Vec<Vector3<f64>>> = vec![Vec::new(); params.bins];
    for p in points {
        let (u, r) = line.locate(p);
        if !(0.0..1.0).contains(&u) || r > radius {
            continue;
        }
        let nearer_other = limbs
            .iter()
            .enumerate()
            .any(|(j, l)| j != k && l.locate(p).1 < r);
        if nearer_other {
            continue;
        }
        let across = (p - line.root) - axis * (p - line.root).dot(&axis);
        bins[((u * params.bins as f64) as usize).min(params.bins - 1)].push(across);
    }
    bins
}

/// The width of limb `k` of `limbs` at each of `params.bins` heights: per bin (its points as
/// [`bins`] takes them), the median distance across the axis from the points' mean. `None` for
/// a bin with too few.
pub fn profile(
    points: &[Point3<f64>],
    limbs: &[LimbLine],
    k: usize,
    radius: f64,
    params: &ProfileParams,
) -> Vec<Option<f64>> {
    bins(points, limbs, k, radius, params)
        .iter()
        .map(|b| {
            if b.len() < params.min_points {
                return None;
            }
            let mean = b.iter().sum::<Vector3<f64>>() / b.len() as f64;
            let mut r: Vec<f64> = b.iter().map(|q| (q - mean).norm()).collect();
            r.sort_by(f64::total_cmp);
            Some(r[r.len() / 2])
        })
        .collect()
}

/// How far limb `k` of `limbs` reaches towards `direction` (across its axis; the back of the
/// leg) at each of `params.bins` heights: per bin, the 90th percentile of its points' distance from
/// the line along `direction`. `None` for a bin with too few.
pub fn reach(
    points: &[Point3<f64>],
    limbs: &[LimbLine],
    k: usize,
    radius: f64,
    direction: &Vector3<f64>,
    params: &ProfileParams,
) -> Vec<Option<f64>> {
    let axis = (limbs[k].end - limbs[k].root).normalize();
    let d = (direction - axis * direction.dot(&axis)).normalize();
    bins(points, limbs, k, radius, params)
        .iter()
        .map(|b| {
            if b.len() < params.min_points {
                return None;
            }
            let mut along: Vec<f64> = b.iter().map(|v| v.dot(&d)).collect();
            along.sort_by(f64::total_cmp);
            Some(along[along.len() * 9 / 10])
        })
        .collect()
}

/// The fraction where `profile` rises fastest towards the limb's end within `half` of `around`:
/// the difference across two bins' spacing, its peak refined by a parabola through its
/// neighbours. `None` when no bin there has both neighbours.
fn steepest_rise(profile: &[Option<f64>], around: f64, half: f64) -> Option<f64> {
    let n = profile.len();
    let slope = |i: usize| -> Option<f64> {
        if i == 0 || i + 1 >= n {
            return None;
        }
        Some(profile[i + 1]? - profile[i - 1]?)
    };
    let u = |i: f64| (i + 0.5) / n as f64;
    let (i, _) = (1..n.saturating_sub(1))
        .filter(|&i| (u(i as f64) - around).abs() <= half)
        .filter_map(|i| Some((i, slope(i)?)))
        .max_by(|a, b| a.1.total_cmp(&b.1))?;
    let shift = match (slope(i - 1), slope(i + 1)) {
        (Some(a), Some(c)) => {
            let b = slope(i).unwrap_or(0.0);
            let curvature = a - 2.0 * b + c;
            if curvature < 0.0 {
                (0.5 * (a - c) / curvature).clamp(-0.5, 0.5)
            } else {
                0.0
            }
        }
        _ => 0.0,
    };
    Some(u(i as f64 + shift))
}

/// The fraction along the scan's leg where the template's knee (fraction `joint` along the
/// template's leg) lands, from the front of the knee: where the front's reach (`template`,
/// `scan`: [`reach`] away from the back of the knee) falls fastest towards the ankle — below
/// the patella and the tibial tuberosity the front of the leg steps back to the shin — on the
/// template within `params.front_search` of its knee, on the scan within it of `around` (where the
/// width's profile put the knee); the knee sits as far above it as the template's. Bone under
/// thin skin shapes the front of the knee; the width's profile smooths it over (the hollow
/// behind balances the patella). It replaced the top of the calf (the steepest rise of the
/// back's reach), which left the knees lower (docs/landmarks-estimate.md). `None` when no fall
/// is found.
pub fn knee_from_front(
    template: &[Option<f64>],
    scan: &[Option<f64>],
    joint: f64,
    around: f64,
    params: &ProfileParams,
) -> Option<f64> {
    let negated =
        |p: &[Option<f64>]| -> Vec<Option<f64>> { p.iter().map(|w| w.map(|w| -w)).collect() };
    let front = steepest_rise(&negated(template), joint, params.front_search)?;
    Some(steepest_rise(&negated(scan), around, params.front_search)? + joint - front)
}

/// The profile's value at fraction `u` (linear between bin centres), `None` off its ends or
/// next to an empty bin.
fn at(profile: &[Option<f64>], u: f64) -> Option<f64> {
    let x = u * profile.len() as f64 - 0.5;
    if x < 0.0 {
        return None;
    }
    let i = x as usize;
    let t = x - i as f64;
    match (profile.get(i)?, profile.get(i + 1)?) {
        (Some(a), Some(b)) => Some(a + (b - a) * t),
        _ => None,
    }
}

/// The fraction along the scan's limb where the template's joint (fraction `joint` along the
/// template's limb) lands: of the piecewise-linear maps taking `joint` to `f` (`f` within
/// `params.search` of `start`), the one under which the template's profile, times a fitted gain (the
/// subject's girth), is nearest the scan's over `params.window`. `None` when too little of the
/// profiles overlaps.
pub fn register(
    template: &[Option<f64>],
    scan: &[Option<f64>],
    joint: f64,
    start: f64,
    params: &ProfileParams,
) -> Option<f64> {
    let steps = 64;
    let candidates = (0..=steps)
        .map(|s| start - params.search + 2.0 * params.search * s as f64 / steps as f64)
        .filter(|f| *f > 0.05 && *f < 0.95);
    least_cost(candidates, |f| {
        let pairs: Vec<(f64, f64)> = scan
            .iter()
            .enumerate()
            .filter_map(|(i, w)| {
                let u = (i as f64 + 0.5) / scan.len() as f64;
                if !(params.window.0..=params.window.1).contains(&u) {
                    return None;
                }
                let ut = if u < f {
                    u * joint / f
                } else {
                    joint + (u - f) * (1.0 - joint) / (1.0 - f)
                };
                Some(((*w)?, at(template, ut)?))
            })
            .collect();
        (pairs.len() >= scan.len() / 3).then_some(pairs)
    })
}

/// The shift (fraction of the line) that brings the template's profile, times a fitted gain,
/// nearest the scan's over `window` (fractions along the template's line): of the shifts from
/// `shifts.0` to `shifts.1` in `params.shift_steps` steps, the one with the least mean squared
/// difference. `None` when too little of the profiles overlaps at every shift.
pub fn register_shift(
    template: &[Option<f64>],
    scan: &[Option<f64>],
    window: (f64, f64),
    shifts: (f64, f64),
    params: &ProfileParams,
) -> Option<f64> {
    let bins = |u: f64| (u * template.len() as f64) as usize;
    let (first, last) = (bins(window.0), bins(window.1).min(template.len() - 1));
    let candidates = (0..=params.shift_steps)
        .map(|s| shifts.0 + (shifts.1 - shifts.0) * s as f64 / params.shift_steps as f64);
    least_cost(candidates, |shift| {
        let pairs: Vec<(f64, f64)> = (first..=last)
            .filter_map(|i| {
                let u = (i as f64 + 0.5) / template.len() as f64;
                Some((at(scan, u + shift)?, template[i]?))
            })
            .collect();
        (pairs.len() * 3 >= (last + 1 - first) * 2).then_some(pairs)
    })
}

/// Of `candidates`, the first with the least [`gained_cost`] of its (scan, template) width
/// pairs (`pairs`: `None` when too little of the profiles overlaps there).
fn least_cost(
    candidates: impl Iterator<Item = f64>,
    pairs: impl Fn(f64) -> Option<Vec<(f64, f64)>>,
) -> Option<f64> {
    let mut best: Option<(f64, f64)> = None;
    for c in candidates {
        let Some(cost) = pairs(c).and_then(|p| gained_cost(&p)) else {
            continue;
        };
        if best.is_none_or(|(least, _)| cost < least) {
            best = Some((cost, c));
        }
    }
    best.map(|(_, c)| c)
}

/// The mean squared difference of (scan, template) widths `pairs` with the template's times the
/// least-squares gain (the subject's girth); `None` for no template width.
fn gained_cost(pairs: &[(f64, f64)]) -> Option<f64> {
    let st: f64 = pairs.iter().map(|(s, t)| s * t).sum();
    let tt: f64 = pairs.iter().map(|(_, t)| t * t).sum();
    if tt <= 0.0 {
        return None;
    }
    let gain = st / tt;
    let sum: f64 = pairs.iter().map(|(s, t)| (s - gain * t).powi(2)).sum();
    Some(sum / pairs.len() as f64)
}

/// The triangles of `triangles` (on `positions`) that may reach within `radius` (m) of `line`:
/// those with a corner within `radius` and the triangle's longest edge of it (every point of a
/// triangle lies within its longest edge of each corner).
pub fn triangles_near(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    line: &LimbLine,
    radius: f64,
) -> Vec<[u32; 3]> {
    let distance: Vec<f64> = positions.iter().map(|p| line.locate(p).1).collect();
    triangles
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|v| positions[v as usize]);
            let longest = (b - a).norm().max((c - b).norm()).max((a - c).norm());
            t.iter().any(|&v| distance[v as usize] <= radius + longest)
        })
        .copied()
        .collect()
}

/// Fraction along `line` of the projection of `p`.
pub fn fraction(line: &LimbLine, p: &Point3<f64>) -> f64 {
    line.locate(p).0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rings around the z axis from z = 1 (root) to 0 (end), radius `r(u)`.
    fn limb(r: impl Fn(f64) -> f64) -> Vec<Point3<f64>> {
        let mut out = Vec::new();
        for i in 0..400 {
            let u = (i as f64 + 0.5) / 400.0;
            for j in 0..24 {
                let a = j as f64 / 24.0 * std::f64::consts::TAU;
                out.push(Point3::new(r(u) * a.cos(), r(u) * a.sin(), 1.0 - u));
            }
        }
        out
    }

    /// The line of the limbs `limb` makes: from the root at z = 1 to the end at the origin.
    fn axis() -> LimbLine {
        LimbLine {
            root: Point3::new(0.0, 0.0, 1.0),
            end: Point3::origin(),
        }
    }

    /// The width profile of `points` about `limbs[0]` (within 14 cm, default parameters).
    fn widths(points: &[Point3<f64>], limbs: &[LimbLine]) -> Vec<Option<f64>> {
        profile(points, limbs, 0, 0.14, &ProfileParams::default())
    }

    /// A leg: wide thigh narrowing to the knee at `k`, a calf bulge below it.
    fn leg(k: f64, girth: f64) -> impl Fn(f64) -> f64 {
        move |u: f64| {
            let r = if u < k {
                0.08 - 0.03 * u / k
            } else {
                let t = (u - k) / (1.0 - k);
                0.05 + 0.015 * (std::f64::consts::PI * t.min(0.6) / 0.6).sin() - 0.02 * t
            };
            r * girth
        }
    }

    #[test]
    fn the_knee_is_found_where_the_profile_puts_it() {
        let line = [axis()];
        let template = widths(&limb(leg(0.5, 1.0)), &line);
        // The scan's knee sits lower (0.55) and its leg is thicker; the fit put it at 0.5.
        let scan = widths(&limb(leg(0.55, 1.2)), &line);
        let f = register(&template, &scan, 0.5, 0.5, &ProfileParams::default()).unwrap();
        assert!((f - 0.55).abs() < 0.01, "{f}");
        // Points nearer another limb's line are not this limb's.
        let other = LimbLine {
            root: Point3::new(0.02, 0.0, 1.0),
            end: Point3::new(0.02, 0.0, 0.0),
        };
        let half = widths(&limb(leg(0.5, 1.0)), &[line[0], other]);
        assert!(half.iter().flatten().count() > 0);
        assert_ne!(half, template);
    }

    /// A forearm narrowing to the wrist at `w` and the hand widening out of it, then a hollow and
    /// the hip beyond (a hand on the hip).
    fn forearm(w: f64, girth: f64) -> impl Fn(f64) -> f64 {
        move |u: f64| {
            let r = if u < w {
                0.03 - 0.01 * u / w
            } else if u < w + 0.1 {
                0.02 + 0.01 * (u - w) / 0.1
            } else if u < w + 0.2 {
                0.03 - 0.02 * (u - w - 0.1) / 0.1
            } else {
                0.01 + 0.04 * (u - w - 0.2)
            };
            r * girth
        }
    }

    #[test]
    fn the_wrist_is_found_by_the_forearm_and_the_hand_around_it() {
        let line = [axis()];
        let template = widths(&limb(forearm(0.6, 1.0)), &line);
        for (w, girth) in [(0.68, 1.1), (0.6, 0.9), (0.55, 1.0)] {
            let scan = widths(&limb(forearm(w, girth)), &line);
            let shift = register_shift(
                &template,
                &scan,
                (0.45, 0.72),
                (-0.1, 0.2),
                &ProfileParams::default(),
            )
            .unwrap();
            assert!((shift - (w - 0.6)).abs() < 0.01, "{w}: {shift}");
        }
    }

    /// A leg seen from the side: how far forward it reaches, the thigh's front narrowing to the
    /// patella's bulge at the knee (`k`), the front falling back to the shin from `k + 0.02`.
    fn front(k: f64) -> impl Fn(f64, f64) -> f64 {
        move |u: f64, a: f64| {
            let r = if u < k - 0.04 {
                0.07 - 0.02 * u / (k - 0.04)
            } else if u < k + 0.02 {
                0.05 + 0.005 * ((u - k + 0.04) / 0.06 * std::f64::consts::PI).sin()
            } else {
                let t = ((u - k - 0.02) / 0.04).min(1.0);
                0.05 - 0.015 * t * t * (3.0 - 2.0 * t)
            };
            // x of the point at angle `a` about the axis: the front (−x) reaches `r`, the back
            // stays round.
            if a.cos() < 0.0 {
                r * a.cos()
            } else {
                0.05 * a.cos()
            }
        }
    }

    #[test]
    fn the_knee_is_found_above_the_fall_of_the_front() {
        let rings = |k: f64| {
            let mut out = Vec::new();
            for i in 0..400 {
                let u = (i as f64 + 0.5) / 400.0;
                for j in 0..48 {
                    let a = j as f64 / 48.0 * std::f64::consts::TAU;
                    out.push(Point3::new(front(k)(u, a), 0.05 * a.sin(), 1.0 - u));
                }
            }
            out
        };
        let line = [axis()];
        let ahead = -Vector3::x();
        let template = reach(
            &rings(0.45),
            &line,
            0,
            0.14,
            &ahead,
            &ProfileParams::default(),
        );
        let scan = reach(
            &rings(0.5),
            &line,
            0,
            0.14,
            &ahead,
            &ProfileParams::default(),
        );
        // The width's profile put the scan's knee at 0.48; the front says 0.5.
        let f = knee_from_front(&template, &scan, 0.45, 0.48, &ProfileParams::default()).unwrap();
        assert!((f - 0.5).abs() < 0.01, "{f}");
        // No front, no fall.
        assert_eq!(
            knee_from_front(
                &template,
                &vec![None; ProfileParams::default().bins],
                0.45,
                0.48,
                &ProfileParams::default()
            ),
            None
        );
    }
}
