//! The table: a spec and its checked form, the one quantizer, per-step,
//! segment and compressed layouts, owned tables.

#[cfg(feature = "std")]
pub(crate) mod compress;
#[cfg(feature = "std")]
pub(crate) mod computed;
pub(crate) mod fall;
pub(crate) mod generate;
pub(crate) mod quantize;
pub mod runs;
pub(crate) mod segments;
pub(crate) mod spec;
