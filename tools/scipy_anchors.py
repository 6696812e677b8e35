#!/usr/bin/env python3
"""Anchors for docs/accuracy.md: what a Python user would pick instead of our integrators,
measured side by side on the same problem with the same error.

The problem is the lesson's ball with drag: from (40, 40) at (5.2, 0) px/frame in the lesson's
box (320 x 240, radius 12, gravity 0.5 px/frame^2, wall damping 0.88), 200 frames, with drag
0.01 (the accuracy study's; gravity alone is integrated exactly by any Runge-Kutta method).
Drag is the program's law `dv/dt = g - k*v`, `k = -ln(1 - drag)`, and a bounce is what our
exact collisions do: at the moment of contact the ball is put on the wall and the velocity's
component into it is reflected and multiplied by the damping.

- The reference: the closed-form flight between bounces (the accuracy study's formula), each
  time of impact solved to rounding (on the x axis in closed form, on the y axis by Brent's
  method on the closed form).
- SciPy: `solve_ivp` (RK45 and DOP853 at several tolerances) with a terminal event for each
  wall, restarted after each bounce; positions at every frame through `t_eval`.
- The lesson's loop written in Python (semi-implicit Euler, clamp-then-reflect): it must give
  the same numbers as our `semi-implicit-euler:1:clamp`, to the bit, or the script stops.
- Ours: `cargo run --release --example anchors` prints every frame's position and times whole
  runs of the simulation alone.

Error: the largest distance, px, between a method's position and the reference's at the end of
frames 1..200. Time: one whole run divided by the number of bounces in it; median, min and max
of REPS repetitions, Python and Rust interleaved.

    python3 tools/scipy_anchors.py [--reps N]

Needs numpy and scipy (`pip install scipy numpy`) and cargo. Not used by `cargo test`.
"""
import argparse
import math
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

try:
    import numpy as np
    import scipy
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq
except ImportError:
    sys.exit("scipy_anchors.py needs numpy and scipy: pip install scipy numpy")

ROOT = Path(__file__).resolve().parent.parent

# The lesson's constants, plus drag.
WIDTH, HEIGHT, RADIUS = 320.0, 240.0, 12.0
GRAVITY = 0.5  # px/frame², downwards (y grows downwards)
START = (40.0, 40.0, 5.2, 0.0)  # x, y, vx, vy
DAMPING = 0.88
FRAMES = 200
DRAG = 0.01  # share of speed lost per frame
RATE = -math.log1p(-DRAG)  # k, per frame
# Our exact mode lets a floor bounce slower than this end in rest (src/physics/tolerances.rs);
# the run stays clear of it, and every bounce here checks that it does.
REST_SPEED = 1.7

# The walls as (axis, where the centre is when touching, +1 at the high end / -1 at the low end).
WALLS = [
    (0, RADIUS, -1.0),
    (0, WIDTH - RADIUS, 1.0),
    (1, RADIUS, -1.0),
    (1, HEIGHT - RADIUS, 1.0),
]
ACCEL = (0.0, GRAVITY)

SCIPY_METHODS = [
    ("RK45", 1e-3, 1e-6),  # solve_ivp's defaults
    ("RK45", 1e-6, 1e-9),
    ("RK45", 1e-10, 1e-10),
    ("DOP853", 1e-3, 1e-6),
    ("DOP853", 1e-6, 1e-9),
    ("DOP853", 1e-10, 1e-10),
    ("DOP853", 1e-13, 1e-13),
]
OUR_METHODS = [
    "semi-implicit-euler:1:clamp",
    "semi-implicit-euler:1:exact",
    "velocity-verlet:1:exact",
    "rk4:1:exact",
    "rk4:4:exact",
    "rk4:16:exact",
]
LESSON_METHOD = "semi-implicit-euler:1:clamp"
# Whole runs timed together per repetition (one run of ours is tens of microseconds).
RUST_RUNS = 1000
LESSON_RUNS = 50


