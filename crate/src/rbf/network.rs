//! The fitted RBF network f: R³ → R³ ([`RbfNetwork`], built by [`super::fit`]) and its
//! evaluation at many points: the warp loop of paper §3.1.2 ("new positions of those non-feature
//! vertices are calculated by using this RBF network").
//!
//! Centres are stored in blocks of [`LANES`] so the loop vectorises; the Gaussian and the
//! thin-plate spline use the branch-free exp/ln of [`super::fast_math`]; on x86-64 an AVX2+FMA
//! build of the loop is chosen at run time; natively the points are split over the cores.

use crate::utils::parallel::for_each_chunk_pair;
use nalgebra::{DMatrix, Point3};

use super::fast_math;
use super::kernel::Kernel;
use crate::mesh::bounding_box;

/// A fitted RBF network mapping R³ → R³.
#[derive(Debug, Clone, PartialEq)]
pub struct RbfNetwork {
    pub(super) kernel: Kernel,
    /// Centres p_j and weights w_j per coordinate, in vectorisable blocks.
    pub(super) blocks: Vec<Block>,
    /// Affine part: row 0 the constant a_0, rows 1..4 the linear map (x, y, z → output).
    /// All zero when the fit had no affine term.
    pub(super) affine: [[f64; 3]; 4],
    pub(super) rcond: f64,
}

impl RbfNetwork {
    /// The kernel the network was fitted with.
    pub fn kernel(&self) -> Kernel {
        self.kernel
    }

    /// Reciprocal 1-norm condition number of the fitted system (1 = perfect, ~1e-16 = singular).
    pub fn rcond(&self) -> f64 {
        self.rcond
    }

    /// f(x) for one point.
    pub fn evaluate(&self, x: &Point3<f64>) -> Point3<f64> {
        let mut out = [Point3::origin()];
        self.warp_into(std::slice::from_ref(x), &mut out);
        out[0]
    }

    /// f applied to every point: `#V` points in, `#V` points out.
    pub fn warp(&self, points: &[Point3<f64>]) -> Vec<Point3<f64>> {
        let mut out = vec![Point3::origin(); points.len()];
        self.warp_into(points, &mut out);
        out
    }

    /// f applied to every point of `points`, written to `out` (same length; extra entries of
    /// either are ignored). No allocation per vertex; the kernel is matched once, outside the
    /// loop. Natively the points are split over the available cores (`utils::parallel`).
    pub fn warp_into(&self, points: &[Point3<f64>], out: &mut [Point3<f64>]) {
        let len = points.len().min(out.len());
        let (points, out) = (&points[..len], &mut out[..len]);
        // Below ~20K points a thread costs more than it saves.
        for_each_chunk_pair(points, out, 20_000, |p, o| self.warp_serial(p, o));
    }

    /// [`Self::warp_into`] on the calling thread only (for benchmarks and single-threaded hosts).
    pub fn warp_serial(&self, points: &[Point3<f64>], out: &mut [Point3<f64>]) {
        match self.kernel {
            Kernel::ThinPlate => self.warp_with(points, out, |r2| {
                // r2 = 0 would give 0·(−∞); max() keeps the log finite and the product 0.
                0.5 * r2 * fast_math::ln_positive(r2.max(f64::MIN_POSITIVE))
            }),
            Kernel::Multiquadric { s } => {
                let s2 = s * s;
                self.warp_with(points, out, |r2| (r2 + s2).sqrt())
            }
            Kernel::Gaussian { c } => self.warp_gaussian(points, out, c),
        }
    }

