//! Native timing of one full fine alignment at realistic size, and a comparison of the
//! correspondence searches (nearest vertex / vertex + one-ring / exact closest on triangle).
//!
//! `cargo run --release --example align_bench [-- TEMPLATE_RINGS SCAN_RINGS]`
//! Defaults: 84 rings (≈14K-vertex template) onto 316 rings (≈200K-vertex scan). The subject is a
//! body-sized bumpy ellipsoid with 0.5 mm scanner-like noise; the template is its smooth,
//! slightly misplaced version (as after the RBF warp).

use bodyspace::align::{
    fine_align, CorrespondenceMode, FineAlignInput, FineAlignParams, MatchQuery, SurfaceIndex,
};
use bodyspace::mesh::Mesh;
use nalgebra::{Point3, Vector3};
use std::time::Instant;

fn uv_sphere(rings: usize, segments: usize) -> Mesh {
    let mut positions = vec![Point3::new(0.0, 0.0, 1.0)];
    for r in 1..rings {
        let theta = std::f64::consts::PI * r as f64 / rings as f64;
        for s in 0..segments {
            let phi = 2.0 * std::f64::consts::PI * s as f64 / segments as f64;
            positions.push(Point3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ));
        }
    }
    positions.push(Point3::new(0.0, 0.0, -1.0));
    let south = (positions.len() - 1) as u32;
    let ring = |r: usize, s: usize| (1 + (r - 1) * segments + s % segments) as u32;
    let mut triangles = Vec::new();
    for s in 0..segments {
        triangles.push([0, ring(1, s), ring(1, s + 1)]);
        triangles.push([south, ring(rings - 1, s + 1), ring(rings - 1, s)]);
    }
    for r in 1..rings - 1 {
        for s in 0..segments {
            let (a, b, c, d) = (
                ring(r, s),
                ring(r, s + 1),
                ring(r + 1, s),
                ring(r + 1, s + 1),
            );
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
    }
    Mesh::new(positions, triangles)
}

const AXES: Vector3<f64> = Vector3::new(0.16, 0.12, 0.85);

