//! Regions without data follow their neighbours: the transforms of the `free` vertices are set to
//! the minimiser of E_s = Σ_edges ‖T_i − T_j‖²_F with every other vertex held — each free T_i the
//! mean of its neighbours' (the harmonic extension). When the neighbours around a region share one
//! rigid (or affine) transform, the region takes exactly that transform: a never-scanned region
//! moves rigidly with what surrounds it. Without data E_s alone would reach the same optimum, but
//! a few dozen L-BFGS iterations leave a large region lagging where the warp put it.
//!
//! Solved by Gauss–Seidel sweeps over the free vertices until the largest change of a transform
//! entry falls below `tolerance` (or `max_sweeps`).

use super::energy::DOF;

/// Sets the transforms (`x`, 12 per vertex) of the vertices with `free[i]` to the harmonic
/// extension of the others' over the mesh `edges`. A free component touching no held vertex
/// keeps its transforms. Returns the number of sweeps made.
pub fn follow_neighbours(
    x: &mut [f64],
    free: &[bool],
    edges: &[[u32; 2]],
    tolerance: f64,
    max_sweeps: usize,
) -> usize {
    let n = free.len();
    let mut offsets = vec![0usize; n + 1];
    for &[i, j] in edges {
        offsets[i as usize + 1] += 1;
        offsets[j as usize + 1] += 1;
    }
    for v in 0..n {
        offsets[v + 1] += offsets[v];
    }
    let mut fill = offsets.clone();
    let mut neighbours = vec![0u32; offsets[n]];
    for &[i, j] in edges {
        neighbours[fill[i as usize]] = j;
        fill[i as usize] += 1;
        neighbours[fill[j as usize]] = i;
        fill[j as usize] += 1;
    }
    let order: Vec<usize> = (0..n).filter(|&i| free[i]).collect();
    let mut sweeps = 0;
    while sweeps < max_sweeps && !order.is_empty() {
        sweeps += 1;
        let mut change: f64 = 0.0;
        for &i in &order {
            let around = &neighbours[offsets[i]..offsets[i + 1]];
            if around.is_empty() {
                continue;
            }
            let mut mean = [0.0; DOF];
            for &j in around {
                let t = &x[DOF * j as usize..DOF * j as usize + DOF];
                for k in 0..DOF {
                    mean[k] += t[k];
                }
            }
            let t = &mut x[DOF * i..DOF * i + DOF];
            for k in 0..DOF {
                let value = mean[k] / around.len() as f64;
                change = change.max((value - t[k]).abs());
                t[k] = value;
            }
        }
        if change < tolerance {
            break;
        }
    }
    sweeps
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_free_region_takes_the_transform_its_neighbours_share() {
        // A 4 × 4 grid; the inner 2 × 2 free, the ring held at one rigid transform.
        let id = |r: u32, c: u32| 4 * r + c;
        let mut edges = Vec::new();
        for r in 0..4 {
            for c in 0..4 {
                if c < 3 {
                    edges.push([id(r, c), id(r, c + 1)]);
                }
                if r < 3 {
                    edges.push([id(r, c), id(r + 1, c)]);
                }
            }
        }
        let (s, co) = 0.3f64.sin_cos();
        let rigid = [co, -s, 0.0, 0.01, s, co, 0.0, -0.02, 0.0, 0.0, 1.0, 0.005];
        let free: Vec<bool> = (0..16).map(|v| [5, 6, 9, 10].contains(&v)).collect();
        let mut x = vec![0.0; 16 * DOF];
        for (v, t) in x.chunks_exact_mut(DOF).enumerate() {
            // Free vertices start anywhere (they "drifted").
            t.copy_from_slice(&rigid);
            if free[v] {
                t[3] += 0.05 * v as f64;
                t[0] -= 0.1;
            }
        }
        follow_neighbours(&mut x, &free, &edges, 1e-13, 10_000);
        for t in x.chunks_exact(DOF) {
            for k in 0..DOF {
                assert!((t[k] - rigid[k]).abs() < 1e-10);
            }
        }
    }

    #[test]
    fn a_free_path_takes_the_mean_of_its_ends() {
        // Path 0 – 1 – 2 – 3: ends held at 0 and 3 (in every entry), inside free: linear.
        let edges = [[0, 1], [1, 2], [2, 3]];
        let mut x = vec![0.0; 4 * DOF];
        x[3 * DOF..].fill(3.0);
        let free = [false, true, true, false];
        follow_neighbours(&mut x, &free, &edges, 1e-12, 10_000);
        for k in 0..DOF {
            assert!((x[DOF + k] - 1.0).abs() < 1e-9);
            assert!((x[2 * DOF + k] - 2.0).abs() < 1e-9);
        }
    }
}
