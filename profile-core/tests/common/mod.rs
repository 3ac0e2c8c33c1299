//! Support for the player's tests: the reference model.

pub mod reference;
