//! Tests of what exact mode's events leave untouched: the flights of a straight step and the
//! TC model's times of an elastic scene.

use super::*;
use crate::physics::maths;
use crate::physics::walls::Walls;

/// Twelve balls of radius 5 in a 100 × 100 box whose walls keep half the speed, moving
/// in twelve directions, with no gravity: they bounce off each other and the walls, and
/// every flight is straight.
fn gas() -> (Vec<Ball>, Effects) {
    let balls = (0..12)
        .map(|k| {
            let angle = f64::from(k) * 0.52;
            let (x, y) = (
                15.0 + f64::from(k % 4) * 23.0,
                20.0 + f64::from(k / 4) * 28.0,
            );
            Ball::new(
                x,
                y,
                3.0 * maths::cos(angle),
                3.0 * maths::sin(angle),
                5.0,
                0,
            )
        })
        .collect();
    let walls = Walls {
        width: 100.0,
        height: 100.0,
        damping: 0.5,
    };
    let effects = Effects {
        walls: Some(walls),
        ..Effects::default()
    };
    (balls, effects)
}

/// Runs `frames` frames of [`gas`] with ball-ball `restitution`, calling `check` after
/// each; returns the counts of all of them.
fn run_gas(restitution: f64, frames: u32, check: impl Fn(&EventDriven, &Forces)) -> EventCounts {
    let (mut balls, effects) = gas();
    let forces = Forces::new(&effects);
    let mut events = EventDriven::new(restitution);
    let mut total = EventCounts::default();
    for _ in 0..frames {
        events.frame(
            &mut balls,
            Integrator::SemiImplicitEuler,
            1,
            &forces,
            &effects,
        );
        check(&events, &forces);
        total.ball_collisions += events.counts().ball_collisions;
        total.contacts += events.counts().contacts;
    }
    total
}

#[test]
fn in_a_straight_step_every_ball_flies_with_the_steps_own_forces() {
    // `EventDriven::flight` reads the step's forces for every ball in a straight step,
    // which is right only while each ball's own flight is the same, bounces included.
    let counts = run_gas(0.5, 200, |events, forces| {
        let differs = events.flight.iter().position(|flight| flight != forces);
        assert_eq!(
            differs, None,
            "a ball's flight differs from the step's {forces:?}"
        );
    });
    assert!(
        counts.ball_collisions > 0 && counts.contacts > 0,
        "expected bounces off balls and walls, got {counts:?}"
    );
}

#[test]
fn elastic_collisions_note_no_times_and_inelastic_ones_do() {
    let never = |events: &EventDriven| {
        let noted = events
            .last_collision
            .iter()
            .filter(|t| t.is_finite())
            .count();
        noted == 0
    };
    let elastic = run_gas(1.0, 200, |events, _| {
        assert!(never(events), "an elastic collision noted its time");
    });
    assert!(
        elastic.ball_collisions > 0,
        "expected collisions, got {elastic:?}"
    );
    let noted = std::cell::Cell::new(false);
    run_gas(0.5, 200, |events, _| {
        noted.set(noted.get() || !never(events))
    });
    assert!(
        noted.get(),
        "expected inelastic collisions to note their times"
    );
}
