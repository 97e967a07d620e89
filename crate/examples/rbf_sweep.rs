//! Sweeps kernel, kernel parameter and the affine term of `rbf_warp` on the procedural body of
//! `tests/rbf_support` warped onto its known non-linear subject (CAESAR frame: mm, z-up), and
//! prints the mean/max distance of warped template vertices from their true positions (mm).
//! `cargo run --release --example rbf_sweep [SCAN_DENSITY]`. The figures behind the defaults in docs/rbf.md.

#[path = "../tests/rbf_support/mod.rs"]
mod rbf_support;

use bodyspace::landmarks::{Landmark, LandmarkSet};
use bodyspace::mesh::Mesh;
use bodyspace::rbf::{rbf_warp_mesh, Kernel, RbfParams};

fn main() {
    let template = rbf_support::body(20);
    let template_landmarks = rbf_support::landmarks(&template);
    // The scan is sampled differently from the template, as a real scan is.
    // `rbf_sweep N` samples the scan at density N (default 23; 20 = the template's sampling).
    let density = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(23);
    let scan_body = rbf_support::body(density);
    let scan = Mesh::new(
        scan_body
            .positions
            .iter()
            .map(rbf_support::subject)
            .collect(),
        scan_body.triangles.clone(),
    );
    let truth: Vec<_> = template
        .positions
        .iter()
        .map(rbf_support::subject)
        .collect();
    for noise_mm in [0.0, 2.0] {
        let mut scan_landmarks = LandmarkSet {
            landmarks: template_landmarks
                .landmarks
                .iter()
                .map(|l| Landmark {
                    name: l.name.clone(),
                    position: rbf_support::subject(&l.position),
                })
                .collect(),
            ..LandmarkSet::default()
        };
        rbf_support::jitter(&mut scan_landmarks.landmarks, noise_mm, 7);
        println!(
            "\nlandmark noise ±{noise_mm} mm, {} template vertices",
            template.positions.len()
        );
        println!("kernel        param   affine virtual  mean mm   max mm   rcond");
        let mut kernels = vec![Kernel::ThinPlate];
        for s in [0.0, 0.005, 0.01, 0.05, 0.1] {
            kernels.push(Kernel::Multiquadric { s });
        }
        for c in [0.001, 0.01, 0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 1.0, 10.0] {
            kernels.push(Kernel::Gaussian { c });
        }
        for kernel in kernels {
            for (affine, virtual_landmarks) in [(true, true), (false, true), (true, false)] {
                let params = RbfParams {
                    kernel,
                    affine,
                    virtual_landmarks,
                    ..RbfParams::default()
                };
                let line = match rbf_warp_mesh(
                    &template,
                    &template_landmarks,
                    &scan,
                    &scan_landmarks,
                    &params,
                ) {
                    Ok(w) => {
                        let d: Vec<f64> = w
                            .positions
                            .iter()
                            .zip(&truth)
                            .map(|(a, b)| (a - b).norm())
                            .collect();
                        let mean = d.iter().sum::<f64>() / d.len() as f64;
                        let max = d.iter().copied().fold(0.0, f64::max);
                        format!("{mean:8.2} {max:8.2}   {:.1e}", w.network.rcond())
                    }
                    Err(e) => format!("error: {e}"),
                };
                println!(
                    "{:13} {:7} {:6} {:7} {line}",
                    kernel.name(),
                    kernel.param().map_or("-".into(), |p| format!("{p}")),
                    affine,
                    virtual_landmarks
                );
            }
        }
    }
}
