//! The GIF encoder: lossless however it crops and queues frames, exact in frame count and
//! timing, and bounded in memory by construction.

mod common;

use std::path::Path;

use bouncing_ball::gif::delta::{changed_rect, Rect};
use bouncing_ball::gif::lzw::{min_code_size, Choices, Lzw};
use bouncing_ball::gif::GifWriter;
use bouncing_ball::physics::{CollisionMode, Integrator, Motion};
use bouncing_ball::render::IndexedFrame;
use bouncing_ball::render::Palette;
use bouncing_ball::render::Renderer;
use bouncing_ball::scene::random::Random;
use bouncing_ball::testing::interlace;
use bouncing_ball::testing::{
    mark_mixed_stretches, mark_unchanged, mixed_neighbours, transparent_index,
};
use bouncing_ball::testing::{queue_frames, MAX_QUEUED_FRAMES, QUEUE_PIXELS, THREADS_VARIABLE};
use bouncing_ball::{run, BallSpec, Job, OutputKind, Scene};
use common::{decode_gif, lesson_scene, render_frames};
use image::Luma;

/// Runs `scene` through the library into a temporary folder and returns the GIF's path.
fn write_gif(scene: &Scene, dir: &Path) -> std::path::PathBuf {
    let outputs = Job::pictures(dir.join("scene.gif"), dir.join("scene.png"));
    run(scene, &outputs).expect("the scene runs");
    outputs.path(OutputKind::Gif).unwrap().to_path_buf()
}

/// Decodes `scene`'s GIF and checks every frame against the renderer's, pixel for pixel.
fn assert_lossless(scene: &Scene) {
    let dir = tempfile::tempdir().unwrap();
    let gif = decode_gif(&write_gif(scene, dir.path()));
    let rendered = render_frames(scene);
    let shown = gif.timeline((scene.frame_ms / 10) as u16);
    assert_eq!(shown.len(), rendered.len(), "frames shown over time");
    for (n, (decoded, drawn)) in shown.iter().zip(&rendered).enumerate() {
        let differing = decoded.pixels().zip(drawn.pixels()).filter(|(a, b)| a != b);
        assert_eq!(
            differing.count(),
            0,
            "frame {n}: pixels differ between the decoded GIF and the renderer"
        );
    }
}

/// A ball that runs into a dead wall (damping 0) and stops there for good, beside a ball
/// that never moves: frames that change, then frames identical to the one before.
fn ball_that_stops() -> Scene {
    let ball = |x, vx| BallSpec {
        x,
        y: 30.0,
        vx,
        vy: 0.0,
        radius: 5.0,
        colour: [255, 200, 60],
        trail_colour: [60, 140, 255],
        trail: 3,
    };
    Scene {
        balls: vec![ball(20.0, 4.0), ball(8.0, 0.0)],
        walls: Some(0.0),
        frames: 40,
        ..Scene::empty(80, 60)
    }
}

/// Every image of a GIF as stored (before compositing): its rectangle.
fn stored_rects(path: &Path) -> Vec<Rect> {
    let mut decoder = gif::DecodeOptions::new()
        .read_info(std::fs::File::open(path).unwrap())
        .unwrap();
    let mut rects = Vec::new();
    while let Some(frame) = decoder.read_next_frame().unwrap() {
        rects.push(Rect {
            left: frame.left.into(),
            top: frame.top.into(),
            width: frame.width.into(),
            height: frame.height.into(),
        });
    }
    rects
}

#[test]
fn every_decoded_frame_of_the_lesson_equals_the_rendered_frame() {
    // 200 frames: several full queues and a part-filled last one.
    assert!(queue_frames(320, 240) < 200);
    assert_lossless(&lesson_scene());
}

#[test]
fn a_narrow_interlaced_frame_decodes_to_the_rendered_frame() {
    // Found by the hostile suite: a 13 px wide canvas whose one frame is smallest interlaced.
    // Such frames are valid GIF (browsers, Pillow, ffmpeg and ImageMagick read them) that the
    // gif crate's own pixel decoder rejects; the tests' reader decodes them itself.
    let scene = Scene {
        balls: vec![BallSpec {
            x: 5.112808810294357,
            y: 120.6030304521823,
            vx: 35.153243372167005,
            vy: 16.168510353107365,
            radius: 5.112808810294357,
            colour: [0, 0, 1],
            trail_colour: [0, 0, 0],
            trail: 0,
        }],
        walls: Some(0.42545374233412747),
        motion: Motion {
            integrator: Integrator::ExplicitEuler,
            collisions: CollisionMode::Exact,
            ..Motion::default()
        },
        frames: 1,
        ..Scene::empty(13, 265)
    };
    assert_lossless(&scene);
}

