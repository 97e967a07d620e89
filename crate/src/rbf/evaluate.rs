//! Evaluating a fitted RBF network at many points: the warp loop of paper §3.1.2 ("new
//! positions of those non-feature vertices are calculated by using this RBF network").
//!
//! Centres are stored in blocks of [`LANES`] so the loop vectorises; the Gaussian and the
//! thin-plate spline use the branch-free exp/ln of [`super::fast_math`]; on x86-64 an AVX2+FMA
//! build of the loop is chosen at run time; natively the points are split over the cores.

use nalgebra::{DMatrix, Point3};

use super::fast_math;
use super::fit::RbfNetwork;
use super::kernel::Kernel;

impl RbfNetwork {
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
    /// loop. Natively the points are split over the available cores (scoped std threads).
    pub fn warp_into(&self, points: &[Point3<f64>], out: &mut [Point3<f64>]) {
        let len = points.len().min(out.len());
        let (points, out) = (&points[..len], &mut out[..len]);
        #[cfg(not(target_arch = "wasm32"))]
        {
            // Below ~20K points a thread costs more than it saves.
            let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
            if threads > 1 && len >= 20_000 {
                let chunk = len.div_ceil(threads);
                std::thread::scope(|scope| {
                    for (p, o) in points.chunks(chunk).zip(out.chunks_mut(chunk)) {
                        scope.spawn(move || self.warp_serial(p, o));
                    }
                });
                return;
            }
        }
        self.warp_serial(points, out);
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
            Kernel::Gaussian { c } => {
                let inv_c2 = 1.0 / (c * c);
                self.warp_with(points, out, |r2| fast_math::exp_nonpositive(-r2 * inv_c2))
            }
        }
    }

    /// The warp loop: LANES independent accumulators per coordinate so the compiler can
    /// vectorise across centres (a single running sum would force sequential order).
    #[inline(always)]
    fn warp_with(&self, points: &[Point3<f64>], out: &mut [Point3<f64>], phi: impl Fn(f64) -> f64) {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2")
                && std::arch::is_x86_feature_detected!("fma")
            {
                // SAFETY: the CPU was just checked for the features the function is built with.
                unsafe { warp_blocks_avx2(&self.blocks, &self.affine, points, out, phi) };
                return;
            }
        }
        warp_blocks(&self.blocks, &self.affine, points, out, phi);
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
