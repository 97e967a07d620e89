//! Scan parsing benchmark: a deterministic 300,000-triangle binary PLY (a wavy grid) is built in
//! memory, parsed N times with `read_scan`, and the median time is printed.
//!
//! `cargo run --release --example parse_bench [N]`

use std::time::Instant;

use bodyspace::io::{read_scan, write_obj, write_ply};
use bodyspace::mesh::Mesh;
use nalgebra::Point3;

/// A `(n+1)²`-vertex grid of `2n²` triangles with a smooth height field.
fn grid(n: u32) -> Mesh {
    let mut positions = Vec::with_capacity(((n + 1) * (n + 1)) as usize);
    for j in 0..=n {
        for i in 0..=n {
            let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
            positions.push(Point3::new(u, v, 0.05 * (7.0 * u).sin() * (5.0 * v).cos()));
        }
    }
    let mut triangles = Vec::with_capacity((2 * n * n) as usize);
    for j in 0..n {
        for i in 0..n {
            let a = j * (n + 1) + i;
            let (b, c, d) = (a + 1, a + n + 1, a + n + 2);
            triangles.push([a, b, d]);
            triangles.push([a, d, c]);
        }
    }
    Mesh::new(positions, triangles)
}

fn median_ms(runs: usize, bytes: &[u8], name: &str, triangles: usize) -> f64 {
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            let mesh = read_scan(bytes, name).expect("the generated file parses");
            let ms = start.elapsed().as_secs_f64() * 1e3;
            assert_eq!(mesh.triangles.len(), triangles);
            ms
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn main() {
    let runs: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(21);
    let mesh = grid(388); // 2·388² = 301,088 triangles
    let ply = write_ply(&mesh);
    println!(
        "binary PLY: {} vertices, {} triangles, {:.1} MB; median of {runs}: {:.2} ms",
        mesh.positions.len(),
        mesh.triangles.len(),
        ply.len() as f64 / 1e6,
        median_ms(runs, &ply, "bench.ply", mesh.triangles.len())
    );
    let obj = write_obj(&mesh);
    println!(
        "OBJ: {:.1} MB; median of {runs}: {:.2} ms",
        obj.len() as f64 / 1e6,
        median_ms(runs.min(5), &obj, "bench.obj", mesh.triangles.len())
    );
}
