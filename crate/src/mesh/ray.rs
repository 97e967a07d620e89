//! Ray–triangle intersection (Möller & Trumbore 1997), shared by the virtual scanner's BVH and
//! the template build's enclosure test.

use nalgebra::{Point3, Vector3};

/// Where the line `o + t·d` crosses triangle `(a, b, c)`: `(t, u, v)` with the hit at
/// `(1 − u − v)·a + u·b + v·c`, or `None` when it misses or when |det| = |(b − a)·(d × (c − a))|
/// is below `min_det` (ray parallel to the plane). `t` may be negative (behind `o`); callers
/// bound it.
pub fn ray_triangle(
    o: &Point3<f64>,
    d: &Vector3<f64>,
    [a, b, c]: [&Point3<f64>; 3],
    min_det: f64,
) -> Option<(f64, f64, f64)> {
    let e1 = b - a;
    let e2 = c - a;
    let p = d.cross(&e2);
    let det = e1.dot(&p);
    if det.abs() < min_det {
        return None;
    }
    let inv_det = 1.0 / det;
    let s = o - a;
    let u = s.dot(&p) * inv_det;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(&e1);
    let v = d.dot(&q) * inv_det;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    Some((e2.dot(&q) * inv_det, u, v))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_inside_misses_outside_and_parallel() {
        let [a, b, c] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]].map(Point3::from);
        let hit = |o: [f64; 3], d: Vector3<f64>| ray_triangle(&o.into(), &d, [&a, &b, &c], 1e-18);
        let (t, u, v) = hit([0.25, 0.5, 2.0], -Vector3::z()).unwrap();
        assert!((t - 2.0).abs() < 1e-15 && (u - 0.25).abs() < 1e-15 && (v - 0.5).abs() < 1e-15);
        assert!(hit([0.8, 0.8, 2.0], -Vector3::z()).is_none());
        assert!(hit([-1.0, 0.1, 0.0], Vector3::x()).is_none());
        assert!((hit([0.1, 0.1, -1.0], -Vector3::z()).unwrap().0 + 1.0).abs() < 1e-15);
    }
}
