//! Where the correspondence error of an alignment is, and what kind it is (issue 12): a diagnosis
//! on synthetic subjects with ground truth (`bodyspace synth`), never a tuning loop.
//!
//! `cargo run --release --example correspondence_diagnosis -- DIR [--n N] [--preset paper|anchored]
//!  [--fine 0|1]`
//!
//! DIR as for `align_accuracy` (`scan_XXX.ply`, `landmarks_XXX.lnd`, `truth_XXX.ply`). Aligns
//! each subject at `base` with the preset, then prints:
//!
//! 1. **The worst 1 % of vertices** per subject: how many fall in each body part and region flag
//!    (`unseen`, `ear`, `hand`, `sole`, none), the template landmark nearest to them, how far the
//!    true vertex lies from the scan (> 5 mm: a part the scanner never saw), and the split of
//!    their error into the normal and the tangential component (by the truth's vertex normal).
//! 2. With `--fine 1`, the same subjects at `fine` (coarse to fine), compared on the base
//!    vertices: mean per body part and flag at each resolution, and where the vertices that got
//!    worse by more than 2 mm are.
//! 3. **Common and subject-specific error**: the split of `align::correspondence_split` (the
//!    part common to all subjects, each subject's own, and both leave one out), per body part
//!    and over all vertices (`support/split_table.rs`).

#[cfg(not(target_arch = "wasm32"))]
#[path = "support/subject_files.rs"]
mod subject_files;

