//! Seeded randomness for spawning balls: SplitMix64, small enough to read, and fixed forever,
//! so a seed gives the same scene (and the same GIF bytes) on every machine and every
//! version of every dependency.

use crate::physics::ball::Ball;

/// A deterministic stream of pseudo-random numbers from a seed.
#[derive(Clone, Debug)]
pub struct Random {
    state: u64,
}

impl Random {
    pub fn new(seed: u64) -> Random {
        Random { state: seed }
    }

    /// The next 64 random bits (SplitMix64, Steele, Lea and Flood 2014).
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number uniformly in `[low, high)`.
    pub fn range(&mut self, low: f64, high: f64) -> f64 {
        // The top 53 bits make every f64 in [0, 1) equally likely.
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        low + (high - low) * unit
    }
}

/// `count` balls of `radius` in rows across a box `width` wide, from its top-left corner, on a
/// square lattice with 2 px between neighbours, each moved by up to 1 px and given up to
/// `speed` px/frame along each axis (seeded by `seed`): a heap to drop that starts without
/// overlaps, as the exact-mode pile test and `examples/exact_piles.rs` do.
pub fn jittered_lattice(count: usize, radius: f64, width: f64, speed: f64, seed: u64) -> Vec<Ball> {
    let mut random = Random::new(seed);
    let spacing = 2.0 * radius + 2.0;
    let per_row = ((width - 2.0 * radius) / spacing) as usize;
    (0..count)
        .map(|k| {
            let (column, row) = ((k % per_row) as f64, (k / per_row) as f64);
            let x = radius + 1.0 + column * spacing + random.range(0.0, 1.0);
            let y = radius + 1.0 + row * spacing + random.range(0.0, 1.0);
            let (vx, vy) = (random.range(-speed, speed), random.range(-speed, speed));
            Ball::new(x, y, vx, vy, radius, 0)
        })
        .collect()
}
