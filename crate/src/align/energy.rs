//! The fine-alignment energy E = a·E_d + b·E_s (paper eq. 6–8), its gradient and curvature.
//!
//! Unknowns: one affine transform T_i = [A_i | t_i] (3×4, 12 numbers) per template vertex, stored
//! row-major in `x[12·i .. 12·i + 12]` (row r at `12·i + 4·r`). With ṽ_i = (v_i, 1) the homogeneous
//! (centred) template vertex and c_i its current closest scan point, for fixed correspondences
//!
//! E = Σ_i α_i ‖T_i ṽ_i − c_i‖² + β Σ_{(i,j) ∈ edges} ‖T_i − T_j‖²_F,
//!
//! where α_i = a·κ·w_i (0 for vertices without a valid match this round) and β = b·s (s = stiffness
//! annealing factor). Its gradient is ∂E/∂T_i = 2 α_i (T_i ṽ_i − c_i) ṽ_iᵀ + 2 β Σ_j (T_i − T_j).
//! E is quadratic in x, so the curvature dᵀHd along any direction d is exact and cheap:
//! dᵀHd = 2 Σ α_i ‖D_i ṽ_i‖² + 2 β Σ_edges ‖D_i − D_j‖²_F — the line search uses it.
//!
//! Optionally (not in the paper) a tangential term μ Σ_i ‖P_i (T_i ṽ_i − r_i)‖², P_i = I − n_i n_iᵀ,
//! holds each vertex near its start r_i (the RBF-warped template) *along* that surface (normal
//! n_i at the start) while leaving it free across it: the warp places landmarks' neighbourhoods
//! well, and smooth parts (thighs, torso) otherwise slide ([`TangentialTerm`]).
//! The three rows of every T_i never interact (the Hessian is the same 4V×4V matrix per row), which
//! is what makes the per-vertex 4×4 block preconditioner in [`BlockPreconditioner`] exact per block.

use super::scan_term::ScanSample;
use nalgebra::{Point3, Vector3};

/// The tangential term μ Σ_i ‖P_i (T_i ṽ_i − r_i)‖² (see the module documentation); empty slices
/// or μ = 0 switch it off (the paper's energy).
#[derive(Debug, Clone, Copy, Default)]
pub struct TangentialTerm<'a> {
    /// r_i: start positions (centred frame), `#V` or empty.
    pub rest: &'a [Point3<f64>],
    /// n_i: unit normals at the start, `#V` or empty.
    pub normals: &'a [Vector3<f64>],
    /// μ.
    pub coefficient: f64,
}

impl TangentialTerm<'_> {
    fn is_on(&self) -> bool {
        self.coefficient > 0.0 && !self.rest.is_empty()
    }

    /// P_i u: `u` without its component along n_i.
    #[inline]
    fn tangential(&self, i: usize, u: Vector3<f64>) -> Vector3<f64> {
        let n = &self.normals[i];
        u - n * n.dot(&u)
    }
}

/// Number of unknowns per template vertex.
pub const DOF: usize = 12;

/// Parts of the energy at one point, as reported in progress.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct EnergyTerms {
    /// The minimised objective Σ α_i d_i² + β E_s.
    pub total: f64,
    /// Σ α_i d_i² (data error as weighted inside the objective).
    pub data_weighted: f64,
    /// E_s = Σ_edges ‖T_i − T_j‖²_F (paper eq. 7, unweighted).
    pub smoothness: f64,
    /// Σ γ_s ‖x_s − p_s‖², the scan-to-template term as weighted inside the objective
    /// (0 when it is switched off; see `scan_term.rs`).
    pub scan_weighted: f64,
    /// μ Σ ‖P_i (T_i ṽ_i − r_i)‖², the tangential term as weighted inside the objective.
    pub tangential_weighted: f64,
    /// Σ d_i² over vertices with α_i > 0 (unweighted squared distances to their matches).
    pub matched_sq_sum: f64,
    /// Number of vertices with α_i > 0.
    pub matched: usize,
}

/// E for one correspondence round: borrowed template, edges, matches and coefficients.
#[derive(Debug, Clone, Copy)]
pub struct AlignEnergy<'a> {
    /// ṽ_i: centred template vertices with a trailing 1, `#V`.
    pub vertices: &'a [[f64; 4]],
    /// Unique template edges (i, j), `#E`.
    pub edges: &'a [[u32; 2]],
    /// c_i: matched scan points (same centred frame), `#V` (ignored where α_i = 0).
    pub targets: &'a [Point3<f64>],
    /// α_i = a·κ·w_i, or 0 where the vertex has no data term this round, `#V`.
    pub data_coefficients: &'a [f64],
    /// β = b·s.
    pub smoothness_coefficient: f64,
    /// Scan points pulling the template surface (the optional scan-to-template term); empty
    /// for the paper's energy.
    pub scan_samples: &'a [ScanSample],
    /// The tangential term (off for the paper's energy).
    pub tangential: TangentialTerm<'a>,
}

