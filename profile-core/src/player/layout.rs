//! Which ramps a player plays, known from its type.

mod sealed {
    pub trait Sealed {}
}

/// Which ramps a [`Player`](super::Player) plays: [`AnyLayout`] or
/// [`Compressed`]. The step path plays the layout's own kind of run first,
/// so that a player of compressed tables does not pay for checking the
/// per-step table's runs, and the other way round. Sealed: the two are all
/// there is.
pub trait Layout: sealed::Sealed {
    /// Only compressed tables: the step path plays a compressed run first.
    #[doc(hidden)]
    const COMPRESSED: bool;
}

/// Every layout: per-step, held, segment and compressed tables
/// ([`Player::new`](super::Player::new)). Its step path is the cheapest for
/// per-step tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnyLayout {}

/// Compressed tables only
/// ([`Player::compressed`](super::Player::compressed)). Its step path is
/// the cheapest for compressed runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Compressed {}

impl sealed::Sealed for AnyLayout {}
impl sealed::Sealed for Compressed {}

impl Layout for AnyLayout {
    const COMPRESSED: bool = false;
}

impl Layout for Compressed {
    const COMPRESSED: bool = true;
}
