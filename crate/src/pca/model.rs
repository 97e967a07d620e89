//! The body model of paper §4 ([`BodyModel`]): the whole-body model, the six segment models and
//! what built them, with everything done to a body model — assembling and checking one,
//! projecting a mesh onto it (rigid alignment to the mean with the model's own pose removal, then
//! B = Φᵀ(x − S̄) for every part), and the stitched reconstruction of [`super::stitch`] (full,
//! as slider deltas, and the seam report).

use nalgebra::Point3;

use super::error::PcaError;
use super::params::BuildParams;
use super::procrustes_gpa::{rigid_align, PoseRemoval};
use super::shape_model::{ShapeModel, TemplateIdentity};
use super::stitch::{
    add_modes, axpy, kahan_add, nonzero_modes, scatter_axpy, Coefficients, ModeDelta, ModeTarget,
    SeamReport, StitchPlan,
};
use crate::mesh::bounds::bounding_extent;
use crate::mesh::similarity::Similarity;
use crate::mesh::units::detect_units;
use crate::template::Segment;

/// Result of [`BodyModel::project`].
#[derive(Debug, Clone, PartialEq)]
pub struct Projection {
    /// Whole-body and all six segment coefficients (model units).
    pub coefficients: Coefficients,
    /// The transform that brought the mesh into the model frame.
    pub pose: Similarity,
    /// Mean per-vertex distance between the aligned mesh and its whole-body reconstruction.
    pub residual: f64,
}

/// The whole-body model and the six segment models of paper §4, with everything needed to use
/// them: template identity, triangles, the segments' blend weights and the build settings.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyModel {
    pub template: TemplateIdentity,
    pub settings: BuildParams,
    /// Subject names (file stems) in score order.
    pub subjects: Vec<String>,
    /// Template triangles, to write reconstructed bodies.
    pub triangles: Vec<[u32; 3]>,
    /// Per-vertex blend weights in [`Segment::ALL`] order; a vertex is in a segment when its
    /// weight is > 0.
    pub segment_weights: Vec<[f32; 6]>,
    /// The whole-body model over all V vertices.
    pub whole: ShapeModel,
    /// Six segment models in [`Segment::ALL`] order, sharing the whole body's GPA frame.
    pub segments: Vec<ShapeModel>,
    /// Per segment, the normalised blend weight w̃ᵥ,ₛ = wᵥ,ₛ / Σₜ wᵥ,ₜ of each of its vertices.
    pub(crate) blend: Vec<Vec<f32>>,
}

impl BodyModel {
    /// Assembles a model and derives the normalised blend weights; checks that the parts agree.
    pub fn assemble(
        template: TemplateIdentity,
        settings: BuildParams,
        subjects: Vec<String>,
        triangles: Vec<[u32; 3]>,
        segment_weights: Vec<[f32; 6]>,
        whole: ShapeModel,
        segments: Vec<ShapeModel>,
    ) -> Result<Self, PcaError> {
        let v = template.vertex_count;
        let bad = |m: String| Err(PcaError::Corrupted(m));
        if whole.mean.len() != 3 * v || segment_weights.len() != v {
            return bad(format!(
                "template has {v} vertices but the whole-body mean has {} and the segment weights {}",
                whole.mean.len() / 3,
                segment_weights.len()
            ));
        }
        if segments.len() != Segment::ALL.len() {
            return bad(format!("{} segment models instead of 6", segments.len()));
        }
        if triangles.iter().flatten().any(|&i| i as usize >= v) {
            return bad("a triangle indexes a vertex beyond the template".into());
        }
        let subsets = super::segments::segment_subsets(&segment_weights);
        for ((s, model), subset) in Segment::ALL.iter().zip(&segments).zip(&subsets) {
            if model.vertex_indices != *subset || model.mean.len() != 3 * subset.len() {
                return bad(format!(
                    "segment {} vertex list does not match its blend weights",
                    s.name()
                ));
            }
        }
        for m in std::iter::once(&whole).chain(&segments) {
            let n = m.mode_count();
            if m.basis.len() != n * m.mean.len() || m.scores.len() != n * subjects.len() {
                return bad("a basis or score array does not match its mode count".into());
            }
        }
        let blend = super::segments::normalised_blend(&segment_weights, &subsets);
        Ok(Self {
            template,
            settings,
            subjects,
            triangles,
            segment_weights,
            whole,
            segments,
            blend,
        })
    }

