//! Finite-difference check of the fine-alignment energy's analytic gradient and curvature.

mod align_support;

use align_support::{uv_sphere, Rng};
use bodyspace::align::energy::{AlignEnergy, DOF};
use bodyspace::align::scan_term::ScanSample;
use bodyspace::mesh::topology::unique_edges;
use nalgebra::Point3;

#[test]
fn gradient_and_curvature_match_finite_differences() {
    let mesh = uv_sphere(5, 7);
    let n = mesh.positions.len();
    let mut rng = Rng(7);
    let vertices: Vec<[f64; 4]> = mesh
        .positions
        .iter()
        .map(|p| [0.3 * p.x, 0.3 * p.y, 0.3 * p.z, 1.0])
        .collect();
    let edges = unique_edges(&mesh.triangles);
    let targets: Vec<Point3<f64>> = (0..n)
        .map(|_| Point3::new(rng.symmetric(), rng.symmetric(), rng.symmetric()) * 0.3)
        .collect();
    // Some vertices without a data term, as in a round with rejected matches.
    let coefficients: Vec<f64> = (0..n)
        .map(|i| {
            if i % 5 == 0 {
                0.0
            } else {
                0.5 + rng.next_f64()
            }
        })
        .collect();
    // Scan-to-template samples on random triangles (one on a vertex, λ = (1, 0, 0)).
    let samples: Vec<ScanSample> = mesh
        .triangles
        .iter()
        .step_by(3)
        .enumerate()
        .map(|(k, t)| {
            let (u, v) = (rng.next_f64(), rng.next_f64());
            let barycentric = if k == 0 {
                [1.0, 0.0, 0.0]
            } else {
                [0.5 * u, 0.5 * v, 1.0 - 0.5 * u - 0.5 * v]
            };
            ScanSample {
                corners: *t,
                barycentric,
                target: Point3::new(rng.symmetric(), rng.symmetric(), rng.symmetric()) * 0.3,
                coefficient: 0.2 + rng.next_f64(),
            }
        })
        .collect();
    assert!(samples.len() > 5);
    let energy = AlignEnergy {
        vertices: &vertices,
        edges: &edges,
        targets: &targets,
        data_coefficients: &coefficients,
        smoothness_coefficient: 0.37,
        scan_samples: &samples,
    };
    let x: Vec<f64> = (0..DOF * n).map(|_| rng.symmetric()).collect();
    let mut grad = vec![0.0; DOF * n];
    let mut scratch = vec![0.0; DOF * n];
    let f0 = energy.evaluate(&x, &mut grad).total;
    let h = 1e-6;
    let mut worst: f64 = 0.0;
    for k in 0..DOF * n {
        let mut xp = x.clone();
        xp[k] += h;
        let fp = energy.evaluate(&xp, &mut scratch).total;
        xp[k] -= 2.0 * h;
        let fm = energy.evaluate(&xp, &mut scratch).total;
        let fd = (fp - fm) / (2.0 * h);
        worst = worst.max((fd - grad[k]).abs() / (1.0 + grad[k].abs()));
    }
    assert!(worst < 1e-6, "worst relative gradient error {worst}");

    // E is quadratic: E(x + t d) = E + t gᵀd + ½ t² dᵀHd exactly.
    let d: Vec<f64> = (0..DOF * n).map(|_| rng.symmetric()).collect();
    let t = 0.3;
    let xt: Vec<f64> = x.iter().zip(&d).map(|(a, b)| a + t * b).collect();
    let ft = energy.evaluate(&xt, &mut scratch).total;
    let gd: f64 = grad.iter().zip(&d).map(|(a, b)| a * b).sum();
    let predicted = f0 + t * gd + 0.5 * t * t * energy.curvature(&d);
    assert!(
        (ft - predicted).abs() < 1e-9 * (1.0 + ft.abs()),
        "quadratic model {predicted} vs {ft}"
    );
}
