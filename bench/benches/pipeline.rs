//! The pipeline's cost on the lesson's scene: one frame rendered, one frame compressed (and
//! in both row orders, as the encoder codes each layout), and the whole 200-frame scene
//! simulated, rendered and encoded into memory.
//!
//! Run: `cargo bench --bench pipeline` (about 15 s; add `-- --warm-up-time 1
//! --measurement-time 3` for a quicker look).

use bouncing_ball::gif::lzw::{min_code_size, Choices, Lzw};
use bouncing_ball::gif::GifWriter;
use bouncing_ball::physics::simulation::Simulation;
use bouncing_ball::render::{IndexedFrame, Renderer};
use bouncing_ball::scene::file as scene_file;
use bouncing_ball::testing::interlace;
use bouncing_ball::Scene;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

/// The frame the golden tests also check mid-flight: a full trail, the ball falling.
const SAMPLE_FRAME: u32 = 57;

fn lesson() -> Scene {
    scene_file::preset("lesson", 1).expect("the lesson preset loads")
}

/// The simulation after `frames` frames, and the renderer for its scene.
fn after(scene: &Scene, frames: u32) -> (Simulation, Renderer) {
    let mut simulation = scene.simulation();
    for _ in 0..frames {
        simulation.step();
    }
    let renderer = Renderer::new(scene).expect("the lesson's colours fit");
    (simulation, renderer)
}

/// Simulates, renders and encodes every frame of `scene` into memory; returns the GIF size.
fn whole_scene(scene: &Scene, renderer: &Renderer) -> usize {
    let mut simulation = scene.simulation();
    let mut frame = renderer.new_frame();
    let mut gif = GifWriter::new(
        Vec::new(),
        scene.width as u16,
        scene.height as u16,
        renderer.palette(),
        scene.frame_ms,
    )
    .expect("writing to memory");
    for _ in 0..scene.frames {
        simulation.step();
        renderer.draw(simulation.balls(), &mut frame);
        gif.write_frame(&frame).expect("writing to memory");
    }
    gif.finish().expect("writing to memory").len()
}

fn pipeline(c: &mut Criterion) {
    let scene = lesson();
    let (simulation, renderer) = after(&scene, SAMPLE_FRAME + 1);
    let mut frame: IndexedFrame = renderer.new_frame();
    let pixels = u64::from(scene.width * scene.height);

    let mut group = c.benchmark_group("lesson");
    group.throughput(Throughput::Elements(pixels));
    group.bench_function("render one frame", |b| {
        b.iter(|| renderer.draw(simulation.balls(), &mut frame))
    });

    renderer.draw(simulation.balls(), &mut frame);
    let code_size = min_code_size(renderer.palette().colours().len());
    let (mut lzw, mut out) = (Lzw::new(), Vec::new());
    group.bench_function("compress one whole frame (LZW)", |b| {
        b.iter(|| {
            lzw.compress(
                code_size,
                frame.as_raw(),
                Choices::GREEDY,
                usize::MAX,
                &mut out,
            )
        })
    });

    // A layout's two row orders, as the encoder codes every frame.
    let mut interlaced = Vec::new();
    interlace(frame.as_raw(), scene.width as usize, &mut interlaced);
    let orders = [frame.as_raw(), &interlaced[..]];
    group.throughput(Throughput::Elements(2 * pixels));
    group.bench_function("both row orders", |b| {
        b.iter(|| {
            orders.map(|pixels| {
                lzw.compress(code_size, pixels, Choices::GREEDY, usize::MAX, &mut out)
            })
        })
    });

    group.throughput(Throughput::Elements(u64::from(scene.frames)));
    group.bench_function("whole scene in memory (200 frames)", |b| {
        b.iter(|| whole_scene(&scene, &renderer))
    });
    group.finish();
}

criterion_group!(benches, pipeline);
criterion_main!(benches);
