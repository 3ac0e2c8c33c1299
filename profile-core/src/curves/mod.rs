//! The curves, one module each: a curve's parameters, its own keys, its
//! checks and its model in time live in its own file, which implements
//! [`CurveKind`].
//!
//! The list at the end of this file names every curve once; the macro that
//! reads it makes the public [`Curve`] enum, the dispatch over it, and the
//! table of [`CurveSchema`]s the checks read a curve's name and modes from.
//! Adding a curve is one new file, its `mod` line and one line in that list,
//! and how the code generator reads it (ARCHITECTURE.md).

use crate::base::error::Error;
use crate::base::solve::TimeCurve;

pub(crate) mod check;
mod kind;

// The curves, one module each, declared here rather than by `curves!` so that
// `cargo fmt` reaches them (rustfmt does not follow modules a macro declares).
mod exponential;
mod jerk_limited;
mod linear;
mod proved;
mod sigmoid;
mod three_stage;
mod torque_limited;

pub(crate) use kind::{CurveKind, CurveSchema, IndexEntry, Length, Modes};
pub(crate) use proved::LinearEdges;

impl CurveSchema {
    /// The schema of the curve named `name`.
    pub(crate) fn named(name: &str) -> Option<&'static CurveSchema> {
        CURVE_SCHEMAS.iter().find(|r| r.name == name)
    }
}

macro_rules! curves {
    ($( $(#[$doc:meta])* $module:ident :: $Curve:ident, )+) => {
        $( pub use $module::$Curve; )+

        /// What the curves make public: the enum, each curve's parameters and
        /// constants. Re-exported at the crate root.
        pub mod public {
            pub use super::Curve;
            $( pub use super::$module::*; )+
        }

        /// A curve and its parameters.
        // `no_std` and allocation-free: a torque-limited ramp's acceleration
        // curve is held inline.
        #[allow(clippy::large_enum_variant)]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #[non_exhaustive]
        pub enum Curve {
            $( $(#[$doc])* $Curve($Curve), )+
        }

        $(
            impl From<$Curve> for Curve {
                fn from(c: $Curve) -> Self {
                    Curve::$Curve(c)
                }
            }
        )+

        /// Every curve's schema, in the order of the list.
        pub(crate) const CURVE_SCHEMAS: &[CurveSchema] = &[
            $(
                CurveSchema {
                    name: <$Curve as CurveKind>::NAME,
                    arithmetic: <$Curve as CurveKind>::ARITHMETIC,
                    index: <$Curve as CurveKind>::INDEX,
                },
            )+
        ];

        /// A checked curve's model in time.
        #[allow(clippy::large_enum_variant)]
        pub(crate) enum TimeModel {
            $( $Curve(<$Curve as CurveKind>::Time), )+
        }

        impl TimeModel {
            /// The model, whatever the curve.
            pub(crate) fn curve(&self) -> &dyn TimeCurve {
                match self {
                    $( TimeModel::$Curve(c) => c, )+
                }
            }
        }

        impl Curve {
            /// The curve's schema.
            pub(crate) fn schema(&self) -> &'static CurveSchema {
                let name = match self {
                    $( Curve::$Curve(_) => <$Curve as CurveKind>::NAME, )+
                };
                CurveSchema::named(name).unwrap_or(&CURVE_SCHEMAS[0])
            }

            /// The name used in macro arguments and TOML.
            pub fn name(&self) -> &'static str {
                self.schema().name
            }

            /// The start and end frequencies, in Hz.
            pub fn frequencies(&self) -> (f64, f64) {
                match self {
                    $( Curve::$Curve(c) => c.frequencies(), )+
                }
            }

            pub(crate) fn length(&self, index: bool) -> Length {
                match self {
                    $( Curve::$Curve(c) => c.length(index), )+
                }
            }

            pub(crate) fn check(&self, index: bool) -> Result<(), Error> {
                match self {
                    $( Curve::$Curve(c) => c.check(index), )+
                }
            }

            pub(crate) fn check_modes(&self, modes: &Modes) -> Result<(), Error> {
                match self {
                    $( Curve::$Curve(c) => c.check_modes(modes), )+
                }
            }

            pub(crate) fn index_entries(
                &self,
                modes: &Modes,
                sink: &mut dyn FnMut(IndexEntry) -> Result<(), Error>,
            ) -> Result<(), Error> {
                match self {
                    $( Curve::$Curve(c) => c.index_entries(modes, sink), )+
                }
            }

            pub(crate) fn time_model(&self) -> TimeModel {
                match self {
                    $( Curve::$Curve(c) => TimeModel::$Curve(c.time()), )+
                }
            }
        }
    };
}

curves! {
    /// The sigmoid S-curve (the S-curve articles).
    sigmoid::Sigmoid,
    /// The exponential ramp (the exponential-ramp article).
    exponential::Exponential,
    /// Constant acceleration (the constant-acceleration article).
    linear::Linear,
    /// Exponential, linear, parabolic (Zeng, Hu and Hu).
    three_stage::ThreeStage,
    /// Jerk-limited S-curve.
    jerk_limited::JerkLimited,
    /// The fastest ramp a motor allows, with a margin.
    torque_limited::TorqueLimited,
}
