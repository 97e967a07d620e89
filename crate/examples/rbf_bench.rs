//! Times the RBF warp of ~650K template vertices with n = 85 landmark pairs (the paper's n and
//! our `fine` resolution), for each kernel. `cargo run --release --example rbf_bench`.
//! Prints wall milliseconds (all cores) and single-thread CPU milliseconds (meaningful on a
//! shared, loaded machine); it asserts nothing about time.

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
        Kernel::Gaussian { c: 0.1 },
        Kernel::Gaussian { c: 0.2 },
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
        // CPU time of one thread is what the code costs when the machine is shared.
        let cpu0 = cpu_seconds();
        for _ in 0..5 {
            network.warp_serial(&template.positions, &mut out);
        }
        let cpu_ms = cpu_seconds().map(|c1| (c1 - cpu0.unwrap_or(c1)) * 1e3 / 5.0);
        let t = Instant::now();
        let whole = rbf_warp(
            &template.positions,
            &landmarks.landmarks,
            &scan_landmarks,
            &params,
        );
        let whole_ms = t.elapsed().as_secs_f64() * 1e3;
        println!(
            "{:13} {:5} fit (LU + rcond) {fit_ms:6.2} ms   warp {best:7.1} ms wall (best of 5, all \
             cores)   {} ms CPU (one thread)   rbf_warp total {whole_ms:7.1} ms wall{}",
            kernel.name(),
            kernel.param().map_or(String::new(), |p| format!("{p}")),
            cpu_ms.map_or("?".into(), |c| format!("{c:.1}")),
            if whole.is_ok() { "" } else { " (failed)" }
        );
    }
}

/// User + system CPU seconds of this process from /proc/self/stat (Linux), if readable.
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    let after = stat.rsplit_once(')')?.1;
    let fields: Vec<&str> = after.split_whitespace().collect();
    let utime: f64 = fields.get(11)?.parse().ok()?;
    let stime: f64 = fields.get(12)?.parse().ok()?;
    // Linux reports clock ticks of 1/100 s (USER_HZ) on every architecture we build for.
    Some((utime + stime) / 100.0)
}