# --- the reference -----------------------------------------------------------------------


def flight(x0, v0, g, t):
    """Position and velocity along one axis after t frames of free flight under g and drag."""
    terminal = g / RATE
    lost = -math.expm1(-RATE * t)  # 1 - e^(-kt), keeping its digits when kt is small
    x = x0 + terminal * t + (v0 - terminal) * lost / RATE
    return x, terminal + (v0 - terminal) * (1 - lost)


def turning_time(v0, g):
    """When the velocity along an axis passes zero (gravity turning it round), or None."""
    if g == 0.0 or v0 * g >= 0.0:
        return None
    return math.log1p(-v0 * RATE / g) / RATE


def first_contact(state, left):
    """The earliest (time, wall) within `left` frames at which the flight from `state` touches
    a wall, or None. Along an axis the flight is monotonic on each side of its turning time."""
    best = None
    for wall in WALLS:
        axis, contact, outward = wall
        x0, v0, g = state[axis], state[2 + axis], ACCEL[axis]

        def gap(t):
            return outward * (contact - flight(x0, v0, g, t)[0])

        turn = turning_time(v0, g)
        cuts = [0.0] + ([turn] if turn is not None and turn < left else []) + [left]
        for a, b in zip(cuts, cuts[1:]):
            if gap(a) >= 0.0 > gap(b):
                t = solve_contact(gap, axis, x0, v0, contact, a, b)
                if best is None or t < best[0]:
                    best = (t, wall)
                break
    return best


def solve_contact(gap, axis, x0, v0, contact, a, b):
    """The time of impact in [a, b]: in closed form without gravity, else by Brent's method."""
    if ACCEL[axis] == 0.0:
        return -math.log1p(-RATE * (contact - x0) / v0) / RATE
    return brentq(gap, a, b, xtol=1e-14, rtol=4 * np.finfo(float).eps, maxiter=500)


def bounce(state, wall):
    """Our exact mode's bounce: on the wall, the velocity into it reflected times the damping."""
    axis, contact, _ = wall
    state = list(state)
    state[axis] = contact
    state[2 + axis] = -state[2 + axis] * DAMPING
    if axis == 1 and contact > HEIGHT / 2 and abs(state[3]) < REST_SPEED:
        sys.exit("a floor bounce would end in rest (our exact mode's rule): shorten the run")
    return state


def reference():
    """The reference run: (its flights as (start time, state), the bounce count)."""
    t, state, flights = 0.0, list(START), []
    while True:
        flights.append((t, state))
        hit = first_contact(state, FRAMES - t)
        if hit is None:
            return flights, len(flights) - 1
        dt, wall = hit
        x, vx = flight(state[0], state[2], ACCEL[0], dt)
        y, vy = flight(state[1], state[3], ACCEL[1], dt)
        t, state = t + dt, bounce([x, y, vx, vy], wall)


def reference_positions(flights):
    """The reference's (x, y) at the end of frames 1..FRAMES."""
    out = np.empty((FRAMES, 2))
    for frame in range(1, FRAMES + 1):
        t0, s = max((f for f in flights if f[0] <= frame), key=lambda f: f[0])
        out[frame - 1] = [flight(s[a], s[2 + a], ACCEL[a], frame - t0)[0] for a in (0, 1)]
    return out


def error(positions, ref):
    """The largest distance, px, between two runs' positions over all frames."""
    return float(np.max(np.hypot(*(positions - ref).T)))


# --- SciPy --------------------------------------------------------------------------------


def rhs(t, s):
    x, y, vx, vy = s
    return [vx, vy, -RATE * vx, GRAVITY - RATE * vy]


def wall_event(axis, contact, outward):
    def event(t, s):
        return outward * (contact - s[axis])

    event.terminal = True
    event.direction = -1  # only when the gap closes
    return event


EVENTS = [wall_event(*wall) for wall in WALLS]


