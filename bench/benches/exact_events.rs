//! How fast exact mode resolves ball-ball collisions, and whether the cost of one stays flat
//! as the number of balls grows (the event calendar files an event in O(1), the grid finds
//! neighbours in O(1)).
//!
//! An elastic gas: equal balls of radius 3 covering 30 % of a box with elastic walls, no
//! gravity, started on a jittered square lattice with random velocities and stirred for a few
//! frames first. Criterion times one frame (`Simulation::step`) and reports, as "elements",
//! collision events per second: bounces between two balls and off the walls, not the
//! crossings between grid cells (the mean over 20 frames before timing sets the count per
//! frame; it is printed with the other events). 1,000, 10,000, 100,000 balls.
//!
//! Run: `cargo bench -p bouncing_ball_bench --bench exact_events` (about 40 s).

use std::time::Duration;

use bouncing_ball_bench::{exact_gas, EXACT_GAS_STIR as STIR};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

fn exact_events(c: &mut Criterion) {
    let mut group = c.benchmark_group("exact_ball_collisions");
    for count in [1_000, 10_000, 100_000] {
        let scene = exact_gas(count);
        scene.validate().expect("a valid benchmark scene");
        let mut simulation = scene.simulation();
        for _ in 0..STIR {
            simulation.step();
        }
        let (mut balls, mut walls, mut events) = (0, 0, 0);
        for _ in 0..STIR {
            simulation.step();
            let counts = simulation.event_counts().expect("exact mode counts events");
            balls += counts.ball_collisions;
            walls += counts.contacts;
            events += counts.events;
        }
        let per_frame = (balls + walls) / u64::from(STIR);
        println!(
            "{count} balls, per frame: {per_frame} collision events ({} ball-ball, {} wall), \
             {} events in all (with cell crossings)",
            balls / u64::from(STIR),
            walls / u64::from(STIR),
            events / u64::from(STIR)
        );
        group.throughput(Throughput::Elements(per_frame));
        group.bench_function(BenchmarkId::from_parameter(count), |bencher| {
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
        .measurement_time(Duration::from_secs(4));
    targets = exact_events
}
criterion_main!(benches);
