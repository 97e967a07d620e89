//! The RBF network alone (paper eq. 1–5): exact interpolation, affine reproduction, smoothing,
//! and the documented errors on singular input — never NaNs.
// Native only; tests/rbf_wasm.rs runs the same checks in the browser.
#![cfg(not(target_arch = "wasm32"))]
mod rbf_support;

use bodyspace::rbf::{fit, Kernel, RbfError, RbfParams};
use nalgebra::{Matrix3, Point3, Vector3};

const KERNELS: [Kernel; 3] = [
    Kernel::ThinPlate,
    Kernel::Multiquadric { s: 0.01 },
    Kernel::Gaussian { c: 0.15 },
];

/// The 73 landmarks of the procedural body (metres) and their places on the subject (metres).
fn pairs() -> (Vec<String>, Vec<Point3<f64>>, Vec<Point3<f64>>) {
    let body = rbf_support::body(8);
    let set = rbf_support::landmarks(&body);
    let names = set.landmarks.iter().map(|l| l.name.clone()).collect();
    let p: Vec<_> = set.landmarks.iter().map(|l| l.position).collect();
    let q = p.iter().map(rbf_support::subject_shape).collect();
    (names, p, q)
}

fn params(kernel: Kernel, affine: bool) -> RbfParams {
    RbfParams {
        kernel,
        affine,
        ..RbfParams::default()
    }
}

#[test]
fn interpolation_is_exact_at_the_landmarks_for_every_kernel() {
    let (names, p, q) = pairs();
    let size = 1.8; // the body's height in metres
    for kernel in KERNELS {
        for affine in [true, false] {
            let net = fit(&names, &p, &q, &params(kernel, affine)).unwrap();
            for (pi, qi) in p.iter().zip(&q) {
                let r = (net.evaluate(pi) - qi).norm();
                assert!(r < 1e-8 * size, "{kernel:?} affine={affine}: residual {r}");
            }
        }
    }
}

#[test]
fn an_affine_map_is_reproduced_everywhere_with_the_affine_term() {
    let (names, p, _) = pairs();
    let a = Matrix3::new(1.1, 0.2, -0.1, 0.05, 0.9, 0.3, -0.2, 0.1, 1.3);
    let b = Vector3::new(0.4, -1.2, 2.0);
    let map = |x: &Point3<f64>| Point3::from(a * x.coords + b);
    let q: Vec<_> = p.iter().map(map).collect();
    let elsewhere = rbf_support::body(5).positions;
    for kernel in KERNELS {
        let net = fit(&names, &p, &q, &params(kernel, true)).unwrap();
        for x in elsewhere
            .iter()
            .chain([Point3::new(10.0, -5.0, 3.0)].iter())
        {
            let err = (net.evaluate(x) - map(x)).norm();
            assert!(err < 1e-9, "{kernel:?}: {err} at {x:?}");
        }
    }
}

#[test]
fn without_the_affine_term_a_gaussian_collapses_far_from_the_landmarks() {
    let (names, p, q) = pairs();
    let net = fit(&names, &p, &q, &params(Kernel::Gaussian { c: 0.15 }, false)).unwrap();
    // Three metres from every landmark the Gaussian is ~exp(-400): the map returns the origin.
    assert!(net.evaluate(&Point3::new(0.0, 5.0, 0.0)).coords.norm() < 1e-9);
    let with = fit(&names, &p, &q, &params(Kernel::Gaussian { c: 0.15 }, true)).unwrap();
    assert!(with.evaluate(&Point3::new(0.0, 5.0, 0.0)).y > 4.0);
}

