//! Exercise 3 of the lesson: implement the physics from scratch.
//!
//! Run it: `cargo run --release --example starter`. It writes `starter.gif` with the
//! library's renderer, then compares your ball with the library's `Ball::step` frame by frame.
//! As shipped the ball just floats (nothing moves it); fill in the three TODOs in
//! `StarterBall::step` until it reports a match. When your ball differs, it says at which
//! frame, shows the values, names the lesson's pitfall the difference looks like, and exits
//! with 1 (0 on a match), so a script or a class's CI can grade it.

use std::io::BufWriter;
use std::path::Path;
use std::process::ExitCode;

use bouncing_ball::check::pitfalls::Pitfall;
use bouncing_ball::gif::GifWriter;
use bouncing_ball::output::{commit_all, AtomicFile};
use bouncing_ball::physics::{Ball, Trail, Vec2, Walls};
use bouncing_ball::render::Renderer;
use bouncing_ball::{BallSpec, Scene};

const WIDTH: f64 = 320.0; // canvas width, px
const HEIGHT: f64 = 240.0; // canvas height, px
const RADIUS: f64 = 12.0; // ball radius, px
const START: (f64, f64) = (40.0, 40.0); // start position, px
const INITIAL_VEL: (f64, f64) = (5.2, 0.0); // start velocity, px/frame
const GRAVITY: f64 = 0.5; // px/frame²
const BOUNCE_DAMPING: f64 = 0.88; // share of speed kept at a bounce
const TRAIL_LEN: usize = 20; // points
const FRAMES: u32 = 200;

/// Your ball.
struct StarterBall {
    x: f64,
    y: f64,
    vx: f64,
    vy: f64,
    radius: f64,
    trail: Trail,
}

impl StarterBall {
    fn step(&mut self) {
        // TODO 1: add GRAVITY to self.vy.

        // TODO 2: advance self.x by self.vx and self.y by self.vy.

        // TODO 3: for each of the four walls (left, right, top, bottom), clamp the
        // position to the wall, then flip the relevant velocity times BOUNCE_DAMPING.
        // Left/right as one if/else, top/bottom as another.

        // Given: the trail remembers where the ball is after the move.
        self.trail.push(Vec2::new(self.x, self.y));
    }

    /// The library's ball at the same state, so the library can draw it.
    fn as_ball(&self) -> Ball {
        Ball {
            x: self.x,
            y: self.y,
            vx: self.vx,
            vy: self.vy,
            radius: self.radius,
            trail: self.trail.clone(),
        }
    }
}

fn scene() -> Scene {
    Scene {
        balls: vec![BallSpec {
            x: START.0,
            y: START.1,
            vx: INITIAL_VEL.0,
            vy: INITIAL_VEL.1,
            radius: RADIUS,
            colour: [255, 200, 60],
            trail_colour: [60, 140, 255],
            trail: TRAIL_LEN,
        }],
        gravity: Some(Vec2::new(0.0, GRAVITY)),
        walls: Some(BOUNCE_DAMPING),
        frames: FRAMES,
        frame_ms: 30,
        ..Scene::empty(WIDTH as u32, HEIGHT as u32)
    }
}

/// Which of the lesson's pitfalls turns `before` into `yours` in one step, if any does (the
/// library simulates each: `bouncing_ball::check::pitfalls`, which `bouncing_ball check` uses
/// too), or whole numbers for the position, which no one step shows.
fn diagnose(before: &Ball, yours: &Ball, library: &Ball, walls: &Walls) -> Option<&'static str> {
    let simulated = Pitfall::of_step(before, yours, GRAVITY, walls).map(Pitfall::explain);
    let whole = |ball: &Ball| ball.x.fract() == 0.0 && ball.y.fract() == 0.0;
    simulated.or_else(|| {
        (whole(yours) && !whole(library)).then_some(
            "using whole numbers for the position: sub-pixel motion vanishes and slow balls \
             freeze (keep x and y as f64)",
        )
    })
}

/// Exits 0 on a match and 1 on a mismatch, so a script or CI can grade it.
fn main() -> std::io::Result<ExitCode> {
    let scene = scene();
    let renderer = Renderer::new(&scene).expect("the lesson's colours fit a GIF");
    // Written to a temporary file and renamed into place at the end, so a failed or
    // interrupted run never leaves half a GIF (or clobbers the last good one).
    let file = AtomicFile::create(Path::new("starter.gif")).map_err(std::io::Error::other)?;
    let out = BufWriter::new(file.file());
    let mut gif = GifWriter::new(
        out,
        WIDTH as u16,
        HEIGHT as u16,
        renderer.palette(),
        scene.frame_ms,
    )?;
    let mut frame = renderer.new_frame();

    let mut yours = StarterBall {
        x: START.0,
        y: START.1,
        vx: INITIAL_VEL.0,
        vy: INITIAL_VEL.1,
        radius: RADIUS,
        trail: Trail::new(TRAIL_LEN),
    };
    let walls = Walls {
        width: WIDTH,
        height: HEIGHT,
        damping: BOUNCE_DAMPING,
    };
    let mut library = yours.as_ball();
    let mut first_difference = None;
    for n in 0..FRAMES {
        let before = library.clone();
        yours.step();
        library.step(GRAVITY, &walls);
        let mine = yours.as_ball();
        if first_difference.is_none() && mine != library {
            first_difference = Some((n, before, mine.clone(), library.clone()));
        }
        renderer.draw(&[mine], &mut frame);
        gif.write_frame(&frame)?;
    }
    gif.finish()?.into_inner().map_err(|e| e.into_error())?;
    commit_all(vec![file]).map_err(std::io::Error::other)?;
    println!("wrote starter.gif ({FRAMES} frames)");

    match first_difference {
        None => {
            println!(
                "MATCH: your ball follows the library's Ball exactly for all {FRAMES} frames."
            );
            Ok(ExitCode::SUCCESS)
        }
        Some((n, before, a, b)) => {
            println!("MISMATCH at frame {n} (0 = after the first step):");
            for (name, yours, library) in [
                ("x", a.x, b.x),
                ("y", a.y, b.y),
                ("vx", a.vx, b.vx),
                ("vy", a.vy, b.vy),
            ] {
                let marker = if yours == library {
                    ""
                } else {
                    "   <- differs"
                };
                println!("  {name:>2}: yours {yours:<22} library {library:<22}{marker}");
            }
            if a.trail != b.trail {
                println!("  the trails differ");
            }
            match diagnose(&before, &a, &b, &walls) {
                Some(pitfall) => println!("Looks like a pitfall from the lesson: {pitfall}."),
                None => {
                    println!("This is not one of the lesson's pitfalls: compare with the hint.")
                }
            }
            Ok(ExitCode::FAILURE)
        }
    }
}
