//! `rbf_warp`: the template warped onto a scan by its landmarks (paper §3.1).
//!
//! 1. Pair template and scan landmarks by name; a landmark missing on either side is skipped.
//! 2. Similarity Procrustes S: template → scan on the pairs (units and frame of the scan).
//! 3. Bring the scan landmarks into the TEMPLATE frame, q'_i = S⁻¹(q_i), and fit the RBF
//!    network f(p_i) = q'_i there — kernel parameters are therefore in template units (metres).
//! 4. Every template vertex v goes to S(f(v)): the output is in the SCAN's frame and units, in
//!    template vertex order.

use nalgebra::Point3;
use serde::Serialize;

use super::checks::check_unique_names;
use super::error::RbfError;
use super::fit::fit;
use super::kernel::Kernel;
use super::network::RbfNetwork;
use super::params::RbfParams;
use super::procrustes::{similarity_named, Similarity};
use crate::landmarks::virtual_landmarks::{virtual_landmarks_detailed, VIRTUAL_PREFIX};
use crate::landmarks::{Landmark, LandmarkSet};
use crate::mesh::Mesh;

/// Landmark distance to its scan position, in scan units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LandmarkResidual {
    pub name: String,
    /// ‖S(p_i) − q_i‖: after the similarity alone.
    pub before: f64,
    /// ‖S(f(p_i)) − q_i‖: after the RBF warp (0 up to rounding when λ = 0).
    pub after: f64,
}

/// Which landmarks a warp paired, by name.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct LandmarkPairing {
    /// Names of the landmark pairs the fit used, in template order.
    pub used: Vec<String>,
    /// Names present on one side only (missing on the scan, or unknown to the template).
    pub skipped: Vec<String>,
    /// Virtual landmarks whose snap rule found no surface point (constructed point kept).
    pub virtual_off_surface: Vec<String>,
}

/// What `rbf_warp` produced.
#[derive(Debug, Clone)]
pub struct RbfWarp {
    /// `#V` warped template vertices, scan frame and units, template vertex order.
    pub positions: Vec<Point3<f64>>,
    /// The landmarks paired, skipped and off the surface.
    pub pairing: LandmarkPairing,
    /// One residual per used landmark, in `pairing.used` order.
    pub residuals: Vec<LandmarkResidual>,
    /// Template → scan similarity from Procrustes.
    pub similarity: Similarity,
    pub kernel: Kernel,
    /// The fitted network, in template frame (maps template points to S⁻¹ of scan points).
    pub network: RbfNetwork,
}

/// Warps `template` (`#V` points, template frame) by the landmark pairs matched by name.
///
/// Shapes: `template` #V; the landmark slices in any order, names unique per side.
pub fn rbf_warp(
    template: &[Point3<f64>],
    template_landmarks: &[Landmark],
    scan_landmarks: &[Landmark],
    params: &RbfParams,
) -> Result<RbfWarp, RbfError> {
    let t_names: Vec<String> = template_landmarks.iter().map(|l| l.name.clone()).collect();
    let s_names: Vec<String> = scan_landmarks.iter().map(|l| l.name.clone()).collect();
    check_unique_names(&t_names, "template")?;
    check_unique_names(&s_names, "scan")?;
    let mut used = Vec::new();
    let mut skipped = Vec::new();
    let (mut p, mut q) = (Vec::new(), Vec::new());
    for t in template_landmarks {
        match scan_landmarks.iter().find(|s| s.name == t.name) {
            Some(s) => {
                used.push(t.name.clone());
                p.push(t.position);
                q.push(s.position);
            }
            None => skipped.push(t.name.clone()),
        }
    }
    skipped.extend(s_names.iter().filter(|n| !t_names.contains(n)).cloned());
    let similarity = similarity_named(&used, &p, &q)?;
    let q_template: Vec<_> = q.iter().map(|y| similarity.apply_inverse(y)).collect();
    let network = fit(&used, &p, &q_template, params)?;

    let mut positions = network.warp(template);
    for v in &mut positions {
        *v = similarity.apply(v);
    }
    let fitted = network.warp(&p);
    let residuals = used
        .iter()
        .zip(p.iter().zip(&fitted))
        .zip(&q)
        .map(|((name, (p, f)), q)| LandmarkResidual {
            name: name.clone(),
            before: (similarity.apply(p) - q).norm(),
            after: (similarity.apply(f) - q).norm(),
        })
        .collect();
    Ok(RbfWarp {
        positions,
        pairing: LandmarkPairing {
            used,
            skipped,
            virtual_off_surface: Vec::new(),
        },
        residuals,
        similarity,
        kernel: params.kernel,
        network,
    })
}

/// [`rbf_warp`] of a template mesh onto a scan mesh, adding the virtual landmarks first when
/// `params.virtual_landmarks` is set: on the scan always (snapped to the scan surface), on the
/// template unless its landmark set already carries them.
pub fn rbf_warp_mesh(
    template: &Mesh,
    template_landmarks: &LandmarkSet,
    scan: &Mesh,
    scan_landmarks: &LandmarkSet,
    params: &RbfParams,
) -> Result<RbfWarp, RbfError> {
    let mut t = template_landmarks.landmarks.clone();
    let mut s = scan_landmarks.landmarks.clone();
    let mut off_surface = Vec::new();
    if params.virtual_landmarks {
        if !t.iter().any(|l| l.name.starts_with(VIRTUAL_PREFIX)) {
            t.extend(
                virtual_landmarks_detailed(template_landmarks, template)
                    .into_iter()
                    .map(|v| v.landmark),
            );
        }
        for v in virtual_landmarks_detailed(scan_landmarks, scan) {
            if !v.on_surface {
                off_surface.push(v.landmark.name.clone());
            }
            s.push(v.landmark);
        }
    } else {
        t.retain(|l| !l.name.starts_with(VIRTUAL_PREFIX));
    }
    let mut warp = rbf_warp(&template.positions, &t, &s, params)?;
    warp.pairing.virtual_off_surface = off_surface;
    Ok(warp)
}
