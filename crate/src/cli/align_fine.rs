//! `bodyspace align` without `--rough-only`: RBF warp (paper §3.1), then fine alignment (§3.2).

use std::ops::ControlFlow;
use std::path::Path;
use std::time::Instant;

use nalgebra::Point3;
use serde_json::{json, Value};

use super::align::{load, rough, rough_params, AlignArgs};
use crate::align::{
    coarse_to_fine_align, fine_align_anchored, AlignReport, CoarseToFineParams, DistanceStats,
    FineAlignParams, ScanIndex,
};
use crate::io::{read_scan, write_ply};
use crate::mesh::units::detect_units;
use crate::mesh::Mesh;
use crate::template::{Resolution, Template};

pub use crate::align::data_weights;

/// Landmark anchors for [`crate::align::fine_align_anchored`]: each landmark vertex of the
/// template (the 73 and the virtual ones) whose landmark the RBF warp used, held at its warped
/// position — where the warp's exact interpolation put it, on the scan landmark.
pub fn landmark_anchors(
    template: &Template,
    warped: &[Point3<f64>],
    used: &[String],
) -> Vec<(u32, Point3<f64>)> {
    let mut named: Vec<(String, u32)> = template.landmark_vertices().to_vec();
    named.extend(template.virtual_landmark_vertices().unwrap_or_default());
    named
        .into_iter()
        .filter(|(name, v)| used.iter().any(|u| u == name) && (*v as usize) < warped.len())
        .map(|(_, v)| (v, warped[v as usize]))
        .collect()
}

fn stats_mm(s: &DistanceStats, to_mm: f64) -> Value {
    json!({
        "count": s.count,
        "mean_mm": s.mean * to_mm,
        "std_dev_mm": s.std_dev * to_mm,
        "rms_mm": s.rms * to_mm,
        "max_abs_mm": s.max_abs * to_mm,
    })
}

fn fine_report(r: &AlignReport, to_mm: f64) -> Value {
    json!({
        "template_vertices": r.template_vertices,
        "scan_vertices": r.scan_vertices,
        "scan_to_template": stats_mm(&r.scan_to_template, to_mm),
        "template_to_scan": stats_mm(&r.template_to_scan, to_mm),
        "iterations": r.iterations,
        "rounds": r.rounds,
        "converged": r.converged,
        "cancelled": r.cancelled,
        "elapsed_ms": r.elapsed_ms,
        "curve": r.curve.iter().map(|p| json!({
            "iteration": p.iteration,
            "elapsed_ms": p.elapsed_ms,
            "energy": p.energy,
            "rms_mm": p.rms * to_mm,
        })).collect::<Vec<_>>(),
    })
}

/// Mean and RMS distance (m) of fitted vertices to their true positions, over the vertices both
/// have (the base vertices when one side is at fine).
fn correspondence_error(fitted: &[Point3<f64>], truth: &[Point3<f64>]) -> (f64, f64) {
    let n = fitted.len().min(truth.len()).max(1) as f64;
    let d: Vec<f64> = fitted
        .iter()
        .zip(truth)
        .map(|(a, b)| (a - b).norm())
        .collect();
    (
        d.iter().sum::<f64>() / n,
        (d.iter().map(|x| x * x).sum::<f64>() / n).sqrt(),
    )
}

/// Ground truth in metres; `expected` lists the vertex counts accepted (the base vertices, which
/// come first at every resolution, or all template vertices).
fn read_truth(path: &Path, expected: &[usize], to_metres: f64) -> Result<Vec<Point3<f64>>, String> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| format!("{name}: cannot read the file: {e}"))?;
    let mesh = read_scan(&bytes, &name).map_err(|e| e.to_string())?;
    if !expected.contains(&mesh.positions.len()) {
        return Err(format!(
            "{name}: {} vertices but the template has {} ({} at base); ground truth must be in template vertex order",
            mesh.positions.len(),
            expected[expected.len() - 1],
            expected[0],
        ));
    }
    Ok(mesh.positions.iter().map(|p| p * to_metres).collect())
}

/// The fitted template (metres, template order) and the JSON of the fine step.
struct Fitted {
    positions: Vec<Point3<f64>>,
    report: Value,
}

