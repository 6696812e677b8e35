//! How the cost of a frame with ball-ball collisions grows with the number of balls.
//!
//! Each frame is `Simulation::step` on a scene with walls and ball-ball collisions at the
//! default settings (the contact solver with its default iterations), for 1,000, 10,000 and
//! 100,000 balls at packing fraction 0.3 (the balls cover 30 % of the box). Criterion
//! reports the time per frame and, as "elements", ball-steps per second; the cost per ball
//! should stay flat as N grows. A second group times a frame of the `pile` preset (150
//! balls heaped under gravity) once it has settled, by the contact solver and in exact
//! mode; a third times a frame of presets that never rest (`billiards`: the contact solver
//! without gravity; `many`: balls that never meet), so that what rest saves is not paid for
//! where nothing rests.
//!
//! Run: `RAYON_NUM_THREADS=1 cargo bench -p bouncing_ball_bench --bench collisions` (about
//! 30 s; the physics is single-threaded either way).

use std::time::Duration;

use bouncing_ball::physics::motion::CollisionMode;
use bouncing_ball::scene::file::preset;
use bouncing_ball::scene::random::Random;
use bouncing_ball::Scene;
use bouncing_ball_bench::lattice_gas;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

/// Share of the box the balls cover.
const PACKING_FRACTION: f64 = 0.3;
/// Radii are spread over this range, px, so masses differ and the grid sees mixed sizes.
const RADII: (f64, f64) = (2.0, 4.0);
/// Starting speeds are up to this much along each axis, px/frame.
const MAX_SPEED: f64 = 2.0;

/// `count` balls of mixed radii in the benchmarks' elastic gas (no gravity, no overlaps).
fn scene(count: usize) -> Scene {
    let mut random = Random::new(count as u64);
    let radii: Vec<f64> = (0..count).map(|_| random.range(RADII.0, RADII.1)).collect();
    lattice_gas(&radii, PACKING_FRACTION, MAX_SPEED, &mut random)
}

fn collisions(c: &mut Criterion) {
    let mut group = c.benchmark_group("frame_with_collisions");
    for count in [1_000, 10_000, 100_000] {
        group.throughput(Throughput::Elements(count as u64));
        group.bench_function(BenchmarkId::from_parameter(count), |bencher| {
            let scene = scene(count);
            scene.validate().expect("a valid benchmark scene");
            let mut simulation = scene.simulation();
            bencher.iter(|| simulation.step());
        });
    }
    group.finish();
}

/// Frames of the pile preset run before timing: by then it has come to rest.
const SETTLING_FRAMES: u32 = 1_000;

fn pile(c: &mut Criterion) {
    let mut group = c.benchmark_group("frame_of_settled_pile");
    for collisions in [CollisionMode::Clamp, CollisionMode::Exact] {
        let mut scene = preset("pile", 1).expect("the pile preset");
        scene.motion.collisions = collisions;
        group.throughput(Throughput::Elements(scene.balls.len() as u64));
        let name = format!("{collisions:?}").to_lowercase();
        group.bench_function(BenchmarkId::new(name, scene.balls.len()), |bencher| {
            let mut simulation = scene.simulation();
            for _ in 0..SETTLING_FRAMES {
                simulation.step();
            }
            bencher.iter(|| simulation.step());
        });
    }
    group.finish();
}

/// A frame of presets whose balls never rest, from their start.
fn restless(c: &mut Criterion) {
    let mut group = c.benchmark_group("frame_of_restless_preset");
    for name in ["billiards", "many"] {
        let scene = preset(name, 1).expect("the preset");
        group.throughput(Throughput::Elements(scene.balls.len() as u64));
        group.bench_function(name, |bencher| {
            let mut simulation = scene.simulation();
            bencher.iter(|| simulation.step());
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
    targets = collisions, pile, restless
}
criterion_main!(benches);
