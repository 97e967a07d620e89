//! Mixed whole-body/segment reconstruction stitched with the segments' blend weights, the f32
//! fast path for sliders, and seam quality.
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

use super::error::PcaError;
use super::model::BodyModel;
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

/// Per-vertex weights for one set of overridden segments, cached between slider moves.
#[derive(Debug, Clone, PartialEq)]
pub struct StitchPlan {
    overridden: [bool; 6],
    /// 1 − cᵥ per vertex; empty when no segment is overridden (then it is 1 everywhere).
    whole_weight: Vec<f32>,
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

impl BodyModel {
    fn check(&self, c: &Coefficients) -> Result<(), PcaError> {
        self.whole.check_coefficients(c.whole.len())?;
        for (model, b) in self.segments.iter().zip(&c.segments) {
            if let Some(b) = b {
                model.check_coefficients(b.len())?;
            }
        }
        Ok(())
    }

    /// The per-vertex weights for a set of overridden segments.
    pub fn stitch_plan(&self, overridden: [bool; 6]) -> StitchPlan {
        let mut whole_weight = Vec::new();
        if overridden.iter().any(|&o| o) {
            whole_weight = vec![1.0f32; self.template.vertex_count];
            for s in (0..6).filter(|&s| overridden[s]) {
                for (&v, &w) in self.segments[s].vertex_indices.iter().zip(&self.blend[s]) {
                    whole_weight[v as usize] -= w;
                }
            }
            // Rounding leaves ±1e-7 where a vertex is fully covered: that is no weight (a
            // whole-body contribution of < 1e-6 of a coordinate), so such vertices skip the
            // whole-body basis.
            whole_weight
                .iter_mut()
                .for_each(|w| *w = if *w < WHOLE_WEIGHT_EPSILON { 0.0 } else { *w });
        }
        StitchPlan {
            overridden,
            whole_weight,
        }
    }

    /// Writes the stitched body for `coefficients` into `out` (flat `[x0, y0, z0, ...]`, 3V f32)
    /// and returns the plan for subsequent [`BodyModel::apply_delta`] calls. Mode-major: each
    /// non-zero coefficient is one pass of out += b·φₖ over contiguous memory.
    pub fn reconstruct_into(
        &self,
        coefficients: &Coefficients,
        out: &mut [f32],
    ) -> Result<StitchPlan, PcaError> {
        self.check(coefficients)?;
        self.check_out(out)?;
        let plan = self.stitch_plan(coefficients.overridden());
        let terms = nonzero_modes(&self.whole, &coefficients.whole);
        if plan.whole_weight.is_empty() {
            out.copy_from_slice(&self.whole.mean);
            add_modes(out, &terms);
        } else {
            // Only where the whole body still has weight: vertex blocks wholly covered by
            // overridden segments skip the whole-body basis (with all six overridden, all of it).
            for (block, weights) in plan.whole_weight.chunks(WHOLE_BLOCK).enumerate() {
                let range = 3 * block * WHOLE_BLOCK..3 * (block * WHOLE_BLOCK + weights.len());
                let out = &mut out[range.clone()];
                if weights.iter().all(|&w| w == 0.0) {
                    out.fill(0.0);
                    continue;
                }
                out.copy_from_slice(&self.whole.mean[range.clone()]);
                let block_terms: Vec<(f32, &[f32])> = terms
                    .iter()
                    .map(|&(b, phi)| (b, &phi[range.clone()]))
                    .collect();
                add_modes(out, &block_terms);
                for (xyz, &w) in out.chunks_exact_mut(3).zip(weights) {
                    xyz.iter_mut().for_each(|x| *x *= w);
                }
            }
        }
        for (s, b) in coefficients.segments.iter().enumerate() {
            let Some(b) = b else { continue };
            let model = &self.segments[s];
            // Reconstruct the segment contiguously, then blend it in with one scatter.
            let mut part = model.mean.clone();
            add_modes(&mut part, &nonzero_modes(model, b));
            scatter_axpy(1.0, &part, &model.vertex_indices, &self.blend[s], out);
        }
        Ok(plan)
    }

    /// Incremental slider move: adds the effect of changing one coefficient by `delta` to `out`
    /// (which holds the body reconstructed with `plan`). Moving a segment mode needs that segment
    /// to be overridden in the plan (otherwise reconstruct with the new override set first).
    pub fn apply_delta(
        &self,
        plan: &StitchPlan,
        target: ModeTarget,
        mode: usize,
        delta: f64,
        out: &mut [f32],
    ) -> Result<(), PcaError> {
        self.check_out(out)?;
        let d = delta as f32;
        match self.delta_pass(plan, target, mode)? {
            DeltaPass::Contiguous(phi) => axpy(d, phi, out),
            DeltaPass::Weighted(phi, weight) => {
                for ((xyz, p), &w) in out.chunks_exact_mut(3).zip(phi.chunks_exact(3)).zip(weight) {
                    let f = d * w;
                    xyz[0] += f * p[0];
                    xyz[1] += f * p[1];
                    xyz[2] += f * p[2];
                }
            }
            DeltaPass::Scatter(phi, indices, blend) => scatter_axpy(d, phi, indices, blend, out),
        }
        Ok(())
    }

