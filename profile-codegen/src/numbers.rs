//! Numbers in messages, printed as `profile-core`'s own messages print them
//! ([`MessageNumber`]).

use core::fmt;

use profile_core::MessageNumber;

/// A number as a user wrote it ([`MessageNumber::plain`]).
pub(crate) struct Num(pub(crate) f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        MessageNumber::plain(self.0).fmt(f)
    }
}

/// A figure to a fixed number of decimals ([`MessageNumber::fixed`]).
pub(crate) struct Fixed(pub(crate) f64, pub(crate) usize);

impl fmt::Display for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        MessageNumber::fixed(self.0, self.1).fmt(f)
    }
}

/// At most six significant digits ([`MessageNumber::significant`]).
pub(crate) struct Significant(pub(crate) f64);

impl fmt::Display for Significant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        MessageNumber::significant(self.0).fmt(f)
    }
}
