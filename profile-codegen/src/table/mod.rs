//! Tables on the heap: each with its spec and figures, in every layout, and
//! the fitter of compressed runs.

pub(crate) mod compress;
pub(crate) mod computed;
