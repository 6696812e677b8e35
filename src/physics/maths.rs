//! Transcendental functions that give the same bits on every system.
//!
//! `f64::sin`, `hypot`, `ln_1p`, `powf` and their kin call the platform's maths library
//! (glibc on Linux, mingw's or Microsoft's runtime on Windows, Apple's libm on macOS), and
//! those round the last bit differently. One bit in a bounce angle becomes another pixel a few
//! hundred frames later, so the GIF would differ from one system to the next. These wrappers
//! call the `libm` crate instead: one Rust implementation (a port of musl's), compiled into the
//! program, so every system computes the same bits.
//!
//! Addition, subtraction, multiplication, division, `sqrt`, `abs`, `floor`, `round`, `min`,
//! `max` and conversions are exactly rounded by IEEE 754 on every system: they stay as they are.
//! `tests/layout.rs` fails if `src/` calls the platform's versions of the functions below.

/// `√(x² + y²)` without overflow for large inputs.
pub fn hypot(x: f64, y: f64) -> f64 {
    libm::hypot(x, y)
}

/// Sine of an angle in radians.
pub(crate) fn sin(angle: f64) -> f64 {
    libm::sin(angle)
}

/// Cosine of an angle in radians.
pub(crate) fn cos(angle: f64) -> f64 {
    libm::cos(angle)
}

/// `ln(1 + x)`, accurate for small `x`.
pub fn ln_1p(x: f64) -> f64 {
    libm::log1p(x)
}

/// `eˣ − 1`, accurate for small `x`.
pub fn exp_m1(x: f64) -> f64 {
    libm::expm1(x)
}

/// Natural logarithm.
pub fn ln(x: f64) -> f64 {
    libm::log(x)
}

/// Base-10 logarithm.
pub(crate) fn log10(x: f64) -> f64 {
    libm::log10(x)
}

/// `baseᵉˣᵖ` for a real exponent.
pub(crate) fn powf(base: f64, exponent: f64) -> f64 {
    libm::pow(base, exponent)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrappers_agree_with_the_platform_to_within_an_ulp() {
        let close = |ours: f64, platform: f64| (ours - platform).abs() <= platform.abs() * 4e-16;
        for k in 1..200 {
            let x = f64::from(k) * 0.0371;
            assert!(close(hypot(x, 1.0 / x), x.hypot(1.0 / x)), "hypot at {x}");
            assert!(close(sin(x), x.sin()) || sin(x).abs() < 1e-15, "sin at {x}");
            assert!(close(cos(x), x.cos()) || cos(x).abs() < 1e-15, "cos at {x}");
            assert!(close(ln_1p(-x / 8.0), (-x / 8.0).ln_1p()), "ln_1p at {x}");
            assert!(close(exp_m1(-x), (-x).exp_m1()), "exp_m1 at {x}");
            assert!(close(ln(x), x.ln()) || ln(x).abs() < 1e-15, "ln at {x}");
            assert!(
                close(log10(x), x.log10()) || log10(x).abs() < 1e-15,
                "log10 at {x}"
            );
            assert!(close(powf(0.998, x), 0.998f64.powf(x)), "powf at {x}");
        }
    }
}
