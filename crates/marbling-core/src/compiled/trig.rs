//! Sine and cosine for the walk's kernels, written without branches or calls so that
//! a loop over samples vectorises (libm's `sin` is a call per sample). The argument is
//! reduced by n·π/2 in two parts (Cody–Waite; exact products for |n| < 2²⁰, so for
//! |x| up to about 1.6·10⁶), then the minimax polynomials of fdlibm's `__kernel_sin`
//! and `__kernel_cos` (under 1 ulp on [−π/4, π/4]) give sin and cos of the rest.
//!
//! Tolerance: |error| ≤ 4·10⁻¹⁶·max(1, |x|/10³) against libm for |x| ≤ 10⁶ (the
//! reduction's rounding grows with n); checked below.

// The constants are written as fdlibm publishes them (21 digits), which round to the
// same f64s as 17 would.
#![allow(clippy::excessive_precision)]

/// π/2 in two parts: its first 33 bits and the rest (fdlibm's `pio2_1`, `pio2_1t`).
const PIO2_HI: f64 = 1.570_796_326_734_125_614_17e0;
const PIO2_LO: f64 = 6.077_100_506_506_192_249_32e-11;

/// fdlibm's `__kernel_sin` coefficients.
const S1: f64 = -1.666_666_666_666_663_243_48e-1;
const S2: f64 = 8.333_333_333_322_489_461_24e-3;
const S3: f64 = -1.984_126_982_985_794_931_34e-4;
const S4: f64 = 2.755_731_370_707_006_767_89e-6;
const S5: f64 = -2.505_076_025_340_686_341_95e-8;
const S6: f64 = 1.589_690_995_211_550_102_21e-10;

/// fdlibm's `__kernel_cos` coefficients.
const C1: f64 = 4.166_666_666_666_660_190_37e-2;
const C2: f64 = -1.388_888_888_887_410_957_49e-3;
const C3: f64 = 2.480_158_728_947_672_941_78e-5;
const C4: f64 = -2.755_731_435_139_066_330_35e-7;
const C5: f64 = 2.087_572_321_298_174_827_90e-9;
const C6: f64 = -1.135_964_755_778_819_482_65e-11;

/// floor(v) for |v| < 2⁵¹ without a call or an integer conversion: rounding to nearest
/// by adding and subtracting 1.5·2⁵², then one step down where that rounded up. Exact.
#[inline(always)]
pub(crate) fn floor_small(v: f64) -> f64 {
    const ROUNDER: f64 = 6_755_399_441_055_744.0;
    let r = (v + ROUNDER) - ROUNDER;
    if r > v { r - 1.0 } else { r }
}

/// sin x for |x| ≤ π/4.
#[inline(always)]
fn kernel_sin(x: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
    x + z * x * (S1 + z * r)
}

/// cos x for |x| ≤ π/4.
#[inline(always)]
fn kernel_cos(x: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    let hz = 0.5 * z;
    let one_minus = 1.0 - hz;
    one_minus + (((1.0 - one_minus) - hz) + z * r)
}

/// (sin x, cos x), branch-free (see the module doc for range and tolerance).
#[inline(always)]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    let (n, q) = nearest(x * std::f64::consts::FRAC_2_PI);
    let y = (x - n * PIO2_HI) - n * PIO2_LO;
    let (s, c) = (kernel_sin(y), kernel_cos(y));
    // The quadrant n mod 4 from n's low bits: odd quadrants swap sin and cos; sin is
    // negative in quadrants 2 and 3, cos in 1 and 2 (sign bits flipped, no branch).
    let (s, c) = if q & 1 == 1 { (c, s) } else { (s, c) };
    let sin_neg = (q >> 1) << 63;
    let cos_neg = ((q ^ (q >> 1)) & 1) << 63;
    (
        f64::from_bits(s.to_bits() ^ sin_neg),
        f64::from_bits(c.to_bits() ^ cos_neg),
    )
}

/// The integer n nearest to `v` (|v| < 2⁵¹), and n's low bits (two's complement) in a
/// `u64`: adding 1.5·2⁵² rounds to a whole number and leaves n in the mantissa's low
/// bits, which four-lane AVX2 reads without an integer conversion it lacks.
#[inline(always)]
fn nearest(v: f64) -> (f64, u64) {
    const ROUNDER: f64 = 6_755_399_441_055_744.0;
    let t = v + ROUNDER;
    (t - ROUNDER, t.to_bits() & 3)
}

