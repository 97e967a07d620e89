//! How much a fit of one subject moves when only the rounding of its input changes: the same
//! scan and landmarks turned a quarter turn (y up → z up), shifted by 1 nm, and written in other
//! units (millimetres ↔ metres), each fitted with `align_scan` and mapped back exactly. The RBF warp (§3.1)
//! absorbs the frame by its Procrustes similarity; fine alignment (§3.2) works in the scan's
//! frame, so what differs there is rounding, amplified (docs/landmarks-estimate.md, "Why the
//! twist is not on by default").
//!
//! `cargo run --release --example fit_rounding -- SCAN LANDMARKS [--leave-out NAME]...
//! [--max-iterations N]`
//!
//! Prints, per variant and per body part (`template/body_part.rs`), the mean, 99th percentile
//! and largest distance (mm) of the warped and of the fitted template from the fit as read, and
//! the iterations each fit ran.

use bodyspace::align::{align_scan, AlignInput, AlignParams};
use bodyspace::io::{read_landmarks, read_scan};
use bodyspace::landmarks::LandmarkSet;
use bodyspace::mesh::bounding_extent;
use bodyspace::mesh::units::{detect_units, Units};
use bodyspace::mesh::Mesh;
use bodyspace::template::{body_parts, BodyPart, Resolution, Template};
use nalgebra::{Point3, Rotation3, Vector3};

/// x' = k·(R·x + t): one variant of the input (t in the file's units).
struct Variant {
    name: &'static str,
    rotation: Rotation3<f64>,
    factor: f64,
    offset: Vector3<f64>,
}

impl Variant {
    fn apply(&self, p: &Point3<f64>) -> Point3<f64> {
        (self.rotation * p + self.offset) * self.factor
    }

    /// A fitted position `p` (metres, the variant's frame, whose units the fit took to metres by
    /// `to_m`) back in the file's frame, in metres (the file's units to metres by `file_to_m`).
    fn undo(&self, p: &Point3<f64>, to_m: f64, file_to_m: f64) -> Point3<f64> {
        let in_variant_units = p / to_m;
        let in_file_units =
            self.rotation.inverse() * (in_variant_units / self.factor - self.offset);
        in_file_units * file_to_m
    }
}

/// `mean / p99 / max` mm of ‖a − b‖ (metres) per body part and over all vertices.
fn spread(a: &[Point3<f64>], b: &[Point3<f64>], parts: &[BodyPart]) -> String {
    let all = BodyPart::ALL.iter().map(|p| (p.name(), Some(*p)));
    all.chain([("all", None)])
        .map(|(name, part)| {
            let mut d: Vec<f64> = (0..a.len())
                .filter(|&i| part.is_none_or(|q| parts[i] == q))
                .map(|i| (a[i] - b[i]).norm() * 1e3)
                .collect();
            d.sort_by(f64::total_cmp);
            let mean = d.iter().sum::<f64>() / d.len().max(1) as f64;
            let (p99, max) = (d[d.len() * 99 / 100], d[d.len() - 1]);
            format!("{name} {mean:.3}/{p99:.3}/{max:.3}")
        })
        .collect::<Vec<_>>()
        .join("  ")
}

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mut files, mut leave_out, mut params) = (Vec::new(), Vec::new(), AlignParams::default());
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--leave-out" => leave_out.push(it.next().ok_or("--leave-out NAME")?.clone()),
            "--max-iterations" => {
                let n = it.next().and_then(|n| n.parse().ok());
                params.fine.max_iterations = n.ok_or("--max-iterations N")?;
            }
            _ => files.push(a.clone()),
        }
    }
    let [scan_path, landmarks_path] = files.as_slice() else {
        return Err("usage: fit_rounding SCAN LANDMARKS [--leave-out NAME]...".into());
    };
    let read = |p: &str| std::fs::read(p).map_err(|e| format!("{p}: {e}"));
    let scan = read_scan(&read(scan_path)?, scan_path).map_err(|e| e.to_string())?;
    let mut landmarks =
        read_landmarks(&read(landmarks_path)?, landmarks_path).map_err(|e| e.to_string())?;
    landmarks.landmarks.retain(|l| !leave_out.contains(&l.name));
    let template = Template::embedded()
        .map_err(|e| e.to_string())?
        .at_resolution(Resolution::Base);
    let parts = body_parts(&template);
    let units = detect_units(bounding_extent(&scan.positions));
    let file_to_m = units.scale_to_metres();
    // Millimetres become metres, anything else millimetres.
    let other_units = if units == Units::Millimetres {
        1e-3
    } else {
        file_to_m * 1e3
    };
    let quarter = Rotation3::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_2);
    let variants = [
        ("as read", Rotation3::identity(), 1.0, 0.0),
        ("turned y up -> z up", quarter, 1.0, 0.0),
        ("shifted 1 nm", Rotation3::identity(), 1.0, 1e-9 / file_to_m),
        ("in other units", Rotation3::identity(), other_units, 0.0),
    ]
    .map(|(name, rotation, factor, shift)| Variant {
        name,
        rotation,
        factor,
        offset: Vector3::repeat(shift),
    });
    // The warp and the fit as read.
    let mut reference: Option<[Vec<Point3<f64>>; 2]> = None;
    for variant in &variants {
        let scan = Mesh::new(
            scan.positions.iter().map(|p| variant.apply(p)).collect(),
            scan.triangles.clone(),
        );
        let mut set = LandmarkSet {
            landmarks: landmarks.landmarks.clone(),
            ..LandmarkSet::default()
        };
        set.landmarks
            .iter_mut()
            .for_each(|l| l.position = variant.apply(&l.position));
        let input = AlignInput {
            template: &template,
            base_template: None,
            scan: &scan,
            landmarks: &set,
            units: None,
        };
        let fit = align_scan(&input, &params, &mut ()).map_err(|e| e.to_string())?;
        let back = |ps: &[Point3<f64>]| -> Vec<Point3<f64>> {
            ps.iter()
                .map(|p| variant.undo(p, fit.scale_to_metres, file_to_m))
                .collect()
        };
        let (warped, fitted) = (back(&fit.warped), back(&fit.positions));
        let iterations = fit.report.fine.as_ref().map_or(0, |f| f.iterations);
        println!("{}: {iterations} iterations", variant.name);
        if let Some([w0, f0]) = &reference {
            println!("  warp mm (mean/p99/max): {}", spread(&warped, w0, &parts));
            println!("  fit  mm (mean/p99/max): {}", spread(&fitted, f0, &parts));
        } else {
            reference = Some([warped, fitted]);
        }
    }
    Ok(())
}
