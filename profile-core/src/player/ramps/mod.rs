//! What a player plays: a ramp and positions along it (`ramp.rs`), the
//! runs of a compressed ramp and where a run being played stands
//! (`runs.rs`), entries read by position (`entries.rs`), and the layout a
//! player's type chooses from the table it is made from (`layout.rs`).

pub(in crate::player) mod entries;
pub(in crate::player) mod layout;
pub(in crate::player) mod ramp;
pub(in crate::player) mod runs;
