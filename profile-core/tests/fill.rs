//! `Player::fill` against the plain `next_period`: over random tables
//! (per-step, held, segments, compressed runs), random buffer sizes and
//! random stops and cruise changes between fills, the fills concatenated
//! are the periods `next_period` hands out, and the player is left where
//! as many steps leave it.
//!
//! `PROPTEST_CASES` sets the number of operation sequences per property
//! (default 256, times 4 here).

use core_test_support as common;

use common::{Shape, any_runs, cases, shape};
use profile_core::TableWord;
use profile_core::player::{Axis, Compressed, Player, Ramp};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};

#[derive(Clone, Debug)]
enum Op {
    Start(u32),
    /// A fill into a buffer of this size.
    Fill(usize),
    Stop,
    Cruise(u32),
}

fn ops() -> impl Strategy<Value = Vec<Op>> {
    let op = prop_oneof![
        2 => prop_oneof![8 => 0u32..1500, 1 => Just(0u32), 1 => Just(u32::MAX)].prop_map(Op::Start),
        8 => prop_oneof![1 => Just(0usize), 1 => Just(1usize), 6 => 2usize..80, 2 => 80usize..700]
            .prop_map(Op::Fill),
        2 => Just(Op::Stop),
        2 => (0u32..250).prop_map(Op::Cruise),
    ];
    proptest::collection::vec(op, 1..16)
}

/// The ramps a shape's tables make, in `W`.
struct Tables<W> {
    steps: Vec<W>,
    pairs: Vec<(W, W)>,
}

impl<W: TableWord> Tables<W> {
    fn new(shape: &Shape) -> Self {
        let steps = match shape {
            Shape::Steps(t, _) => t.iter().map(|&p| W::from_ticks(p)).collect(),
            _ => Vec::new(),
        };
        let pairs = match shape {
            Shape::Segments(t) => t
                .iter()
                .map(|&(p, c)| (W::from_ticks(p), W::from_ticks(c)))
                .collect(),
            _ => Vec::new(),
        };
        Tables { steps, pairs }
    }

    fn ramp<'t>(&'t self, shape: &'t Shape) -> Ramp<'t, W> {
        match shape {
            Shape::Steps(_, hold) => Ramp::held(&self.steps, *hold),
            Shape::Segments(_) => Ramp::segments(&self.pairs),
            Shape::Runs(r) => Ramp::runs(r),
        }
    }
}

/// A player and its twin: one fills, the other steps.
trait Filled {
    fn start(&mut self, n: u32);
    fn stop(&mut self);
    fn set_cruise(&mut self, pos: u32);
    fn fill(&mut self, buf: &mut [u32]) -> usize;
    fn next(&mut self) -> Option<u32>;
    fn remaining(&self) -> u32;
}

macro_rules! filled {
    ($($ty:ty),*) => {$(
        impl<W: TableWord> Filled for $ty {
            fn start(&mut self, n: u32) {
                self.start(n);
            }
            fn stop(&mut self) {
                self.stop();
            }
            fn set_cruise(&mut self, pos: u32) {
                self.set_cruise(pos);
            }
            fn fill(&mut self, buf: &mut [u32]) -> usize {
                // In the player's word, then widened: the buffer's end
                // beyond what was written keeps a value no period has.
                let mut words = vec![W::from_ticks(0); buf.len()];
                let n = self.fill(&mut words);
                for (slot, w) in buf.iter_mut().zip(&words) {
                    *slot = w.into_ticks();
                }
                n
            }
            fn next(&mut self) -> Option<u32> {
                self.next_period().map(|w| w.into_ticks())
            }
            fn remaining(&self) -> u32 {
                self.remaining()
            }
        }
    )*};
}
filled!(Player<'_, W>, Player<'_, W, Compressed>);

