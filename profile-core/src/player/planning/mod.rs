//! Planning a move, from a call (`start`, `stop`, a new cruise or target,
//! a jog) to the stretches the step path plays: the plan (`plan.rs`), the
//! exact searches on ramps ordered but for their slack (`search.rs`),
//! where the deceleration takes over (`crossing.rs`, `direct.rs` on two
//! per-step tables), a move that reaches its cruise before it
//! (`cruising.rs`), how far ahead of one ramp another is faster
//! (`threshold.rs`), a ramp read for the searches (`reader.rs`), `run`,
//! `set_cruise_period` and `retarget` (`motion.rs`), stops, an abort's
//! along an emergency ramp too (`stops.rs`), and moves that end and begin
//! at speed, for lines that join (`join.rs`).

pub(in crate::player) mod crossing;
pub(in crate::player) mod cruising;
pub(in crate::player) mod direct;
pub(in crate::player) mod join;
pub(in crate::player) mod motion;
pub(in crate::player) mod plan;
pub(in crate::player) mod reader;
pub(in crate::player) mod search;
pub(in crate::player) mod stops;
pub(in crate::player) mod threshold;
