//! The scan-to-template term (an addition to the paper, switchable): scan points pull the template
//! surface towards them.
//!
//! The paper's data error E_d (eq. 6) measures template vertex → scan only: every template vertex
//! is pulled onto the scan, but nothing asks the template's *triangles* to pass through the scan
//! points between the vertices. On a coarse template the facets are chords of the curved body, so
//! with every vertex on the surface the facets lie inside it and the scan → template distance (the
//! paper's Table 1 figure) keeps a positive bias of about half a millimetre on `base`
//! (docs/fine-alignment.md). This term adds, for a sample of scan points s with closest template
//! point x_s = Σ_m λ_{s,m} T_m ṽ_m (barycentric in the triangle found at the start of the round),
//!
//! E_r = Σ_s γ_s ‖x_s − p_s‖²,   ∂E_r/∂T_m = 2 γ_s λ_{s,m} (x_s − p_s) ṽ_mᵀ,
//!
//! quadratic in the transforms like E_d, so the exact line search and the block preconditioner
//! keep working (every E_r contribution to vertex m's diagonal block is a multiple of ṽ_m ṽ_mᵀ).
//! Samples whose template match has an incompatible normal, lies on a template rim, touches a
//! vertex of data weight 0 (unseen regions) or is farther than a cut-off get no term that round,
//! mirroring the treatments of E_d (paper §3.2.1).

use super::error::AlignError;
use super::fine_input::FineAlignInput;
use super::params::FineAlignParams;
use super::surface_index::{MatchQuery, SurfaceIndex};
use nalgebra::{Point3, Vector3};

/// One scan point's pull on the template surface for one round.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScanSample {
    /// Template vertices of the triangle holding the closest point.
    pub corners: [u32; 3],
    /// Barycentric coordinates λ of the closest point in `corners`.
    pub barycentric: [f64; 3],
    /// The scan point p_s (centred frame, like the template vertices).
    pub target: Point3<f64>,
    /// γ_s ≥ 0.
    pub coefficient: f64,
}

/// The term across the rounds of one fine alignment: the sampled scan vertices (fixed), an index
/// of the moving template (its topology built once, moved every round) and this round's samples.
#[derive(Default)]
pub struct ScanTerm {
    sample_vertices: Vec<u32>,
    template: Option<SurfaceIndex>,
    samples: Vec<ScanSample>,
    /// γ before the corner weight: a·κ·ρ·Σw_i / #samples, so the samples together weigh ρ times
    /// the template vertices' data terms.
    coefficient: f64,
    max_distance: f64,
    from_stiffness: f64,
}

impl ScanTerm {
    /// The term for one alignment onto `scan`; `data_scale` = a·κ, `weights` the template's data
    /// weights. Switched off (no samples ever) when `params.scan_term_weight` is 0.
    pub fn new(
        scan: &SurfaceIndex,
        params: &FineAlignParams,
        data_scale: f64,
        weights: &[f64],
    ) -> Self {
        if params.scan_term_weight <= 0.0 {
            return Self::default();
        }
        let sample_vertices = sample_scan_vertices(scan, params.scan_term_samples);
        let weight_sum: f64 = weights.iter().sum();
        Self {
            coefficient: data_scale * params.scan_term_weight * weight_sum
                / sample_vertices.len().max(1) as f64,
            sample_vertices,
            template: None,
            samples: Vec::new(),
            max_distance: params.scan_term_max_distance,
            from_stiffness: params.scan_term_from_stiffness,
        }
    }

    /// This round's samples on the template at `positions` (#V, metres, scan frame; the
    /// triangles, scan and weights of `input` every round), or none when the term is off or
    /// `stiffness` is still above `scan_term_from_stiffness`. `query` and `centroid` as for E_d.
    pub fn find(
        &mut self,
        input: &FineAlignInput<'_>,
        positions: &[Point3<f64>],
        query: MatchQuery,
        centroid: Vector3<f64>,
        stiffness: f64,
    ) -> Result<&[ScanSample], AlignError> {
        let FineAlignInput {
            scan,
            triangles,
            weights,
            ..
        } = *input;
        self.samples.clear();
        if self.sample_vertices.is_empty() || stiffness > self.from_stiffness {
            return Ok(&self.samples);
        }
        let template = match self.template.as_mut() {
            Some(index) => {
                index.move_vertices(positions);
                index
            }
            None => self
                .template
                .insert(SurfaceIndex::from_parts("template", positions, triangles)?),
        };
        let settings = ScanTermSettings {
            query,
            weights,
            coefficient: self.coefficient,
            max_distance: self.max_distance,
            centroid,
        };
        find_scan_samples(
            scan,
            &self.sample_vertices,
            template,
            &settings,
            &mut self.samples,
        );
        Ok(&self.samples)
    }
}

