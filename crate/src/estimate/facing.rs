//! Which way a standing body faces, from the shape of its legs seen from the side.
//!
//! * **The feet**: a foot reaches forward of its ankle (heel to toe ≈ 25 cm, the ankle ≈ 5–7 cm
//!   in front of the heel), so the scan's points at the feet lie, on average,
//!   several centimetres forward of those of the lower legs just above them. It holds wherever the
//!   feet are on the scan, whatever the arms, the hair or the clothes do to the nearest points; a
//!   back-to-front fit had been chosen by 7 % of the similarity's energy on a body with hair
//!   (issue 31, the scanner zoo's `hair`). Cut feet leave the lower legs, which do not reach: the
//!   feet do not say. A floor or turntable left under the feet spreads around them and shortens
//!   the reach.
//! * **The legs**, when the feet do not say: seen from the side a leg is an S.
//!   The front of the thigh is convex (the quadriceps) and the back of the lower leg is convex
//!   (the calf), while the back of the thigh and the shin are nearly straight; so the thighs'
//!   points lie forward of the calves'. A bent knee moves both back from the knee alike and
//!   leaves their difference. The two slabs lie far apart in height, so they are compared along
//!   the body's plumb line (from the lower legs' centroid through the shoulders'), not along the
//!   principal axis, which a belly, the buttocks or a head held forward lean by a few degrees. A
//!   scan whose feet were cut had been fitted back to front, the two facings' similarity fits
//!   0.6 % apart (issue 31, blind zoo seed 8461, `feet-cut`).
//!
//! With `up` the body's up (from the head's end, `up.rs`) and the robust extent along it as
//! there (the `EXTENT_PERCENTILE` quantiles of the heights of the triangles' vertices), each cue
//! compares the centroids of two slabs (fractions of the extent from the bottom) along the
//! body's front–back axis `depth` (square to `up`): the front slab's lies forward of the back
//! slab's, and says which way is forward when at least `decisive` times the extent forward. Only
//! that axis is judged: an up tilted by a raised arm (the principal axis leans towards it, in the
//! frontal plane) adds a shift across the body, not along it.

use nalgebra::{Point3, Vector3};

use super::up::{quantile, triangulated, EXTENT_PERCENTILE};

/// The feet and the lower legs just above them, fractions of the extent from the bottom (the
/// feet's with every point under the robust bottom).
const FEET_SLAB: (f64, f64) = (0.0, 0.03);
const SHIN_SLAB: (f64, f64) = (0.06, 0.09);
/// The thighs above the knees (which stand at ≈ 27 % of stature) and the calves below them,
/// fractions of the extent from the bottom. The thighs' slab stays under the fingertips of
/// hanging arms (≈ 38 %) when up to 6 cm of the feet is cut.
const THIGH_SLAB: (f64, f64) = (0.30, 0.36);
const CALF_SLAB: (f64, f64) = (0.08, 0.18);
/// The lower legs and the shoulders: a standing body's plumb line runs from just in front of
/// the ankles through the shoulders (the acromions stand at ≈ 82 % of stature).
const ANKLE_SLAB: (f64, f64) = (0.04, 0.10);
const SHOULDER_SLAB: (f64, f64) = (0.78, 0.84);

/// Which part of the body said which way it faces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FacingCue {
    Feet,
    Legs,
}

/// A cue's verdict on which way the body faces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forward {
    /// Forward (unit, ±`depth` made square to up, for the legs to the plumb line): the way the
    /// front slab lies from the back one.
    pub forward: Vector3<f64>,
    /// How far (the scan's units) the front slab's centroid lies forward of the back one's.
    pub reach: f64,
    /// `reach` as a share of the body's robust extent along up: what `decisive` is compared to.
    pub share: f64,
    pub cue: FacingCue,
}

/// Which way the body in `positions` (the vertices of `triangles` only) faces along `depth`
/// (the body's front–back axis, any length), with `up` the way from the feet to the head: the
/// feet's verdict when they reach at least `feet_decisive` times the body's extent, else the
/// legs' when the thighs lie at least `legs_decisive` times it forward of the calves; `None`
/// when neither says (a decisive of 0 turns its cue off).
pub fn body_forward(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    up: &Vector3<f64>,
    depth: &Vector3<f64>,
    feet_decisive: f64,
    legs_decisive: f64,
) -> Option<Forward> {
    let points = triangulated(positions, triangles);
    let along_up = Slabs::new(&points, up)?;
    let said = |cue, decisive: f64| {
        (decisive > 0.0)
            .then(|| cue_forward(&along_up, depth, cue))
            .flatten()
            .filter(|f| f.share >= decisive)
    };
    said(FacingCue::Feet, feet_decisive).or_else(|| said(FacingCue::Legs, legs_decisive))
}