#[test]
fn every_decoded_frame_equals_the_rendered_frame_when_frames_repeat() {
    let scene = ball_that_stops();
    let rendered = render_frames(&scene);
    let repeats = rendered.windows(2).filter(|w| w[0] == w[1]).count();
    assert!(
        repeats > 10,
        "the scene should repeat frames once the ball stops; it repeats {repeats}"
    );
    assert_lossless(&scene);
}

#[test]
fn a_repeated_frame_is_not_stored_and_the_frame_before_shows_that_much_longer() {
    let scene = ball_that_stops();
    let dir = tempfile::tempdir().unwrap();
    let path = write_gif(&scene, dir.path());
    let (rects, delays) = (stored_rects(&path), decode_gif(&path).delays_cs);
    let rendered = render_frames(&scene);
    let frame_cs = (scene.frame_ms / 10) as u16;
    // Each stored frame starts a run of identical rendered frames, and shows for all of them.
    let mut runs = Vec::new();
    for n in 0..rendered.len() {
        if n == 0 || rendered[n] != rendered[n - 1] {
            runs.push(1);
        } else {
            *runs.last_mut().unwrap() += 1;
        }
    }
    let expected: Vec<u16> = runs.iter().map(|&run| run * frame_cs).collect();
    assert_eq!(delays, expected, "each stored frame's delay, cs");
    let whole = Rect {
        left: 0,
        top: 0,
        width: 80,
        height: 60,
    };
    assert_eq!(rects[0], whole, "the first frame is whole");
    for (n, rect) in rects.iter().enumerate().skip(1) {
        assert!(
            rect.width < 80 && rect.height < 60,
            "stored frame {n} should be only the part that changed: {rect:?}"
        );
    }
}

#[test]
fn the_changed_rectangle_is_the_bounding_box_of_the_changed_pixels() {
    let before = IndexedFrame::new(10, 8);
    assert_eq!(changed_rect(&before, &before), None, "identical frames");
    let mut after = before.clone();
    after.put_pixel(7, 1, Luma([3]));
    after.put_pixel(2, 5, Luma([4]));
    after.put_pixel(9, 6, Luma([5]));
    let expected = Rect {
        left: 2,
        top: 1,
        width: 8,
        height: 6,
    };
    let actual = changed_rect(&before, &after);
    assert_eq!(
        actual,
        Some(expected),
        "expected {expected:?}, got {actual:?}"
    );
}

#[test]
fn the_changed_rectangle_matches_a_pixel_by_pixel_search_on_wide_random_frames() {
    let mut random = Random::new(21);
    for case in 0..300 {
        let (width, height) = (1 + random.next_u64() % 100, 1 + random.next_u64() % 20);
        let before = random_frame(width as u32, height as u32, 7, &mut random);
        let mut after = before.clone();
        for _ in 0..random.next_u64() % 4 {
            let (x, y) = (random.next_u64() % width, random.next_u64() % height);
            let pixel = after.get_pixel_mut(x as u32, y as u32);
            pixel.0[0] = pixel.0[0].wrapping_add(1);
        }
        let changed: Vec<(u32, u32)> = before
            .enumerate_pixels()
            .filter(|&(x, y, pixel)| after.get_pixel(x, y) != pixel)
            .map(|(x, y, _)| (x, y))
            .collect();
        let expected = (!changed.is_empty()).then(|| {
            let (xs, ys): (Vec<u32>, Vec<u32>) = changed.iter().copied().unzip();
            let (left, top) = (*xs.iter().min().unwrap(), *ys.iter().min().unwrap());
            Rect {
                left,
                top,
                width: xs.iter().max().unwrap() + 1 - left,
                height: ys.iter().max().unwrap() + 1 - top,
            }
        });
        let actual = changed_rect(&before, &after);
        assert_eq!(actual, expected, "case {case}, {width}x{height}");
    }
}

