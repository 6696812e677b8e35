//! The progress bar: only for runs that look long enough to need one.

use std::time::Duration;

use bouncing_ball::progress::{looks_long, SAMPLE, WORTH_A_BAR};

#[test]
fn only_a_run_projected_past_a_second_gets_a_progress_bar() {
    // 150 ms for 10 of 100 frames projects 1.5 s; for 50 of 100, 0.3 s.
    let ms = Duration::from_millis;
    assert!(WORTH_A_BAR == Duration::from_secs(1) && SAMPLE <= ms(150));
    assert!(looks_long(ms(150), 10, 100), "projected 1.5 s");
    assert!(!looks_long(ms(150), 50, 100), "projected 0.3 s");
    assert!(
        !looks_long(SAMPLE / 2, 1, 1_000_000),
        "too early to project anything"
    );
    assert!(!looks_long(ms(500), 0, 100), "nothing done yet");
}
