//! The host side of stepper-profiles: what turns profiles into code, and
//! never runs on the target.
//!
//! Firmware depends on `profile-core` (curves, tables computed without
//! allocation, the player); this crate is what the `period_table!` and
//! `include_profiles!` macros, build scripts and the `stepper-profiles`
//! command-line tool run on the host:
//!
//! - [`profiles`]: profiles files, the build-script entry point
//!   ([`profiles::build_script`]), the C header and source files;
//! - [`golden`]: golden files that pin a table in a user's tests;
//! - [`Table`], [`Generated`], [`RunTable`]: tables owned on the heap, in
//!   every layout, and the fitter of compressed ramps, through
//!   [`SpecTables`] on a `Spec`;
//! - [`motor`]: the motor model, the check of a table against a motor, the
//!   fastest ramp a motor allows, and [`simulate`], the step-loss
//!   simulation.
//!
//! ```
//! use profile_codegen::SpecTables;
//! use profile_core::{Curve, Linear, LinearExtent, Spec, Timer};
//!
//! let spec = Spec::new(
//!     Curve::Linear(Linear { fmin: 500.0, fmax: 20_000.0, extent: LinearExtent::Len(200) }),
//!     Timer::new(1_000_000),
//! );
//! let table = spec.table()?;
//! assert_eq!(table.periods.len(), 200);
//! // Compressed: runs of a linear recurrence, every edge within 0.75 tick.
//! let runs = spec.run_table(0.75)?;
//! assert!(runs.figures.max_edge_error_ticks <= 0.75);
//! # Ok::<(), profile_core::Error>(())
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bands;
pub mod capture;
pub mod cpu;
pub mod driver;
mod emit;
pub mod golden;
pub mod motor;
mod numbers;
mod pipeline;
pub mod profiles;
mod schema;
mod table;

#[doc(inline)]
pub use motor::simulate;
pub use table::compress::{MAX_COMPRESS_TICKS, MIN_COMPRESS_TICKS, RunTable};
pub use table::computed::{Generated, SegmentTable, SpecTables, Table};

/// What this workspace's other crates use and users do not: the argument
/// schema, the pipeline and the emitter (for `profile-macros` and the
/// command-line tool), and what a golden file holds (for the repository's
/// own golden tests). Not API: it changes in any release, without notice.
/// ARCHITECTURE.md says where the API ends and why.
#[doc(hidden)]
pub mod __private {
    /// The argument schema `profile-macros` reads tokens into, and the
    /// descriptions the command-line tool prints.
    pub mod schema {
        pub use crate::schema::keys::all as all_keys;
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
    pub mod golden {
        pub use crate::golden::file::{Body, Entries, blessing, compare, read};
    }
}
