//! A model built at the template's `base` resolution, mapped exactly to a finer resolution.
//!
//! The fine template is a linear subdivision of the base one: fine = S·base, with S a sparse
//! stencil matrix whose first rows are the identity (base vertices come first, unchanged; see
//! [`crate::template::subdivide`]). Since S is linear, the whole-body model maps exactly:
//! S·(S̄ + ΦB) = S·S̄ + (S·Φ)·B, so the fine model has mean S·S̄ and modes S·φₖ, with the same
//! variances, scores and coefficients (sliders, links and σ units carry over unchanged). The
//! fine modes are no longer orthonormal: the mapped model is for reconstruction, not for
//! projecting meshes (project on the base model).
//!
//! Segments. A fine vertex belongs to segment s when its (interpolated) template blend weight is
//! positive, which is when at least one base vertex of its stencil is in the segment. Near the
//! segment's border some stencil vertices are not, and the segment model has no values there,
//! so the segment's rows of S are restricted to its own base vertices and renormalised to sum
//! to 1 (still an affine combination, so a point of the surface patch). The fine body is then
//! stitched with the fine template's blend weights, as a model built at fine would be. Hence:
//! * with no segment overridden the fine body is exactly S·(base body);
//! * at the base vertices (the first #V_base fine vertices) it equals the base body exactly in
//!   every case, so measurements taken on the base vertices do not change;
//! * elsewhere, with segments overridden, it differs from S·(base body) only inside overlap
//!   bands, by at most the change of blend weight across one stencil times the disagreement of
//!   the two segments there (what the seam report measures).

use super::error::PcaError;
use super::model::BodyModel;
use super::segments::segment_subsets;
use super::shape_model::{ShapeModel, TemplateIdentity};
use crate::template::{Resolution, Template};

/// What a base model needs of a finer template resolution.
#[derive(Debug, Clone)]
pub struct FineTemplate<'a> {
    /// Identity of the base resolution the model must have been built for.
    pub base: TemplateIdentity,
    /// Identity of the finer resolution the mapped model will carry.
    pub fine: TemplateIdentity,
    /// Per fine vertex (#V_fine), the base vertices and weights it is made from (rows of S).
    pub stencils: &'a [Vec<(u32, f64)>],
    /// Fine triangles.
    pub triangles: &'a [[u32; 3]],
    /// Fine per-vertex segment blend weights ([`crate::template::Segment::ALL`] order).
    pub segment_weights: &'a [[f32; 6]],
}

impl<'a> FineTemplate<'a> {
    /// The pieces of `fine`, a finer resolution of `base` (the base template the model was
    /// built for; its identity is taken from `base` itself, since the fine template holds its
    /// base vertices' blend weights renormalised).
    pub fn of_templates(base: &Template, fine: &'a Template) -> Result<Self, PcaError> {
        let stencils = fine.stencils().ok_or_else(|| {
            PcaError::BadParameter(format!(
                "the template at {} resolution is not a subdivision of base",
                fine.resolution().name()
            ))
        })?;
        let vb = base.mesh().vertex_count();
        if base.resolution() != Resolution::Base
            || fine.base_vertex_count() != vb
            || fine.mesh().positions[..vb] != base.mesh().positions[..]
        {
            return Err(PcaError::BadParameter(
                "the fine template is not a subdivision of this base template".into(),
            ));
        }
        Ok(Self {
            base: TemplateIdentity::of_template(base),
            fine: TemplateIdentity::of_template(fine),
            stencils,
            triangles: &fine.mesh().triangles,
            segment_weights: fine.segment_weight_table(),
        })
    }
}

/// Maps `model` (built on `fine.base`) to the fine resolution: every mean and mode through the
/// stencils, triangles and blend weights from the fine template, everything else as it was.
/// `progress` gets the fraction done (0–1) after each mapped vector.
pub fn subdivide_model(
    model: &BodyModel,
    fine: &FineTemplate<'_>,
    progress: &mut dyn FnMut(f64),
) -> Result<BodyModel, PcaError> {
    model.check_template(&fine.base)?;
    let (vb, vf) = (fine.base.vertex_count, fine.fine.vertex_count);
    let corrupted = |m: String| Err(PcaError::Corrupted(m));
    if fine.stencils.len() != vf || fine.segment_weights.len() != vf {
        return corrupted(format!(
            "fine template of {vf} vertices has {} stencils and {} segment weights",
            fine.stencils.len(),
            fine.segment_weights.len()
        ));
    }
    if fine
        .stencils
        .iter()
        .flatten()
        .any(|&(u, _)| u as usize >= vb)
    {
        return corrupted("a stencil names a vertex beyond the base template".into());
    }
    let total: usize = std::iter::once(&model.whole)
        .chain(&model.segments)
        .map(|m| 1 + m.mode_count())
        .sum();
    let mut done = 0usize;
    let mut step = || {
        done += 1;
        progress(done as f64 / total as f64);
    };

    let whole_rows = StencilRows::whole(fine.stencils);
    let whole = mapped(&model.whole, &whole_rows, Vec::new(), &mut step);
    let fine_subsets = segment_subsets(fine.segment_weights);
    let mut segments = Vec::with_capacity(model.segments.len());
    for (s, (part, subset)) in model.segments.iter().zip(fine_subsets).enumerate() {
        let rows = StencilRows::segment(fine.stencils, &subset, &part.vertex_indices, vb)
            .map_err(|v| {
                PcaError::Corrupted(format!(
                    "fine vertex {v} of segment {} has no base vertex of that segment in its stencil",
                    crate::template::Segment::ALL[s].name()
                ))
            })?;
        segments.push(mapped(part, &rows, subset, &mut step));
    }
    BodyModel::assemble(
        fine.fine.clone(),
        model.settings,
        model.subjects.clone(),
        fine.triangles.to_vec(),
        fine.segment_weights.to_vec(),
        whole,
        segments,
    )
}