/// Which scan vertices are sampled: every `stride`-th vertex used by a triangle, so at most
/// `max_samples` (deterministic, spread over the scan in its vertex order).
pub fn sample_scan_vertices(scan: &SurfaceIndex, max_samples: usize) -> Vec<u32> {
    let all = scan.surface_vertex_indices();
    if max_samples == 0 || all.is_empty() {
        return Vec::new();
    }
    let stride = all.len().div_ceil(max_samples).max(1);
    all.iter().step_by(stride).copied().collect()
}

/// What [`find_scan_samples`] needs besides the meshes.
#[derive(Debug, Clone, Copy)]
pub struct ScanTermSettings<'a> {
    /// Normal compatibility and search strategy (the same as the round's E_d matches).
    pub query: MatchQuery,
    /// Per-template-vertex data weights w_i (a sample touching w = 0 is dropped; otherwise its
    /// coefficient is scaled by the smallest corner weight, so hands and ears pull less).
    pub weights: &'a [f64],
    /// γ before the corner weight.
    pub coefficient: f64,
    /// Samples farther than this (m) from the template are dropped.
    pub max_distance: f64,
    /// Subtracted from scan points (the energy's centred frame).
    pub centroid: Vector3<f64>,
}

/// Finds this round's samples: for each scan vertex in `sample_vertices`, the closest compatible
/// point on the current template (`template`, indexed from the current positions). Clears and
/// fills `out` in the order of `sample_vertices` (natively the search runs on all cores; the
/// result does not depend on their number); returns the number kept.
pub fn find_scan_samples(
    scan: &SurfaceIndex,
    sample_vertices: &[u32],
    template: &SurfaceIndex,
    settings: &ScanTermSettings<'_>,
    out: &mut Vec<ScanSample>,
) -> usize {
    crate::utils::parallel::filter_map_into(sample_vertices, out, |&s: &u32| {
        sample_of(scan, s as usize, template, settings)
    });
    out.len()
}

/// The sample of scan vertex `s`, or `None` when the treatments drop it this round.
fn sample_of(
    scan: &SurfaceIndex,
    s: usize,
    template: &SurfaceIndex,
    settings: &ScanTermSettings<'_>,
) -> Option<ScanSample> {
    let p = scan.positions()[s];
    let m = template.closest_face(&p, Some(scan.vertex_normal(s)), &settings.query)?;
    if m.on_boundary || (m.point - p).norm() > settings.max_distance {
        return None;
    }
    let mut weight = f64::INFINITY;
    for (corner, lambda) in m.corners.iter().zip(m.barycentric) {
        if lambda > 0.0 {
            weight = weight.min(settings.weights[*corner as usize]);
        }
    }
    (weight.is_finite() && weight > 0.0).then(|| ScanSample {
        corners: m.corners,
        barycentric: m.barycentric,
        target: p - settings.centroid,
        coefficient: settings.coefficient * weight,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::align::params::CorrespondenceMode;
    use crate::mesh::Mesh;

    fn square(z: f64) -> Mesh {
        Mesh::new(
            vec![
                Point3::new(0.0, 0.0, z),
                Point3::new(1.0, 0.0, z),
                Point3::new(1.0, 1.0, z),
                Point3::new(0.0, 1.0, z),
                Point3::new(0.5, 0.5, z),
            ],
            vec![[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
        )
    }

    #[test]
    fn samples_interpolate_the_closest_template_point() {
        let scan = SurfaceIndex::new(&square(0.1)).unwrap();
        let template_mesh = square(0.0);
        let template = SurfaceIndex::new(&template_mesh).unwrap();
        let weights = vec![1.0; 5];
        let settings = ScanTermSettings {
            query: MatchQuery {
                mode: CorrespondenceMode::VertexOneRing,
                min_cos: Some(0.5),
                candidates: 4,
            },
            weights: &weights,
            coefficient: 2.0,
            max_distance: 1.0,
            centroid: Vector3::zeros(),
        };
        let mut out = Vec::new();
        let all = sample_scan_vertices(&scan, 100);
        assert_eq!(all.len(), 5);
        find_scan_samples(&scan, &all, &template, &settings, &mut out);
        // The rim vertices of the square are on the template's boundary; the centre is not.
        assert_eq!(out.len(), 1);
        let s = out[0];
        let x = s
            .corners
            .iter()
            .zip(s.barycentric)
            .fold(Vector3::zeros(), |acc, (c, l)| {
                acc + template_mesh.positions[*c as usize].coords * l
            });
        assert!((x - Vector3::new(0.5, 0.5, 0.0)).norm() < 1e-12);
        assert_eq!(s.coefficient, 2.0);
        assert!((s.target - Point3::new(0.5, 0.5, 0.1)).norm() < 1e-12);
        assert_eq!(sample_scan_vertices(&scan, 2).len(), 2);
    }
}
