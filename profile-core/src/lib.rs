//! Stepper-motor acceleration curves turned into timer-period tables.
//!
//! A step-pulse timer is reloaded once per step; entry `k` of a period table
//! is the number of timer ticks between step `k` and step `k + 1`. This crate
//! computes such tables from a curve ([`Curve`]), a timer ([`Timer`]) and a
//! choice of [`Discretization`] and [`Rounding`], bit-identically on every host
//! and target (`libm` everywhere, no fused multiply-add, integers out).
//!
//! It is `#![no_std]` and allocation-free: firmware can call
//! [`Spec::generate`] at run time and get the same bits the `period_table!`
//! macro puts in flash at compile time.
//!
//! ```
//! use profile_core::{Curve, Sigmoid, Spec, Timer};
//!
//! let spec = Spec::new(
//!     Curve::Sigmoid(Sigmoid { fmin: 500.0, fmax: 64_000.0, flexible: 8.0, len: 1000 }),
//!     Timer::new(10_000_000),
//! );
//! let mut table = [0u16; 1000];
//! let figures = spec.generate(&mut table)?;
//! // Default mode: every pulse edge within half a tick of the continuous curve.
//! assert!(figures.max_edge_error_ticks <= 0.5);
//! # Ok::<(), profile_core::Error>(())
//! ```
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

#[cfg(any(test, feature = "std"))]
extern crate std;

mod base;
mod curves;
#[cfg(feature = "codegen")]
mod emit;
#[cfg(feature = "golden")]
pub mod golden;
pub mod motor;
#[cfg(feature = "codegen")]
mod pipeline;
pub mod player;
#[cfg(feature = "codegen")]
pub mod profiles;
#[cfg(feature = "codegen")]
mod schema;
mod table;

/// The `fugit` crate whose durations [`player::Timed`] hands out (feature
/// `fugit`), so that a firmware names the same version.
#[cfg(feature = "fugit")]
pub use fugit;

pub use base::MAX_LEN;
pub use base::error::Error;
pub use base::key::Key;
pub use base::modes::{Arithmetic, Discretization, Rounding};
pub use base::timer::{TableWord, Timer, Word};
pub use curves::public::*;
#[doc(inline)]
pub use motor::simulate;
#[cfg(feature = "std")]
pub use table::compress::{MAX_COMPRESS_TICKS, MIN_COMPRESS_TICKS, RunFigures, RunTable};
#[cfg(feature = "std")]
pub use table::computed::{Compact, Generated, SegmentTable, Table};
pub use table::quantize::{AccelWindows, Figures};
pub use table::runs;
pub use table::segments::SegmentFigures;
pub use table::spec::{CheckedSpec, Spec};

/// What this workspace's other crates use and users do not: the argument
/// schema, the pipeline and the emitter (for `profile-macros` and the
/// command-line tool), and what a golden file holds (for the repository's
/// own golden tests). Not API: it changes in any release, without notice.
/// ARCHITECTURE.md says where the API ends and why.
#[doc(hidden)]
#[cfg(feature = "codegen")]
pub mod __private {
    /// The argument schema `profile-macros` reads tokens into, and the
    /// descriptions the command-line tool prints.
    pub mod schema {
        pub use crate::schema::{
            Arg, Diagnostic, MAX_DIGITS, Request, Value, describe, describe_motor, read,
            too_many_digits, units,
        };
    }

    /// The one route from arguments to a table.
    pub mod pipeline {
        pub use crate::pipeline::{Budget, Compiled, Options, compile};
    }

    /// The emitter's tokens for the macros, and the command-line tool's note
    /// on a table that starts far above `fmin`.
    pub mod emit {
        pub use crate::emit::{rust, start_note};
    }

    /// What a golden file holds, read back and compared.
    #[cfg(feature = "golden")]
    pub mod golden {
        pub use crate::golden::file::{Body, Entries, blessing, compare, read};
    }
}
