//! Point-to-surface geometry the scan index needs: the vertex → triangle table (one-rings), the
//! closest point on a triangle and barycentric coordinates.

use nalgebra::Point3;

/// Vertex → incident triangles in compressed rows: triangles of vertex `v` are
/// `indices[offsets[v]..offsets[v + 1]]`.
#[derive(Debug, Clone)]
pub struct OneRings {
    /// `#V + 1` row starts.
    pub offsets: Vec<u32>,
    /// Triangle indices, `3·#F` in total.
    pub indices: Vec<u32>,
}

impl OneRings {
    /// Builds the vertex → triangle table.
    pub fn new(vertex_count: usize, triangles: &[[u32; 3]]) -> Self {
        let mut offsets = vec![0u32; vertex_count + 1];
        for t in triangles {
            for &v in t {
                offsets[v as usize + 1] += 1;
            }
        }
        for v in 0..vertex_count {
            offsets[v + 1] += offsets[v];
        }
        let mut fill = offsets.clone();
        let mut indices = vec![0u32; triangles.len() * 3];
        for (f, t) in triangles.iter().enumerate() {
            for &v in t {
                indices[fill[v as usize] as usize] = f as u32;
                fill[v as usize] += 1;
            }
        }
        Self { offsets, indices }
    }

    /// Triangles incident to vertex `v`.
    pub fn triangles_of(&self, v: usize) -> &[u32] {
        &self.indices[self.offsets[v] as usize..self.offsets[v + 1] as usize]
    }
}

/// Closest point to `p` on triangle `(a, b, c)` (Ericson, *Real-Time Collision Detection* §5.1.5).
pub fn closest_point_on_triangle(
    p: &Point3<f64>,
    a: &Point3<f64>,
    b: &Point3<f64>,
    c: &Point3<f64>,
) -> Point3<f64> {
    let ab = b - a;
    let ac = c - a;
    let ap = p - a;
    let d1 = ab.dot(&ap);
    let d2 = ac.dot(&ap);
    if d1 <= 0.0 && d2 <= 0.0 {
        return *a;
    }
    let bp = p - b;
    let d3 = ab.dot(&bp);
    let d4 = ac.dot(&bp);
    if d3 >= 0.0 && d4 <= d3 {
        return *b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return a + ab * v;
    }
    let cp = p - c;
    let d5 = ab.dot(&cp);
    let d6 = ac.dot(&cp);
    if d6 >= 0.0 && d5 <= d6 {
        return *c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return a + ac * w;
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return b + (c - b) * w;
    }
    let denom = va + vb + vc;
    if denom.abs() < f64::MIN_POSITIVE {
        return *a;
    }
    let v = vb / denom;
    let w = vc / denom;
    a + ab * v + ac * w
}

/// Barycentric coordinates (λ_a, λ_b, λ_c), summing to 1, of a point `x` on (or projected onto the
/// plane of) triangle `(a, b, c)`; a degenerate triangle gives (1, 0, 0).
pub fn barycentric(x: &Point3<f64>, a: &Point3<f64>, b: &Point3<f64>, c: &Point3<f64>) -> [f64; 3] {
    let (v0, v1, v2) = (b - a, c - a, x - a);
    let (d00, d01, d11) = (v0.dot(&v0), v0.dot(&v1), v1.dot(&v1));
    let (d20, d21) = (v2.dot(&v0), v2.dot(&v1));
    let denom = d00 * d11 - d01 * d01;
    if denom.abs() <= f64::EPSILON * d00 * d11 || denom == 0.0 {
        return [1.0, 0.0, 0.0];
    }
    let v = (d11 * d20 - d01 * d21) / denom;
    let w = (d00 * d21 - d01 * d20) / denom;
    [1.0 - v - w, v, w]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn barycentric_reproduces_the_point() {
        let (a, b, c) = (
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 1.0),
        );
        let x = Point3::from(a.coords * 0.2 + b.coords * 0.3 + c.coords * 0.5);
        let l = barycentric(&x, &a, &b, &c);
        for (got, want) in l.iter().zip([0.2, 0.3, 0.5]) {
            assert!((got - want).abs() < 1e-12, "{l:?}");
        }
        assert_eq!(barycentric(&x, &a, &a, &a), [1.0, 0.0, 0.0]);
    }

    #[test]
    fn one_rings_list_each_vertex_triangles() {
        let t = [[0, 1, 2], [0, 2, 3]];
        let rings = OneRings::new(4, &t);
        assert_eq!(rings.triangles_of(0), &[0, 1]);
        assert_eq!(rings.triangles_of(1), &[0]);
    }

    #[test]
    fn closest_point_on_triangle_regions() {
        let a = Point3::new(0.0, 0.0, 0.0);
        let b = Point3::new(1.0, 0.0, 0.0);
        let c = Point3::new(0.0, 1.0, 0.0);
        let inside = closest_point_on_triangle(&Point3::new(0.2, 0.3, 5.0), &a, &b, &c);
        assert!((inside - Point3::new(0.2, 0.3, 0.0)).norm() < 1e-12);
        let vertex = closest_point_on_triangle(&Point3::new(-1.0, -1.0, 1.0), &a, &b, &c);
        assert!((vertex - a).norm() < 1e-12);
        let edge = closest_point_on_triangle(&Point3::new(1.0, 1.0, 0.0), &a, &b, &c);
        assert!((edge - Point3::new(0.5, 0.5, 0.0)).norm() < 1e-12);
    }
}