#[test]
fn the_encoder_queue_is_bounded_in_frames_and_pixels_for_any_canvas() {
    for (width, height) in [(1, 1), (320, 240), (1920, 1080), (8192, 8192)] {
        let frames = queue_frames(width, height);
        let frame_pixels = width as usize * height as usize;
        assert!(
            (1..=MAX_QUEUED_FRAMES).contains(&frames),
            "{width}x{height}: {frames} frames queued"
        );
        assert!(
            frames * frame_pixels <= QUEUE_PIXELS.max(frame_pixels),
            "{width}x{height}: {frames} frames of {frame_pixels} px exceed the budget of {QUEUE_PIXELS} px"
        );
    }
}

#[test]
fn a_canvas_bigger_than_the_queue_still_writes_frame_after_frame() {
    // One frame fills the queue's pixels, so the writer has a single slot: each frame must be
    // written before the next is cut, even though a repeat could still have lengthened it.
    let side = 2049;
    assert_eq!(queue_frames(side, side), 1, "a single slot");
    let mut palette = Palette::new();
    for colour in [[0, 0, 0], [255, 255, 255]] {
        palette.insert(colour);
    }
    let mut gif = GifWriter::new(Vec::new(), side as u16, side as u16, &palette, 30).unwrap();
    let mut frame = IndexedFrame::new(side, side);
    for n in 0..3 {
        frame.put_pixel(n, n, Luma([1]));
        gif.write_frame(&frame).unwrap();
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("big.gif");
    std::fs::write(&path, gif.finish().unwrap()).unwrap();
    let stored: Vec<(u32, u32)> = stored_rects(&path)
        .iter()
        .map(|rect| (rect.left, rect.width))
        .collect();
    assert_eq!(
        stored,
        [(0, side), (1, 1), (2, 1)],
        "(left, width) of each stored frame"
    );
}

#[test]
fn a_frame_of_the_wrong_size_or_an_empty_canvas_is_an_error_not_a_panic() {
    let scene = lesson_scene();
    let renderer = Renderer::new(&scene).unwrap();
    let mut gif = GifWriter::new(Vec::new(), 320, 240, renderer.palette(), 30).unwrap();
    let error = gif.write_frame(&IndexedFrame::new(32, 24)).unwrap_err();
    assert_eq!(error.kind(), std::io::ErrorKind::InvalidInput, "{error}");
    let empty = GifWriter::new(Vec::new(), 0, 240, renderer.palette(), 30);
    assert!(empty.is_err(), "a GIF without pixels is refused");
}

/// A frame of seeded random indices below `colours`, in runs of 1 to 40, so the LZW
/// dictionary gets both many short strings and long ones.
fn random_frame(width: u32, height: u32, colours: usize, random: &mut Random) -> IndexedFrame {
    let mut pixels = Vec::with_capacity((width * height) as usize);
    while pixels.len() < pixels.capacity() {
        let index = (random.next_u64() % colours as u64) as u8;
        let run = 1 + (random.next_u64() % 40) as usize;
        let room = pixels.capacity() - pixels.len();
        pixels.extend(std::iter::repeat_n(index, run.min(room)));
    }
    IndexedFrame::from_raw(width, height, pixels).unwrap()
}

/// `pixels` seeded random indices below 16: strings that seldom repeat, which fill the
/// dictionary quickly.
fn noise(pixels: usize, random: &mut Random) -> Vec<u8> {
    (0..pixels)
        .map(|_| (random.next_u64() % 16) as u8)
        .collect()
}

#[test]
fn lzw_data_decodes_to_the_same_indices_for_every_code_size_and_across_dictionary_resets() {
    let mut random = Random::new(6);
    // From 2 colours (the smallest code size) to 256; 400x300 px fill the 4096-code
    // dictionary many times over.
    for colours in [2, 3, 5, 16, 129, 256] {
        let mut palette = Palette::new();
        for i in 0..colours {
            palette.insert([i as u8, 0, 0]);
        }
        let frame = random_frame(400, 300, colours, &mut random);
        let mut gif = GifWriter::new(Vec::new(), 400, 300, &palette, 30).unwrap();
        gif.write_frame(&frame).unwrap();
        let bytes = gif.finish().unwrap();

        let mut options = gif::DecodeOptions::new();
        options.set_color_output(gif::ColorOutput::Indexed);
        let mut decoder = options.read_info(&bytes[..]).unwrap();
        let decoded = decoder.read_next_frame().unwrap().expect("one frame");
        let first_wrong = decoded
            .buffer
            .iter()
            .zip(frame.as_raw())
            .position(|(a, b)| a != b);
        assert_eq!(
            (decoded.buffer.len(), first_wrong),
            (frame.as_raw().len(), None),
            "{colours} colours: decoded length and first wrong index"
        );
    }
}

#[test]
fn lzw_writes_the_gif_crates_own_bytes_while_the_dictionary_has_room() {
    // The gif crate's coder picks the code size from the largest index, so pick ours alike.
    let gif_code_size = |pixels: &[u8]| {
        let colours = u32::from(pixels.iter().copied().max().unwrap_or(0)) + 1;
        colours.max(4).next_power_of_two().trailing_zeros() as u8
    };
    let mut random = Random::new(6);
    let mut lzw = Lzw::new();
    let mut ours = Vec::new();
    for colours in [2, 3, 4, 7, 16, 200] {
        for len in 0..300 {
            let pixels: Vec<u8> = (0..len)
                .map(|_| (random.next_u64() % colours) as u8)
                .collect();
            lzw.compress(
                gif_code_size(&pixels),
                &pixels,
                Choices::GREEDY,
                usize::MAX,
                &mut ours,
            );
            let mut frame = gif::Frame {
                width: len as u16,
                height: 1,
                buffer: pixels.into(),
                ..gif::Frame::default()
            };
            frame.make_lzw_pre_encoded();
            assert_eq!(
                ours, *frame.buffer,
                "{len} random indices below {colours}: ours, then the gif crate's"
            );
        }
    }
}

/// Wraps LZW data for one `width` x `height` image into a GIF and decodes its indices.
fn decode_lzw(width: u16, height: u16, colours: usize, data: &[u8]) -> Vec<u8> {
    let table = vec![0u8; 3 * colours.next_power_of_two().max(2)];
    let mut encoder = gif::Encoder::new(Vec::new(), width, height, &table).unwrap();
    let frame = gif::Frame {
        width,
        height,
        buffer: data.into(),
        ..gif::Frame::default()
    };
    encoder.write_lzw_pre_encoded_frame(&frame).unwrap();
    let bytes = encoder.into_inner().unwrap();
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(&bytes[..]).unwrap();
    decoder
        .read_next_frame()
        .unwrap()
        .expect("one frame")
        .buffer
        .to_vec()
}

#[test]
fn lzw_decodes_to_the_same_indices_for_every_code_size_and_dictionary_choice() {
    // 400x300 px of noise fill even the 4096-code dictionary many times over, so each choice
    // reaches its size: cleared there (greedy, half, small) or kept full to the end.
    let mut random = Random::new(9);
    let mut lzw = Lzw::new();
    let mut data = Vec::new();
    for colours in [2, 3, 5, 16, 129, 256] {
        let noise: Vec<u8> = (0..400 * 300)
            .map(|_| (random.next_u64() % colours as u64) as u8)
            .collect();
        let code_size = min_code_size(colours);
        for choices in [
            Choices::GREEDY,
            Choices::HALF,
            Choices::SMALL,
            Choices::KEEP_FULL,
        ] {
            let most = lzw.compress(code_size, &noise, choices, usize::MAX, &mut data);
            assert_eq!(
                most,
                Some(choices.max_codes),
                "{colours} colours, {choices:?}: the dictionary reaches its size"
            );
            let decoded = decode_lzw(400, 300, colours, &data);
            assert!(
                decoded == noise,
                "{colours} colours, {choices:?}: decoded indices differ"
            );
        }
    }
}

#[test]
fn a_dictionary_choice_started_from_its_fork_writes_the_same_bytes_as_from_the_start() {
    let mut random = Random::new(12);
    let mut lzw = Lzw::new();
    let mut forked = 0;
    for colours in [2, 5, 16, 129] {
        for (width, height) in [(40, 30), (200, 150)] {
            let frame = random_frame(width, height, colours, &mut random);
            // Noise, so that the dictionary fills (the frames above are blocky).
            let noise: Vec<u8> = (0..width * height)
                .map(|_| (random.next_u64() % colours as u64) as u8)
                .collect();
            for pixels in [frame.as_raw(), &noise] {
                forked += assert_fork_equals_start(&mut lzw, colours, (width, height), pixels);
            }
        }
    }
    assert!(
        forked >= 12,
        "only {forked} codings forked: the test checks too little"
    );
}

/// Codes `pixels` with each dictionary choice from the start, and from the greedy coding's
/// fork, and checks the two are the same bytes and decode to `pixels`. Returns how many
/// choices forked (the others never grew the dictionary that far).
fn assert_fork_equals_start(
    lzw: &mut Lzw,
    colours: usize,
    (width, height): (u32, u32),
    pixels: &[u8],
) -> usize {
    let (mut first, mut resumed, mut whole) = (Vec::new(), Vec::new(), Vec::new());
    let size = min_code_size(colours);
    let mut forked = 0;
    for choices in [Choices::SMALL, Choices::HALF, Choices::KEEP_FULL] {
        let expected = lzw.compress(size, pixels, choices, usize::MAX, &mut whole);
        lzw.compress(size, pixels, Choices::GREEDY, usize::MAX, &mut first);
        let forks = lzw.forks();
        let fork = match choices {
            Choices::SMALL => forks.small,
            Choices::HALF => forks.half,
            _ => forks.full,
        };
        let case = format!("{colours} colours, {width}x{height}, {choices:?}");
        let Some(fork) = fork else {
            assert!(
                whole == first,
                "{case}: no fork, so the coding is the greedy one"
            );
            continue;
        };
        forked += 1;
        let codes = lzw.compress_from(fork, choices, pixels, &first, usize::MAX, &mut resumed);
        assert_eq!(codes, expected, "{case}: codes held");
        assert!(
            resumed == whole,
            "{case}: {} B from the fork, {} B from the start",
            resumed.len(),
            whole.len()
        );
        let decoded = decode_lzw(width as u16, height as u16, colours, &whole);
        assert!(decoded == pixels, "{case}: decoded indices differ");
    }
    forked
}

#[test]
fn lzw_gives_up_once_its_output_reaches_the_budget() {
    let frame = random_frame(100, 100, 16, &mut Random::new(3));
    let (mut lzw, mut data) = (Lzw::new(), Vec::new());
    let whole = lzw.compress(4, frame.as_raw(), Choices::GREEDY, usize::MAX, &mut data);
    let size = data.len();
    assert!(whole.is_some(), "no budget, no giving up");
    let cut = lzw.compress(4, frame.as_raw(), Choices::GREEDY, size, &mut data);
    assert_eq!(
        cut, None,
        "a budget of its own size ({size} B) is not enough"
    );
    let again = lzw.compress(4, frame.as_raw(), Choices::GREEDY, size + 1, &mut data);
    assert_eq!(
        (again, data.len()),
        (whole, size),
        "one byte more is enough, and the coder starts clean after giving up"
    );
}

#[test]
fn long_runs_of_one_colour_are_coded_as_the_gif_crate_codes_them() {
    // Runs longer and shorter than the longest run the dictionary holds of their colour, and
    // runs that end where the image does: our coder takes a run in one step, the gif
    // crate's a pixel at a time.
    let mut random = Random::new(11);
    let mut lzw = Lzw::new();
    let mut ours = Vec::new();
    for image in 0..40 {
        let mut pixels = Vec::new();
        for _ in 0..1 + image {
            let run = 1 + (random.next_u64() % 600) as usize;
            pixels.extend(std::iter::repeat_n((random.next_u64() % 3) as u8, run));
        }
        let most = lzw.compress(2, &pixels, Choices::GREEDY, usize::MAX, &mut ours);
        assert!(most < Some(4096), "image {image}: the dictionary has room");
        let mut frame = gif::Frame {
            width: pixels.len() as u16,
            height: 1,
            buffer: pixels.into(),
            ..gif::Frame::default()
        };
        frame.make_lzw_pre_encoded();
        assert_eq!(
            ours, *frame.buffer,
            "image {image}: ours, then the gif crate's"
        );
    }
}

#[test]
fn the_end_code_is_twelve_bits_wide_when_the_dictionary_ends_full() {
    // A dictionary kept full holds 4096 codes at the end: the decoder reads the end code at
    // 12 bits, and a 13th would spill into a byte of its own now and then. With 4-bit indices
    // the end code is 17 (0b1_0001): its top set bit is the data's last set bit, and the
    // code's 7 zero bits above it end the data, rounded up to a whole byte.
    let mut random = Random::new(10);
    let (mut lzw, mut data) = (Lzw::new(), Vec::new());
    for extra in 0..24 {
        let height: u16 = 100 + extra;
        let noise = noise(200 * usize::from(height), &mut random);
        lzw.compress(4, &noise, Choices::KEEP_FULL, usize::MAX, &mut data);
        let codes = &data[1..];
        let last = codes
            .iter()
            .rposition(|&byte| byte != 0)
            .expect("some codes");
        let last_set_bit = 8 * last + 7 - codes[last].leading_zeros() as usize;
        assert_eq!(
            codes.len(),
            (last_set_bit + 8).div_ceil(8),
            "{} pixels: bytes of codes",
            noise.len()
        );
        assert!(
            decode_lzw(200, height, 16, &data) == noise,
            "{} pixels decode",
            noise.len()
        );
    }
}

#[test]
fn interlaced_order_is_every_eighth_row_then_every_fourth_then_every_second_then_the_rest() {
    let rows: Vec<u8> = (0..10).flat_map(|row| [row, row]).collect();
    let mut out = Vec::new();
    interlace(&rows, 2, &mut out);
    let order: Vec<u8> = out.chunks(2).map(|row| row[0]).collect();
    assert_eq!(order, [0, 8, 4, 2, 6, 1, 3, 5, 7, 9]);
}

#[test]
fn only_unchanged_stretches_of_more_than_one_colour_become_transparent() {
    // Changed pixels are where `now` and `before` differ: columns 2 and 7.
    let before = [1, 1, 5, 3, 3, 4, 4, 9, 2, 2];
    let now = [1, 1, 6, 3, 3, 4, 4, 8, 2, 2];
    let mut out = Vec::new();
    let marked = mark_mixed_stretches(&now, &before, 0, &mut out);
    // 1 1 is one colour: kept. 3 3 4 4 mixes two: transparent. 2 2 is one colour: kept.
    assert_eq!(out, [1, 1, 6, 0, 0, 0, 0, 8, 2, 2]);
    assert_eq!(marked, 4);
}

#[test]
fn marking_every_unchanged_pixel_marks_exactly_those_and_counts_them() {
    // The same rows as above: only columns 2 and 7 changed, and every other pixel is marked.
    let before = [1, 1, 5, 3, 3, 4, 4, 9, 2, 2];
    let now = [1, 1, 6, 3, 3, 4, 4, 8, 2, 2];
    let mut out = Vec::new();
    let marked = mark_unchanged(&now, &before, 0, &mut out);
    assert_eq!(out, [0, 0, 6, 0, 0, 0, 0, 8, 0, 0]);
    assert_eq!(marked, 8, "pixels marked");
}

/// How many runs of one index `pixels` holds (0 for none).
fn runs(pixels: &[u8]) -> usize {
    let changes = pixels.windows(2).filter(|pair| pair[0] != pair[1]).count();
    usize::from(!pixels.is_empty()) + changes
}

#[test]
fn the_unchanged_pairs_of_two_colours_are_counted_and_bound_the_runs_marking_removes() {
    // The encoder tries a marking only if it could remove enough runs; it bounds that by
    // the neighbouring pairs of unchanged pixels of two colours. The count must be exact
    // (counted here pair by pair, on rows shorter and longer than its blocks of 255) and
    // the bound must hold.
    let mut random = Random::new(17);
    for len in [0, 1, 2, 3, 254, 255, 256, 257, 1000] {
        for colours in [2, 3] {
            let mut pick = || (random.next_u64() % colours) as u8;
            let before: Vec<u8> = (0..len).map(|_| pick()).collect();
            let now: Vec<u8> = before
                .iter()
                .map(|&b| if pick() == 0 { pick() } else { b })
                .collect();
            let by_hand = (1..len)
                .filter(|&i| now[i - 1] == before[i - 1] && now[i] == before[i])
                .filter(|&i| now[i - 1] != now[i])
                .count();
            let counted = mixed_neighbours(&now, &before);
            assert_eq!(counted, by_hand, "{len} pixels of {colours} colours");
            let mut marked = Vec::new();
            mark_mixed_stretches(&now, &before, colours as u8, &mut marked);
            let removed = runs(&now).saturating_sub(runs(&marked));
            assert!(
                removed <= counted,
                "{len} pixels of {colours} colours: marking removed {removed} runs, over the bound {counted}"
            );
        }
    }
}

#[test]
fn the_transparent_index_is_the_lowest_that_no_changed_pixel_uses() {
    let before = [0, 1, 2, 3];
    let now = [0, 0, 1, 3];
    // Changed pixels use 0 and 1; 2 and 3 appear only unchanged, so 2 is free.
    assert_eq!(transparent_index(&now, &before, 4), Some(2));
    assert_eq!(
        transparent_index(&[0, 1], &[1, 0], 2),
        None,
        "changed pixels use the whole table"
    );
}

#[test]
fn the_gif_is_the_same_bytes_on_one_thread_and_on_four() {
    let dir = tempfile::tempdir().unwrap();
    let render = |threads: &str| {
        let gif = dir.path().join(format!("{threads}.gif"));
        let status = std::process::Command::new(env!("CARGO_BIN_EXE_bouncing_ball"))
            .args([
                "--preset",
                "billiards",
                "--frames",
                "40",
                "--quiet",
                "--gif",
            ])
            .arg(&gif)
            .arg("--png")
            .arg(dir.path().join(format!("{threads}.png")))
            .env(THREADS_VARIABLE, threads)
            .status()
            .unwrap();
        assert!(status.success());
        std::fs::read(gif).unwrap()
    };
    assert!(render("1") == render("4"), "the bytes differ");
}

#[test]
#[should_panic(expected = "a fork into a full dictionary is taken before the next coding")]
fn a_fork_into_a_full_dictionary_taken_after_another_coding_is_refused() {
    // The coder keeps a full dictionary only until its next coding: a fork into it taken later
    // would start from another image's strings and write a wrong GIF, so it is refused.
    let mut random = Random::new(5);
    let noise = noise(200 * 150, &mut random);
    let (mut lzw, mut first, mut other, mut resumed) = (Lzw::new(), vec![], vec![], vec![]);
    lzw.compress(4, &noise, Choices::GREEDY, usize::MAX, &mut first);
    let fork = lzw.forks().full.expect("noise fills the dictionary");
    lzw.compress(4, &noise[..100], Choices::GREEDY, usize::MAX, &mut other);
    lzw.compress_from(
        fork,
        Choices::KEEP_FULL,
        &noise,
        &first,
        usize::MAX,
        &mut resumed,
    );
}

#[test]
fn a_canvas_empty_above_and_busy_below_is_coded_with_half_the_dictionary() {
    // The pyramid's first frame: black above, 55 balls stacked below. Its greedy coding holds
    // more than 2048 codes but never 4096, so the busy part is written in 12-bit codes of
    // strings learnt from the black part; cleared at 2048 codes instead, the busy part learns
    // its own strings in codes of at most 11 bits.
    let scene = bouncing_ball::scene::preset("pyramid", 1).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = write_gif(&scene, dir.path());
    let first_frame = |options: gif::DecodeOptions| {
        let mut decoder = options
            .read_info(std::fs::File::open(&path).unwrap())
            .unwrap();
        decoder.read_next_frame().unwrap().unwrap().buffer.to_vec()
    };
    let mut indexed = gif::DecodeOptions::new();
    indexed.set_color_output(gif::ColorOutput::Indexed);
    let pixels = first_frame(indexed);
    let mut compressed = gif::DecodeOptions::new();
    compressed.skip_frame_decoding(true);
    let stored = first_frame(compressed);

    let (mut lzw, mut greedy, mut half) = (Lzw::new(), Vec::new(), Vec::new());
    let code_size = stored[0];
    let codes = lzw.compress(code_size, &pixels, Choices::GREEDY, usize::MAX, &mut greedy);
    let fork = lzw
        .forks()
        .half
        .expect("the greedy coding reaches 2048 codes");
    lzw.compress_from(fork, Choices::HALF, &pixels, &greedy, usize::MAX, &mut half);
    assert!(
        half.len() < greedy.len(),
        "half the dictionary: {} B, greedy ({codes:?} codes): {} B",
        half.len(),
        greedy.len()
    );
    assert!(
        stored == half,
        "the GIF's first frame is {} B, not the half-dictionary coding's {} B",
        stored.len(),
        half.len()
    );
}
