//! The facing cues (`estimate::facing`) on `bodyspace synth` directories, whose files stand z up
//! facing −y: per subject the feet's reach forward of the lower legs and the thighs' of the
//! calves, each as a percentage of the body's extent along the true forward (negative: the cue
//! points backwards), and which cue decides with the default parameters and whether it is right.
//! The figures behind `EstimateParams::legs_forward_decisive` (docs/landmarks-estimate.md, "The
//! legs say which way is forward when the feet are cut").
//!
//! `cargo run --release --example facing_cues -- DIR [DIR…]`

use bodyspace::estimate::facing::{body_forward, cue_says, FacingCue, Forward};
use bodyspace::estimate::up::head_end;
use bodyspace::estimate::EstimateParams;
use bodyspace::io::scan::read_scan;
use nalgebra::Vector3;

fn main() {
    let params = EstimateParams::default();
    let forward = -Vector3::<f64>::y();
    for dir in std::env::args().skip(1) {
        let table = std::fs::read_to_string(format!("{dir}/subjects.csv")).expect("subjects.csv");
        let mut lines = table.lines();
        let header: Vec<&str> = lines.next().expect("a header").split(',').collect();
        let class = header.iter().position(|h| *h == "scanner_class");
        for line in lines {
            let fields: Vec<&str> = line.split(',').collect();
            let id = fields[0];
            let path = format!("{dir}/scan_{id}.ply");
            let bytes = std::fs::read(&path).expect("a scan");
            let scan = read_scan(&bytes, &path).expect("a readable scan");
            let (p, t) = (&scan.positions, &scan.triangles);
            let Some(end) = head_end(p, t, params.head_end_decisive) else {
                println!("{dir} {id}: the shape does not say which end is the head");
                continue;
            };
            // A cue's share of the extent, signed along the true forward, in per cent.
            let share = |f: Option<Forward>| {
                f.map_or(f64::NAN, |f| {
                    100.0 * f.share * f.forward.dot(&forward).signum()
                })
            };
            let feet = share(cue_says(FacingCue::Feet, p, t, &end.up, &forward));
            let legs = share(cue_says(FacingCue::Legs, p, t, &end.up, &forward));
            let decided = body_forward(
                p,
                t,
                &end.up,
                &forward,
                params.feet_forward_decisive,
                params.legs_forward_decisive,
            )
            .map_or("neither says".to_string(), |f| {
                let right = if f.forward.dot(&forward) > 0.0 {
                    "right"
                } else {
                    "WRONG"
                };
                format!("{:?} say, {right}", f.cue)
            });
            println!(
                "{dir} {id} {:15} feet {feet:5.2} % legs {legs:5.2} %: {decided}",
                class.map_or("", |k| fields[k])
            );
        }
    }
}
