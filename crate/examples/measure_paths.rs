//! Writes the tape paths of every girth and the landmark anchors of the template's measurements
//! for docs/tools/render_measurements.py, and prints the template's measurements as JSON.
//!
//! Usage: cargo run --release --example measure_paths -- OUT_DIR

use bodyspace::measure::{BodyMeasurer, MeasureParams};
use bodyspace::template::Template;
use std::fmt::Write;

fn main() {
    let out = std::env::args()
        .nth(1)
        .expect("usage: measure_paths OUT_DIR");
    let template = Template::embedded().expect("embedded template");
    let mesh = template.mesh();
    let positions: Vec<f32> = mesh
        .positions
        .iter()
        .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
        .collect();
    let measurer = BodyMeasurer::new(
        &positions,
        &mesh.triangles,
        template.segment_weight_table(),
        template.landmark_vertices(),
        MeasureParams::default(),
    )
    .expect("measurer");
    let m = measurer.measure(&positions).expect("measurements");
    println!("{}", serde_json::to_string_pretty(&m).unwrap());
    let mut csv = String::from("measure,point,x,y,z\n");
    for path in measurer.tape_paths(&positions).expect("paths") {
        for (i, p) in path.points.iter().enumerate() {
            let name = path.measure.definition().name;
            writeln!(csv, "{name},{i},{},{},{}", p[0], p[1], p[2]).unwrap();
        }
    }
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(format!("{out}/tape_paths.csv"), csv).unwrap();
}
