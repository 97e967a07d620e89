//! Points spread over a mesh's surface: its triangles sampled on barycentric grids, everywhere
//! ([`surface_samples`]) or near a point ([`surface_near`]). A coarse mesh's vertices lie too far
//! apart for a profile's bins or a prominence's cap; its surface does not.

use nalgebra::Point3;

/// Points spread over the triangles of a mesh (`positions`, `triangles`) about `spacing` (m)
/// apart: on each triangle a barycentric grid with as many steps per edge as its longest edge
/// holds `spacing`. A coarse template's vertices lie in rings too far apart for a profile's bins
/// (and more densely where the mesh is finer); its surface does not.
pub fn surface_samples(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    spacing: f64,
) -> Vec<Point3<f64>> {
    let mut out = Vec::new();
    for &[i, j, k] in triangles {
        let [a, b, c] = [
            positions[i as usize],
            positions[j as usize],
            positions[k as usize],
        ];
        let longest = (b - a).norm().max((c - b).norm()).max((a - c).norm());
        let n = ((longest / spacing).ceil() as usize).clamp(1, 64);
        for i in 0..n {
            for j in 0..n - i {
                // Grid cell centres (a third of a step in), so shared edges are not counted twice.
                let u = (i as f64 + 1.0 / 3.0) / n as f64;
                let v = (j as f64 + 1.0 / 3.0) / n as f64;
                out.push(a + (b - a) * u + (c - a) * v);
            }
        }
    }
    out
}

/// Points spread `spacing` apart over the triangles of a mesh (`positions`, `triangles`) that
/// lie within `radius` of `centre` (barycentric grids, as [`surface_samples`]).
pub fn surface_near(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    centre: &Point3<f64>,
    radius: f64,
    spacing: f64,
) -> Vec<Point3<f64>> {
    let r2 = radius * radius;
    let near: Vec<[u32; 3]> = triangles
        .iter()
        .filter(|t| {
            let [a, b, c] = [
                positions[t[0] as usize],
                positions[t[1] as usize],
                positions[t[2] as usize],
            ];
            let longest = (b - a).norm().max((c - b).norm()).max((a - c).norm());
            [a, b, c]
                .iter()
                .any(|p| (p - centre).norm() <= radius + longest)
        })
        .copied()
        .collect();
    surface_samples(positions, &near, spacing)
        .into_iter()
        .filter(|p| (p - centre).norm_squared() <= r2)
        .collect()
}
