//! A closed surface made of rings, for the measurement tests' shapes with known answers.
#![allow(dead_code)]

/// `rings` rings of `around` vertices, vertex `a` of ring `i` at `point(i, t)` with
/// t = 2πa/`around`, closed by a `bottom` and a `top` pole; outward triangles when the rings go
/// up and t turns from +x towards +z. Flat `#V·3` positions and triangles.
pub fn ring_surface(
    rings: usize,
    around: usize,
    point: impl Fn(usize, f64) -> [f64; 3],
    bottom: [f64; 3],
    top: [f64; 3],
) -> (Vec<f32>, Vec<[u32; 3]>) {
    let mut p = Vec::new();
    for i in 0..rings {
        for a in 0..around {
            let t = std::f64::consts::TAU * a as f64 / around as f64;
            p.extend(point(i, t).map(|x| x as f32));
        }
    }
    let (b, t) = ((rings * around) as u32, (rings * around + 1) as u32);
    p.extend(bottom.map(|x| x as f32));
    p.extend(top.map(|x| x as f32));
    let v = |i: usize, a: usize| (i * around + a % around) as u32;
    let mut tri = Vec::new();
    for i in 0..rings - 1 {
        for a in 0..around {
            tri.push([v(i, a), v(i + 1, a), v(i + 1, a + 1)]);
            tri.push([v(i, a), v(i + 1, a + 1), v(i, a + 1)]);
        }
    }
    for a in 0..around {
        tri.push([b, v(0, a), v(0, a + 1)]);
        tri.push([t, v(rings - 1, a + 1), v(rings - 1, a)]);
    }
    (p, tri)
}