/// Runs the whole pipeline, writes the fitted template (scan units) and prints the report. At
/// `fine` the template is aligned coarse to fine ([`coarse_to_fine_align`]).
pub fn run_full(args: &AlignArgs) -> Result<(), String> {
    let rbf_params = rough_params(args)?;
    let params = FineAlignParams {
        a: args.a,
        b: args.b,
        max_iterations: args.max_iterations,
        ..FineAlignParams::default()
    };
    let params = FineAlignParams {
        landmark_weight: args.landmark_weight.unwrap_or(params.landmark_weight),
        scan_term_weight: args.scan_term_weight.unwrap_or(params.scan_term_weight),
        ..params
    };
    params.validate().map_err(|e| e.to_string())?;
    let inputs = load(args)?;
    let refinement = inputs.template.refinement();
    // Coarse to fine warps and fits the base template first; its vertices come first at fine.
    let base_template = inputs.template.at_resolution(Resolution::Base);
    let warped_template = if refinement.is_some() {
        &base_template
    } else {
        &inputs.template
    };
    let started = Instant::now();
    let warp = rough(warped_template, &inputs, &rbf_params)?;
    let rough_ms = started.elapsed().as_secs_f64() * 1e3;

    let extent = bounding_extent(&inputs.scan.positions);
    let units = detect_units(extent);
    let to_m = units.scale_to_metres();
    let scan_m = Mesh::new(
        inputs.scan.positions.iter().map(|p| p * to_m).collect(),
        inputs.scan.triangles.clone(),
    );
    let warped_m: Vec<Point3<f64>> = warp.positions.iter().map(|p| p * to_m).collect();
    let triangles = &inputs.template.mesh().triangles;
    let weights = data_weights(&inputs.template);

    let index_start = Instant::now();
    let index = ScanIndex::new(&scan_m).map_err(|e| format!("{}: {e}", args.scan.display()))?;
    let index_ms = index_start.elapsed().as_secs_f64() * 1e3;
    let anchors = landmark_anchors(warped_template, &warped_m, &warp.used);
    let fitted = match refinement {
        None => {
            let result = fine_align_anchored(
                &warped_m,
                triangles,
                &index,
                &weights,
                &anchors,
                &params,
                &mut |_| ControlFlow::Continue(()),
            )
            .map_err(|e| format!("fine alignment: {e}"))?;
            Fitted {
                report: fine_report(&result.report, 1e3),
                positions: result.positions,
            }
        }
        Some(refinement) => {
            let c2f = CoarseToFineParams::around(&params, args.fine_iterations);
            let result = coarse_to_fine_align(
                &warped_m,
                &warped_template.mesh().triangles,
                refinement,
                &index,
                &weights,
                &anchors,
                &c2f,
                &mut |_, _| ControlFlow::Continue(()),
                &mut |_, _, _| {},
            )
            .map_err(|e| format!("fine alignment: {e}"))?;
            let mut report = fine_report(&result.report, 1e3);
            report["stages"] = json!({
                "base": fine_report(&result.base, 1e3),
                "subdivide_ms": result.subdivide_ms,
                "fine_iterations": result.report.iterations - result.base.iterations,
                "fine_max_iterations": c2f.fine.max_iterations,
            });
            report["stages"]["base"]
                .as_object_mut()
                .map(|o| o.remove("curve"));
            Fitted {
                report,
                positions: result.positions,
            }
        }
    };
    let total_ms = started.elapsed().as_secs_f64() * 1e3;

    let mesh = Mesh::new(
        fitted.positions.iter().map(|p| p / to_m).collect(),
        triangles.clone(),
    );
    let out = args.out.display().to_string();
    std::fs::write(&args.out, write_ply(&mesh))
        .map_err(|e| format!("{out}: cannot write the fitted template: {e}"))?;

    let mut report = json!({
        "step": "rough+fine",
        "out": out,
        "units": units.name(),
        "template_resolution": inputs.template.resolution().name(),
        "coarse_to_fine": refinement.is_some(),
        "landmarks_used": warp.used.len(),
        "a": params.a,
        "b": params.b,
        "landmark_weight": params.landmark_weight,
        "scan_term_weight": params.scan_term_weight,
        "anchors": anchors.len(),
        "rough_ms": rough_ms,
        "scan_index_ms": index_ms,
        "total_ms": total_ms,
        "fine": fitted.report,
    });
    if let Some(truth) = &args.truth {
        let truth = read_truth(
            truth,
            &[inputs.template.base_vertex_count(), fitted.positions.len()],
            to_m,
        )?;
        let (rough_mean, rough_rms) = correspondence_error(&warped_m, &truth);
        let (mean, rms) = correspondence_error(&fitted.positions, &truth);
        report["correspondence_error"] = json!({
            "vertices": truth.len(),
            "rough_mean_mm": rough_mean * 1e3,
            "rough_rms_mm": rough_rms * 1e3,
            "mean_mm": mean * 1e3,
            "rms_mm": rms * 1e3,
        });
    }
    let text = serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?;
    if let Some(path) = &args.report {
        std::fs::write(path, &text)
            .map_err(|e| format!("{}: cannot write the report: {e}", path.display()))?;
    }
    println!("{text}");
    Ok(())
}

fn bounding_extent(points: &[Point3<f64>]) -> f64 {
    let mut lo = Point3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY);
    let mut hi = Point3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    for p in points {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    (hi - lo).max().max(0.0)
}
