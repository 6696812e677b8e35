//! Drawing and encoding reuse their buffers: once warmed up, more frames allocate nothing. And
//! a trail, and each collision solver, take the memory the memory budget counts for them.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError};

use bouncing_ball::budget::Estimate;
use bouncing_ball::gif::GifWriter;
use bouncing_ball::physics::replay::{KeptFrames, Playback};
use bouncing_ball::physics::{Trail, Vec2};
use bouncing_ball::render::{Canvas, Renderer};
use bouncing_ball::scene::file as scene_file;
use bouncing_ball::testing::{kept_frames_bytes, queue_frames};
use bouncing_ball::Scene;

/// The system allocator, counting every allocation, and the bytes each thread holds.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Bytes allocated minus bytes freed on this thread (tests run side by side on threads).
    static BYTES_HELD: Cell<isize> = const { Cell::new(0) };
    /// The most `BYTES_HELD` has been since it was last set.
    static PEAK_HELD: Cell<isize> = const { Cell::new(0) };
}

fn hold(bytes: isize) {
    let held = BYTES_HELD.with(|held| {
        held.set(held.get() + bytes);
        held.get()
    });
    PEAK_HELD.with(|peak| peak.set(peak.get().max(held)));
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        hold(layout.size() as isize);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        hold(-(layout.size() as isize));
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        hold(new_size as isize - layout.size() as isize);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.load(Ordering::Relaxed)
}

/// Taken by the tests that allocate much, so that none runs while another counts every
/// thread's allocations.
static ALLOCATING: Mutex<()> = Mutex::new(());

/// Takes [`ALLOCATING`], also after a test that held it failed (that test's failure is the
/// one to read, not a poisoned lock in the next).
fn alone() -> MutexGuard<'static, ()> {
    ALLOCATING.lock().unwrap_or_else(PoisonError::into_inner)
}

#[test]
fn drawing_and_encoding_frames_allocate_nothing_once_warmed_up() {
    let _alone = alone();
    let scene = scene_file::preset("elastic", 1).unwrap();
    let renderer = Renderer::new(&scene).unwrap();
    let mut simulation = scene.simulation();
    let mut canvas = Canvas::new(&renderer);
    let mut gif = GifWriter::new(std::io::sink(), 320, 240, renderer.palette(), 30).unwrap();
    // Warm up for 10 queues' worth of frames, then count over the next 30 (960 frames).
    let (warm_up, counted) = (10 * queue_frames(320, 240), 30 * queue_frames(320, 240));
    let mut during = 0;
    for n in 0..warm_up + counted {
        simulation.step();
        let before = allocations();
        canvas.redraw(&renderer, simulation.balls());
        gif.write_changes(canvas.frame(), canvas.damage()).unwrap();
        if n >= warm_up {
            during += allocations() - before;
        }
    }
    // Buffers reach their largest size early.
    assert!(
        during < 30,
        "{during} allocations over {counted} frames: something allocates per frame or per queue"
    );
}

#[test]
fn a_full_trail_holds_exactly_the_bytes_the_memory_budget_counts_for_it() {
    // The budget refuses a scene whose memory would pass its limit before any work, from
    // `Trail::heap_bytes`: it must be what a trail really takes once it has cycled.
    for capacity in [0, 1, 2, 3, 4, 5, 7, 8, 20, 100] {
        let before = BYTES_HELD.with(Cell::get);
        let mut trail = Trail::new(capacity);
        for i in 0..3 * capacity + 5 {
            trail.push(Vec2::new(i as f64, 0.0));
        }
        let held = BYTES_HELD.with(Cell::get) - before;
        let counted = Trail::heap_bytes(capacity);
        assert_eq!(
            held as u64, counted,
            "a full trail of {capacity} points holds {held} bytes; the budget counts {counted}"
        );
        drop(trail);
    }
}

/// The most heap 20 frames of `scene` hold at once on this thread, bytes, and the memory the
/// budget estimates for it.
fn peak_over_frames(scene: &Scene) -> (i64, i64) {
    let before = BYTES_HELD.with(Cell::get);
    PEAK_HELD.with(|peak| peak.set(before));
    let mut simulation = scene.simulation();
    for _ in 0..20 {
        simulation.step();
    }
    let peak = PEAK_HELD.with(Cell::get) - before;
    drop(simulation);
    (peak as i64, Estimate::of(scene).memory as i64)
}

