//! The table: a spec and its checked form, the one quantizer, per-step and
//! segment layouts, owned tables.

pub(crate) mod generate;
#[cfg(feature = "std")]
pub(crate) mod owned;
pub(crate) mod quantize;
pub(crate) mod segments;
pub(crate) mod spec;
