//! One linear shape model S = S̄ + Φ·B (paper eq. 9) over a body part ([`ShapeModel`]), and the
//! identity of the template a model was built on ([`TemplateIdentity`]).

use super::error::PcaError;
use super::metrics::QualityCurves;
use serde::{Deserialize, Serialize};

/// Which template a model belongs to. A model only makes sense on meshes in this template's vertex
/// order, so loading checks it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct TemplateIdentity {
    /// Template name, e.g. `makehuman-base`.
    pub name: String,
    /// Content hash of the template mesh (hex), whatever the template module computes.
    pub hash: String,
    /// Resolution name (`base`, `fine`, ...).
    pub resolution: String,
    /// `#V` of the template at this resolution.
    pub vertex_count: usize,
}

impl TemplateIdentity {
    /// The identity of `template` at its resolution: name `bodyspace-makehuman`, hash = CRC-32
    /// (hex) of its positions (f64 LE), triangles (u32 LE) and segment weights (f32 LE), so a
    /// model refuses a template whose geometry or segments changed. The web side must use this
    /// same function to check models against the embedded template.
    pub fn of_template(template: &crate::template::Template) -> Self {
        let mesh = template.mesh();
        let mut crc = flate2::Crc::new();
        for p in &mesh.positions {
            for c in [p.x, p.y, p.z] {
                crc.update(&c.to_le_bytes());
            }
        }
        for t in &mesh.triangles {
            for i in t {
                crc.update(&i.to_le_bytes());
            }
        }
        for v in 0..mesh.vertex_count() as u32 {
            for w in template.segment_weights(v) {
                crc.update(&w.to_le_bytes());
            }
        }
        Self {
            name: "bodyspace-makehuman".into(),
            hash: format!("{:08x}", crc.sum()),
            resolution: template.resolution().name().into(),
            vertex_count: mesh.vertex_count(),
        }
    }
}

impl std::fmt::Display for TemplateIdentity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} ({}, {} vertices, hash {})",
            self.name, self.resolution, self.vertex_count, self.hash
        )
    }
}

/// One PCA model over `n` vertices (the whole body or one segment's subset), stored in f32 in the
/// layout the slider loop reads: `basis` is mode-major, mode k at `basis[k·3n .. (k+1)·3n]`, each
/// mode `[x0, y0, z0, x1, ...]`. Coefficients Bₖ are in model units (metres); a slider value tₖ in
/// standard deviations is Bₖ = tₖ·√λₖ.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeModel {
    /// Template vertex index of each model vertex, ascending; empty for the whole body (= all).
    pub vertex_indices: Vec<u32>,
    /// S̄ flat, length 3n.
    pub mean: Vec<f32>,
    /// Φ mode-major, length M·3n, orthonormal modes.
    pub basis: Vec<f32>,
    /// λ₁ ≥ … ≥ λ_M of the kept modes.
    pub variances: Vec<f64>,
    /// All non-zero eigenvalues before truncation (at most N−1), for compactness.
    pub all_variances: Vec<f64>,
    /// Per-subject coefficients, row-major N × M.
    pub scores: Vec<f32>,
    /// Compactness / generalization / specificity.
    pub quality: QualityCurves,
}

impl ShapeModel {
    /// A model whose every variance is kept (no truncation record), with the quality curves
    /// the variances alone give: compactness over the kept modes (no generalization or
    /// specificity, which need the training data). For models read or derived without them.
    pub fn with_all_modes_kept(
        vertex_indices: Vec<u32>,
        mean: Vec<f32>,
        basis: Vec<f32>,
        variances: Vec<f64>,
        scores: Vec<f32>,
    ) -> Self {
        Self {
            vertex_indices,
            mean,
            basis,
            quality: QualityCurves {
                compactness: super::metrics::compactness(&variances),
                ..QualityCurves::default()
            },
            all_variances: variances.clone(),
            variances,
            scores,
        }
    }

    /// Number of kept modes M.
    pub fn mode_count(&self) -> usize {
        self.variances.len()
    }

    /// Number of vertices n of this model.
    pub fn vertex_count(&self) -> usize {
        self.mean.len() / 3
    }

    /// Mode k (φₖ, length 3n). The caller guarantees k < M.
    pub fn mode(&self, k: usize) -> &[f32] {
        let d = self.mean.len();
        &self.basis[k * d..(k + 1) * d]
    }

    /// √λₖ for every kept mode.
    pub fn standard_deviations(&self) -> Vec<f64> {
        self.variances.iter().map(|v| v.sqrt()).collect()
    }

    /// Bₖ = tₖ·√λₖ for slider values `sigma` (extra entries beyond M are an error).
    pub fn coefficients_from_sigma(&self, sigma: &[f64]) -> Result<Vec<f64>, PcaError> {
        self.check_coefficients(sigma.len())?;
        Ok(sigma
            .iter()
            .zip(&self.variances)
            .map(|(t, v)| t * v.sqrt())
            .collect())
    }

    /// tₖ = Bₖ/√λₖ.
    pub fn sigma_from_coefficients(&self, coefficients: &[f64]) -> Vec<f64> {
        coefficients
            .iter()
            .zip(&self.variances)
            .map(|(b, v)| if *v > 0.0 { b / v.sqrt() } else { 0.0 })
            .collect()
    }

    pub(crate) fn check_coefficients(&self, len: usize) -> Result<(), PcaError> {
        if len > self.mode_count() {
            return Err(PcaError::BadLength {
                what: "coefficients".into(),
                expected: self.mode_count(),
                got: len,
            });
        }
        Ok(())
    }

    /// S = S̄ + Σₖ Bₖφₖ in f64, flat length 3n; missing trailing coefficients are 0.
    pub fn reconstruct(&self, coefficients: &[f64]) -> Result<Vec<f64>, PcaError> {
        self.check_coefficients(coefficients.len())?;
        let mut out: Vec<f64> = self.mean.iter().map(|&m| m as f64).collect();
        for (k, &b) in coefficients.iter().enumerate() {
            if b != 0.0 {
                for (o, &p) in out.iter_mut().zip(self.mode(k)) {
                    *o += b * p as f64;
                }
            }
        }
        Ok(out)
    }

    /// The body at σ-unit coefficients `sigma` (Bₖ = zₖ·√λₖ) as flat f32 positions, what the
    /// measurer, the PLY writer and the app take.
    pub fn body_at_sigma(&self, sigma: &[f64]) -> Result<Vec<f32>, PcaError> {
        let b = self.coefficients_from_sigma(sigma)?;
        Ok(self.reconstruct(&b)?.iter().map(|&x| x as f32).collect())
    }

    /// B = Φᵀ(x − S̄) for a flat shape `x` of length 3n already in the model frame.
    pub fn project_flat(&self, x: &[f64]) -> Vec<f64> {
        (0..self.mode_count())
            .map(|k| {
                self.mode(k)
                    .iter()
                    .zip(x.iter().zip(&self.mean))
                    .map(|(&p, (&xi, &m))| p as f64 * (xi - m as f64))
                    .sum()
            })
            .collect()
    }

    /// A random plausible shape: bₖ ~ N(0, λₖ) for every kept mode, reproducible from `seed`.
    pub fn random_coefficients(&self, seed: u64) -> Vec<f64> {
        let mut rng = super::random::NormalRng::new(seed);
        self.variances
            .iter()
            .map(|v| rng.next_normal() * v.sqrt())
            .collect()
    }

    /// Coefficients of training subject i (row of `scores`).
    pub fn subject_scores(&self, i: usize) -> Option<&[f32]> {
        let m = self.mode_count();
        self.scores.get(i * m..(i + 1) * m)
    }
}
