//! Checks that no box a circle can make meets a tie in Pillow's quarter-ellipse trace
//! (`src/render/ellipse.rs`, `QuarterTrace::climb`), so the trace's tie rules (up before
//! diagonal, both before left) never decide a pixel, and cargo-mutants' `<` → `<=` mutants of
//! those comparisons are equivalent (`.cargo/mutants.toml`). A circle's box is `a` by `b`
//! pixels with `a` and `b` below 32,768 and at most 2 apart (truncating its two float edges).
//! Standalone, with the same arithmetic as `climb`:
//!
//!   rustc -O tools/trace_ties.rs -o target/trace_ties && target/trace_ties
//!
//! Prints each box with a tie, then how many. Run 2026-11-27: 0 boxes with a tie (28 s).

fn ties(a: i64, b: i64) -> bool {
    let (a2, b2) = (a * a, b * b);
    let a2b2 = a2 * b2;
    let miss = |x: i64, y: i64| (a2 * y * y + b2 * x * x - a2b2).abs();
    let (mut x, mut y) = (a, b % 2);
    while y < b {
        while x > 1 {
            let (up, diag, left) = (miss(x, y + 2), miss(x - 2, y + 2), miss(x - 2, y));
            if left == up.min(diag) || diag == up {
                return true;
            }
            if left < up.min(diag) {
                x -= 2;
                continue;
            }
            if diag < up {
                x -= 2;
            }
            break;
        }
        y += 2;
    }
    false
}
fn main() {
    let mut n = 0;
    for a in 1..=32768i64 {
        for b in [a - 2, a - 1, a, a + 1, a + 2] {
            if b > 0 && b <= 32768 && ties(a, b) {
                println!("tie {a} {b}");
                n += 1;
            }
        }
    }
    println!("{n} boxes with a tie");
}
