//! Where a fit's Acromion vertices lie against its truth's, and what shoulder breadth makes of
//! it (issue 33's diagnosis, docs/measurements.md).
//!
//! `cargo run --release --example shoulder_diagnosis -- DIR CACHE [KIND]`: DIR a `bodyspace
//! synth` output (`truth_XXX.ply`), CACHE the `--fits` folder of `measure_accuracy` on it
//! (`KIND_XXX.ply`, KIND `landmarks` or `free`; default `landmarks`). Per subject and side: the
//! fit's Acromion vertex minus the truth's in the truth's shoulder frame (lateral, up, forward;
//! mm) and the upper arm's abduction; then the fit's breadth minus the truth's between the
//! Acromion vertices and between the acromia found on the surface (`measure/acromion.rs`).

#[cfg(not(target_arch = "wasm32"))]
fn main() -> Result<(), String> {
    use bodyspace::cli::model::read_fit;
    use bodyspace::landmarks::shoulder::{acromion_indices, ShoulderFrame};
    use bodyspace::landmarks::CAESAR_LANDMARKS;
    use bodyspace::measure::acromion::turn_rises;
    use bodyspace::measure::{upright, BodyMeasurer, Measure, MeasureParams};
    use bodyspace::mesh::surface_points::surface_near;
    use bodyspace::template::Template;
    use nalgebra::Point3;
    use std::path::PathBuf;

    let args: Vec<String> = std::env::args().skip(1).collect();
    let (dir, cache) = match &args[..] {
        [d, c, ..] => (PathBuf::from(d), PathBuf::from(c)),
        _ => return Err("usage: shoulder_diagnosis DIR CACHE [KIND]".into()),
    };
    let kind = args.get(2).map_or("landmarks", String::as_str);
    let template = Template::embedded().map_err(|e| e.to_string())?;
    let measurer = BodyMeasurer::of_template(&template, MeasureParams::default())
        .map_err(|e| e.to_string())?;
    let rest = &template.mesh().positions;
    let triangles = &template.mesh().triangles;
    let n = rest.len();
    let vertex_of: Vec<usize> = CAESAR_LANDMARKS
        .iter()
        .map(|l| template.landmark_vertex(l.name).map_or(0, |v| v as usize))
        .collect();
    let points = |flat: &[f32]| -> Vec<Point3<f64>> {
        flat.chunks_exact(3)
            .map(|p| Point3::new(p[0] as f64, p[1] as f64, p[2] as f64))
            .collect()
    };
    let [rt, lt] = acromion_indices();
    let mut sums = [[0.0f64; 3]; 2];
    let (mut count, mut between_abs, mut found_abs) = (0, 0.0, 0.0);
    for id in 1.. {
        let truth_path = dir.join(format!("truth_{id:03}.ply"));
        let fit_path = cache.join(format!("{kind}_{id:03}.ply"));
        if !truth_path.exists() || !fit_path.exists() {
            break;
        }
        let truth = read_fit(&truth_path)?.positions;
        let fit = read_fit(&fit_path)?.positions;
        let truth = upright(&truth[..n], rest).ok_or("degenerate truth")?;
        let fit = upright(&fit[..n], rest).ok_or("degenerate fit")?;
        let breadth = |flat: &[f32]| -> Result<f64, String> {
            let m = measurer
                .measure_some(flat, &[Measure::ShoulderBreadth])
                .map_err(|e| e.to_string())?;
            Ok(m.get(Measure::ShoulderBreadth).unwrap_or(f64::NAN) * 1e3)
        };
        let found = breadth(&fit)? - breadth(&truth)?;
        let acromia = |flat: &[f32]| measurer.acromia(flat).map_err(|e| e.to_string());
        let (truth_acromia, fit_acromia) = (acromia(&truth)?, acromia(&fit)?);
        let (truth, fit) = (points(&truth), points(&fit));
        let frames = ShoulderFrame::both(&|k| truth[vertex_of[k]]).ok_or("no frame")?;
        let mut line = format!("{kind} {id:03}:");
        let mut detail = String::new();
        for (side, k) in [rt, lt].into_iter().enumerate() {
            let f = &frames[side];
            let d = fit[vertex_of[k]] - truth[vertex_of[k]];
            let c = [d.dot(&f.lateral), d.dot(&f.up), d.dot(&f.forward)].map(|x| x * 1e3);
            for (s, x) in sums[side].iter_mut().zip(c) {
                *s += x;
            }
            let abduction = f.arm.dot(&f.lateral).atan2(-f.arm.dot(&f.up)).to_degrees();
            line += &format!(
                "  {} lat {:+5.1} up {:+5.1} fwd {:+5.1} (arm out {abduction:2.0}°)",
                ["Rt", "Lt"][side],
                c[0],
                c[1],
                c[2],
            );
            // Each body's shoulder point against its own Acromion vertex (lateral, up; mm) and
            // the surface's drops beside it (towards the neck, towards the arm; mm).
            for (who, a) in [("truth", &truth_acromia[side]), ("fit", &fit_acromia[side])] {
                let v = Point3::from(a.vertex);
                let shift = a.shoulder_point.map_or("none".to_string(), |s| {
                    let d = Point3::from(s) - v;
                    format!(
                        "{:+5.1} {:+5.1}",
                        d.dot(&f.lateral) * 1e3,
                        d.dot(&f.up) * 1e3
                    )
                });
                let drops = a.rises.map_or("none".to_string(), |[m, l]| {
                    format!("{:+5.1} {:+5.1}", m * 1e3, l * 1e3)
                });
                let moved = (Point3::from(a.point) - v).norm() * 1e3;
                let body = if who == "truth" { &truth } else { &fit };
                let profile = a.shoulder_point.map_or(String::new(), |sp| {
                    let sp = Point3::from(sp);
                    let Some(frames) = ShoulderFrame::both(&|k| body[vertex_of[k]]) else {
                        return String::new();
                    };
                    let frame = &frames[side];
                    let Some((dl, du)) = frame.direction(90.0) else {
                        return String::new();
                    };
                    let near = surface_near(body, triangles, &sp, 0.06, 0.003);
                    let d = frame.vector([dl, du, 0.0]);
                    let medial = frame.vector([-du, dl, 0.0]);
                    [0.02, 0.03, 0.04]
                        .map(|r| {
                            turn_rises(&near, &sp, &d, &medial, &frame.forward, (r, 0.003))
                                .map_or(" -".into(), |[m, l]| {
                                    format!(" {:.0}:{:+.1}/{:+.1}", r * 1e3, m * 1e3, l * 1e3)
                                })
                        })
                        .concat()
                });
                detail += &format!(
                    "\n    {} {who}: shoulder point − vertex {shift}, rises {drops}, {} (moved {moved:.1}); profile{profile}",
                    ["Rt", "Lt"][side],
                    if a.on_surface { "on the turn" } else { "vertex" },
                );
            }
        }
        let vertices = |b: &[Point3<f64>]| (b[vertex_of[rt]] - b[vertex_of[lt]]).norm() * 1e3;
        let between = vertices(&fit) - vertices(&truth);
        println!(
            "{line}  breadth fit − truth: vertices {between:+5.1}, acromia {found:+5.1} mm{detail}"
        );
        count += 1;
        between_abs += between.abs();
        found_abs += found.abs();
    }
    let count = count.max(1) as f64;
    for (side, s) in sums.iter().enumerate() {
        let m = s.map(|x| x / count);
        println!(
            "{} vertex mean: lat {:+.1} up {:+.1} fwd {:+.1} mm",
            ["Rt", "Lt"][side],
            m[0],
            m[1],
            m[2]
        );
    }
    println!(
        "breadth MAE: vertices {:.1} mm, acromia {:.1} mm",
        between_abs / count,
        found_abs / count
    );
    Ok(())
}

#[cfg(target_arch = "wasm32")]
fn main() {}