fn body(p: &Point3<f64>) -> Point3<f64> {
    let bump = 1.0 + 0.06 * (5.0 * p.z).sin() * (2.0 * p.x).cos() + 0.03 * (9.0 * p.y).sin();
    Point3::from(p.coords.component_mul(&AXES) * bump)
}

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let template_rings = args.first().copied().unwrap_or(84);
    let scan_rings = args.get(1).copied().unwrap_or(316);

    let mut seed = 0x2545_F491_4F6C_DD1Du64;
    let mut noise = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut scan = uv_sphere(scan_rings, 2 * scan_rings);
    for p in scan.positions.iter_mut() {
        *p = body(p) + Vector3::new(noise(), noise(), noise()) * 0.0005;
    }
    let mut template = uv_sphere(template_rings, 2 * template_rings);
    for p in template.positions.iter_mut() {
        *p = Point3::from(
            p.coords.component_mul(&(AXES * 1.03)) + Vector3::new(0.005, -0.003, 0.004),
        );
    }
    println!(
        "template {} vertices, scan {} vertices",
        template.positions.len(),
        scan.positions.len()
    );

    let t = Instant::now();
    let index = match SurfaceIndex::new(&scan) {
        Ok(index) => index,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    println!("scan index (k-d tree, normals, boundary): {:.1} ms", ms(t));
    let t = Instant::now();
    index.prepare_triangle_bvh();
    println!("triangle BVH (parry3d-f64): {:.1} ms", ms(t));

    // One correspondence pass per mode from the unfitted template: time and distance found.
    let exact = MatchQuery {
        mode: CorrespondenceMode::ClosestOnTriangle,
        min_cos: None,
        candidates: 1,
    };
    let truth: Vec<f64> = template
        .positions
        .iter()
        .map(|p| {
            index
                .closest(p, None, &exact)
                .map_or(0.0, |m| (m.point - p).norm())
        })
        .collect();
    for mode in [
        CorrespondenceMode::NearestVertex,
        CorrespondenceMode::VertexOneRing,
        CorrespondenceMode::ClosestOnTriangle,
    ] {
        let query = MatchQuery {
            mode,
            min_cos: Some(0.5),
            candidates: 8,
        };
        let t = Instant::now();
        let mut excess = 0.0;
        let mut found = 0;
        for (p, d) in template.positions.iter().zip(&truth) {
            if let Some(m) = index.closest(p, None, &query) {
                excess += (m.point - p).norm() - d;
                found += 1;
            }
        }
        println!(
            "correspondences {mode:?}: {:.1} ms for {} queries, mean excess over exact closest {:.4} mm",
            ms(t),
            template.positions.len(),
            excess / found.max(1) as f64 * 1e3
        );
    }

    schedules(&template, &index);
    let weights = vec![1.0; template.positions.len()];
    for mode in [
        CorrespondenceMode::NearestVertex,
        CorrespondenceMode::VertexOneRing,
        CorrespondenceMode::ClosestOnTriangle,
    ] {
        let params = FineAlignParams {
            correspondence: mode,
            ..FineAlignParams::default()
        };
        let t = Instant::now();
        let result = fine_align(
            &FineAlignInput::of_mesh(&template, &index, &weights),
            &params,
            &mut (),
        );
        let total = ms(t);
        match result {
            Ok(r) => {
                let rep = &r.report;
                println!(
                    "fine_align {mode:?}: {:.0} ms total ({:.0} ms fitting + report), {} iterations, {} rounds, converged {}; \
scan→template RMS {:.3} mm mean {:+.3} mm sd {:.3} mm; template→scan RMS {:.3} mm",
                    total,
                    rep.elapsed_ms,
                    rep.iterations,
                    rep.rounds,
                    rep.converged,
                    rep.scan_to_template.rms * 1e3,
                    rep.scan_to_template.mean * 1e3,
                    rep.scan_to_template.std_dev * 1e3,
                    rep.template_to_scan.rms * 1e3,
                );
                if let Ok(d) = bodyspace::align::report::scan_to_template_distances(
                    &r.positions,
                    &template.triangles,
                    &index,
                ) {
                    let mut d: Vec<f64> = d.iter().map(|s| s.distance).collect();
                    let worst = d
                        .iter()
                        .enumerate()
                        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
                        .map(|(i, v)| (scan.positions[i], *v));
                    d.iter_mut().for_each(|v| *v = v.abs());
                    d.sort_by(f64::total_cmp);
                    let q = |f: f64| d[((d.len() - 1) as f64 * f) as usize] * 1e3;
                    println!(
                        "  |scan→template| percentiles 50/90/99/100: {:.3}/{:.3}/{:.3}/{:.3} mm; worst at {:?}",
                        q(0.5),
                        q(0.9),
                        q(0.99),
                        q(1.0),
                        worst
                    );
                }
                let marks: Vec<String> = rep
                    .curve
                    .iter()
                    .filter(|p| p.iteration % 20 == 0)
                    .map(|p| format!("{}:{:.0}ms/{:.2}mm", p.iteration, p.elapsed_ms, p.rms * 1e3))
                    .collect();
                println!(
                    "  time-to-RMS curve (iteration:time/rms): {}",
                    marks.join(" ")
                );
            }
            Err(e) => println!("fine_align {mode:?}: {e}"),
        }
    }
}

/// Time/accuracy trade-off of the schedule (VertexOneRing): iterations per round × limit.
fn schedules(template: &Mesh, index: &SurfaceIndex) {
    let weights = vec![1.0; template.positions.len()];
    for (per_round, limit) in [(10, 60), (10, 100), (20, 100), (20, 200), (40, 200)] {
        let params = FineAlignParams {
            iterations_per_round: per_round,
            max_iterations: limit,
            ..FineAlignParams::default()
        };
        let t = Instant::now();
        if let Ok(r) = fine_align(
            &FineAlignInput::of_mesh(template, index, &weights),
            &params,
            &mut (),
        ) {
            println!(
                "schedule {per_round:>2}/round, max {limit:>3}: {:.0} ms, {} iterations, scan→template RMS {:.3} mm, template→scan RMS {:.3} mm",
                ms(t),
                r.report.iterations,
                r.report.scan_to_template.rms * 1e3,
                r.report.template_to_scan.rms * 1e3
            );
        }
    }
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}
