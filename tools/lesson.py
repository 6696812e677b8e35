#!/usr/bin/env python3
"""The lesson's script, as the lesson describes it ("5.3.1 Bouncing Ball"), plus the
commands that turn its pictures into the project's test data.

It is the project's own rendition, written from the lesson text: the same constants, the
same step (gravity, move, clamp and reflect at each wall, append to the trail), and the same
drawing with Pillow (`ImageDraw.ellipse([x - r, y - r, x + r, y + r], fill=colour)`, trail
oldest first, fading and shrinking, then the ball). It needs Pillow only
(`pip install pillow`); Python 3.11 or newer reads scene files.

    lesson.py gif [OUT_DIR]                 bouncing_ball.gif and bouncing_ball.png, as the lesson
    lesson.py trajectory                    x y vx vy per frame (Python's repr), no pictures
    lesson.py frames OUT_DIR N [N ...]      frames N (0 = after the first step) as RGB PNGs
    lesson.py bless                         regenerate the tests' data from Pillow's pictures

`gif`, `trajectory` and `frames` take `--scene scenes/NAME.toml` to use a single-ball scene's
constants instead of the lesson's, `--frames N` to stop after N frames, and `--pitfall NAME`
to make one of the lesson's mistakes on purpose (the names `bouncing_ball check` reports:
src/check/pitfalls.rs), for grading tests. `bless` rewrites, on purpose only:
    tests/golden/*.png               chosen frames of lesson, elastic, heavy and moon
    tests/data/script_frames.txt     CRC-32 of every RGB frame of those four scenes
    tests/data/pillow_circles.txt    pixels Pillow fills for random float circles
"""
import argparse
import random
import sys
import zlib
from pathlib import Path

try:
    from PIL import Image, ImageDraw
except ImportError:
    sys.exit("lesson.py needs Pillow: pip install pillow")

ROOT = Path(__file__).resolve().parent.parent

# The lesson's constants.
LESSON = dict(
    WIDTH=320,
    HEIGHT=240,
    RADIUS=12.0,
    START=(40.0, 40.0),
    INITIAL_VEL=(5.2, 0.0),
    GRAVITY=0.5,
    BOUNCE_DAMPING=0.88,
    TRAIL_LEN=20,
    FRAMES=200,
    FRAME_MS=30,
    BACKGROUND=(0, 0, 0),
    BALL_COLOUR=(255, 200, 60),
    TRAIL_COLOUR=(60, 140, 255),
)

# Which frames of which scene become golden PNGs (scene name: frame numbers).
GOLDEN_FRAMES = {
    "lesson": [0, 1, 57, 120, 199],
    "elastic": [10, 100, 199],
    "heavy": [10, 100, 199],
    "moon": [10, 100, 199],
}


# The lesson's mistakes, made on purpose with --pitfall (the names src/check/pitfalls.rs gives).
PITFALLS = ["nothing-moves", "no-clamp", "gravity-twice", "gravity-at-bounce", "position-first",
            "trail-before-move", "trail-over-ball"]


class Ball:
    def __init__(self, k, pitfall=None):
        self.k = k
        self.x, self.y = k["START"]
        self.vx, self.vy = k["INITIAL_VEL"]
        self.radius = k["RADIUS"]
        self.trail = []
        self.pitfall = pitfall

    def step(self):
        """The lesson's step; each `p ==` line is a mistake made only when asked for."""
        k, p = self.k, self.pitfall
        if p == "nothing-moves":
            return self.remember()
        if p == "trail-before-move":
            self.remember()
        if p != "position-first":
            self.vy += k["GRAVITY"]
        if p == "gravity-twice":
            self.vy += k["GRAVITY"]
        self.x += self.vx
        self.y += self.vy
        if p == "position-first":
            self.vy += k["GRAVITY"]
        clamp = p != "no-clamp"
        kick = k["GRAVITY"] if p == "gravity-at-bounce" else 0.0
        if self.x - self.radius < 0:
            if clamp:
                self.x = self.radius
            self.vx = -self.vx * k["BOUNCE_DAMPING"]
        elif self.x + self.radius > k["WIDTH"]:
            if clamp:
                self.x = k["WIDTH"] - self.radius
            self.vx = -self.vx * k["BOUNCE_DAMPING"]
        if self.y - self.radius < 0:
            if clamp:
                self.y = self.radius
            self.vy = -self.vy * k["BOUNCE_DAMPING"] + kick
        elif self.y + self.radius > k["HEIGHT"]:
            if clamp:
                self.y = k["HEIGHT"] - self.radius
            self.vy = -self.vy * k["BOUNCE_DAMPING"] + kick
        if p != "trail-before-move":
            self.remember()

    def remember(self):
        self.trail.append((self.x, self.y))
        if len(self.trail) > self.k["TRAIL_LEN"]:
            self.trail.pop(0)


