//! Enclosed volume and surface area of a closed triangle mesh.

use nalgebra::{Point3, Vector3};

/// Signed volume `V = Σ a · (b × c) / 6` and area `A = Σ ‖(b − a) × (c − a)‖ / 2` over
/// `triangles` (`#F` index triples), `point(i)` giving vertex `i`. `V` is the enclosed volume,
/// positive when a closed surface is oriented with outward normals (divergence theorem); on an
/// open surface it depends on the origin.
pub fn volume_and_area(triangles: &[[u32; 3]], point: impl Fn(u32) -> Vector3<f64>) -> (f64, f64) {
    let mut volume = 0.0;
    let mut area = 0.0;
    for &[i, j, k] in triangles {
        // Not `t.map(&point)`: an array's `map` is not always inlined, and this runs per triangle.
        let (a, b, c) = (point(i), point(j), point(k));
        volume += a.dot(&b.cross(&c));
        area += (b - a).cross(&(c - a)).norm();
    }
    (volume / 6.0, area / 2.0)
}

/// Signed volume of `triangles` over `#V` points ([`volume_and_area`]).
pub fn signed_volume(positions: &[Point3<f64>], triangles: &[[u32; 3]]) -> f64 {
    volume_and_area(triangles, |i| positions[i as usize].coords).0
}

/// [`volume_and_area`] of flat `#V·3` f32 positions (xyz interleaved).
pub fn volume_and_area_flat(positions: &[f32], triangles: &[[u32; 3]]) -> (f64, f64) {
    volume_and_area(triangles, |i| {
        let p = &positions[3 * i as usize..3 * i as usize + 3];
        Vector3::new(p[0] as f64, p[1] as f64, p[2] as f64)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_tetrahedron() {
        let p = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.0, 0.0, 1.0),
        ];
        let t = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        assert!((signed_volume(&p, &t) - 1.0 / 6.0).abs() < 1e-12);
        let (_, area) = volume_and_area(&t, |i| p[i as usize].coords);
        assert!((area - (1.5 + 3f64.sqrt() / 2.0)).abs() < 1e-12);
    }
}
