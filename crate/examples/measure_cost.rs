//! What measuring a fit costs natively, per measurement, and every value it gives, so that a
//! change meant to make it cheaper can be checked to change no value (docs/measurements.md,
//! "Accuracy against ISO 20685-1": its cost paragraphs). Prints figures; asserts nothing.
//!
//!   cargo run --release --example measure_cost -- FITS_DIR [--repeat R] [--values OUT]
//!   [--measure-only]
//!
//! FITS_DIR holds fits in the template's vertex order (`*.ply`, e.g. `measure_accuracy --fits`'s
//! cache: template frame, metres); each is moved rigidly onto the base template (`upright`) and,
//! with the template itself at rest, measured R times (default 20). Prints the median over the
//! bodies of each body's median time: every measurement (`BodyMeasurer::measure`), each one
//! alone (`measure_some`, which pays for what it shares with others: the acromia, the crotch,
//! the hip level, volume and area), the acromia, the tapes' paths, and the subject report's
//! trust (`fit_measurements_trust`, every landmark estimated, every vertex on the scan).
//! `--measure-only` times `measure` alone (for a profiler's samples).
//! `--values OUT` writes every value (measurements, tapes' corners, acromia, the trust's JSON) to
//! OUT, one per line at full precision, for a diff against another build's.

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use bodyspace::cli::model::read_fit;
    use bodyspace::landmarks::CAESAR_LANDMARKS;
    use bodyspace::measure::{upright, BodyMeasurer, Measure, MeasureParams, Origin, TrustParams};
    use bodyspace::subject::fit_measurements_trust;
    use bodyspace::template::{Resolution, Template};
    use nalgebra::Point3;
    use std::fmt::Write;
    use std::time::Instant;

    fn median(mut v: Vec<f64>) -> f64 {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    }

    /// The median over `repeat` runs of `f`, in ms.
    fn time(repeat: usize, mut f: impl FnMut()) -> f64 {
        median(
            (0..repeat)
                .map(|_| {
                    let t = Instant::now();
                    f();
                    t.elapsed().as_secs_f64() * 1e3
                })
                .collect(),
        )
    }

    pub fn main() {
        let args: Vec<String> = std::env::args().skip(1).collect();
        let dir = args
            .first()
            .expect("usage: measure_cost FITS_DIR [--repeat R] [--values OUT]");
        let option = |name: &str| {
            args.iter()
                .position(|a| a == name)
                .and_then(|i| args.get(i + 1))
        };
        let repeat: usize = option("--repeat").map_or(20, |r| r.parse().expect("R is a number"));
        let template = Template::embedded()
            .expect("embedded template")
            .at_resolution(Resolution::Base);
        let rest = &template.mesh().positions;
        let n = rest.len();
        let measurer = BodyMeasurer::of_template(&template, MeasureParams::default()).unwrap();

        let mut files: Vec<_> = std::fs::read_dir(dir)
            .expect("FITS_DIR")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "ply"))
            .collect();
        files.sort();
        let mut bodies: Vec<(String, Vec<Point3<f64>>)> = vec![("template".into(), rest.clone())];
        for f in &files {
            let mesh = read_fit(f).expect("a fit");
            assert!(
                mesh.positions.len() >= n,
                "{}: too few vertices",
                f.display()
            );
            let name = f.file_stem().unwrap().to_string_lossy().into_owned();
            bodies.push((name, mesh.positions[..n].to_vec()));
        }

        let origins = vec![Origin::Estimated; CAESAR_LANDMARKS.len()];
        let distances = vec![0.0; n];
        let trust_params = TrustParams::default();
        let mut values = String::new();
        let (mut all, mut acromia, mut paths, mut trust) = (vec![], vec![], vec![], vec![]);
        let mut each: Vec<Vec<f64>> = vec![vec![]; Measure::ALL.len()];
        for (name, positions) in &bodies {
            let stood = upright(positions, rest).expect("upright");
            let m = measurer.measure(&stood).unwrap();
            for r in m.readings() {
                writeln!(values, "{name} {} {:?}", r.name, r.value).unwrap();
            }
            for a in measurer.acromia(&stood).unwrap() {
                writeln!(values, "{name} acromion {a:?}").unwrap();
            }
            for p in measurer.tape_paths(&stood).unwrap() {
                let m = p.measure.definition().name;
                writeln!(values, "{name} tape {m} {:?}", p.points).unwrap();
            }
            let t =
                fit_measurements_trust(&template, positions, &distances, &origins, &trust_params);
            writeln!(
                values,
                "{name} trust {}",
                serde_json::to_string(&t).unwrap()
            )
            .unwrap();

            all.push(time(repeat, || {
                measurer.measure(&stood).unwrap();
            }));
            if args.iter().any(|a| a == "--measure-only") {
                continue;
            }
            for (k, m) in Measure::ALL.into_iter().enumerate() {
                each[k].push(time(repeat, || {
                    measurer.measure_some(&stood, &[m]).unwrap();
                }));
            }
            acromia.push(time(repeat, || {
                measurer.acromia(&stood).unwrap();
            }));
            paths.push(time(repeat, || {
                measurer.tape_paths(&stood).unwrap();
            }));
            trust.push(time(repeat, || {
                fit_measurements_trust(&template, positions, &distances, &origins, &trust_params);
            }));
        }
        println!(
            "{} bodies (the template and {} fits of {dir}), {repeat} runs each; the median over the \
             bodies of each body's median (ms)",
            bodies.len(),
            files.len()
        );
        println!("| what | ms |\n| --- | ---: |");
        println!("| every measurement (`measure`) | {:.3} |", median(all));
        if each[0].is_empty() {
            return;
        }
        for (k, m) in Measure::ALL.into_iter().enumerate() {
            let t = median(std::mem::take(&mut each[k]));
            println!("| {} alone | {t:.3} |", m.definition().name);
        }
        println!("| the acromia | {:.3} |", median(acromia));
        println!("| the tapes' paths | {:.3} |", median(paths));
        println!("| the subject report's trust | {:.3} |", median(trust));
        if let Some(out) = option("--values") {
            std::fs::write(out, values).expect("--values OUT");
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    native::main();
}

#[cfg(target_arch = "wasm32")]
fn main() {}