/// Position T_i ṽ_i of vertex `i` under transforms `x`.
#[inline]
pub fn transformed(x: &[f64], v: &[f64; 4], i: usize) -> Point3<f64> {
    let t = &x[DOF * i..DOF * i + DOF];
    Point3::new(
        t[0] * v[0] + t[1] * v[1] + t[2] * v[2] + t[3],
        t[4] * v[0] + t[5] * v[1] + t[6] * v[2] + t[7],
        t[8] * v[0] + t[9] * v[1] + t[10] * v[2] + t[11],
    )
}

/// Identity transforms for `n` vertices: T_i = [I | 0].
pub fn identity_transforms(n: usize) -> Vec<f64> {
    let mut x = vec![0.0; DOF * n];
    for t in x.chunks_exact_mut(DOF) {
        t[0] = 1.0;
        t[5] = 1.0;
        t[10] = 1.0;
    }
    x
}

impl AlignEnergy<'_> {
    /// E(x) and its parts; writes ∇E(x) into `grad` (length 12·#V). Allocation-free.
    pub fn evaluate(&self, x: &[f64], grad: &mut [f64]) -> EnergyTerms {
        let mut terms = EnergyTerms::default();
        for (i, v) in self.vertices.iter().enumerate() {
            let g = &mut grad[DOF * i..DOF * i + DOF];
            let alpha = self.data_coefficients[i];
            if alpha <= 0.0 {
                g.fill(0.0);
                continue;
            }
            let r = transformed(x, v, i) - self.targets[i];
            let d2 = r.norm_squared();
            terms.data_weighted += alpha * d2;
            terms.matched_sq_sum += d2;
            terms.matched += 1;
            for row in 0..3 {
                let s = 2.0 * alpha * r[row];
                for c in 0..4 {
                    g[4 * row + c] = s * v[c];
                }
            }
        }
        for sample in self.scan_samples {
            let r = self.sample_point(x, sample) - sample.target;
            let gamma = sample.coefficient;
            terms.scan_weighted += gamma * r.norm_squared();
            for (&m, &lambda) in sample.corners.iter().zip(&sample.barycentric) {
                if lambda == 0.0 {
                    continue;
                }
                let m = m as usize;
                let v = &self.vertices[m];
                let g = &mut grad[DOF * m..DOF * m + DOF];
                for row in 0..3 {
                    let s = 2.0 * gamma * lambda * r[row];
                    for c in 0..4 {
                        g[4 * row + c] += s * v[c];
                    }
                }
            }
        }
        let tangential = &self.tangential;
        if tangential.is_on() {
            let mu = tangential.coefficient;
            for (i, v) in self.vertices.iter().enumerate() {
                let r = tangential.tangential(i, transformed(x, v, i) - tangential.rest[i]);
                terms.tangential_weighted += mu * r.norm_squared();
                let g = &mut grad[DOF * i..DOF * i + DOF];
                for row in 0..3 {
                    let s = 2.0 * mu * r[row];
                    for c in 0..4 {
                        g[4 * row + c] += s * v[c];
                    }
                }
            }
        }
        let beta = self.smoothness_coefficient;
        for &[i, j] in self.edges {
            let (i, j) = (DOF * i as usize, DOF * j as usize);
            let mut sq = 0.0;
            for k in 0..DOF {
                let diff = x[i + k] - x[j + k];
                sq += diff * diff;
                grad[i + k] += 2.0 * beta * diff;
                grad[j + k] -= 2.0 * beta * diff;
            }
            terms.smoothness += sq;
        }
        terms.total = terms.data_weighted
            + terms.scan_weighted
            + terms.tangential_weighted
            + beta * terms.smoothness;
        terms
    }

    /// x_s = Σ_m λ_m T_m ṽ_m, the template point a scan sample pulls (centred frame).
    #[inline]
    fn sample_point(&self, x: &[f64], sample: &ScanSample) -> Point3<f64> {
        let mut p = nalgebra::Vector3::zeros();
        for (&m, &lambda) in sample.corners.iter().zip(&sample.barycentric) {
            if lambda != 0.0 {
                let m = m as usize;
                p += transformed(x, &self.vertices[m], m).coords * lambda;
            }
        }
        Point3::from(p)
    }

    /// dᵀHd, the exact second derivative of E along `d` (E is quadratic in x).
    pub fn curvature(&self, d: &[f64]) -> f64 {
        let mut data = 0.0;
        for (i, v) in self.vertices.iter().enumerate() {
            let alpha = self.data_coefficients[i];
            if alpha > 0.0 {
                data += alpha * transformed_direction(d, v, i);
            }
        }
        for sample in self.scan_samples {
            data += sample.coefficient * self.sample_point(d, sample).coords.norm_squared();
        }
        let tangential = &self.tangential;
        if tangential.is_on() {
            for (i, v) in self.vertices.iter().enumerate() {
                let r = tangential.tangential(i, transformed(d, v, i).coords);
                data += tangential.coefficient * r.norm_squared();
            }
        }
        let mut smooth = 0.0;
        for &[i, j] in self.edges {
            let (i, j) = (DOF * i as usize, DOF * j as usize);
            for k in 0..DOF {
                let diff = d[i + k] - d[j + k];
                smooth += diff * diff;
            }
        }
        2.0 * data + 2.0 * self.smoothness_coefficient * smooth
    }
}