    /// The Gaussian warp, skipping centres whose kernel is below 1e-17 for a whole chunk of
    /// points: Φ = exp(−r²/c²) < 1e-17 beyond r = 6.26·c, so each chunk of
    /// [`GAUSSIAN_CHUNK`] consecutive points (template order is spatially coherent) only visits
    /// centres within that distance of its bounding box. The dropped terms are below rounding.
    fn warp_gaussian(&self, points: &[Point3<f64>], out: &mut [Point3<f64>], c: f64) {
        let inv_c2 = 1.0 / (c * c);
        let phi = |r2: f64| fast_math::exp_nonpositive(-r2 * inv_c2);
        let cutoff2 = 39.2 * c * c;
        let mut near: Vec<Block> = Vec::with_capacity(self.blocks.len());
        for (p, o) in points
            .chunks(GAUSSIAN_CHUNK)
            .zip(out.chunks_mut(GAUSSIAN_CHUNK))
        {
            let Some((lo, hi)) = bounding_box(p) else {
                continue;
            };
            near.clear();
            let mut block: Option<Block> = None;
            let mut lane = 0;
            for b in &self.blocks {
                for l in 0..LANES {
                    let centre = Point3::new(b.cx[l], b.cy[l], b.cz[l]);
                    let gap = (lo - centre)
                        .sup(&(centre - hi))
                        .sup(&nalgebra::Vector3::zeros());
                    if gap.norm_squared() > cutoff2
                        || b.wx[l] == 0.0 && b.wy[l] == 0.0 && b.wz[l] == 0.0
                    {
                        continue;
                    }
                    let nb = block.get_or_insert(Block::padding(centre));
                    nb.cx[lane] = b.cx[l];
                    nb.cy[lane] = b.cy[l];
                    nb.cz[lane] = b.cz[l];
                    nb.wx[lane] = b.wx[l];
                    nb.wy[lane] = b.wy[l];
                    nb.wz[lane] = b.wz[l];
                    lane += 1;
                    if lane == LANES {
                        near.extend(block.take());
                        lane = 0;
                    }
                }
            }
            near.extend(block.take());
            self.warp_with_blocks(&near, p, o, phi);
        }
    }

    /// The warp loop: LANES independent accumulators per coordinate so the compiler can
    /// vectorise across centres (a single running sum would force sequential order).
    #[inline(always)]
    fn warp_with(&self, points: &[Point3<f64>], out: &mut [Point3<f64>], phi: impl Fn(f64) -> f64) {
        self.warp_with_blocks(&self.blocks, points, out, phi)
    }

    #[inline(always)]
    fn warp_with_blocks(
        &self,
        blocks: &[Block],
        points: &[Point3<f64>],
        out: &mut [Point3<f64>],
        phi: impl Fn(f64) -> f64,
    ) {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2")
                && std::arch::is_x86_feature_detected!("fma")
            {
                // SAFETY: the CPU was just checked for the features the function is built with.
                unsafe { warp_blocks_avx2(blocks, &self.affine, points, out, phi) };
                return;
            }
        }
        warp_blocks(blocks, &self.affine, points, out, phi);
    }
}

/// [`warp_blocks`] compiled for AVX2 + FMA: 4 lanes per instruction instead of SSE2's 2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn warp_blocks_avx2(
    blocks: &[Block],
    affine: &[[f64; 3]; 4],
    points: &[Point3<f64>],
    out: &mut [Point3<f64>],
    phi: impl Fn(f64) -> f64,
) {
    warp_blocks(blocks, affine, points, out, phi)
}

#[inline(always)]
fn warp_blocks(
    blocks: &[Block],
    a: &[[f64; 3]; 4],
    points: &[Point3<f64>],
    out: &mut [Point3<f64>],
    phi: impl Fn(f64) -> f64,
) {
    for (p, o) in points.iter().zip(out.iter_mut()) {
        let mut ax = [0.0; LANES];
        let mut ay = [0.0; LANES];
        let mut az = [0.0; LANES];
        for b in blocks {
            for l in 0..LANES {
                let (dx, dy, dz) = (p.x - b.cx[l], p.y - b.cy[l], p.z - b.cz[l]);
                let k = phi(dx * dx + dy * dy + dz * dz);
                ax[l] += b.wx[l] * k;
                ay[l] += b.wy[l] * k;
                az[l] += b.wz[l] * k;
            }
        }
        let (fx, fy, fz) = (
            ax.iter().sum::<f64>(),
            ay.iter().sum::<f64>(),
            az.iter().sum::<f64>(),
        );
        *o = Point3::new(
            fx + a[0][0] + a[1][0] * p.x + a[2][0] * p.y + a[3][0] * p.z,
            fy + a[0][1] + a[1][1] * p.x + a[2][1] * p.y + a[3][1] * p.z,
            fz + a[0][2] + a[1][2] * p.x + a[2][2] * p.y + a[3][2] * p.z,
        );
    }
}