def run_scipy(method, rtol, atol):
    """One run with solve_ivp, restarted after each bounce: (positions, bounces, f evaluations)."""
    frames = np.arange(1, FRAMES + 1, dtype=float)
    out = np.empty((FRAMES, 2))
    t, state, bounces, nfev = 0.0, list(START), 0, 0
    while True:
        pending = frames > t
        sol = solve_ivp(rhs, (t, FRAMES), state, method=method, rtol=rtol, atol=atol,
                        events=EVENTS, t_eval=frames[pending])
        nfev += sol.nfev
        first = int(np.argmax(pending))
        out[first:first + len(sol.t)] = sol.y[:2].T
        if sol.status != 1:
            return out, bounces, nfev
        k = next(i for i, te in enumerate(sol.t_events) if len(te))
        t, state = float(sol.t_events[k][0]), bounce(sol.y_events[k][0], WALLS[k])
        bounces += 1


# --- the lesson's loop in Python ------------------------------------------------------------


def run_lesson_loop():
    """The lesson's step with its drag exercise, as our `semi-implicit-euler:1:clamp` does it."""
    x, y, vx, vy = START
    keep = 1.0 - DRAG
    out = []
    for _ in range(FRAMES):
        vy += GRAVITY
        vx *= keep
        vy *= keep
        x += vx
        y += vy
        if x - RADIUS < 0:
            x = RADIUS
            vx = -vx * DAMPING
        elif x + RADIUS > WIDTH:
            x = WIDTH - RADIUS
            vx = -vx * DAMPING
        if y - RADIUS < 0:
            y = RADIUS
            vy = -vy * DAMPING
        elif y + RADIUS > HEIGHT:
            y = HEIGHT - RADIUS
            vy = -vy * DAMPING
        out.append((x, y))
    return np.array(out)


# --- ours ---------------------------------------------------------------------------------


def anchors(*args):
    """Runs our example `anchors` (built by `main`) and returns its lines, split into words."""
    target = Path(os.environ.get("CARGO_TARGET_DIR") or ROOT / "target")
    exe = target / "release" / "examples" / "anchors"
    done = subprocess.run([str(exe), *map(str, args)], check=True, capture_output=True, text=True)
    return [line.split() for line in done.stdout.splitlines()]


def our_positions():
    positions = {m: np.empty((FRAMES, 2)) for m in OUR_METHODS}
    for name, frame, x, y in anchors("path", DRAG, DAMPING, FRAMES, *OUR_METHODS):
        positions[name][int(frame) - 1] = [float(x), float(y)]
    return positions


# --- the table ----------------------------------------------------------------------------


class Row:
    def __init__(self, label, error, nfev=None):
        self.label, self.error, self.nfev, self.seconds = label, error, nfev, []


def measure_errors(ref, bounces):
    """A row per method with its error; stops if the two lesson loops disagree."""
    rows = []
    for method, rtol, atol in SCIPY_METHODS:
        positions, found, nfev = run_scipy(method, rtol, atol)
        if found != bounces:
            print(f"note: {method} rtol {rtol:g} found {found} bounces, the reference {bounces}")
        label = f"SciPy {method}, rtol {rtol:g}, atol {atol:g}"
        rows.append(Row(label, error(positions, ref), nfev))
    lesson_loop = run_lesson_loop()
    label = "the lesson's loop in Python (semi-implicit Euler, clamp)"
    rows.append(Row(label, error(lesson_loop, ref)))
    ours = our_positions()
    if not np.array_equal(ours[LESSON_METHOD], lesson_loop):
        sys.exit(f"the lesson's loop in Python and our {LESSON_METHOD} differ: not one problem")
    rows += [Row(f"ours: `{name}`", error(ours[name], ref)) for name in OUR_METHODS]
    return rows


def timed(function, runs=1):
    """Seconds per run of `function`, `runs` runs timed together."""
    started = time.perf_counter()
    for _ in range(runs):
        function()
    return (time.perf_counter() - started) / runs