def draw(ball):
    """One RGB frame: the trail oldest first, fading and shrinking, then the ball on top
    (under it, with --pitfall trail-over-ball)."""
    k = ball.k
    img = Image.new("RGB", (k["WIDTH"], k["HEIGHT"]), k["BACKGROUND"])
    d = ImageDraw.Draw(img)
    r = ball.radius
    draw_ball = lambda: d.ellipse([ball.x - r, ball.y - r, ball.x + r, ball.y + r], fill=k["BALL_COLOUR"])
    if ball.pitfall == "trail-over-ball":
        draw_ball()
    n = len(ball.trail)
    for i, (tx, ty) in enumerate(ball.trail):
        fade = (i + 1) / n
        colour = tuple(int(c * fade) for c in k["TRAIL_COLOUR"])
        tr = ball.radius * fade
        d.ellipse([tx - tr, ty - tr, tx + tr, ty + tr], fill=colour)
    if ball.pitfall != "trail-over-ball":
        draw_ball()
    return img


def frames(k, pitfall=None):
    """Every frame of the run, each drawn right after its step."""
    ball = Ball(k, pitfall)
    for _ in range(k["FRAMES"]):
        ball.step()
        yield draw(ball)


def scene_constants(path):
    """The lesson's constants with a single-ball scene file's values in their place."""
    import tomllib  # Python 3.11+

    with open(path, "rb") as f:
        s = tomllib.load(f)
    extra = set(s) - {"width", "height", "background", "frames", "frame_ms", "gravity", "walls", "balls"}
    balls = s.get("balls", [])
    gravity = s.get("gravity", [0.0, 0.0])
    if extra or len(balls) != 1 or "walls" not in s or gravity[0] != 0.0:
        sys.exit(f"{path}: the lesson's script draws one ball between four walls with downward "
                 f"gravity; this scene has more ({sorted(extra) or 'balls, walls or sideways gravity'})")
    b = balls[0]
    return dict(
        WIDTH=s["width"],
        HEIGHT=s["height"],
        RADIUS=float(b["radius"]),
        START=(float(b["x"]), float(b["y"])),
        INITIAL_VEL=(float(b.get("vx", 0.0)), float(b.get("vy", 0.0))),
        GRAVITY=float(gravity[1]),
        BOUNCE_DAMPING=float(s["walls"].get("damping", 1.0)),
        TRAIL_LEN=b.get("trail", LESSON["TRAIL_LEN"]),
        FRAMES=s["frames"],
        FRAME_MS=s["frame_ms"],
        BACKGROUND=tuple(s.get("background", LESSON["BACKGROUND"])),
        BALL_COLOUR=tuple(b.get("colour", LESSON["BALL_COLOUR"])),
        TRAIL_COLOUR=tuple(b.get("trail_colour", LESSON["TRAIL_COLOUR"])),
    )


def constants(scene, frames=None):
    k = dict(scene_constants(scene) if scene else LESSON)
    if frames is not None:
        k["FRAMES"] = frames
    return k


def write_gif(k, out, pitfall=None):
    """What the lesson's script writes: the animated GIF and the last frame as a PNG."""
    images = list(frames(k, pitfall))
    images[0].save(out / "bouncing_ball.gif", save_all=True, append_images=images[1:],
                   duration=k["FRAME_MS"], loop=0)
    images[-1].save(out / "bouncing_ball.png")


def print_trajectory(k, pitfall=None):
    ball = Ball(k, pitfall)
    for _ in range(k["FRAMES"]):
        ball.step()
        print(repr(ball.x), repr(ball.y), repr(ball.vx), repr(ball.vy))


def write_frames(k, out, wanted, prefix="frame", pitfall=None):
    for n, img in enumerate(frames(k, pitfall)):
        if n in wanted:
            img.save(out / f"{prefix}_{n:03}.png")


