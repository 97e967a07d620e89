//! ISO 8559-1's cervicale found on the back of the neck rather than taken from the Cervicale
//! vertex: the tip of the 7th cervical vertebra's spinous process, at the base of the neck
//! behind, where the back's line turns into the neck's.
//!
//! The body's **back profile** is its mid-sagittal section (the plane through the neck's base,
//! the midpoint of the Cervicale and the Suprasternale, across the body) seen from behind: at
//! each height the rearmost point of the head's and torso's section. Going up from the upper
//! back's most rearward point (its **peak**, under the guess) the profile comes forward to the
//! back of the neck's deepest point (its **trough**, over the peak). The cervicale is the first
//! level above the peak where the profile has come the fraction `f` of that way, `f` the
//! template's own: where its Cervicale vertex stands at rest (`MeasureParams::cervicale_fraction`,
//! held to the template by `crate/tests/measure_cervicale.rs`). A guess a few centimetres off names the same level, and the level moves continuously with the
//! surface (the profile is interpolated between the section's points and between heights). The
//! neck base girth's tape does not use it (docs/measurements.md, "The cervicale on the back of
//! the neck").

use super::section::{plane_section, Plane};
use super::vec3::{cross, dot, unit};

/// The back profile: at heights `step` apart from `low`, the rearmost point of the section
/// along `backward` (metres), `None` where the section has no point at that height.
#[derive(Debug, Clone, PartialEq)]
pub struct BackProfile {
    pub low: f64,
    pub step: f64,
    pub back: Vec<Option<f64>>,
}

/// The back profile of the body at flat `positions` cut from `region` (indices into
/// `triangles`: the head's and torso's), through `base` (the neck's base) and square to the
/// horizontal across the body (`up` × `backward`), from `low` to `high` every `step` (metres).
/// `None` when `backward` has no horizontal part or nothing is cut.
#[allow(clippy::too_many_arguments)]
pub fn back_profile(
    positions: &[f32],
    triangles: &[[u32; 3]],
    region: &[u32],
    base: [f64; 3],
    backward: [f64; 3],
    up_axis: usize,
    (low, high): (f64, f64),
    step: f64,
) -> Option<BackProfile> {
    let mut backward = backward;
    backward[up_axis] = 0.0;
    let backward = unit(backward)?;
    let mut up = [0.0; 3];
    up[up_axis] = 1.0;
    let lateral = cross(up, backward);
    let plane = Plane::new(base, lateral)?;
    let loops = plane_section(positions, triangles, region, &plane);
    let count = ((high - low) / step).floor() as usize + 1;
    let mut back: Vec<Option<f64>> = vec![None; count];
    for l in &loops {
        let points: Vec<[f64; 3]> = l.points.iter().map(|&q| plane.from_plane(q)).collect();
        let n = points.len();
        let edges = if l.closed { n } else { n.saturating_sub(1) };
        for i in 0..edges {
            let (p, q) = (points[i], points[(i + 1) % n]);
            let (hp, hq) = (p[up_axis], q[up_axis]);
            let (lo, hi) = (hp.min(hq), hp.max(hq));
            let first = ((lo - low) / step).ceil().max(0.0) as usize;
            let mut k = first;
            while k < count {
                let h = low + k as f64 * step;
                if h > hi {
                    break;
                }
                let t = if hq == hp { 0.5 } else { (h - hp) / (hq - hp) };
                let b = dot(p, backward) + t * (dot(q, backward) - dot(p, backward));
                back[k] = Some(back[k].map_or(b, |x: f64| x.max(b)));
                k += 1;
            }
        }
    }
    back.iter()
        .any(Option::is_some)
        .then_some(BackProfile { low, step, back })
}

/// Where the back of the neck turns: the peak under a height, the trough over it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NeckTurn {
    /// The upper back's rearmost level and how far back it is (metres).
    pub peak: (f64, f64),
    /// The back of the neck's deepest level over the peak and its depth (metres).
    pub trough: (f64, f64),
}

impl BackProfile {
    fn height(&self, k: usize) -> f64 {
        self.low + k as f64 * self.step
    }

    /// The upper back's peak at or under `guess` and the neck's trough over it; `None` when the
    /// profile has no point under the guess or the trough is not forward of the peak.
    pub fn turn(&self, guess: f64) -> Option<NeckTurn> {
        let samples = || {
            self.back
                .iter()
                .enumerate()
                .filter_map(|(k, b)| b.map(|b| (k, b)))
        };
        let (kp, bp) = samples()
            .filter(|&(k, _)| self.height(k) <= guess)
            .max_by(|a, b| a.1.total_cmp(&b.1))?;
        let (kt, bt) = samples()
            .filter(|&(k, _)| k > kp)
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        (bt < bp).then_some(NeckTurn {
            peak: (self.height(kp), bp),
            trough: (self.height(kt), bt),
        })
    }

    /// The first level over `turn`'s peak where the profile has come the fraction `f` of the way
    /// from the peak's rearmost to the trough's depth, interpolated between the samples.
    pub fn level(&self, turn: &NeckTurn, f: f64) -> Option<f64> {
        let wanted = turn.peak.1 - f * (turn.peak.1 - turn.trough.1);
        let mut below: Option<(f64, f64)> = None;
        for (k, b) in self.back.iter().enumerate() {
            let (h, Some(b)) = (self.height(k), *b) else {
                continue;
            };
            if h < turn.peak.0 || h > turn.trough.0 {
                continue;
            }
            if b <= wanted {
                return Some(match below {
                    Some((h0, b0)) if b0 > b => h0 + (b0 - wanted) / (b0 - b) * (h - h0),
                    _ => h,
                });
            }
            below = Some((h, b));
        }
        None
    }

    /// How far the profile's turn has come at `height`: 0 at the peak, 1 at the trough (the
    /// inverse of [`BackProfile::level`]); `None` off the profile.
    pub fn fraction_at(&self, turn: &NeckTurn, height: f64) -> Option<f64> {
        let b = self.back_at(height)?;
        Some((turn.peak.1 - b) / (turn.peak.1 - turn.trough.1))
    }

    /// The profile's rearmost point at `height`, interpolated between the samples.
    pub fn back_at(&self, height: f64) -> Option<f64> {
        let x = (height - self.low) / self.step;
        if x < 0.0 {
            return None;
        }
        let k = x.floor() as usize;
        let t = x - k as f64;
        match (
            self.back.get(k).copied()?,
            self.back.get(k + 1).copied().flatten(),
        ) {
            (Some(a), Some(b)) => Some(a + t * (b - a)),
            (Some(a), None) if t == 0.0 => Some(a),
            _ => None,
        }
    }
}