    /// The model of one segment.
    pub fn segment(&self, segment: Segment) -> &ShapeModel {
        &self.segments[segment.index()]
    }

    /// Fails with [`PcaError::TemplateMismatch`] unless the model was built for `template`.
    pub fn check_template(&self, template: &TemplateIdentity) -> Result<(), PcaError> {
        if self.template != *template {
            return Err(PcaError::TemplateMismatch {
                model: self.template.to_string(),
                expected: template.to_string(),
            });
        }
        Ok(())
    }

    /// Projects `positions` (`#V` points in template order, any frame, in metres, centimetres or
    /// millimetres unless the model removes no pose) onto every model; `pose` is the map of the
    /// mesh into the model's frame.
    pub fn project(&self, positions: &[Point3<f64>]) -> Result<Projection, PcaError> {
        let v = self.template.vertex_count;
        if positions.len() != v {
            return Err(PcaError::VertexCountMismatch {
                subject: "mesh".into(),
                got: positions.len(),
                expected: v,
            });
        }
        if positions
            .iter()
            .any(|p| !p.coords.iter().all(|c| c.is_finite()))
        {
            return Err(PcaError::NonFinite("mesh".into()));
        }
        let mean: Vec<Point3<f64>> = self
            .whole
            .mean
            .chunks_exact(3)
            .map(|c| Point3::new(c[0] as f64, c[1] as f64, c[2] as f64))
            .collect();
        // In its units' metres first, as the build brings every training shape
        // ([`super::template_frame`]): a fit in millimetres projects as in metres.
        let u = match self.settings.gpa.pose {
            PoseRemoval::None => 1.0,
            _ => detect_units(bounding_extent(positions)).scale_to_metres(),
        };
        let metres: Vec<Point3<f64>> = positions
            .iter()
            .map(|p| Point3::from(p.coords * u))
            .collect();
        let pose = match self.settings.gpa.pose {
            PoseRemoval::None => Similarity::identity(),
            PoseRemoval::Rigid => rigid_align(&metres, &mean, false),
            PoseRemoval::Similarity => rigid_align(&metres, &mean, true),
        };
        let pose = Similarity {
            scale: pose.scale * u,
            ..pose
        };
        let x: Vec<f64> = positions
            .iter()
            .flat_map(|p| {
                let q = pose.apply(p);
                [q.x, q.y, q.z]
            })
            .collect();
        let whole = self.whole.project_flat(&x);
        let segments = std::array::from_fn(|s| {
            let model = &self.segments[s];
            let sub: Vec<f64> = model
                .vertex_indices
                .iter()
                .flat_map(|&i| x[3 * i as usize..3 * i as usize + 3].iter().copied())
                .collect();
            Some(model.project_flat(&sub))
        });
        let rebuilt = self.whole.reconstruct(&whole)?;
        let diff: Vec<f64> = rebuilt.iter().zip(&x).map(|(a, b)| a - b).collect();
        Ok(Projection {
            coefficients: Coefficients { whole, segments },
            pose,
            residual: super::metrics::mean_vertex_norm(&diff),
        })
    }

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
        change: ModeDelta,
        out: &mut [f32],
    ) -> Result<(), PcaError> {
        self.check_out(out)?;
        let d = change.delta as f32;
        match self.delta_pass(plan, change.target, change.mode)? {
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
        change: ModeDelta,
        out: &mut [f32],
        carry: &mut [f32],
    ) -> Result<(), PcaError> {
        self.check_out(out)?;
        self.check_out(carry)?;
        let d = change.delta as f32;
        match self.delta_pass(plan, change.target, change.mode)? {
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

/// Vertices per block of the whole-body pass under overrides (blocks without whole-body weight
/// are skipped; 4096 vertices keep a block's slice of `out` in L1/L2 across its modes).
const WHOLE_BLOCK: usize = 4096;

/// Whole-body weights below this (left by rounding where overridden segments cover a vertex
/// fully) count as zero.
const WHOLE_WEIGHT_EPSILON: f32 = 1e-6;
