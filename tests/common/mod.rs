//! Helpers shared by the integration tests: the lesson's scene spelled out, a GIF decoder
//! that composites frames as a viewer does, and golden-image comparison.
#![allow(dead_code)] // each test file uses its own subset

pub mod process;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use bouncing_ball::physics::Vec2;
use bouncing_ball::render::{to_rgb, Renderer};
use bouncing_ball::testing::lzw_indices;
use bouncing_ball::{BallSpec, Scene};
use image::RgbImage;

/// The lesson's default scene, written out here so that a learner's edits to main.rs
/// never change what the tests expect.
pub fn lesson_scene() -> Scene {
    Scene {
        balls: vec![BallSpec {
            x: 40.0,
            y: 40.0,
            vx: 5.2,
            vy: 0.0,
            radius: 12.0,
            colour: [255, 200, 60],
            trail_colour: [60, 140, 255],
            trail: 20,
        }],
        gravity: Some(Vec2::new(0.0, 0.5)),
        walls: Some(0.88),
        frames: 200,
        frame_ms: 30,
        ..Scene::empty(320, 240)
    }
}

/// Every frame of `scene` as RGB, rendered by the library.
pub fn render_frames(scene: &Scene) -> Vec<RgbImage> {
    let renderer = Renderer::new(scene).expect("scene colours fit a GIF");
    let mut simulation = scene.simulation();
    let mut frame = renderer.new_frame();
    (0..scene.frames)
        .map(|_| {
            simulation.step();
            renderer.draw(simulation.balls(), &mut frame);
            to_rgb(&frame, renderer.palette())
        })
        .collect()
}

/// A decoded GIF: each frame as a viewer shows it, plus the timing and loop fields.
pub struct DecodedGif {
    pub width: u32,
    pub height: u32,
    pub frames: Vec<RgbImage>,
    pub delays_cs: Vec<u16>,
    pub repeat: gif::Repeat,
}

impl DecodedGif {
    /// The frames as a viewer sees them over time, one per `frame_cs`: a frame shown for k
    /// frames' time (the encoder merges identical frames into the one before) comes k times.
    /// With `frame_cs` 0 no frame is merged, and the frames are as stored.
    pub fn timeline(&self, frame_cs: u16) -> Vec<&RgbImage> {
        if frame_cs == 0 {
            return self.frames.iter().collect();
        }
        let shown = self.frames.iter().zip(&self.delays_cs);
        shown
            .flat_map(|(frame, &delay)| {
                assert!(
                    delay > 0 && delay % frame_cs == 0,
                    "a delay of {delay} cs is not a whole number of {frame_cs} cs frames"
                );
                std::iter::repeat_n(frame, usize::from(delay / frame_cs))
            })
            .collect()
    }
}

/// Decodes a GIF, compositing each frame over the previous one (disposal Keep and
/// transparency), so tests see exactly what a viewer shows.
///
/// The gif crate reads the blocks; each frame's pixels are decoded by the library's
/// `lzw_indices` (the gif crate's own pixel decoding rejects some valid interlaced frames).
pub fn decode_gif(path: &Path) -> DecodedGif {
    let file = std::fs::File::open(path).unwrap_or_else(|e| panic!("open {}: {e}", path.display()));
    let mut options = gif::DecodeOptions::new();
    options.skip_frame_decoding(true);
    let mut decoder = options.read_info(file).expect("a valid GIF header");
    let (width, height) = (u32::from(decoder.width()), u32::from(decoder.height()));
    let global = decoder.global_palette().map(<[u8]>::to_vec);
    let mut canvas = RgbImage::new(width, height);
    let (mut frames, mut delays_cs) = (Vec::new(), Vec::new());
    while let Some(frame) = decoder.read_next_frame().expect("a valid GIF frame") {
        let (width, height) = (u32::from(frame.width), u32::from(frame.height));
        let pixels = lzw_indices(&frame.buffer, width, height, frame.interlaced)
            .expect("a whole frame of pixels");
        let palette = frame
            .palette
            .clone()
            .or_else(|| global.clone())
            .expect("a palette");
        for row in 0..u32::from(frame.height) {
            for col in 0..u32::from(frame.width) {
                let index = pixels[(row * u32::from(frame.width) + col) as usize];
                if Some(index) == frame.transparent {
                    continue;
                }
                let at = usize::from(index) * 3;
                let rgb = image::Rgb([palette[at], palette[at + 1], palette[at + 2]]);
                canvas.put_pixel(u32::from(frame.left) + col, u32::from(frame.top) + row, rgb);
            }
        }
        frames.push(canvas.clone());
        delays_cs.push(frame.delay);
    }
    DecodedGif {
        width,
        height,
        frames,
        delays_cs,
        repeat: decoder.repeat(),
    }
}