/// Plays `ops` on `filled` (by fills) and `stepped` (by `next_period`):
/// every fill returns what as many steps return, and both have as many
/// steps left after every operation. Returns the periods compared.
fn compare(
    filled: &mut dyn Filled,
    stepped: &mut dyn Filled,
    ops: &[Op],
) -> Result<u64, TestCaseError> {
    let mut compared = 0u64;
    for (i, op) in ops.iter().enumerate() {
        match *op {
            Op::Start(n) => {
                filled.start(n);
                stepped.start(n);
            }
            Op::Stop => {
                filled.stop();
                stepped.stop();
            }
            Op::Cruise(pos) => {
                filled.set_cruise(pos);
                stepped.set_cruise(pos);
            }
            Op::Fill(size) => {
                let mut buf = vec![0u32; size];
                let n = filled.fill(&mut buf);
                let want: Vec<u32> = (0..size).map_while(|_| stepped.next()).collect();
                prop_assert_eq!(n, want.len(), "op {} ({:?}): periods written", i, op);
                prop_assert_eq!(&buf[..n], &want[..], "op {} ({:?})", i, op);
                prop_assert!(
                    buf[n..].iter().all(|&v| v == 0),
                    "op {}: written past the end",
                    i
                );
                compared += n as u64;
            }
        }
        prop_assert_eq!(
            filled.remaining(),
            stepped.remaining(),
            "after op {} ({:?})",
            i,
            op
        );
    }
    Ok(compared)
}

fn run(
    what: &str,
    strategy: impl Strategy<Value = (Shape, Shape, Vec<Op>, bool)>,
    compressed: bool,
) {
    let mut runner = TestRunner::new(Config {
        cases: cases() * 4,
        failure_persistence: None,
        ..Config::default()
    });
    let total = std::cell::Cell::new(0u64);
    runner
        .run(&strategy, |(accel, decel, ops, wide)| {
            fn both<W: TableWord>(
                accel: &Shape,
                decel: &Shape,
                ops: &[Op],
                compressed: bool,
            ) -> Result<u64, TestCaseError> {
                let (a, d) = (Tables::<W>::new(accel), Tables::<W>::new(decel));
                let (ra, rd) = (a.ramp(accel), d.ramp(decel));
                if let (true, Ramp::Runs(x), Ramp::Runs(y)) = (compressed, ra, rd) {
                    let mut f = Player::<W, Compressed>::new(x).with_decel(y);
                    let mut s = f.clone();
                    return compare(&mut f, &mut s, ops);
                }
                let mut f = Player::new(ra).with_decel(rd);
                let mut s = f.clone();
                compare(&mut f, &mut s, ops)
            }
            let n = if wide {
                both::<u32>(&accel, &decel, &ops, compressed)?
            } else {
                both::<u16>(&accel, &decel, &ops, compressed)?
            };
            total.set(total.get() + n);
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
    println!("{what}: {} periods filled and compared", total.get());
}

/// Every layout, one ramp or two, either word.
#[test]
fn fills_are_the_periods_next_period_hands_out() {
    let ramps = shape(200, 30, 2).prop_flat_map(|a| {
        let same = Just(a.clone());
        (Just(a), prop_oneof![1 => same, 1 => shape(200, 30, 2)])
    });
    let strategy = (ramps, ops(), any::<bool>()).prop_map(|((a, d), ops, w)| (a, d, ops, w));
    run("Player::new", strategy, false);
}

/// The player of compressed tables, on runs (empty runs included).
#[test]
fn compressed_fills_are_the_periods_next_period_hands_out() {
    let runs = || any_runs().prop_map(Shape::Runs);
    let ramps = runs().prop_flat_map(move |a| {
        let same = Just(a.clone());
        (Just(a), prop_oneof![1 => same, 1 => runs()])
    });
    let strategy = (ramps, ops(), any::<bool>()).prop_map(|((a, d), ops, w)| (a, d, ops, w));
    run("compressed Player", strategy, true);
}

/// The axis fills as its player does, and its position follows the fills.
#[test]
fn an_axis_fills_and_keeps_its_position() {
    static RAMP: [u16; 6] = [5000, 4000, 3000, 2500, 2200, 2000];
    let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), 100);
    axis.move_by(-25);
    let mut buf = [0u16; 10];
    assert_eq!(axis.fill(&mut buf), 10);
    assert_eq!(
        buf,
        [5000, 4000, 3000, 2500, 2200, 2000, 2000, 2000, 2000, 2000]
    );
    assert_eq!(axis.position(), 90);
    assert_eq!(axis.fill(&mut buf), 10);
    assert_eq!(axis.fill(&mut buf), 5);
    assert_eq!(buf[..5], [2200, 2500, 3000, 4000, 5000]);
    assert_eq!((axis.position(), axis.fill(&mut buf)), (75, 0));
}
