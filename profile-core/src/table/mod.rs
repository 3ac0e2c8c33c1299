//! The table: a spec and its checked form, the one quantizer, per-step,
//! segment layouts, and compressed runs with their expansion and index.

pub(crate) mod fall;
pub(crate) mod generate;
pub(crate) mod quantize;
pub mod runs;
pub(crate) mod segments;
pub(crate) mod spec;