/// Points per chunk of the Gaussian's centre culling.
const GAUSSIAN_CHUNK: usize = 64;

impl Block {
    /// A block of zero-weight copies of `centre` (contributes exactly 0).
    fn padding(centre: Point3<f64>) -> Block {
        Block {
            cx: [centre.x; LANES],
            cy: [centre.y; LANES],
            cz: [centre.z; LANES],
            wx: [0.0; LANES],
            wy: [0.0; LANES],
            wz: [0.0; LANES],
        }
    }
}

/// LANES centres and their weights, side by side so the warp loop vectorises.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Block {
    cx: [f64; LANES],
    cy: [f64; LANES],
    cz: [f64; LANES],
    wx: [f64; LANES],
    wy: [f64; LANES],
    wz: [f64; LANES],
}

/// Centres in blocks of LANES; the last block is padded with zero-weight copies of centre 0.
pub(super) fn blocks(source: &[Point3<f64>], weights: &DMatrix<f64>) -> Vec<Block> {
    let n = source.len();
    (0..n.div_ceil(LANES))
        .map(|b| {
            let mut block = Block {
                cx: [source[0].x; LANES],
                cy: [source[0].y; LANES],
                cz: [source[0].z; LANES],
                wx: [0.0; LANES],
                wy: [0.0; LANES],
                wz: [0.0; LANES],
            };
            for l in 0..LANES {
                let j = b * LANES + l;
                if j < n {
                    block.cx[l] = source[j].x;
                    block.cy[l] = source[j].y;
                    block.cz[l] = source[j].z;
                    block.wx[l] = weights[(j, 0)];
                    block.wy[l] = weights[(j, 1)];
                    block.wz[l] = weights[(j, 2)];
                }
            }
            block
        })
        .collect()
}

/// Centres per block of the warp loop (4 f64 = one AVX2 register).
const LANES: usize = 4;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rbf::{fit, RbfParams};

    /// The vectorised, culled loop against the plain sum Σ w_j Φ(‖x − p_j‖) + affine with the
    /// standard library's exp/ln, on scattered centres and a dense line of points through them.
    #[test]
    fn fast_loop_matches_the_plain_sum() {
        let source: Vec<Point3<f64>> = (0..30)
            .map(|i| {
                let t = i as f64;
                Point3::new((t * 0.37).sin(), t * 0.06, (t * 0.91).cos() * 0.3)
            })
            .collect();
        let target: Vec<Point3<f64>> = source
            .iter()
            .map(|p| Point3::new(p.x + 0.1 * p.y.sin(), p.y * 1.1, p.z - 0.05 * p.x))
            .collect();
        let names: Vec<String> = (0..30).map(|i| format!("L{i}")).collect();
        let points: Vec<Point3<f64>> = (0..500)
            .map(|i| Point3::new(-1.2 + i as f64 * 0.005, i as f64 * 0.004, 0.1))
            .collect();
        for kernel in [
            Kernel::Gaussian { c: 0.1 },
            Kernel::Gaussian { c: 0.5 },
            Kernel::ThinPlate,
            Kernel::Multiquadric { s: 0.02 },
        ] {
            let params = RbfParams {
                kernel,
                ..RbfParams::default()
            };
            let net = fit(&names, &source, &target, &params).unwrap();
            let fast = net.warp(&points);
            for (x, f) in points.iter().zip(&fast) {
                let a = &net.affine;
                let mut plain = [a[0][0], a[0][1], a[0][2]];
                for k in 0..3 {
                    plain[k] += a[1][k] * x.x + a[2][k] * x.y + a[3][k] * x.z;
                }
                for b in &net.blocks {
                    for l in 0..LANES {
                        let c = Point3::new(b.cx[l], b.cy[l], b.cz[l]);
                        let phi = kernel.eval_r2((x - c).norm_squared());
                        plain[0] += b.wx[l] * phi;
                        plain[1] += b.wy[l] * phi;
                        plain[2] += b.wz[l] * phi;
                    }
                }
                let d = (f - Point3::from(plain)).norm();
                assert!(d < 1e-11, "{kernel:?} at {x:?}: {d:e}");
            }
        }
    }
}
