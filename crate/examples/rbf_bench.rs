//! Times the RBF warp of ~650K template vertices with n = 85 landmark pairs (the paper's n and
//! our `fine` resolution), for each kernel. `cargo run --release --example rbf_bench`.
//! Prints milliseconds; it asserts nothing about time (speed goals live here, not in tests).

#[path = "../tests/rbf_support/mod.rs"]
mod rbf_support;

use std::time::Instant;

use bodyspace::landmarks::Landmark;
use bodyspace::rbf::{fit, rbf_warp, virtual_landmarks, Kernel, RbfParams};

fn main() {
    let template = rbf_support::body(104);
    let mut landmarks = rbf_support::landmarks(&template);
    let virtuals = virtual_landmarks(&landmarks, &template);
    landmarks.landmarks.extend(virtuals);
    let scan_landmarks: Vec<Landmark> = landmarks
        .landmarks
        .iter()
        .map(|l| Landmark {
            name: l.name.clone(),
            position: rbf_support::subject(&l.position),
        })
        .collect();
    let n = landmarks.landmarks.len();
    let v = template.positions.len();
    println!("{v} template vertices, n = {n} landmark pairs");
    for kernel in [
        Kernel::Gaussian { c: 0.15 },
        Kernel::ThinPlate,
        Kernel::Multiquadric { s: 0.01 },
    ] {
        let params = RbfParams {
            kernel,
            ..RbfParams::default()
        };
        let names: Vec<String> = landmarks.landmarks.iter().map(|l| l.name.clone()).collect();
        let p: Vec<_> = landmarks.landmarks.iter().map(|l| l.position).collect();
        let q: Vec<_> = scan_landmarks.iter().map(|l| l.position).collect();
        let t0 = Instant::now();
        let network = match fit(&names, &p, &q, &params) {
            Ok(n) => n,
            Err(e) => {
                println!("{}: {e}", kernel.name());
                continue;
            }
        };
        let fit_ms = t0.elapsed().as_secs_f64() * 1e3;
        let mut out = vec![nalgebra::Point3::origin(); v];
        let mut best = f64::INFINITY;
        for _ in 0..5 {
            let t = Instant::now();
            network.warp_into(&template.positions, &mut out);
            best = best.min(t.elapsed().as_secs_f64() * 1e3);
        }
        let t = Instant::now();
        let whole = rbf_warp(
            &template.positions,
            &landmarks.landmarks,
            &scan_landmarks,
            &params,
        );
        let whole_ms = t.elapsed().as_secs_f64() * 1e3;
        println!(
            "{:13} fit (LU + rcond) {fit_ms:6.2} ms   warp {best:7.1} ms (best of 5)   \
             rbf_warp total {whole_ms:7.1} ms{}",
            kernel.name(),
            if whole.is_ok() { "" } else { " (failed)" }
        );
    }
}