#[cfg(not(target_arch = "wasm32"))]
#[path = "support/split_table.rs"]
mod split_table;

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use super::split_table::print_split;
    use super::subject_files::{read_subject, SubjectFiles};
    use bodyspace::align::{
        align_scan, correspondence_split, AlignInput, CorrespondenceMode, FitAndTruth, MatchQuery,
        Preset, SurfaceIndex,
    };
    use bodyspace::mesh::normals::vertex_normals;
    use bodyspace::mesh::Mesh;
    use bodyspace::template::{body_parts, BodyPart, RegionFlags, Resolution, Template};
    use nalgebra::Point3;
    use std::collections::BTreeMap;
    use std::path::{Path, PathBuf};

    /// One subject at one resolution: fitted and true base vertices (metres, scan frame), and
    /// the truth's distance to the scan per base vertex (mm).
    struct Fit {
        fitted: Vec<Point3<f64>>,
        truth: Vec<Point3<f64>>,
        truth_to_scan_mm: Vec<f64>,
    }

    fn fit(
        dir: &Path,
        id: usize,
        template: &Template,
        base: &Template,
        preset: Preset,
    ) -> Result<Fit, String> {
        let SubjectFiles {
            scan,
            truth,
            landmarks,
        } = read_subject(dir, id)?;
        let input = AlignInput {
            template,
            base_template: Some(base),
            scan: &scan,
            landmarks: &landmarks,
            units: None,
        };
        let alignment = align_scan(&input, &preset.params(), &mut ()).map_err(|e| e.to_string())?;
        let to_m = alignment.scale_to_metres;
        let truth: Vec<Point3<f64>> = truth.positions.iter().map(|p| p * to_m).collect();
        let scan_m = Mesh::new(
            scan.positions.iter().map(|p| p * to_m).collect(),
            scan.triangles.clone(),
        );
        let index = SurfaceIndex::new(&scan_m).map_err(|e| e.to_string())?;
        let query = MatchQuery {
            mode: CorrespondenceMode::ClosestOnTriangle,
            min_cos: None,
            candidates: 1,
        };
        let truth_to_scan_mm = truth
            .iter()
            .map(|p| {
                index
                    .closest(p, None, &query)
                    .map_or(f64::INFINITY, |m| (m.point - p).norm() * 1e3)
            })
            .collect();
        let n = truth.len();
        Ok(Fit {
            fitted: alignment.positions[..n].to_vec(),
            truth,
            truth_to_scan_mm,
        })
    }

    /// The flag class of a vertex, for counting.
    fn flag_name(flags: RegionFlags) -> &'static str {
        if flags.unseen() {
            "unseen"
        } else if flags.ear() {
            "ear"
        } else if flags.hand() {
            "hand"
        } else if flags.sole() {
            "sole"
        } else {
            "none"
        }
    }

    /// Counts of `items`, largest first, as "name n, name n, …".
    fn counts<'a>(items: impl Iterator<Item = &'a str>, top: usize) -> String {
        let mut map: BTreeMap<&str, usize> = BTreeMap::new();
        for i in items {
            *map.entry(i).or_default() += 1;
        }
        let mut v: Vec<_> = map.into_iter().collect();
        v.sort_by_key(|e| std::cmp::Reverse(e.1));
        v.iter()
            .take(top)
            .map(|(n, c)| format!("{n} {c}"))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// What the worst 1 % of the vertices of `fit` are (section 1).
    fn worst_vertices(id: usize, fit: &Fit, template: &Template, parts: &[BodyPart]) {
        let n = fit.truth.len();
        let errors: Vec<f64> = (0..n)
            .map(|i| (fit.fitted[i] - fit.truth[i]).norm() * 1e3)
            .collect();
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|a, b| errors[*b].total_cmp(&errors[*a]));
        let worst = &order[..n.div_ceil(100)];
        let normals = vertex_normals(&fit.truth, &template.mesh().triangles);
        let rest = &template.mesh().positions;
        let landmarks = template.landmark_vertices();
        let nearest_landmark = |i: usize| {
            landmarks
                .iter()
                .min_by(|a, b| {
                    let da = (rest[a.1 as usize] - rest[i]).norm();
                    let db = (rest[b.1 as usize] - rest[i]).norm();
                    da.total_cmp(&db)
                })
                .map_or("-", |(name, _)| name.as_str())
        };
        let unscanned = worst
            .iter()
            .filter(|i| fit.truth_to_scan_mm[**i] > 5.0)
            .count();
        let (mut normal_sq, mut tangential_sq) = (0.0, 0.0);
        for &i in worst {
            let e = (fit.fitted[i] - fit.truth[i]) * 1e3;
            let en = e.dot(&normals[i]);
            normal_sq += en * en;
            tangential_sq += e.norm_squared() - en * en;
        }
        let k = worst.len() as f64;
        println!(
            "{id:03}: worst 1 % ({} vertices, {:.1}–{:.1} mm): normal / tangential RMS {:.1} / {:.1} mm; truth > 5 mm from the scan: {unscanned}",
            worst.len(),
            errors[*worst.last().unwrap()],
            errors[worst[0]],
            (normal_sq / k).sqrt(),
            (tangential_sq / k).sqrt(),
        );
        println!(
            "     parts: {}",
            counts(worst.iter().map(|i| parts[*i].name()), 6)
        );
        println!(
            "     flags: {}",
            counts(
                worst.iter().map(|i| flag_name(template.flags(*i as u32))),
                5
            )
        );
        println!(
            "     nearest landmark: {}",
            counts(worst.iter().map(|i| nearest_landmark(*i)), 6)
        );
    }

    /// Mean error (mm) per body part and flag class of base vertices (section 2).
    fn by_group(fits: &[Fit], template: &Template, parts: &[BodyPart]) -> BTreeMap<String, f64> {
        let mut sums: BTreeMap<String, (f64, usize)> = BTreeMap::new();
        for fit in fits {
            for (i, part) in parts.iter().enumerate() {
                let e = (fit.fitted[i] - fit.truth[i]).norm() * 1e3;
                let flag = flag_name(template.flags(i as u32));
                for key in [part.name().to_string(), format!("flag {flag}")] {
                    let s = sums.entry(key).or_default();
                    s.0 += e;
                    s.1 += 1;
                }
            }
        }
        sums.into_iter()
            .map(|(k, (s, c))| (k, s / c as f64))
            .collect()
    }

    /// Section 3: the common and the subject-specific part of the error, per body part.
    fn common_and_specific(fits: &[Fit], template: &Template, parts: &[BodyPart]) {
        let subjects: Vec<FitAndTruth> = fits
            .iter()
            .map(|f| FitAndTruth {
                fitted: &f.fitted,
                truth: &f.truth,
            })
            .collect();
        match correspondence_split(&subjects, &template.mesh().positions, parts) {
            Ok(split) => print_split(&split),
            Err(e) => println!("no split: {e}"),
        }
    }

    pub fn main() {
        let mut args = std::env::args().skip(1);
        let Some(dir) = args.next().map(PathBuf::from) else {
            eprintln!("usage: correspondence_diagnosis DIR [--n N] [--preset P] [--fine 0|1]");
            std::process::exit(2);
        };
        let (mut n, mut preset, mut with_fine) = (10usize, Preset::Paper, false);
        while let (Some(flag), Some(value)) = (args.next(), args.next()) {
            match flag.as_str() {
                "--n" => n = value.parse().expect("--n N"),
                "--preset" => preset = Preset::from_name(&value).expect("--preset paper|anchored"),
                "--fine" => with_fine = value != "0",
                _ => {
                    eprintln!("unknown option {flag}");
                    std::process::exit(2);
                }
            }
        }
        let fine = Template::embedded().expect("embedded template");
        let base = fine.at_resolution(Resolution::Base);
        let parts = body_parts(&base);
        println!("preset {}; {}", preset.name(), dir.display());
        let fits: Vec<Fit> = (1..=n)
            .map(|id| fit(&dir, id, &base, &base, preset).unwrap_or_else(|e| panic!("{id}: {e}")))
            .collect();
        println!("\n1. The worst 1 % of the vertices (base)");
        for (k, f) in fits.iter().enumerate() {
            worst_vertices(k + 1, f, &base, &parts);
        }
        if with_fine {
            let fine = fine.at_resolution(Resolution::Fine);
            let fine_fits: Vec<Fit> = (1..=n)
                .map(|id| {
                    fit(&dir, id, &fine, &base, preset).unwrap_or_else(|e| panic!("{id}: {e}"))
                })
                .collect();
            println!("\n2. base vs fine on the base vertices: mean (mm)");
            let (b, f) = (
                by_group(&fits, &base, &parts),
                by_group(&fine_fits, &base, &parts),
            );
            for (k, v) in &b {
                println!("{k:<12} {v:>6.2} {:>6.2}", f[k]);
            }
            let worse: Vec<(usize, usize)> = fits
                .iter()
                .zip(&fine_fits)
                .enumerate()
                .flat_map(|(s, (a, c))| {
                    (0..a.truth.len())
                        .filter(move |i| {
                            (c.fitted[*i] - c.truth[*i]).norm()
                                - (a.fitted[*i] - a.truth[*i]).norm()
                                > 2e-3
                        })
                        .map(move |i| (s, i))
                })
                .collect();
            println!("vertices > 2 mm worse at fine: {}", worse.len());
            println!(
                "  parts: {}",
                counts(worse.iter().map(|(_, i)| parts[*i].name()), 6)
            );
            println!(
                "  flags: {}",
                counts(
                    worse.iter().map(|(_, i)| flag_name(base.flags(*i as u32))),
                    5
                )
            );
            for (k, f) in fine_fits.iter().enumerate() {
                worst_vertices(k + 1, f, &base, &parts);
            }
        }
        println!("\n3. Common and subject-specific error (base)");
        common_and_specific(&fits, &base, &parts);
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    native::main();
}

#[cfg(target_arch = "wasm32")]
fn main() {}