/// The way along `depth` that `cue` says the body faces, however little: for the feet, the way
/// they reach from the lower legs (the front slab `FEET_SLAB`, the back `SHIN_SLAB`, along `up`);
/// for the legs, the way the thighs lie from the calves (`THIGH_SLAB`, `CALF_SLAB`, along the
/// plumb line). `None` when a slab is empty.
pub fn cue_says(
    cue: FacingCue,
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    up: &Vector3<f64>,
    depth: &Vector3<f64>,
) -> Option<Forward> {
    let points = triangulated(positions, triangles);
    cue_forward(&Slabs::new(&points, up)?, depth, cue)
}

/// One cue's verdict on the scan's triangulated vertices in slabs along the given up.
fn cue_forward(along_up: &Slabs, depth: &Vector3<f64>, cue: FacingCue) -> Option<Forward> {
    let plumb_slabs;
    let (slabs, front, back) = match cue {
        FacingCue::Feet => (along_up, FEET_SLAB, SHIN_SLAB),
        // The thighs and calves lie far apart in height, so they are compared along the plumb
        // line: a principal axis leaning 1° forward or back moves the thighs 3–4 mm against the
        // calves (0.34 % of the extent; it leant −2.2° to +3.3° on the zoo).
        FacingCue::Legs => {
            let plumb = along_up.centroid(SHOULDER_SLAB)? - along_up.centroid(ANKLE_SLAB)?;
            plumb_slabs = Slabs::new(along_up.points, &plumb)?;
            (&plumb_slabs, THIGH_SLAB, CALF_SLAB)
        }
    };
    let depth = (depth - slabs.up * depth.dot(&slabs.up)).try_normalize(1e-12)?;
    let along = (slabs.centroid(front)? - slabs.centroid(back)?).dot(&depth);
    Some(Forward {
        forward: depth * along.signum(),
        reach: along.abs(),
        share: along.abs() / slabs.extent,
        cue,
    })
}

/// The body's points in slabs of height along an up.
struct Slabs<'a> {
    points: &'a [Point3<f64>],
    /// Unit.
    up: Vector3<f64>,
    /// Each point's height above the robust bottom as a fraction of the extent.
    fractions: Vec<f64>,
    extent: f64,
}

impl<'a> Slabs<'a> {
    fn new(points: &'a [Point3<f64>], up: &Vector3<f64>) -> Option<Self> {
        let up = up.try_normalize(1e-12)?;
        let heights: Vec<f64> = points.iter().map(|p| p.coords.dot(&up)).collect();
        let lo = quantile(&heights, EXTENT_PERCENTILE)?;
        let extent = quantile(&heights, 1.0 - EXTENT_PERCENTILE)? - lo;
        if extent.is_nan() || extent <= 0.0 {
            return None;
        }
        let fractions = heights.iter().map(|t| (t - lo) / extent).collect();
        Some(Self {
            points,
            up,
            fractions,
            extent,
        })
    }