/// π in two parts (twice [`PIO2_HI`] and [`PIO2_LO`]: the high part keeps 33 bits).
const PI_HI: f64 = 2.0 * PIO2_HI;
const PI_LO: f64 = 2.0 * PIO2_LO;

/// The Taylor coefficients (−1)ᵏ/(2k+1)! of sin, k = 1…10: to y²¹ the series is within
/// 1.2·10⁻¹⁸ of sin y on [−π/2, π/2].
const TAYLOR: [f64; 10] = [
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5_040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
    1.0 / 355_687_428_096_000.0,
    -1.0 / 121_645_100_408_832_000.0,
    1.0 / 51_090_942_171_709_440_000.0,
];

/// sin x alone, branch-free, cheaper than [`sin_cos`]: x is reduced by n·π to
/// y ∈ [−π/2, π/2] and sin x = (−1)ⁿ sin y, one polynomial (same range and tolerance).
#[inline(always)]
pub(crate) fn sin(x: f64) -> f64 {
    let (n, q) = nearest(x * std::f64::consts::FRAC_1_PI);
    let y = (x - n * PI_HI) - n * PI_LO;
    let z = y * y;
    // Σ TAYLOR[i]·zⁱ by Estrin's scheme: pairs, then pairs of pairs, so the products
    // do not wait on each other one by one as in Horner's.
    let [a0, a1, a2, a3, a4, a5, a6, a7, a8, a9] = TAYLOR;
    let (z2, b4) = (z * z, a8 + a9 * z);
    let z4 = z2 * z2;
    let low = (a0 + a1 * z) + (a2 + a3 * z) * z2;
    let high = (a4 + a5 * z) + (a6 + a7 * z) * z2;
    let p = (low + high * z4) + b4 * (z4 * z4);
    let s = y + y * z * p;
    // (−1)ⁿ: n's lowest bit into the sign bit.
    f64::from_bits(s.to_bits() ^ ((q & 1) << 63))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tolerance of the module doc at `x`.
    fn budget(x: f64) -> f64 {
        4e-16 * (x.abs() / 1e3).max(1.0)
    }

    #[test]
    fn sine_and_cosine_match_libm_within_the_stated_tolerance() {
        let mut worst: f64 = 0.0;
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for i in 0..200_000 {
            // Uniform on ±4π, then log-uniform out to 10⁶, both signs.
            let x = if i % 2 == 0 {
                (next() - 0.5) * 8.0 * std::f64::consts::PI
            } else {
                (next() - 0.5).signum() * 10f64.powf(6.0 * next())
            };
            let (s, c) = sin_cos(x);
            let err = (s - x.sin())
                .abs()
                .max((c - x.cos()).abs())
                .max((sin(x) - x.sin()).abs());
            assert!(err <= budget(x), "x = {x:e}: error {err:e}");
            worst = worst.max(err / budget(x));
        }
        assert!(
            worst > 0.0,
            "no rounding difference at all: is libm being called?"
        );
    }

    #[test]
    fn quadrant_edges_and_exact_values() {
        use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
        for k in -8..=8 {
            for x in [
                f64::from(k) * FRAC_PI_2,
                f64::from(k) * FRAC_PI_2 + FRAC_PI_4,
                f64::from(k) * FRAC_PI_2 - FRAC_PI_4,
                f64::from(k) * FRAC_PI_2 + 1e-9,
                f64::from(k) * FRAC_PI_2 - 1e-9,
            ] {
                let (s, c) = sin_cos(x);
                assert!((s - x.sin()).abs() <= 4e-16, "sin {x}");
                assert!((sin(x) - x.sin()).abs() <= 4e-16, "sin alone {x}");
                assert!((c - x.cos()).abs() <= 4e-16, "cos {x}");
            }
        }
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
        assert!((sin(PI / 6.0) - 0.5).abs() <= 2e-16);
    }

    #[test]
    fn floor_small_is_floor() {
        for v in [
            0.0,
            0.5,
            0.999_999_999,
            1.0,
            1.5,
            2.5,
            -0.5,
            -1.0,
            -1.5,
            -2.5,
            1e15 + 0.5,
            -3e14,
            123_456.789,
            4.0e15 / 2.0,
        ] {
            assert_eq!(floor_small(v), v.floor(), "{v}");
        }
    }

    /// The check itself: a sine off by one part in 10¹⁵ is outside the budget.
    #[test]
    fn the_budget_notices_a_small_error() {
        let x = 0.7_f64;
        assert!((x.sin() * (1.0 + 1e-15) - x.sin()).abs() > budget(x));
    }
}
