//! The lab: what the tests, examples and benches of `bouncing_ball` measure the program with,
//! kept out of the program itself. Closed forms to hold the solvers to, and measures of a
//! scene's state that only an experiment needs.

pub mod accuracy;
