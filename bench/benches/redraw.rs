//! Drawing each frame and finding what changed in it, two ways: every frame drawn whole and
//! compared whole, or drawn again only where it changed and compared only there (what a run
//! does, `Canvas`). On scenes that never rest (many, billiards) and the pile, whose balls come
//! to rest. The physics is run beforehand and the GIF's compression left out: only drawing and
//! comparing are timed.
//!
//! Run: `cargo bench -p bouncing_ball_bench --bench redraw` (add `-- --warm-up-time 1
//! --measurement-time 3` for a quicker look).

use bouncing_ball::gif::delta::{changed_rect, changed_rect_within, paste, Rect};
use bouncing_ball::physics::Ball;
use bouncing_ball::render::{Canvas, Damage, IndexedFrame, Renderer};
use bouncing_ball::scene::file as scene_file;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

/// Every frame's balls of a preset, simulated once.
fn states(name: &str) -> (Renderer, Vec<Vec<Ball>>) {
    let scene = scene_file::preset(name, 1).expect("the preset loads");
    let mut simulation = scene.simulation();
    let states = (0..scene.frames)
        .map(|_| {
            simulation.step();
            simulation.balls().to_vec()
        })
        .collect();
    (Renderer::new(&scene).expect("the colours fit"), states)
}

/// Lays what changed in `frame` over `shown`, as the GIF encoder does; returns the rectangle.
fn follow(shown: &mut IndexedFrame, frame: &IndexedFrame, changed: Option<Rect>) -> Option<Rect> {
    if let Some(rect) = changed {
        paste(frame, rect, shown);
    }
    changed
}

fn redraw(c: &mut Criterion) {
    for name in ["many", "billiards", "pile"] {
        let (renderer, states) = states(name);
        let mut group = c.benchmark_group(name);
        group.throughput(Throughput::Elements(states.len() as u64));
        group.bench_function("every frame whole", |b| {
            b.iter(|| {
                let (mut frame, mut shown) = (renderer.new_frame(), renderer.new_frame());
                let mut rects = 0;
                for balls in &states {
                    renderer.draw(balls, &mut frame);
                    let changed = changed_rect(&shown, &frame);
                    rects += usize::from(follow(&mut shown, &frame, changed).is_some());
                }
                rects
            })
        });
        group.bench_function("only what changed", |b| {
            b.iter(|| {
                let (mut canvas, mut shown) = (Canvas::new(&renderer), renderer.new_frame());
                let mut rects = 0;
                for balls in &states {
                    canvas.redraw(&renderer, balls);
                    let frame = canvas.frame();
                    let changed = match canvas.damage() {
                        Damage::Unchanged => None,
                        Damage::Whole => changed_rect(&shown, frame),
                        Damage::Areas(areas) => areas
                            .iter()
                            .filter_map(|&area| changed_rect_within(&shown, frame, area))
                            .reduce(Rect::union),
                    };
                    rects += usize::from(follow(&mut shown, frame, changed).is_some());
                }
                rects
            })
        });
        group.finish();
    }
}

criterion_group!(benches, redraw);
criterion_main!(benches);
