//! The lab: what the tests, examples and benches of `bouncing_ball` measure the program with,
//! kept out of the program itself. Closed forms to hold the solvers to, measures of a
//! scene's state that only an experiment needs, and the scenes the experiments run.

pub mod accuracy;
pub mod scenes;