/// `part` with its mean and every mode mapped through `rows`; variances, scores and quality
/// curves unchanged.
fn mapped(
    part: &ShapeModel,
    rows: &StencilRows,
    vertex_indices: Vec<u32>,
    step: &mut dyn FnMut(),
) -> ShapeModel {
    let mean = rows.apply(&part.mean);
    step();
    let mut basis = Vec::with_capacity(part.mode_count() * mean.len());
    for k in 0..part.mode_count() {
        basis.extend(rows.apply(part.mode(k)));
        step();
    }
    ShapeModel {
        vertex_indices,
        mean,
        basis,
        variances: part.variances.clone(),
        all_variances: part.all_variances.clone(),
        scores: part.scores.clone(),
        quality: part.quality.clone(),
    }
}

/// Rows of S in compressed form: row r is `columns[offsets[r]..offsets[r + 1]]` with `weights`.
struct StencilRows {
    offsets: Vec<usize>,
    columns: Vec<u32>,
    weights: Vec<f64>,
}

impl StencilRows {
    /// All of S (columns are base vertex indices).
    fn whole(stencils: &[Vec<(u32, f64)>]) -> Self {
        let mut rows = Self::with_capacity(stencils.len());
        for stencil in stencils {
            rows.push(stencil.iter().copied());
        }
        rows
    }

    /// The rows of the fine vertices `subset` restricted to the base vertices `base_subset` of
    /// one segment and renormalised; columns are positions in `base_subset`. Fails with the
    /// fine vertex whose stencil has no weight on the segment.
    fn segment(
        stencils: &[Vec<(u32, f64)>],
        subset: &[u32],
        base_subset: &[u32],
        base_count: usize,
    ) -> Result<Self, u32> {
        let mut local = vec![u32::MAX; base_count];
        for (j, &u) in base_subset.iter().enumerate() {
            local[u as usize] = j as u32;
        }
        let mut rows = Self::with_capacity(subset.len());
        for &v in subset {
            let inside: Vec<(u32, f64)> = stencils[v as usize]
                .iter()
                .filter(|(u, _)| local[*u as usize] != u32::MAX)
                .map(|&(u, w)| (local[u as usize], w))
                .collect();
            let sum: f64 = inside.iter().map(|(_, w)| w).sum();
            if sum <= 0.0 {
                return Err(v);
            }
            rows.push(inside.into_iter().map(|(j, w)| (j, w / sum)));
        }
        Ok(rows)
    }

    fn with_capacity(rows: usize) -> Self {
        let mut offsets = Vec::with_capacity(rows + 1);
        offsets.push(0);
        Self {
            offsets,
            columns: Vec::new(),
            weights: Vec::new(),
        }
    }

    fn push(&mut self, entries: impl Iterator<Item = (u32, f64)>) {
        for (c, w) in entries {
            self.columns.push(c);
            self.weights.push(w);
        }
        self.offsets.push(self.columns.len());
    }

    /// S·x for flat xyz `x` (3 per column vertex), summed in f64, stored in f32.
    fn apply(&self, x: &[f32]) -> Vec<f32> {
        let mut out = Vec::with_capacity(3 * (self.offsets.len() - 1));
        for r in self.offsets.windows(2) {
            let mut acc = [0f64; 3];
            for (&c, &w) in self.columns[r[0]..r[1]]
                .iter()
                .zip(&self.weights[r[0]..r[1]])
            {
                let p = &x[3 * c as usize..3 * c as usize + 3];
                acc[0] += w * p[0] as f64;
                acc[1] += w * p[1] as f64;
                acc[2] += w * p[2] as f64;
            }
            out.extend(acc.map(|a| a as f32));
        }
        out
    }
}
