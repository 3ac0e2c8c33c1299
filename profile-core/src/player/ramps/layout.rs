//! Which ramps a player plays, known from its type, and the tables that
//! choose it.

use crate::base::timer::TableWord;
use crate::player::ramps::ramp::Ramp;
use crate::table::runs::RunIndex;

mod sealed {
    pub trait Sealed {}
}

/// Which ramps a [`Player`](crate::player::Player) plays: [`AnyLayout`] or
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
/// ([`Player::new`](crate::player::Player::new)). Its step path is the cheapest for
/// per-step tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnyLayout {}

/// Compressed tables only
/// ([`Player::new`](crate::player::Player::new) of a compressed table). Its step path is
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

/// What a player is made from: a table, and through its type the step
/// path the player takes ([`Layout`]). A per-step table (`&[u16]`,
/// `&[u32]`, a `[W; N]` by reference) or any [`Ramp`] gives a player of
/// [`AnyLayout`]; a compressed table (`&[[u16; 5]]`, a profile's `RUNS`)
/// or its index ([`RunIndex`], a profile's `RUN_INDEX`) gives one of
/// [`Compressed`], whose step path knows its ramps are runs.
///
/// ```
/// use profile_core::player::{AnyLayout, Compressed, Player, Ramp};
///
/// static PERIODS: [u16; 4] = [4000, 3000, 2000, 1500];
/// static RUNS: [[u16; 5]; 1] = [[4, 2000, 0, 0, 0]];
/// let steps: Player<u16, AnyLayout> = Player::new(&PERIODS);
/// let held: Player<u16, AnyLayout> = Player::new(Ramp::held(&PERIODS, 2));
/// let runs: Player<u16, Compressed> = Player::new(&RUNS);
/// # let _ = (steps, held, runs);
/// ```
pub trait IntoRamp<'a, W> {
    /// The step path a player of this table takes.
    type Layout: Layout;
    /// The table as a ramp.
    fn into_ramp(self) -> Ramp<'a, W>;
}

impl<'a, W: TableWord> IntoRamp<'a, W> for Ramp<'a, W> {
    type Layout = AnyLayout;
    fn into_ramp(self) -> Ramp<'a, W> {
        self
    }
}

impl<'a, W: TableWord> IntoRamp<'a, W> for &'a [W] {
    type Layout = AnyLayout;
    fn into_ramp(self) -> Ramp<'a, W> {
        Ramp::steps(self)
    }
}

impl<'a, W: TableWord, const N: usize> IntoRamp<'a, W> for &'a [W; N] {
    type Layout = AnyLayout;
    fn into_ramp(self) -> Ramp<'a, W> {
        Ramp::steps(self)
    }
}

impl<'a, W: TableWord> IntoRamp<'a, W> for &'a [[u16; 5]] {
    type Layout = Compressed;
    fn into_ramp(self) -> Ramp<'a, W> {
        Ramp::runs(self)
    }
}

impl<'a, W: TableWord, const N: usize> IntoRamp<'a, W> for &'a [[u16; 5]; N] {
    type Layout = Compressed;
    fn into_ramp(self) -> Ramp<'a, W> {
        Ramp::runs(self)
    }
}

impl<'a, W: TableWord, const N: usize> IntoRamp<'a, W> for &'a RunIndex<N> {
    type Layout = Compressed;
    fn into_ramp(self) -> Ramp<'a, W> {
        Ramp::indexed(self)
    }
}
