//! Correspondence as the shape model sees it (issue 33): the common / own split
//! ([`correspondence_split`]) of fits written to files — ours (`align_accuracy --export DIR`
//! writes `fitted_XXX.ply`) or the peer's (`bench/peer/nricp.py` writes `peer_XXX.ply`) — so
//! both methods are split by the same code.
//!
//! `cargo run --release --example correspondence_split -- DATA_DIR FITS_DIR [--n N]
//!  [--prefix fitted|peer]`
//!
//! DATA_DIR holds `truth_XXX.ply` (`bodyspace synth`); FITS_DIR `PREFIX_XXX.ply`, the template's
//! base vertices in template order. Each file's units are detected from its extent
//! (`detect_units`), so fits in metres and truths in millimetres compare. Prints the split per
//! body part and over all vertices (`support/split_table.rs`).

#[cfg(not(target_arch = "wasm32"))]
#[path = "support/split_table.rs"]
mod split_table;

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use super::split_table::print_split;
    use bodyspace::align::{correspondence_split, FitAndTruth};
    use bodyspace::io::read_scan;
    use bodyspace::mesh::bounds::bounding_extent;
    use bodyspace::mesh::units::detect_units;
    use bodyspace::template::{body_parts, Resolution, Template};
    use nalgebra::Point3;
    use std::path::{Path, PathBuf};

    /// The vertices of the PLY at `path`, in metres.
    fn read_metres(path: &Path) -> Result<Vec<Point3<f64>>, String> {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| format!("{name}: {e}"))?;
        let mesh = read_scan(&bytes, &name).map_err(|e| format!("{name}: {e}"))?;
        let to_m = detect_units(bounding_extent(&mesh.positions)).scale_to_metres();
        Ok(mesh.positions.iter().map(|p| p * to_m).collect())
    }

    pub fn main() {
        let mut args = std::env::args().skip(1);
        let (Some(data), Some(fits)) = (args.next(), args.next()) else {
            eprintln!("usage: correspondence_split DATA_DIR FITS_DIR [--n N] [--prefix P]");
            std::process::exit(2);
        };
        let (data, fits) = (PathBuf::from(data), PathBuf::from(fits));
        let (mut n, mut prefix) = (8usize, "fitted".to_string());
        while let (Some(flag), Some(value)) = (args.next(), args.next()) {
            match flag.as_str() {
                "--n" => n = value.parse().expect("--n N"),
                "--prefix" => prefix = value,
                _ => {
                    eprintln!("unknown option {flag}");
                    std::process::exit(2);
                }
            }
        }
        let base = Template::embedded()
            .expect("embedded template")
            .at_resolution(Resolution::Base);
        let pairs: Vec<_> = (1..=n)
            .map(|id| {
                let fitted = read_metres(&fits.join(format!("{prefix}_{id:03}.ply")));
                let truth = read_metres(&data.join(format!("truth_{id:03}.ply")));
                match (fitted, truth) {
                    (Ok(f), Ok(t)) => (f, t),
                    (Err(e), _) | (_, Err(e)) => panic!("{id}: {e}"),
                }
            })
            .collect();
        let subjects: Vec<FitAndTruth> = pairs
            .iter()
            .map(|(fitted, truth)| FitAndTruth { fitted, truth })
            .collect();
        let split = correspondence_split(&subjects, &base.mesh().positions, &body_parts(&base))
            .unwrap_or_else(|e| panic!("{e}"));
        println!(
            "{prefix} in {}; truth in {}",
            fits.display(),
            data.display()
        );
        print_split(&split);
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    native::main();
}

#[cfg(target_arch = "wasm32")]
fn main() {}