#[test]
fn lambda_smooths_with_finite_nonzero_residuals() {
    let (names, p, mut q) = pairs();
    // A bump on one landmark: smoothing must not follow it completely.
    q[0].x += 0.05;
    for kernel in KERNELS {
        let smooth = RbfParams {
            lambda: 0.05,
            ..params(kernel, true)
        };
        let net = fit(&names, &p, &q, &smooth).unwrap();
        let r: Vec<f64> = p
            .iter()
            .zip(&q)
            .map(|(a, b)| (net.evaluate(a) - b).norm())
            .collect();
        assert!(r.iter().all(|v| v.is_finite()), "{kernel:?}");
        assert!(
            r[0] > 1e-4 && r[0] < 0.05,
            "{kernel:?}: bump residual {}",
            r[0]
        );
    }
}

#[test]
fn a_duplicated_point_is_reported_by_name_and_lambda_accepts_it() {
    let (names, mut p, q) = pairs();
    p[5] = p[2];
    let err = fit(&names, &p, &q, &RbfParams::default()).unwrap_err();
    match &err {
        RbfError::CoincidentLandmarks { first, second, .. } => {
            assert_eq!(
                (first.as_str(), second.as_str()),
                (names[2].as_str(), names[5].as_str())
            );
        }
        other => panic!("expected CoincidentLandmarks, got {other}"),
    }
    assert!(err.to_string().contains(&names[5]));
    let smooth = RbfParams {
        lambda: 1e-3,
        ..RbfParams::default()
    };
    let net = fit(&names, &p, &q, &smooth).unwrap();
    assert!(net.evaluate(&p[2]).iter().all(|v| v.is_finite()));
}

#[test]
fn a_duplicated_name_is_reported() {
    let (mut names, p, q) = pairs();
    names[7] = names[3].clone();
    let err = fit(&names, &p, &q, &RbfParams::default()).unwrap_err();
    assert_eq!(
        err,
        RbfError::DuplicateName {
            name: names[3].clone(),
            side: "landmark"
        }
    );
}

#[test]
fn coplanar_landmarks_cannot_carry_the_affine_term() {
    let names: Vec<String> = (0..6).map(|i| format!("L{i}")).collect();
    let p: Vec<_> = (0..6)
        .map(|i| Point3::new(i as f64, (i * i % 5) as f64, 0.0))
        .collect();
    let err = fit(&names, &p, &p, &RbfParams::default()).unwrap_err();
    assert!(
        matches!(
            err,
            RbfError::Degenerate {
                shape: "coplanar",
                ..
            }
        ),
        "{err}"
    );
    // Without the affine term a planar set is fine (the Gaussian matrix is positive definite).
    let flat = params(Kernel::Gaussian { c: 1.0 }, false);
    assert!(fit(&names, &p, &p, &flat).is_ok());
    let too_few = fit(&names[..3], &p[..3], &p[..3], &RbfParams::default()).unwrap_err();
    assert!(matches!(
        too_few,
        RbfError::TooFewLandmarks {
            needed: 4,
            got: 3,
            ..
        }
    ));
}

#[test]
fn an_ill_conditioned_system_is_an_error_not_nans() {
    let (names, p, q) = pairs();
    // A 10 m Gaussian on a 1.8 m body: the kernel matrix is numerically rank-deficient.
    let err = fit(&names, &p, &q, &params(Kernel::Gaussian { c: 10.0 }, true)).unwrap_err();
    match err {
        RbfError::IllConditioned { rcond, worst, .. } => {
            assert!(rcond < 1e-13 && rcond.is_finite());
            assert!(names.contains(&worst) || worst == "the affine term");
        }
        other => panic!("expected IllConditioned, got {other}"),
    }
    let mut bad = q.clone();
    bad[4].y = f64::NAN;
    let err = fit(&names, &p, &bad, &RbfParams::default()).unwrap_err();
    assert!(
        matches!(err, RbfError::NonFinite { side: "scan", .. }),
        "{err}"
    );
    let bad_c = params(Kernel::Gaussian { c: -1.0 }, true);
    assert!(matches!(
        fit(&names, &p, &q, &bad_c),
        Err(RbfError::BadParameter { name: "c", .. })
    ));
}