def random_circles(count=160, side=40, seed=12):
    """Random float circles: a third with radius under 1 px, a third centred on .5 steps,
    some hanging over the top-left edge where truncation goes towards zero."""
    rng = random.Random(seed)
    circles = []
    for i in range(count):
        kind = i % 3
        r = rng.uniform(0.0, 1.0) if kind == 0 else rng.uniform(0.0, 12.0)
        if kind == 1:
            x, y = rng.randint(-8, 2 * side) / 2, rng.randint(-8, 2 * side) / 2
        else:
            x, y = rng.uniform(-4.0, side + 4.0), rng.uniform(-4.0, side + 4.0)
        if i % 5 == 0:
            r = float(rng.randint(0, 16)) / 2  # whole and half-pixel radii too
        circles.append((x, y, r))
    return side, circles


def write_circle_table(path):
    """Per circle: `x y r` (Python's repr, exact floats), then `row first last` for each
    row Pillow fills on a side x side canvas (rows are runs: Pillow fills a convex shape)."""
    side, circles = random_circles()
    lines = [f"# Pixels Pillow {Image.__version__} fills with ImageDraw.ellipse([x-r, y-r, x+r, y+r]) "
             f"on a {side}x{side} canvas. Made by tools/lesson.py bless; do not edit.",
             f"side {side}"]
    for x, y, r in circles:
        img = Image.new("L", (side, side), 0)
        ImageDraw.Draw(img).ellipse([x - r, y - r, x + r, y + r], fill=255)
        rows = []
        for row in range(side):
            cols = [c for c in range(side) if img.getpixel((c, row))]
            if cols:
                assert cols == list(range(cols[0], cols[-1] + 1)), "a row with a gap"
                rows.append(f"{row} {cols[0]} {cols[-1]}")
        lines.append(f"circle {x!r} {y!r} {r!r}")
        lines.extend(rows)
    path.write_text("\n".join(lines) + "\n")


def bless():
    golden = ROOT / "tests" / "golden"
    data = ROOT / "tests" / "data"
    crc_lines = [f"# CRC-32 (zlib) of every RGB frame the lesson's script draws with Pillow "
                 f"{Image.__version__}: scene frame crc. Made by tools/lesson.py bless; do not edit."]
    for name, wanted in GOLDEN_FRAMES.items():
        k = LESSON if name == "lesson" else scene_constants(ROOT / "scenes" / f"{name}.toml")
        for n, img in enumerate(frames(k)):
            crc_lines.append(f"{name} {n} {zlib.crc32(img.tobytes()):08x}")
            if n in wanted:
                img.save(golden / f"{name}_frame_{n:03}.png")
    (data / "script_frames.txt").write_text("\n".join(crc_lines) + "\n")
    write_circle_table(data / "pillow_circles.txt")
    print(f"regenerated tests/golden/*.png, tests/data/script_frames.txt and "
          f"tests/data/pillow_circles.txt with Pillow {Image.__version__}")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="command", required=True)
    for name in ("gif", "trajectory", "frames"):
        c = sub.add_parser(name)
        c.add_argument("--scene", help="a single-ball scene file (scenes/NAME.toml)")
        c.add_argument("--frames", type=int, help="how many frames (default: the scene's)")
        c.add_argument("--pitfall", choices=PITFALLS, help="make one of the lesson's mistakes")
        if name == "gif":
            c.add_argument("out", nargs="?", default=".", type=Path)
        if name == "frames":
            c.add_argument("out", type=Path)
            c.add_argument("n", nargs="+", type=int, help="frame numbers, 0 = after the first step")
    sub.add_parser("bless")
    a = p.parse_args()
    if a.command == "gif":
        if not a.out.is_dir():
            # One line, as the program says it (argparse's error adds a usage line).
            print(f"error: lesson.py gif {a.out}: not a folder; give the folder to write "
                  "bouncing_ball.gif and bouncing_ball.png into", file=sys.stderr)
            sys.exit(2)
        write_gif(constants(a.scene, a.frames), a.out, a.pitfall)
    elif a.command == "trajectory":
        print_trajectory(constants(a.scene, a.frames), a.pitfall)
    elif a.command == "frames":
        write_frames(constants(a.scene, a.frames), a.out, set(a.n), pitfall=a.pitfall)
    else:
        bless()


if __name__ == "__main__":
    main()
