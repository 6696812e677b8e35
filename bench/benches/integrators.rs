//! Per-frame cost of each physics option: one ball advanced one frame (one step), by
//! integrator and collision mode, bouncing in the lesson's box, and in free flight with drag.
//!
//! `cargo bench --bench integrators` (short on purpose: 10 samples of 2 s).

use std::hint::black_box;
use std::time::Duration;

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::effects::Effects;
use bouncing_ball::physics::motion::{CollisionMode, Motion};
use bouncing_ball::physics::{Integrator, Vec2};
use bouncing_ball_lab::accuracy::{lesson_effects, GRAVITY, RADIUS};
use criterion::{criterion_group, criterion_main, Criterion};

const INTEGRATORS: [Integrator; 4] = [
    Integrator::ExplicitEuler,
    Integrator::SemiImplicitEuler,
    Integrator::VelocityVerlet,
    Integrator::Rk4,
];

/// Times `motion` advancing the lesson's ball under `effects`, frame after frame.
fn bench_frames(c: &mut Criterion, group: &str, effects: &Effects, modes: &[CollisionMode]) {
    let mut group = c.benchmark_group(group);
    for integrator in INTEGRATORS {
        for &collisions in modes {
            let motion = Motion {
                integrator,
                substeps: 1,
                collisions,
                ..Motion::default()
            };
            let mut ball = Ball::new(40.0, 40.0, 5.2, 0.0, RADIUS, 0);
            group.bench_function(format!("{integrator:?}/{collisions:?}"), |b| {
                b.iter(|| motion.advance(black_box(&mut ball), black_box(effects)))
            });
        }
    }
    group.finish();
}

fn per_frame(c: &mut Criterion) {
    // Elastic, so the ball never comes to rest and every frame costs the same on average.
    bench_frames(
        c,
        "bouncing",
        &lesson_effects(1.0),
        &[CollisionMode::Clamp, CollisionMode::Exact],
    );
    let drag = Effects {
        gravity: Some(Vec2::new(0.0, GRAVITY)),
        drag: Some(0.01),
        ..Effects::default()
    };
    bench_frames(c, "free flight with drag", &drag, &[CollisionMode::Clamp]);
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    targets = per_frame
}
criterion_main!(benches);
