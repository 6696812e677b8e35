//! How long this machine takes to fetch one cache line from a random place in blocks of
//! memory of growing size: the cost the event-driven step pays for each ball it has to
//! fetch, since events come in time order and so at balls anywhere in memory.
//!
//! Each line of the block holds the address of the next line to read, in a random cycle
//! through the whole block, so every load waits for the one before (a pointer chase): the
//! time per load is the latency of whichever level of memory the block fits in.
//!
//! Run: `cargo run --release -p bouncing_ball_bench --example memory_latency` (about 15 s).

use std::hint::black_box;
use std::time::Instant;

use bouncing_ball::scene::random::Random;

/// Bytes in a cache line: one place per line, so no two places share one.
const LINE: usize = 64;
/// Loads timed per block size.
const LOADS: usize = 20_000_000;

fn main() {
    println!("{:>10} {:>12}", "block", "ns per load");
    for megabytes in [1, 2, 4, 8, 16, 32, 64, 128] {
        let lines = megabytes * (1 << 20) / LINE;
        let next = random_cycle(lines, &mut Random::new(megabytes as u64));
        // One word per line, so each load touches a line of its own.
        let stride = LINE / size_of::<u64>();
        let mut block = vec![0u64; lines * stride];
        for (line, &after) in next.iter().enumerate() {
            block[line * stride] = (after * stride) as u64;
        }
        let start = Instant::now();
        let mut at = 0usize;
        for _ in 0..LOADS {
            at = block[at] as usize;
        }
        let nanoseconds = start.elapsed().as_secs_f64() * 1e9 / LOADS as f64;
        black_box(at);
        println!("{:>7} MB {nanoseconds:>12.1}", megabytes);
    }
}

/// For each of `count` places, the next one in a single random cycle through them all (the
/// places shuffled, each pointing at the one after it, the last at the first), so a chase
/// from anywhere visits every place before it repeats.
fn random_cycle(count: usize, random: &mut Random) -> Vec<usize> {
    let mut order: Vec<usize> = (0..count).collect();
    for i in (1..count).rev() {
        let j = (random.next_u64() % (i as u64 + 1)) as usize;
        order.swap(i, j);
    }
    let mut next = vec![0; count];
    for k in 0..count {
        next[order[k]] = order[(k + 1) % count];
    }
    next
}
