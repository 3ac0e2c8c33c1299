//! The table: a spec and its checked form, the one quantizer, per-step,
//! segment and compressed layouts, owned tables.

#[cfg(feature = "std")]
pub(crate) mod compress;
pub(crate) mod generate;
#[cfg(feature = "std")]
pub(crate) mod owned;
pub(crate) mod quantize;
pub mod runs;
pub(crate) mod segments;
pub(crate) mod spec;
