//! How much the order of the balls in memory matters to exact mode, on the `exact_events`
//! bench's gas: the same balls numbered in three orders, each stepped by the library.
//!
//! - *Lattice rows*, as the bench builds them: neighbours in a row are neighbours in memory,
//!   the rows above and below a row's length away.
//! - *Morton order* of their grid cells (one diameter wide): the bits of the column and the
//!   row interleaved, so that most of a ball's neighbours lie within a short stretch of memory.
//! - *Shuffled* (seeded): no locality at all.
//!
//! The three run in turns, so the host's noise falls on each alike; the table gives the
//! median of the turns, in nanoseconds per collision event (bounces between balls and off
//! the walls). Run: `cargo run --release -p bouncing_ball_bench --example ball_order [BALLS]`
//! (100,000 balls by default, about 25 s).

use std::time::Instant;

use bouncing_ball::scene::random::Random;
use bouncing_ball::Scene;
use bouncing_ball_bench::{exact_gas, EXACT_GAS_RADIUS as RADIUS, EXACT_GAS_STIR as STIR};

/// Turns of each order, and frames per turn.
const TURNS: usize = 7;
const FRAMES_PER_TURN: u32 = 10;

/// The orders, by name.
const ORDERS: [&str; 3] = ["lattice rows", "Morton", "shuffled"];

/// `value`'s bits spread out to every other bit (bit k to bit 2k).
fn spread_bits(value: u32) -> u64 {
    let mut v = u64::from(value);
    v = (v | v << 16) & 0x0000_ffff_0000_ffff;
    v = (v | v << 8) & 0x00ff_00ff_00ff_00ff;
    v = (v | v << 4) & 0x0f0f_0f0f_0f0f_0f0f;
    v = (v | v << 2) & 0x3333_3333_3333_3333;
    (v | v << 1) & 0x5555_5555_5555_5555
}

/// Where the cell of column `x` and row `y` comes on the Morton curve.
fn morton(x: u32, y: u32) -> u64 {
    spread_bits(x) | spread_bits(y) << 1
}

/// The gas of `count` balls, its balls numbered in `order`.
fn gas_in(order: &str, count: usize) -> Scene {
    let mut scene = exact_gas(count);
    let cell = 2.0 * RADIUS;
    match order {
        "Morton" => scene
            .balls
            .sort_by_key(|ball| morton((ball.x / cell) as u32, (ball.y / cell) as u32)),
        "shuffled" => {
            let mut random = Random::new(7);
            for i in (1..scene.balls.len()).rev() {
                let j = (random.next_u64() % (i as u64 + 1)) as usize;
                scene.balls.swap(i, j);
            }
        }
        _ => {}
    }
    scene
}

fn main() {
    let count = std::env::args()
        .nth(1)
        .map_or(100_000, |arg| arg.parse().expect("BALLS: a whole number"));
    let mut simulations: Vec<_> = ORDERS
        .iter()
        .map(|order| {
            let mut simulation = gas_in(order, count).simulation();
            for _ in 0..STIR {
                simulation.step();
            }
            simulation
        })
        .collect();
    let mut nanoseconds = vec![Vec::new(); ORDERS.len()];
    for _ in 0..TURNS {
        for (simulation, times) in simulations.iter_mut().zip(&mut nanoseconds) {
            let (mut collisions, started) = (0, Instant::now());
            for _ in 0..FRAMES_PER_TURN {
                simulation.step();
                let counts = simulation.event_counts().expect("exact mode counts events");
                collisions += counts.ball_collisions + counts.contacts;
            }
            times.push(started.elapsed().as_secs_f64() * 1e9 / collisions as f64);
        }
    }
    println!("| {count} balls, order | ns per collision event, median of {TURNS} turns |");
    println!("|---|---:|");
    for (order, times) in ORDERS.iter().zip(&mut nanoseconds) {
        times.sort_by(f64::total_cmp);
        println!("| {order} | {:.0} |", times[TURNS / 2]);
    }
}