    /// [`BodyModel::apply_delta`] with compensated (Kahan) summation: `carry` (same length as
    /// `out`, zero after a full reconstruction) keeps the low-order part each f32 addition loses,
    /// so any number of slider moves stays within a few f32 roundings of a full reconstruction
    /// instead of drifting as a random walk of roundings (tested in `pca::morph`). Costs one
    /// more stream (`carry`) than the plain update.
    pub fn apply_delta_compensated(
        &self,
        plan: &StitchPlan,
        target: ModeTarget,
        mode: usize,
        delta: f64,
        out: &mut [f32],
        carry: &mut [f32],
    ) -> Result<(), PcaError> {
        self.check_out(out)?;
        self.check_out(carry)?;
        let d = delta as f32;
        match self.delta_pass(plan, target, mode)? {
            DeltaPass::Contiguous(phi) => {
                for ((x, c), &p) in out.iter_mut().zip(carry.iter_mut()).zip(phi) {
                    kahan_add(x, c, d * p);
                }
            }
            DeltaPass::Weighted(phi, weight) => {
                for (((xyz, cs), p), &w) in out
                    .chunks_exact_mut(3)
                    .zip(carry.chunks_exact_mut(3))
                    .zip(phi.chunks_exact(3))
                    .zip(weight)
                {
                    let f = d * w;
                    for a in 0..3 {
                        kahan_add(&mut xyz[a], &mut cs[a], f * p[a]);
                    }
                }
            }
            DeltaPass::Scatter(phi, indices, blend) => {
                for ((p, &v), &w) in phi.chunks_exact(3).zip(indices).zip(blend) {
                    let f = d * w;
                    let o = 3 * v as usize;
                    for a in 0..3 {
                        kahan_add(&mut out[o + a], &mut carry[o + a], f * p[a]);
                    }
                }
            }
        }
        Ok(())
    }

    /// What one slider move adds, checked against the plan: φₖ over all vertices, φₖ weighted by
    /// 1 − cᵥ, or a segment's φₖ scattered with its blend weights.
    fn delta_pass<'a>(
        &'a self,
        plan: &'a StitchPlan,
        target: ModeTarget,
        mode: usize,
    ) -> Result<DeltaPass<'a>, PcaError> {
        let bad_mode =
            |m: usize| PcaError::BadParameter(format!("mode {mode} of a model with {m} modes"));
        match target {
            ModeTarget::Whole => {
                if mode >= self.whole.mode_count() {
                    return Err(bad_mode(self.whole.mode_count()));
                }
                let phi = self.whole.mode(mode);
                Ok(if plan.whole_weight.is_empty() {
                    DeltaPass::Contiguous(phi)
                } else {
                    DeltaPass::Weighted(phi, &plan.whole_weight)
                })
            }
            ModeTarget::Segment(segment) => {
                let s = segment.index();
                if !plan.overridden[s] {
                    return Err(PcaError::BadParameter(format!(
                        "segment {} is not overridden in this plan; reconstruct with its coefficients first",
                        segment.name()
                    )));
                }
                let model = &self.segments[s];
                if mode >= model.mode_count() {
                    return Err(bad_mode(model.mode_count()));
                }
                Ok(DeltaPass::Scatter(
                    model.mode(mode),
                    &model.vertex_indices,
                    &self.blend[s],
                ))
            }
        }
    }

    fn check_out(&self, out: &[f32]) -> Result<(), PcaError> {
        if out.len() != 3 * self.template.vertex_count {
            return Err(PcaError::BadLength {
                what: "output positions".into(),
                expected: 3 * self.template.vertex_count,
                got: out.len(),
            });
        }
        Ok(())
    }

    /// Each segment's own contribution xᵥ⁽ˢ⁾ in f64 (flat over its subset), per the semantics above.
    pub fn segment_reconstructions(&self, c: &Coefficients) -> Result<Vec<Vec<f64>>, PcaError> {
        self.check(c)?;
        let whole = self.whole.reconstruct(&c.whole)?;
        self.segments
            .iter()
            .zip(&c.segments)
            .map(|(model, b)| match b {
                Some(b) => model.reconstruct(b),
                None => Ok(model
                    .vertex_indices
                    .iter()
                    .flat_map(|&v| whole[3 * v as usize..3 * v as usize + 3].iter().copied())
                    .collect()),
            })
            .collect()
    }

    /// The stitched body in f64 (reference implementation of [`BodyModel::reconstruct_into`]).
    pub fn reconstruct(&self, c: &Coefficients) -> Result<Vec<f64>, PcaError> {
        let parts = self.segment_reconstructions(c)?;
        let plan = self.stitch_plan(c.overridden());
        let mut out = self.whole.reconstruct(&c.whole)?;
        if !plan.whole_weight.is_empty() {
            for (xyz, &w) in out.chunks_exact_mut(3).zip(&plan.whole_weight) {
                xyz.iter_mut().for_each(|x| *x *= w as f64);
            }
        }
        for s in (0..6).filter(|&s| plan.overridden[s]) {
            for (j, (&v, &w)) in self.segments[s]
                .vertex_indices
                .iter()
                .zip(&self.blend[s])
                .enumerate()
            {
                for a in 0..3 {
                    out[3 * v as usize + a] += w as f64 * parts[s][3 * j + a];
                }
            }
        }
        Ok(out)
    }

    /// Seam quality: the largest jump between two segments' contributions within their overlap.
    pub fn seam_report(&self, c: &Coefficients) -> Result<SeamReport, PcaError> {
        let parts = self.segment_reconstructions(c)?;
        let v = self.template.vertex_count;
        let mut report = SeamReport {
            max_jump: 0.0,
            segments: None,
            vertex: None,
        };
        let mut local = vec![u32::MAX; v];
        for a in 0..6 {
            local.iter_mut().for_each(|l| *l = u32::MAX);
            for (j, &vi) in self.segments[a].vertex_indices.iter().enumerate() {
                local[vi as usize] = j as u32;
            }
            for b in a + 1..6 {
                for (j, &vi) in self.segments[b].vertex_indices.iter().enumerate() {
                    let i = local[vi as usize];
                    if i == u32::MAX {
                        continue;
                    }
                    let (pa, pb) = (&parts[a][3 * i as usize..], &parts[b][3 * j..]);
                    let jump = ((pa[0] - pb[0]).powi(2)
                        + (pa[1] - pb[1]).powi(2)
                        + (pa[2] - pb[2]).powi(2))
                    .sqrt();
                    if jump > report.max_jump || report.segments.is_none() {
                        report.max_jump = report.max_jump.max(jump);
                        report.segments = Some((Segment::ALL[a], Segment::ALL[b]));
                        report.vertex = Some(vi);
                    }
                }
            }
        }
        Ok(report)
    }
}

