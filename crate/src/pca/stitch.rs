//! The stitching of a whole-body and segment reconstructions with the segments' blend weights:
//! the coefficient and plan types, and the f32 kernels of the slider fast path (the methods that
//! use them are on [`super::BodyModel`], in [`super::model`]).
//!
//! Semantics. Coefficients hold the whole-body vector B and, per segment s, either nothing or
//! its own vector Bₛ. Segment s contributes xᵥ⁽ˢ⁾ = its own reconstruction S̄ₛ + ΦₛBₛ when Bₛ is
//! set ("overridden"), else the whole-body reconstruction S̄ + ΦB restricted to its vertices. The
//! body is xᵥ = Σₛ w̃ᵥ,ₛ xᵥ⁽ˢ⁾ with w̃ᵥ,ₛ = wᵥ,ₛ/Σₜwᵥ,ₜ (vertices in no segment take the whole
//! body). As the whole-body part is the same for every non-overridden segment this is
//!   x = (1 − cᵥ)·(S̄ + ΦB) + Σ_{s overridden} w̃ₛ ⊙ (S̄ₛ + ΦₛBₛ),  cᵥ = Σ_{s overridden} w̃ᵥ,ₛ,
//! which is linear in every coefficient: a slider move is x += Δb·(weight ⊙ φₖ).
//! Continuity: the blend weights fall to 0 at a segment's border, so the body is seamless by
//! construction; the seam report measures how much neighbouring reconstructions disagree inside
//! their band (what the blend has to hide).

use super::shape_model::ShapeModel;
use crate::template::Segment;
use serde::{Deserialize, Serialize};

/// Coefficients of a body in model units: whole-body B and optional per-segment overrides Bₛ
/// ([`Segment::ALL`] order). Shorter vectors mean trailing zeros.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Coefficients {
    pub whole: Vec<f64>,
    pub segments: [Option<Vec<f64>>; 6],
}

impl Coefficients {
    /// Which segments are overridden.
    pub fn overridden(&self) -> [bool; 6] {
        std::array::from_fn(|s| self.segments[s].is_some())
    }
}

/// Which model's mode a slider moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModeTarget {
    Whole,
    Segment(Segment),
}

/// One slider move: coefficient `mode` of the `target` model changes by `delta` (model units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeDelta {
    pub target: ModeTarget,
    pub mode: usize,
    pub delta: f64,
}

/// Per-vertex weights for one set of overridden segments, cached between slider moves.
#[derive(Debug, Clone, PartialEq)]
pub struct StitchPlan {
    pub(super) overridden: [bool; 6],
    /// 1 − cᵥ per vertex; empty when no segment is overridden (then it is 1 everywhere).
    pub(super) whole_weight: Vec<f32>,
}

impl StitchPlan {
    /// The overridden segments this plan was made for.
    pub fn overridden(&self) -> [bool; 6] {
        self.overridden
    }
}

/// Largest disagreement between two segments' reconstructions inside their overlap band.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SeamReport {
    /// Largest ‖xᵥ⁽ˢ⁾ − xᵥ⁽ᵗ⁾‖ over vertices in both s and t, model units; 0 if no overlap.
    pub max_jump: f64,
    /// The two segments and the template vertex where it occurs.
    pub segments: Option<(Segment, Segment)>,
    pub vertex: Option<u32>,
}

/// x += a with Kahan compensation: `c` holds what earlier additions lost (x − c is the running
/// sum to within one rounding), and is subtracted from the next addend.
#[inline(always)]
pub(super) fn kahan_add(x: &mut f32, c: &mut f32, a: f32) {
    let y = a - *c;
    let t = *x + y;
    *c = (t - *x) - y;
    *x = t;
}

/// The (bₖ, φₖ) pairs with bₖ ≠ 0.
pub(super) fn nonzero_modes<'m>(model: &'m ShapeModel, b: &[f64]) -> Vec<(f32, &'m [f32])> {
    b.iter()
        .enumerate()
        .filter(|(_, &bk)| bk != 0.0)
        .map(|(k, &bk)| (bk as f32, model.mode(k)))
        .collect()
}

/// out += Σ bₖφₖ, four modes per pass so `out` is read and written once per four modes
/// (the loop is memory-bound: this roughly halves the traffic of one pass per mode).
pub(super) fn add_modes(out: &mut [f32], terms: &[(f32, &[f32])]) {
    for chunk in terms.chunks(4) {
        match *chunk {
            [(a, p), (b, q), (c, r), (d, t)] => {
                for ((((o, &x), &y), &z), &w) in out.iter_mut().zip(p).zip(q).zip(r).zip(t) {
                    *o += a * x + b * y + c * z + d * w;
                }
            }
            [(a, p), (b, q), (c, r)] => {
                for (((o, &x), &y), &z) in out.iter_mut().zip(p).zip(q).zip(r) {
                    *o += a * x + b * y + c * z;
                }
            }
            [(a, p), (b, q)] => {
                for ((o, &x), &y) in out.iter_mut().zip(p).zip(q) {
                    *o += a * x + b * y;
                }
            }
            [(a, p)] => axpy(a, p, out),
            _ => {}
        }
    }
}

/// out += b·φ over contiguous memory (auto-vectorised).
pub(super) fn axpy(b: f32, phi: &[f32], out: &mut [f32]) {
    for (o, &p) in out.iter_mut().zip(phi) {
        *o += b * p;
    }
}

/// out[3vⱼ + a] += b·w̃ⱼ·φ[3j + a] for a segment's vertices vⱼ.
pub(super) fn scatter_axpy(b: f32, phi: &[f32], indices: &[u32], blend: &[f32], out: &mut [f32]) {
    for ((p, &v), &w) in phi.chunks_exact(3).zip(indices).zip(blend) {
        let f = b * w;
        let o = 3 * v as usize;
        out[o] += f * p[0];
        out[o + 1] += f * p[1];
        out[o + 2] += f * p[2];
    }
}