/// ‖D_i ṽ_i‖² for a direction `d`.
#[inline]
fn transformed_direction(d: &[f64], v: &[f64; 4], i: usize) -> f64 {
    transformed(d, v, i).coords.norm_squared()
}

/// Inverse of the per-vertex diagonal blocks of the Hessian, used as L-BFGS's initial matrix H₀.
///
/// Block of vertex i (the same for each of its three rows): B_i = 2 α'_i ṽ_i ṽ_iᵀ + 2 β deg_i I₄,
/// with α'_i = α_i + Σ_s γ_s λ_{s,i}² (every scan-to-template sample adds a multiple of ṽ_i ṽ_iᵀ)
/// plus μ (the tangential term, bounded by its isotropic version).
/// By Sherman–Morrison, B_i⁻¹ q = (q − α_i ṽ_i (ṽ_i·q) / (β deg_i + α_i ‖ṽ_i‖²)) / (2 β deg_i).
#[derive(Debug, Clone, Default)]
pub struct BlockPreconditioner {
    /// Per vertex: (1 / (2 β deg_i), α_i / (β deg_i + α_i ‖ṽ_i‖²)).
    factors: Vec<[f64; 2]>,
    vertices: Vec<[f64; 4]>,
    alphas: Vec<f64>,
}

impl BlockPreconditioner {
    /// Recomputes the blocks for this round's coefficients; `degrees[i]` = edges at vertex i.
    pub fn update(&mut self, energy: &AlignEnergy<'_>, degrees: &[u32]) {
        self.vertices.clear();
        self.vertices.extend_from_slice(energy.vertices);
        self.factors.clear();
        self.alphas.clear();
        self.alphas
            .extend(energy.data_coefficients.iter().map(|a| a.max(0.0)));
        for sample in energy.scan_samples {
            for (&m, &lambda) in sample.corners.iter().zip(&sample.barycentric) {
                self.alphas[m as usize] += sample.coefficient * lambda * lambda;
            }
        }
        // The tangential term's block is μ P_i ⊗ ṽ_i ṽ_iᵀ, which couples the rows; μ ṽ_i ṽ_iᵀ
        // per row bounds it from above and keeps the block form.
        if energy.tangential.is_on() {
            for a in &mut self.alphas {
                *a += energy.tangential.coefficient;
            }
        }
        let beta = energy.smoothness_coefficient;
        let alphas = &self.alphas;
        self.factors
            .extend(energy.vertices.iter().enumerate().map(|(i, v)| {
                let alpha = alphas[i];
                // An isolated vertex without data has a zero block; a tiny floor keeps it finite.
                let bd = (beta * f64::from(degrees[i])).max(1e-12);
                let vv = v.iter().map(|c| c * c).sum::<f64>();
                [1.0 / (2.0 * bd), alpha / (bd + alpha * vv)]
            }));
    }

    /// q ← H₀ q.
    pub fn apply(&self, q: &mut [f64]) {
        for (i, (v, [inv, k])) in self.vertices.iter().zip(&self.factors).enumerate() {
            for row in 0..3 {
                let b = &mut q[DOF * i + 4 * row..DOF * i + 4 * row + 4];
                let dot = v[0] * b[0] + v[1] * b[1] + v[2] * b[2] + v[3] * b[3];
                for c in 0..4 {
                    b[c] = (b[c] - k * v[c] * dot) * inv;
                }
            }
        }
    }
}