/// The arrays one slider move reads (see [`BodyModel::apply_delta`]).
enum DeltaPass<'a> {
    Contiguous(&'a [f32]),
    Weighted(&'a [f32], &'a [f32]),
    Scatter(&'a [f32], &'a [u32], &'a [f32]),
}

/// x += a with Kahan compensation: `c` holds what earlier additions lost (x − c is the running
/// sum to within one rounding), and is subtracted from the next addend.
#[inline(always)]
fn kahan_add(x: &mut f32, c: &mut f32, a: f32) {
    let y = a - *c;
    let t = *x + y;
    *c = (t - *x) - y;
    *x = t;
}

/// The (bₖ, φₖ) pairs with bₖ ≠ 0.
/// Vertices per block of the whole-body pass under overrides (blocks without whole-body weight
/// are skipped; 4096 vertices keep a block's slice of `out` in L1/L2 across its modes).
const WHOLE_BLOCK: usize = 4096;

/// Whole-body weights below this (left by rounding where overridden segments cover a vertex
/// fully) count as zero.
const WHOLE_WEIGHT_EPSILON: f32 = 1e-6;

fn nonzero_modes<'m>(model: &'m super::model::ShapeModel, b: &[f64]) -> Vec<(f32, &'m [f32])> {
    b.iter()
        .enumerate()
        .filter(|(_, &bk)| bk != 0.0)
        .map(|(k, &bk)| (bk as f32, model.mode(k)))
        .collect()
}

/// out += Σ bₖφₖ, four modes per pass so `out` is read and written once per four modes
/// (the loop is memory-bound: this roughly halves the traffic of one pass per mode).
fn add_modes(out: &mut [f32], terms: &[(f32, &[f32])]) {
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
fn axpy(b: f32, phi: &[f32], out: &mut [f32]) {
    for (o, &p) in out.iter_mut().zip(phi) {
        *o += b * p;
    }
}

/// out[3vⱼ + a] += b·w̃ⱼ·φ[3j + a] for a segment's vertices vⱼ.
fn scatter_axpy(b: f32, phi: &[f32], indices: &[u32], blend: &[f32], out: &mut [f32]) {
    for ((p, &v), &w) in phi.chunks_exact(3).zip(indices).zip(blend) {
        let f = b * w;
        let o = 3 * v as usize;
        out[o] += f * p[0];
        out[o + 1] += f * p[1];
        out[o + 2] += f * p[2];
    }
}