def measure_times(rows, reps):
    """Interleaved, REPS times: every Python method, then ours (RUST_RUNS runs each). A SciPy
    run lasts milliseconds; the lesson's loop, a tenth of one, is timed LESSON_RUNS at a time."""
    python = [(lambda m=m: run_scipy(*m), 1) for m in SCIPY_METHODS]
    python.append((run_lesson_loop, LESSON_RUNS))
    ours = rows[len(python):]
    for _ in range(reps):
        for row, (run, runs) in zip(rows, python):
            row.seconds.append(timed(run, runs))
        for name, ns in anchors("time", DRAG, DAMPING, FRAMES, RUST_RUNS, *OUR_METHODS):
            ours[OUR_METHODS.index(name)].seconds.append(float(ns) * 1e-9)


def call_costs():
    """µs, medians of 201 (a median, as a busy machine adds rare long pauses): one solve_ivp call
    (RK45, the four events, a tenth of a frame), and one call of the right-hand side (timed 100
    at a time)."""
    state = np.array(START)  # what solve_ivp hands the right-hand side

    def short_solve():
        solve_ivp(rhs, (0.0, 0.1), state, events=EVENTS)

    solves = [timed(short_solve) for _ in range(201)]
    calls = [timed(lambda: rhs(0.0, state), 100) for _ in range(201)]
    return statistics.median(solves) * 1e6, statistics.median(calls) * 1e6


def spread(seconds, bounces):
    """Median (min–max) of whole-run times, as µs per bounce."""
    us = [s * 1e6 / bounces for s in seconds]

    def show(v):
        return f"{v:.0f}" if v >= 100 else f"{v:.3g}"

    return f"{show(statistics.median(us))} ({show(min(us))}–{show(max(us))})"


def machine():
    """The processor, cores and system, as far as Linux tells them."""
    cpu, system = platform.machine(), platform.system()
    try:
        with open("/proc/cpuinfo") as info:
            names = [l.split(":", 1)[1].strip() for l in info if l.startswith("model name")]
        cpu = f"{names[0]}, {len(names)} vCPU"
        with open("/etc/os-release") as release:
            fields = dict(l.rstrip().split("=", 1) for l in release if "=" in l)
        system = fields.get("PRETTY_NAME", system).strip('"')
    except (OSError, IndexError):
        pass
    return f"{cpu}, {system}"


def load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--reps", type=int, default=21, help="timed repetitions (default 21)")
    reps = parser.parse_args().reps
    build = ["cargo", "build", "--release", "--quiet", "--example", "anchors"]
    subprocess.run(build, cwd=ROOT, check=True)

    flights, bounces = reference()
    rows = measure_errors(reference_positions(flights), bounces)
    load_before = load()
    measure_times(rows, reps)
    call, one = call_costs()

    print(f"{machine()}; Python {platform.python_version()}, numpy {np.__version__}, "
          f"scipy {scipy.__version__}; load average {load_before} before, {load()} after")
    print(f"The lesson's ball with drag {DRAG}, damping {DAMPING}, {FRAMES} frames: {bounces} "
          f"bounces. Times: median (min–max) of {reps} whole runs, per bounce.\n")
    print("| method | largest position error, px | µs per bounce: median (min–max) "
          "| f evaluations per run |")
    print("|---|---:|---:|---:|")
    for row in rows:
        nfev = row.nfev or "—"
        print(f"| {row.label} | {row.error:.2e} | {spread(row.seconds, bounces)} | {nfev} |")
    run = statistics.median(rows[0].seconds) * 1e6
    print(f"\nOne solve_ivp call (RK45, four events, a tenth of a frame): {call:.0f} µs. One call "
          f"of the right-hand side: {one:.2f} µs; the {rows[0].nfev} calls of the default RK45 "
          f"run ({run:.0f} µs) are {rows[0].nfev * one / run:.1%} of it.")


if __name__ == "__main__":
    main()
