//! Where the back of the neck turns against the Cervicale vertex, on true bodies and their fits
//! (issue 33's diagnosis, docs/measurements.md "The cervicale on the back of the neck").
//!
//! `cargo run --release --example cervicale_diagnosis -- DIR [CACHE] [KIND]`: DIR a `bodyspace
//! synth` output (`truth_XXX.ply`), CACHE the `--fits` folder of `measure_accuracy` on it
//! (`KIND_XXX.ply`, KIND `landmarks` or `free`; default `free`). Per body (template frame, mm):
//! the Cervicale vertex's height over the floor, the back profile's peak and trough heights
//! (`measure/cervicale.rs`), the fraction of the turn the vertex stands at, and the level at each
//! fraction of `FRACTIONS` minus the vertex's; with a fit, its values minus its truth's.

#[cfg(not(target_arch = "wasm32"))]
fn main() -> Result<(), String> {
    use bodyspace::cli::model::read_fit;
    use bodyspace::measure::{upright, BodyMeasurer, MeasureParams};
    use bodyspace::template::Template;
    use std::path::PathBuf;

    const FRACTIONS: [f64; 8] = [0.5, 0.6, 0.7, 0.75, 0.8, 0.85, 0.874, 0.9];
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(dir) = args.first().map(PathBuf::from) else {
        return Err("usage: cervicale_diagnosis DIR [CACHE] [KIND]".into());
    };
    let cache = args.get(1).map(PathBuf::from);
    let kind = args.get(2).map_or("free", String::as_str);
    let template = Template::embedded().map_err(|e| e.to_string())?;
    let measurer = BodyMeasurer::of_template(&template, MeasureParams::default())
        .map_err(|e| e.to_string())?;
    let rest = &template.mesh().positions;
    let cervicale = template
        .landmark_vertex("Cervicale")
        .ok_or("no Cervicale")? as usize;
    // (vertex height, peak, trough, fraction at the vertex, levels) in mm over the floor.
    type Reading = (f64, f64, f64, f64, Vec<f64>);
    let read = |flat: &[f32]| -> Option<Reading> {
        let floor = flat
            .chunks_exact(3)
            .map(|p| p[1] as f64)
            .fold(f64::INFINITY, f64::min);
        let (profile, turn) = measurer.back_of_neck(flat).ok()??;
        let vertex = flat[3 * cervicale + 1] as f64;
        let levels = FRACTIONS
            .iter()
            .map(|&f| {
                profile
                    .level(&turn, f)
                    .map_or(f64::NAN, |h| (h - vertex) * 1e3)
            })
            .collect();
        Some((
            (vertex - floor) * 1e3,
            (turn.peak.0 - vertex) * 1e3,
            (turn.trough.0 - vertex) * 1e3,
            profile.fraction_at(&turn, vertex).unwrap_or(f64::NAN),
            levels,
        ))
    };
    let stood = |path: &PathBuf| -> Result<Vec<f32>, String> {
        let mesh = read_fit(path)?;
        upright(&mesh.positions[..rest.len()], rest).ok_or("not upright".into())
    };
    println!("body: vertex height, peak − vertex, trough − vertex (mm), fraction at the vertex, level(f) − vertex for f in {FRACTIONS:?}");
    let show = |name: &str, r: &Reading| {
        let levels: Vec<String> = r.4.iter().map(|x| format!("{x:+6.1}")).collect();
        println!(
            "{name:>10}: {:7.1} {:+6.1} {:+6.1}  f {:.3}  {}",
            r.0,
            r.1,
            r.2,
            r.3,
            levels.join(" ")
        );
    };
    let flat_rest: Vec<f32> = template.mesh().flat_positions_f32();
    if let Some(r) = read(&flat_rest) {
        show("template", &r);
    }
    // The body at `path` read, stood on the template and shown as `name`; `None` when it has no
    // back profile.
    let body = |path: &PathBuf, name: String| -> Result<Option<Reading>, String> {
        let r = read(&stood(path)?);
        match &r {
            Some(r) => show(&name, r),
            None => println!("{name}: no profile"),
        }
        Ok(r)
    };
    for id in 1.. {
        let truth_path = dir.join(format!("truth_{id:03}.ply"));
        if !truth_path.exists() {
            break;
        }
        let Some(t) = body(&truth_path, format!("truth {id:03}"))? else {
            continue;
        };
        let Some(cache) = &cache else { continue };
        let fit_path = cache.join(format!("{kind}_{id:03}.ply"));
        if !fit_path.exists() {
            continue;
        }
        let Some(f) = body(&fit_path, format!("fit {id:03}"))? else {
            continue;
        };
        // The fit's level at each fraction minus the truth's, over the floor (what cervicale
        // height's difference would be), and the vertex's own difference.
        let diffs: Vec<String> =
            f.4.iter()
                .zip(&t.4)
                .map(|(a, b)| format!("{:+6.1}", (f.0 + a) - (t.0 + b)))
                .collect();
        println!(
            "      diff: vertex {:+6.1}  levels {}",
            f.0 - t.0,
            diffs.join(" ")
        );
    }
    Ok(())
}

#[cfg(target_arch = "wasm32")]
fn main() {}