/// Where tests write what they produce (under the target dir, never beside the sources).
pub fn test_output_dir() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("golden");
    std::fs::create_dir_all(&dir).expect("create the test output folder");
    dir
}

/// How to regenerate the lesson-made test data (goldens, frame CRCs, Pillow's circles).
pub const REBLESS: &str = "python3 tools/lesson.py bless (needs Pillow: pip install pillow)";

/// Compares `actual` with the committed golden `tests/golden/NAME.png`, pixel by pixel.
/// Goldens are drawn by the lesson's script with Pillow (`tools/lesson.py bless`), never by
/// this program. On a mismatch it writes `NAME.new.png` and `NAME.diff.png` and names them.
pub fn assert_golden(name: &str, actual: &RgbImage) {
    let golden_path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(format!("{name}.png"));
    let golden = image::open(&golden_path)
        .unwrap_or_else(|e| {
            panic!(
                "cannot read golden {}: {e} (the lesson's script makes it: {REBLESS})",
                golden_path.display()
            )
        })
        .to_rgb8();
    let same_size = golden.dimensions() == actual.dimensions();
    let differing = if same_size {
        golden
            .pixels()
            .zip(actual.pixels())
            .filter(|(g, a)| g != a)
            .count()
    } else {
        usize::MAX
    };
    if differing == 0 {
        return;
    }
    let out = test_output_dir();
    let new_path = out.join(format!("{name}.new.png"));
    let diff_path = out.join(format!("{name}.diff.png"));
    actual.save(&new_path).expect("write the new image");
    if same_size {
        let diff = RgbImage::from_fn(actual.width(), actual.height(), |x, y| {
            if golden.get_pixel(x, y) == actual.get_pixel(x, y) {
                image::Rgb([0, 0, 0])
            } else {
                image::Rgb([255, 0, 255])
            }
        });
        diff.save(&diff_path).expect("write the diff image");
    }
    panic!(
        "{name}: {} pixels differ from the lesson script's {} (sizes {:?} vs {:?}).\n  new:  {}\n  diff: {} (magenta = differs)\n  Our frames must be Pillow's. Only if the lesson's script or Pillow changed on purpose, re-bless: {REBLESS}",
        if same_size { differing.to_string() } else { "all".to_string() },
        golden_path.display(),
        golden.dimensions(),
        actual.dimensions(),
        new_path.display(),
        diff_path.display(),
    );
}

/// A white ball without a trail, for physics tests that never draw it.
pub fn white_ball(x: f64, y: f64, vx: f64, vy: f64, radius: f64) -> BallSpec {
    BallSpec {
        x,
        y,
        vx,
        vy,
        radius,
        colour: [255, 255, 255],
        trail_colour: [255, 255, 255],
        trail: 0,
    }
}

/// The program, run in `dir` with `args`.
pub fn run_in(dir: &Path, args: &[&str]) -> Output {
    output_of(
        Command::new(env!("CARGO_BIN_EXE_bouncing_ball"))
            .args(args)
            .current_dir(dir),
    )
}

/// What `command` printed and how it exited. Wine (the Windows leg of CI) now and then fails
/// to start a process at all, with ERROR_INTERNAL_ERROR (1359), when many tests start
/// processes at once; the program never ran then, so starting it again is safe. Any other
/// failure to start is the test's failure.
pub fn output_of(command: &mut Command) -> Output {
    const WINE_INTERNAL_ERROR: i32 = 1359;
    let mut tries = 0;
    loop {
        match command.output() {
            Err(error) if error.raw_os_error() == Some(WINE_INTERNAL_ERROR) && tries < 5 => {
                tries += 1;
                eprintln!("starting the program failed ({error}); try {tries} of 5 again");
                std::thread::sleep(std::time::Duration::from_millis(200));
            }
            result => return result.expect("the binary runs"),
        }
    }
}

/// What a run printed on stderr.
pub fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// The `frame,ball,x,y,vx,vy` rows of a trace, as numbers.
pub fn trace_rows(path: &Path) -> Vec<[f64; 6]> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .skip(1)
        .map(|line| {
            let v: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3], v[4], v[5]]
        })
        .collect()
}

/// The trace of the default scene with `extra` flags, run in a temporary folder.
pub fn lesson_trace(extra: &[&str]) -> Vec<[f64; 6]> {
    let dir = tempfile::tempdir().unwrap();
    let mut args = vec!["-q", "--trace", "run.csv"];
    args.extend_from_slice(extra);
    let output = run_in(dir.path(), &args);
    assert!(output.status.success(), "{}", stderr(&output));
    trace_rows(&dir.path().join("run.csv"))
}