/// Asserts that the memory budget counts all of what `solver` holds per ball, and at most a
/// quarter more: its share of the estimate, and of the heap 20 frames hold, is scene `with`
/// it less the same scene `without` ball collisions (20,000 balls).
fn assert_solver_counted(solver: &str, with: &Scene, without: &Scene) {
    let (held_with, counted_with) = peak_over_frames(with);
    let (held_without, counted_without) = peak_over_frames(without);
    let (held, counted) = (held_with - held_without, counted_with - counted_without);
    assert!(
        held <= counted && counted <= held + held / 4,
        "{solver} holds {} bytes a ball at most; the budget counts {}",
        held / 20_000,
        counted / 20_000
    );
}

#[test]
fn exact_mode_holds_what_the_memory_budget_counts_for_it_and_at_most_a_quarter_less() {
    // The budget refuses a scene before any work from its estimate, which counts exact mode's
    // buffers per ball: all of them, or a run could pass its limit, and not far more, or runs
    // that fit would be refused. 20,000 balls spread over 2000 px.
    let _alone = alone();
    let crowd = |collisions: &str| {
        let text = format!(
            "width = 2000\nheight = 2000\ngravity = [0.0, 0.5]\nwalls = {{ damping = 0.9 }}\n\
             {collisions}\n[spawn]\ncount = 20000\nradius = 3.0\nmax_speed = 2.0\ntrail = 0\n"
        );
        scene_file::parse("crowd.toml", &text, 1).unwrap()
    };
    let exact = "ball_collisions = { restitution = 0.9 }\ncollisions = \"exact\"";
    assert_solver_counted("exact mode", &crowd(exact), &crowd(""));
}

#[test]
fn the_contact_solver_holds_what_the_memory_budget_counts_for_it_and_at_most_a_quarter_less() {
    // As for exact mode above, in the contact solver's worst case: 20,000 balls on one spot,
    // where every ball has its most contacts (`MAX_PAIRS_PER_BALL`).
    let _alone = alone();
    let heap = |collisions: &str| {
        let text = format!(
            "width = 1280\nheight = 720\ngravity = [0.0, 0.5]\nwalls = {{ damping = 0.5 }}\n\
             {collisions}\n[spawn]\ncount = 20000\nradius = 4.0\nmax_speed = 0.0\ntrail = 0\n"
        );
        let mut scene = scene_file::parse("heap.toml", &text, 1).unwrap();
        for ball in &mut scene.balls {
            (ball.x, ball.y) = (640.0, 360.0);
        }
        scene
    };
    let with = heap("ball_collisions = { restitution = 0.5 }");
    assert_solver_counted("the contact solver", &with, &heap(""));
}

/// The most heap the frames of `scene` take on this thread when its first `kept` frames are
/// stepped, kept and played back, beyond stepping them alone, bytes.
fn kept_frames_held(scene: &bouncing_ball::scene::Scene, kept: usize) -> i64 {
    let peak = |keep: bool| {
        let before = BYTES_HELD.with(Cell::get);
        PEAK_HELD.with(|peak| peak.set(before));
        let mut simulation = scene.simulation();
        let mut frames = keep.then(|| KeptFrames::new(&simulation, kept));
        for _ in 0..kept {
            simulation.step();
            if let Some(frames) = frames.as_mut() {
                assert!(frames.keep(&simulation), "the pile's frames fit");
            }
        }
        if let Some(frames) = frames {
            let mut playback = Playback::new(frames, simulation);
            for _ in 0..kept {
                playback.step();
            }
        }
        PEAK_HELD.with(Cell::get) - before
    };
    (peak(true) - peak(false)) as i64
}

#[test]
fn the_pilots_kept_frames_hold_what_the_memory_budget_counts_for_them_and_at_most_a_quarter_less() {
    // The pile's 300 frames of 150 balls with trails of 4: their motions, and the balls they
    // are played back into, trails filled.
    let _alone = alone();
    let scene = scene_file::preset("pile", 1).unwrap();
    let held = kept_frames_held(&scene, scene.frames as usize);
    let counted = kept_frames_bytes(&scene) as i64;
    assert!(
        held <= counted && counted <= held + held / 4,
        "the kept frames hold {held} bytes; the budget counts {counted}"
    );
}
