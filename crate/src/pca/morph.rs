//! The body on screen while sliders move: the current coefficients and the stitched positions,
//! kept between calls so a slider move costs one rank-1 update instead of a reconstruction.
//!
//! The stitched body x = (1 − cᵥ)·(S̄ + ΦB) + Σ_{s overridden} w̃ₛ ⊙ (S̄ₛ + ΦₛBₛ) is linear in
//! every coefficient (see [`super::stitch`]), so changing one coefficient by Δb adds Δb times
//! one weighted mode. [`Morph::update`] compares the new coefficients with the held ones and
//! applies one such update per changed coefficient; it reconstructs from scratch when the set
//! of overridden segments changed (the blend weights of the whole body change with it) or when
//! more than [`MAX_DELTAS`] coefficients changed at once (a reconstruction adds four modes per
//! pass over the body, so it is then the cheaper of the two).
//!
//! Updates use compensated summation ([`BodyModel::apply_delta_compensated`]): with plain f32
//! additions the positions drift from a full reconstruction as a random walk of roundings
//! (≈ 3e-8 m·√moves per coordinate on a body 1.7 m tall); compensated, they stay within a few
//! roundings after any number of moves, so no periodic rebuild is needed to drop drift.

use super::error::PcaError;
use super::model::BodyModel;
use super::stitch::{Coefficients, ModeDelta, ModeTarget, StitchPlan};
use crate::template::Segment;
use serde::Serialize;

/// More coefficients than this changed at once: reconstruct instead of updating.
pub const MAX_DELTAS: usize = 4;

/// What [`Morph::update`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct MorphUpdate {
    /// The body was reconstructed from scratch.
    pub rebuilt: bool,
    /// Single-coefficient updates applied (0 when rebuilt or nothing changed).
    pub deltas: usize,
}

/// The current coefficients of one [`BodyModel`] and the stitched body they give.
#[derive(Debug, Clone)]
pub struct Morph {
    /// Padded with zeros to every part's mode count.
    coefficients: Coefficients,
    /// Flat `[x0, y0, z0, x1, …]`, 3V.
    positions: Vec<f32>,
    /// Kahan carry of `positions`, zero after a reconstruction.
    carry: Vec<f32>,
    plan: StitchPlan,
}

impl Morph {
    /// Reconstructs the body of `coefficients` (model units) on `model`.
    pub fn new(model: &BodyModel, coefficients: &Coefficients) -> Result<Self, PcaError> {
        let coefficients = padded(model, coefficients)?;
        let v = model.template.vertex_count;
        let mut positions = vec![0.0f32; 3 * v];
        let plan = model.reconstruct_into(&coefficients, &mut positions)?;
        Ok(Self {
            coefficients,
            positions,
            carry: vec![0.0; 3 * v],
            plan,
        })
    }

    /// Reconstructs from scratch (reset, random body, a link, a new model).
    pub fn rebuild(
        &mut self,
        model: &BodyModel,
        coefficients: &Coefficients,
    ) -> Result<MorphUpdate, PcaError> {
        *self = Self::new(model, coefficients)?;
        Ok(MorphUpdate {
            rebuilt: true,
            deltas: 0,
        })
    }

    /// Moves the body to `coefficients`: one rank-1 update per changed coefficient, or a
    /// reconstruction when the overridden segments changed or more than [`MAX_DELTAS`]
    /// coefficients did. `model` must be the one this morph was made with.
    pub fn update(
        &mut self,
        model: &BodyModel,
        coefficients: &Coefficients,
    ) -> Result<MorphUpdate, PcaError> {
        if self.positions.len() != 3 * model.template.vertex_count {
            return Err(PcaError::BadParameter(
                "the morph was made for a model of another size".into(),
            ));
        }
        let next = padded(model, coefficients)?;
        if next.overridden() != self.plan.overridden() {
            return self.rebuild(model, &next);
        }
        let mut changes: Vec<(ModeTarget, usize, f64)> =
            changed(&self.coefficients.whole, &next.whole)
                .map(|(k, d)| (ModeTarget::Whole, k, d))
                .collect();
        for (s, (old, new)) in self
            .coefficients
            .segments
            .iter()
            .zip(&next.segments)
            .enumerate()
        {
            if let (Some(old), Some(new)) = (old, new) {
                let target = ModeTarget::Segment(Segment::ALL[s]);
                changes.extend(changed(old, new).map(|(k, d)| (target, k, d)));
            }
        }
        if changes.len() > MAX_DELTAS {
            return self.rebuild(model, &next);
        }
        for &(target, k, delta) in &changes {
            model.apply_delta_compensated(
                &self.plan,
                ModeDelta {
                    target,
                    mode: k,
                    delta,
                },
                &mut self.positions,
                &mut self.carry,
            )?;
        }
        self.coefficients = next;
        Ok(MorphUpdate {
            rebuilt: false,
            deltas: changes.len(),
        })
    }

    /// The stitched body, flat `[x0, y0, z0, …]` (3V, metres).
    pub fn positions(&self) -> &[f32] {
        &self.positions
    }

    /// The coefficients of the body, padded with zeros to every part's mode count.
    pub fn coefficients(&self) -> &Coefficients {
        &self.coefficients
    }
}

/// `c` checked against `model` and padded with zeros to each part's mode count.
fn padded(model: &BodyModel, c: &Coefficients) -> Result<Coefficients, PcaError> {
    let pad = |b: &[f64], m: usize| -> Result<Vec<f64>, PcaError> {
        if b.len() > m {
            return Err(PcaError::BadLength {
                what: "coefficients".into(),
                expected: m,
                got: b.len(),
            });
        }
        if b.iter().any(|x| !x.is_finite()) {
            return Err(PcaError::BadParameter("coefficients must be finite".into()));
        }
        let mut v = b.to_vec();
        v.resize(m, 0.0);
        Ok(v)
    };
    let mut segments: [Option<Vec<f64>>; 6] = Default::default();
    for (s, b) in c.segments.iter().enumerate() {
        if let Some(b) = b {
            segments[s] = Some(pad(b, model.segments[s].mode_count())?);
        }
    }
    Ok(Coefficients {
        whole: pad(&c.whole, model.whole.mode_count())?,
        segments,
    })
}

/// (k, new − old) for every k where the two equal-length vectors differ.
fn changed<'a>(old: &'a [f64], new: &'a [f64]) -> impl Iterator<Item = (usize, f64)> + 'a {
    old.iter()
        .zip(new)
        .enumerate()
        .filter(|(_, (a, b))| a != b)
        .map(|(k, (a, b))| (k, b - a))
}
