//! Times what the worker's `parseScan` does, natively: read the scan, vertex normals, summary.
//! Usage: parse-native SCAN.ply [RUNS]; prints a Markdown table of medians in milliseconds.

use std::time::Instant;

use bodyspace::io::read_scan;
use bodyspace::mesh::summary::summarise;

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    let m = xs.len() / 2;
    if xs.len() % 2 == 1 {
        xs[m]
    } else {
        (xs[m - 1] + xs[m]) / 2.0
    }
}

fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let path = args.next().ok_or("usage: parse-native SCAN.ply [RUNS]")?;
    let runs: usize = args
        .next()
        .map_or(Ok(7), |r| r.parse())
        .map_err(|e| format!("RUNS: {e}"))?;
    let bytes = std::fs::read(&path).map_err(|e| format!("{path}: {e}"))?;
    let name = std::path::Path::new(&path)
        .file_name()
        .map_or_else(|| path.clone(), |n| n.to_string_lossy().into_owned());

    let (mut read, mut normals, mut summary, mut total) = (vec![], vec![], vec![], vec![]);
    let mut triangles = 0;
    for _ in 0..runs {
        let t0 = Instant::now();
        let mesh = read_scan(&bytes, &name).map_err(|e| e.to_string())?;
        let t1 = Instant::now();
        let n = mesh.vertex_normals();
        let t2 = Instant::now();
        let s = summarise(&mesh);
        let t3 = Instant::now();
        std::hint::black_box((&n, &s));
        triangles = mesh.triangle_count();
        let ms = |a: Instant, b: Instant| (b - a).as_secs_f64() * 1e3;
        read.push(ms(t0, t1));
        normals.push(ms(t1, t2));
        summary.push(ms(t2, t3));
        total.push(ms(t0, t3));
    }
    println!("native, {triangles} triangles, {runs} runs, medians (ms)");
    println!("| {:<48} | {:>8} |", "native (release)", "median");
    println!("|{}|{}|", "-".repeat(50), "-".repeat(10));
    for (label, xs) in [
        ("read_scan", read),
        ("vertex_normals", normals),
        ("summarise (bbox, units, holes, parts)", summary),
        ("total", total),
    ] {
        println!("| {:<48} | {:>8.1} |", label, median(xs));
    }
    Ok(())
}
