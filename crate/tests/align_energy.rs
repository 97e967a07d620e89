//! Finite-difference check of the fine-alignment energy's analytic gradient and curvature.

mod align_support;

use align_support::{uv_sphere, Rng};
use bodyspace::align::energy::{AlignEnergy, TangentialTerm, DOF};
use bodyspace::align::scan_term::ScanSample;
use bodyspace::mesh::topology::unique_edges;
use nalgebra::{Point3, Vector3};

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
    // The tangential term around random start points with random unit normals.
    let rest: Vec<Point3<f64>> = (0..n)
        .map(|_| Point3::new(rng.symmetric(), rng.symmetric(), rng.symmetric()) * 0.3)
        .collect();
    let normals: Vec<Vector3<f64>> = (0..n)
        .map(|_| Vector3::new(rng.symmetric(), rng.symmetric(), 0.5 + rng.next_f64()).normalize())
        .collect();
    let energy = AlignEnergy {
        vertices: &vertices,
        edges: &edges,
        targets: &targets,
        data_coefficients: &coefficients,
        smoothness_coefficient: 0.37,
        scan_samples: &samples,
        tangential: TangentialTerm {
            rest: &rest,
            normals: &normals,
            coefficient: 0.6,
        },
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

/// E = Σ α_i ‖T_i ṽ_i − c_i‖² + β Σ_edges ‖T_i − T_j‖²_F (paper eq. 6–8) on one triangle, with
/// every term worked out by hand.
#[test]
fn energy_of_one_triangle_equals_the_hand_computed_value() {
    // ṽ: the corners (0,0,0), (1,0,0), (0,1,0) with a trailing 1.
    let vertices = [
        [0.0, 0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, 1.0],
    ];
    let edges = [[0, 1], [1, 2], [0, 2]];
    // T_0 = [I | 0]; T_1 = [I | (0, 0, 1)]; T_2 = [diag(2, 1, 1) | 0], rows of [A | t].
    let mut x = vec![0.0; 3 * DOF];
    for t in x.chunks_exact_mut(DOF) {
        t[0] = 1.0;
        t[5] = 1.0;
        t[10] = 1.0;
    }
    x[DOF + 11] = 1.0;
    x[2 * DOF] = 2.0;
    // T_i ṽ_i = (0,0,0), (1,0,1), (0,1,0); against c = (1,0,0), (1,0,0), (0,1,2) the squared
    // distances are 1, 1, 4; with α = 1, 2, 0.5: Σ α d² = 1 + 2 + 2 = 5.
    let targets = [
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(0.0, 1.0, 2.0),
    ];
    let alpha = [1.0, 2.0, 0.5];
    // ‖T_0 − T_1‖² = 1 (t_z), ‖T_1 − T_2‖² = 1 + 1 (A_00, t_z), ‖T_0 − T_2‖² = 1 (A_00): E_s = 4;
    // β = 0.25 gives 1, and E = 5 + 1 = 6.
    let energy = AlignEnergy {
        vertices: &vertices,
        edges: &edges,
        targets: &targets,
        data_coefficients: &alpha,
        smoothness_coefficient: 0.25,
        scan_samples: &[],
        tangential: TangentialTerm::default(),
    };
    let mut grad = vec![0.0; 3 * DOF];
    let terms = energy.evaluate(&x, &mut grad);
    assert!((terms.data_weighted - 5.0).abs() < 1e-14, "{terms:?}");
    assert!((terms.smoothness - 4.0).abs() < 1e-14, "{terms:?}");
    assert!((terms.total - 6.0).abs() < 1e-14, "{terms:?}");
    assert_eq!(terms.matched, 3);
    assert!((terms.matched_sq_sum - 6.0).abs() < 1e-14);
    // ∂E/∂T_0 = 2α_0 r_0 ṽ_0ᵀ + 2β Σ_j (T_0 − T_j), r_0 = (−1, 0, 0), ṽ_0 = (0, 0, 0, 1):
    // t_x gets 2·1·(−1)·1 = −2; A_00 gets 2·0.25·(1 − 2) = −0.5 (from T_2); t_z gets
    // 2·0.25·(0 − 1) = −0.5 (from T_1); every other entry is 0.
    let mut expected = [0.0; DOF];
    expected[3] = -2.0;
    expected[0] = -0.5;
    expected[11] = -0.5;
    for (k, (g, e)) in grad[..DOF].iter().zip(expected).enumerate() {
        assert!((g - e).abs() < 1e-14, "∂E/∂T_0[{k}] = {g}, expected {e}");
    }
}