    /// The centroid of the points in the slab `(a, b)`; a slab from 0 takes every point under
    /// the robust bottom too (the soles' lowest points are the feet's).
    fn centroid(&self, (a, b): (f64, f64)) -> Option<Vector3<f64>> {
        let (mut sum, mut count) = (Vector3::zeros(), 0usize);
        for (p, &f) in self.points.iter().zip(&self.fractions) {
            if (f >= a || a == 0.0) && f <= b {
                sum += p.coords;
                count += 1;
            }
        }
        (count > 0).then(|| sum / count as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Surface points of two legs 0.3 m apart (y up, metres) up to a 1.7 m body, on feet 0.25 m
    /// long reaching `toes` forward (+z) of the ankles, their heels 0.06 m behind (`None`: the
    /// feet cut off at 0.055 m); the calves (0.12–0.36 m) bulge `s` back and the thighs
    /// (0.48–0.75 m) `s` forward. One triangle over all.
    fn legs(toes: Option<f64>, s: f64) -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
        let mut points = Vec::new();
        for i in 0..171 {
            let y = i as f64 * 0.01;
            for k in 0..24 {
                let a = std::f64::consts::TAU * k as f64 / 24.0;
                for cx in [-0.15, 0.15] {
                    let bulge = match y {
                        y if (0.12..0.36).contains(&y) => -s,
                        y if (0.48..0.75).contains(&y) => s,
                        _ => 0.0,
                    };
                    let p = match toes {
                        Some(_) | None if y >= 0.055 => {
                            Point3::new(cx + 0.05 * a.cos(), y, bulge + 0.05 * a.sin())
                        }
                        // The foot: an ellipse from the heel to the toes.
                        Some(front) => {
                            let back = -0.06;
                            let cz = (back + front) / 2.0;
                            Point3::new(
                                cx + 0.045 * a.cos(),
                                y,
                                cz + (front - back) / 2.0 * a.sin(),
                            )
                        }
                        None => continue,
                    };
                    points.push(p);
                }
            }
        }
        let n = points.len() as u32;
        let triangles = (0..n / 3).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect();
        (points, triangles)
    }

    #[test]
    fn the_feet_reach_forward_in_any_frame() {
        let (points, triangles) = legs(Some(0.19), 0.0);
        let turn = nalgebra::Rotation3::from_euler_angles(1.2, -0.4, 2.5);
        let turned: Vec<Point3<f64>> = points.iter().map(|p| turn * p * 1000.0).collect();
        let (up, depth) = (turn * Vector3::y(), turn * Vector3::z());
        // Either way along the front-back axis, and with it leaning 20° off the horizontal.
        for depth in [depth, -depth, depth + 0.36 * up] {
            let feet =
                body_forward(&turned, &triangles, &up, &depth, 0.015, 0.006).expect("the feet say");
            assert_eq!(feet.cue, FacingCue::Feet);
            assert!((feet.forward - turn * Vector3::z()).norm() < 1e-6);
            assert!((feet.reach - 65.0).abs() < 1.0, "{}", feet.reach);
        }
        // Across the body they do not reach.
        let across = turn * Vector3::x();
        assert_eq!(
            body_forward(&turned, &triangles, &up, &across, 0.015, 0.006),
            None
        );
    }

    #[test]
    fn feet_that_do_not_reach_and_straight_legs_do_not_say() {
        // Feet as long forward as back (a foot 0.12 m long centred under the leg).
        let (points, triangles) = legs(Some(0.06), 0.0);
        let (up, depth) = (Vector3::y(), Vector3::z());
        assert_eq!(
            body_forward(&points, &triangles, &up, &depth, 0.015, 0.006),
            None
        );
    }

    #[test]
    fn with_the_feet_cut_the_thighs_lie_forward_of_the_calves() {
        let (points, triangles) = legs(None, 0.02);
        let turn = nalgebra::Rotation3::from_euler_angles(-0.7, 2.1, 0.3);
        let turned: Vec<Point3<f64>> = points.iter().map(|p| turn * p * 1000.0).collect();
        let (up, depth) = (turn * Vector3::y(), turn * Vector3::z());
        for depth in [depth, -depth] {
            let legs =
                body_forward(&turned, &triangles, &up, &depth, 0.015, 0.006).expect("the legs say");
            assert_eq!(legs.cue, FacingCue::Legs);
            // The bulges are 40 mm apart; the plumb line leans back a little (the lower legs'
            // slab takes in the top of the calves) and the reach along it is shorter.
            assert!(legs.forward.dot(&(turn * Vector3::z())) > 0.999);
            assert!((25.0..=40.0).contains(&legs.reach), "{}", legs.reach);
        }
        // The legs' cue turned off, the feet alone do not say.
        assert_eq!(
            body_forward(&turned, &triangles, &up, &depth, 0.015, 0.0),
            None
        );
    }

    #[test]
    fn the_legs_are_read_along_the_plumb_line_not_a_leaning_up() {
        // An up leaning 6° back from the body's (a principal axis leant up to 3.3° on the zoo):
        // along it the thighs would lie 38 mm further back, level with the calves.
        let (points, triangles) = legs(None, 0.02);
        let (up, depth) = (Vector3::y(), Vector3::z());
        let upright = cue_says(FacingCue::Legs, &points, &triangles, &up, &depth).unwrap();
        let lean = nalgebra::Rotation3::from_axis_angle(&Vector3::x_axis(), 6f64.to_radians());
        let leaning = cue_says(FacingCue::Legs, &points, &triangles, &(lean * up), &depth).unwrap();
        assert!(
            leaning.forward.dot(&depth) > 0.999,
            "{leaning:?} vs {upright:?}"
        );
        assert!(
            (leaning.reach - upright.reach).abs() < 1e-3,
            "{}",
            leaning.reach
        );
    }

    #[test]
    fn the_feet_are_asked_first() {
        // Legs shaped back to front (thighs behind the calves) on feet reaching forward.
        let (points, triangles) = legs(Some(0.19), -0.02);
        let (up, depth) = (Vector3::y(), Vector3::z());
        let said = body_forward(&points, &triangles, &up, &depth, 0.015, 0.006).unwrap();
        assert_eq!((said.cue, said.forward), (FacingCue::Feet, Vector3::z()));
        let legs = cue_says(FacingCue::Legs, &points, &triangles, &up, &depth).unwrap();
        assert!(legs.forward.dot(&Vector3::z()) < -0.9995);
    }
}
