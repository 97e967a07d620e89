//! `exp` and `ln` written so the warp loop vectorises: no libm call, no branch, only float and
//! integer bit operations. Accurate to ~1e-14 relative (tests below), which is far below the
//! interpolation tolerance; the fit itself uses the standard library's functions.
//!
//! Hand-written because the warp evaluates ~55 million kernels at the `fine` resolution and a
//! libm call per kernel is what kept it above 0.1 s (measured in examples/rbf_bench.rs).

const LN2_HI: f64 = 6.931_471_803_691_238e-1;
const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;
/// 1.5·2⁵²: adding it rounds to an integer and leaves that integer in the low mantissa bits.
const ROUND_MAGIC: f64 = 6_755_399_441_055_744.0;

/// e^x for x ≤ 0 (the Gaussian's argument); x below −708 gives ≈ 3e−308 instead of 0.
#[inline(always)]
pub fn exp_nonpositive(x: f64) -> f64 {
    let x = x.max(-708.0);
    let t = x * std::f64::consts::LOG2_E + ROUND_MAGIC;
    let n = t - ROUND_MAGIC;
    // Cody–Waite reduction: r = x − n·ln2 with |r| ≤ ln2/2, exact to ~1 ulp.
    let r = (x - n * LN2_HI) - n * LN2_LO;
    // Taylor series of e^r to degree 11: the remainder (ln2/2)^12/12! < 7e-15 relative, far
    // below any tolerance the warp is held to, and two multiply-adds cheaper than degree 13.
    let p = horner(
        r,
        [
            1.0 / 39_916_800.0,
            1.0 / 3_628_800.0,
            1.0 / 362_880.0,
            1.0 / 40_320.0,
            1.0 / 5_040.0,
            1.0 / 720.0,
            1.0 / 120.0,
            1.0 / 24.0,
            1.0 / 6.0,
            0.5,
            1.0,
            1.0,
        ],
    );
    // 2^n from the low bits of t: (n + 1023) << 52 is the IEEE exponent field.
    let scale = f64::from_bits(t.to_bits().wrapping_add(1023) << 52);
    p * scale
}

/// ln x for finite x > 0 (normal numbers).
#[inline(always)]
pub fn ln_positive(x: f64) -> f64 {
    const SQRT_HALF_BITS: u64 = 0x3FE6_A09E_667F_3BCD;
    // Split x = m·2^e with m in [√½, √2): shift the exponent so the mantissa lands there.
    let bits = x.to_bits();
    let adjusted = bits.wrapping_sub(SQRT_HALF_BITS);
    let e_bits = (adjusted as i64 >> 52) as u64;
    let m = f64::from_bits(bits.wrapping_sub(e_bits << 52));
    // e as a float without an int→float conversion (none vectorises on SSE2).
    let e = f64::from_bits(0x4330_0000_0000_0000 | (e_bits.wrapping_add(1 << 20) & 0x1F_FFFF))
        - (4_503_599_627_370_496.0 + 1_048_576.0);
    // ln m = 2·atanh(s), s = (m−1)/(m+1), |s| ≤ 0.172: odd series to s^21 (< 1e-17).
    let s = (m - 1.0) / (m + 1.0);
    let s2 = s * s;
    let p = horner(
        s2,
        [
            1.0 / 21.0,
            1.0 / 19.0,
            1.0 / 17.0,
            1.0 / 15.0,
            1.0 / 13.0,
            1.0 / 11.0,
            1.0 / 9.0,
            1.0 / 7.0,
            1.0 / 5.0,
            1.0 / 3.0,
            1.0,
        ],
    );
    e * LN2_HI + (e * LN2_LO + 2.0 * s * p)
}

/// c₀·x^(N−1) + c₁·x^(N−2) + … + c_{N−1} by Horner's rule (highest degree first), one
/// multiply-add per coefficient; N is a constant, so the loop unrolls.
#[inline(always)]
fn horner<const N: usize>(x: f64, c: [f64; N]) -> f64 {
    let mut p = c[0];
    for &k in &c[1..] {
        p = p * x + k;
    }
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp_matches_std_to_a_few_ulp() {
        let mut worst: f64 = 0.0;
        for i in 0..=200_000 {
            let x = -700.0 * (i as f64 / 200_000.0).powi(3);
            let rel = (exp_nonpositive(x) - x.exp()).abs() / x.exp();
            worst = worst.max(rel);
        }
        assert!(worst < 1e-14, "worst relative error {worst:e}");
        assert_eq!(exp_nonpositive(0.0), 1.0);
        assert!(exp_nonpositive(-1e6) < 1e-300);
    }

    #[test]
    fn ln_matches_std_to_a_few_ulp() {
        let mut worst: f64 = 0.0;
        for i in 0..=200_000 {
            let x = 10f64.powf(-12.0 + 24.0 * i as f64 / 200_000.0);
            let err = (ln_positive(x) - x.ln()).abs() / x.ln().abs().max(1.0);
            worst = worst.max(err);
        }
        assert!(worst < 1e-15, "worst error {worst:e}");
        assert_eq!(ln_positive(1.0), 0.0);
    }
}
