//! Scan parsing benchmark: a deterministic 300,000-triangle binary PLY (a wavy grid) is built in
//! memory, parsed N times with `read_scan`, and the median time is printed; likewise the same mesh
//! as OBJ, and the mesh analysis (`summarise`, of which `winding`, and `vertex_normals`) on it.
//!
//! `cargo run --release --example parse_bench [N]`

use std::time::Instant;

use bodyspace::io::{read_scan, write_obj, write_ply};
use bodyspace::mesh::winding::{winding, WindingParams};
use bodyspace::mesh::{summarise, Mesh};
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

fn median_of(runs: usize, mut work: impl FnMut()) -> f64 {
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            work();
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn median_ms(runs: usize, bytes: &[u8], name: &str, triangles: usize) -> f64 {
    median_of(runs, || {
        let mesh = read_scan(bytes, name).expect("the generated file parses");
        assert_eq!(mesh.triangles.len(), triangles);
    })
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
        median_ms(runs, &obj, "bench.obj", mesh.triangles.len())
    );
    let summary_ms = median_of(runs, || {
        let s = summarise(&mesh);
        assert_eq!((s.components, s.boundary_loops), (1, 1));
    });
    let winding_ms = median_of(runs, || {
        winding(&mesh, &WindingParams::default());
    });
    let normals_ms = median_of(runs, || {
        assert_eq!(mesh.vertex_normals().len(), mesh.positions.len());
    });
    println!("summarise: {summary_ms:.2} ms (of which winding {winding_ms:.2} ms); vertex_normals: {normals_ms:.2} ms");
}
