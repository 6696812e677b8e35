//! How the cost of a frame with ball-ball collisions grows with the number of balls.
//!
//! Each frame moves every ball (the lesson's step: gravity, move, walls, trail) and then
//! resolves the collisions, for 1,000, 10,000 and 100,000 balls at packing fraction 0.3
//! (the balls cover 30 % of the box). Criterion reports the time per frame and, as
//! "elements", ball-steps per second; the cost per ball should stay flat as N grows.
//!
//! Run: `cargo bench --bench collisions` (about 20 s).

use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Duration;

use bouncing_ball::ball::Ball;
use bouncing_ball::collisions::Collisions;
use bouncing_ball::walls::Walls;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

/// Share of the box the balls cover.
const PACKING_FRACTION: f64 = 0.3;
/// Radii are spread over this range, px, so masses differ and the grid sees mixed sizes.
const RADII: (f64, f64) = (2.0, 4.0);
/// Starting speeds are up to this much along each axis, px/frame.
const MAX_SPEED: f64 = 2.0;
/// Zero, so the balls stay spread at the packing fraction while the benchmark runs (with the
/// lesson's 0.5 px/frame² they pile up on the floor within ~100 frames, and each size would
/// be measured at a different density). The addition still runs every step.
const GRAVITY: [f64; 2] = [0.0, 0.0];

/// SplitMix64: a tiny seeded generator, so every run benchmarks the same scene.
struct SplitMix64(u64);

impl SplitMix64 {
    /// A number in `low..high`.
    fn range(&mut self, low: f64, high: f64) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        let unit = (z >> 11) as f64 / (1u64 << 53) as f64;
        low + unit * (high - low)
    }
}

/// `count` balls in a square box sized for the packing fraction, with random radii and
/// velocities. Each starts near the middle of its own square of a lattice (jittered), so the
/// scene starts without overlaps, as a valid scene would.
fn scene(count: usize) -> (Vec<Ball>, Walls) {
    let mut random = SplitMix64(count as u64);
    let radii: Vec<f64> = (0..count).map(|_| random.range(RADII.0, RADII.1)).collect();
    let area: f64 = radii.iter().map(|r| PI * r * r).sum();
    let side = (area / PACKING_FRACTION).sqrt();
    let per_row = (count as f64).sqrt().ceil() as usize;
    let spacing = side / per_row as f64;
    assert!(
        spacing > 2.0 * RADII.1,
        "the lattice is too tight to start without overlaps"
    );
    let balls = radii
        .iter()
        .enumerate()
        .map(|(i, &radius)| {
            let slack = spacing / 2.0 - radius;
            let x = ((i % per_row) as f64 + 0.5) * spacing + random.range(-slack, slack);
            let y = ((i / per_row) as f64 + 0.5) * spacing + random.range(-slack, slack);
            let vx = random.range(-MAX_SPEED, MAX_SPEED);
            let vy = random.range(-MAX_SPEED, MAX_SPEED);
            Ball::new(x, y, vx, vy, radius, 0)
        })
        .collect();
    let walls = Walls {
        width: side,
        height: side,
        damping: 1.0,
    };
    (balls, walls)
}

/// One frame: the lesson's step for every ball, then the collisions. The step is written out
/// here rather than called as `Ball::step`, whose signature belongs to the scene work and may
/// change; it is the same arithmetic, in the same order.
fn frame(balls: &mut [Ball], walls: &Walls, gravity: [f64; 2], collisions: &mut Collisions) {
    for ball in balls.iter_mut() {
        ball.vx += gravity[0];
        ball.vy += gravity[1];
        ball.x += ball.vx;
        ball.y += ball.vy;
        walls.bounce(ball);
        ball.trail.push(ball.x, ball.y);
    }
    collisions.resolve(balls);
}

fn collisions(c: &mut Criterion) {
    let mut group = c.benchmark_group("frame_with_collisions");
    for count in [1_000, 10_000, 100_000] {
        group.throughput(Throughput::Elements(count as u64));
        group.bench_function(BenchmarkId::from_parameter(count), |bencher| {
            let (mut balls, walls) = scene(count);
            let mut collisions = Collisions::new(1.0);
            bencher.iter(|| frame(&mut balls, &walls, black_box(GRAVITY), &mut collisions));
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    targets = collisions
}
criterion_main!(benches);
