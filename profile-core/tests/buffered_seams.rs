//! `Buffered` at the seams between moves, over random tables and random
//! sequences of new targets, the same target again, runs, stops and cruise
//! changes, many of them in the last two intervals of a move (the last
//! period in the timer's hands, or the one before it).
//!
//! The buffered stepper is driven by a model of a timer whose reload
//! register takes effect at the next wrap; every edge the pins take is
//! recorded with the interval before it, the direction the stepper says
//! for it and the position it reports after it. That must be, edge for
//! edge, what the plain `Axis` (or `Axes`) hands out when the same calls
//! come after the same number of periods handed out: the pin of a
//! buffered register plays the periods one interval late, in the
//! directions of the moves they belong to. And, from the table alone:
//!
//! - the position counted at the pins (one step an edge, signed by the
//!   direction the stepper says for that edge) is the one it reports;
//! - a direction changes only at rest: the intervals on both sides of the
//!   first edge after a change are the table's slowest entry;
//! - after the last target (sent once or again), the axes arrive there.
//!
//! `PROPTEST_CASES` sets the number of cases (default 256 per property).

use core_test_support as common;

use common::{cases, falling};
use profile_core::player::{Axes, Axis, Buffered, Direction, Player, Ramp};
use proptest::prelude::*;

/// When a call comes, counted from the one before.
#[derive(Clone, Copy, Debug)]
enum When {
    /// After this many interrupts (at once at rest).
    After(u32),
    /// At the first interrupt where at most `k + 1` edges are left to
    /// take: `k = 0` the last interval, its period in the timer's hands
    /// and none left to hand out; `k = 1` the one before (at once at rest).
    Last(u32),
}

/// A call, for one axis (`Axis`) or several (`Axes`: each target a
/// position per axis drawn from the same range).
#[derive(Clone, Debug)]
enum Op<T> {
    MoveTo(T),
    /// The target sent last, again.
    Again,
    Run(bool),
    Stop,
    Cruise(u32),
    CruisePeriod(u16),
    /// Nothing: where a call left out was.
    Wait,
}

fn when() -> impl Strategy<Value = When> {
    prop_oneof![
        2 => (0u32..40).prop_map(When::After),
        3 => (0u32..2).prop_map(When::Last),
    ]
}

fn ops<T: Clone + core::fmt::Debug>(
    target: impl Strategy<Value = T>,
    runs: bool,
) -> impl Strategy<Value = Vec<(When, Op<T>)>> {
    let run_weight = if runs { 1 } else { 0 };
    let op = prop_oneof![
        5 => target.prop_map(Op::MoveTo),
        3 => Just(Op::Again),
        run_weight => any::<bool>().prop_map(Op::Run),
        1 => Just(Op::Stop),
        1 => (0u32..40).prop_map(Op::Cruise),
        1 => any::<u16>().prop_map(Op::CruisePeriod),
    ];
    proptest::collection::vec((when(), op), 1..10)
}

fn direction(forward: bool) -> Direction {
    if forward {
        Direction::Forward
    } else {
        Direction::Backward
    }
}

/// An edge the pins take: the interval before it (`None` for the first of
/// a move from rest), the mask of the axes that step (1 for an `Axis`),
/// their directions and their positions after it.
type Edge<const N: usize> = (Option<u64>, u32, [Direction; N], [i64; N]);

/// A call made: after how many periods handed out, whether at rest (the
/// timer stopped), and what.
type Made<T> = (usize, bool, Op<T>);

/// The edges a drive took and the calls it made.
type Driven<const N: usize, T> = (Vec<Edge<N>>, Vec<Made<T>>);

/// What a call hands the timer: a period to start the counter with, one
/// for the register, and the mask of the edge taken at the start.
type Load = (Option<u16>, Option<u16>, u32);

/// What a buffered stepper does that the driver needs.
trait Stepper<const N: usize> {
    type Target: Clone + core::fmt::Debug;
    /// Applies a call: what to load (the first period, to start the
    /// counter with; the next, for the register) and the first edge's mask.
    fn call(&mut self, op: &Op<Self::Target>, last: &Self::Target) -> Load;
    /// An interrupt: the mask of the edge taken now (0: the move is over),
    /// the period after the interval now starting to `write`.
    fn interrupt(&mut self, write: &mut dyn FnMut(u16)) -> u32;
    /// Edges left to take.
    fn left(&self) -> u32;
    fn pin_directions(&self) -> [Direction; N];
    fn pin_position(&self) -> [i64; N];
}

impl Stepper<1> for Buffered<Axis<'_, u16>> {
    type Target = i64;
    fn call(&mut self, op: &Op<i64>, last: &i64) -> Load {
        let (_, first, next) = match op {
            Op::MoveTo(t) => self.move_to(*t),
            Op::Again => self.move_to(*last),
            Op::Run(forward) => self.run(direction(*forward)),
            Op::Stop => {
                self.stop();
                return (None, None, 0);
            }
            Op::Cruise(pos) => {
                self.set_cruise(*pos);
                return (None, None, 0);
            }
            Op::CruisePeriod(p) => {
                self.set_cruise_period(*p);
                return (None, None, 0);
            }
            Op::Wait => return (None, None, 0),
        };
        (first, next, u32::from(first.is_some()))
    }
    fn interrupt(&mut self, write: &mut dyn FnMut(u16)) -> u32 {
        u32::from(self.step(write))
    }
    fn left(&self) -> u32 {
        self.remaining()
    }
    fn pin_directions(&self) -> [Direction; 1] {
        [self.direction()]
    }
    fn pin_position(&self) -> [i64; 1] {
        [self.position()]
    }
}

impl<const N: usize> Stepper<N> for Buffered<Axes<'_, u16, N>> {
    type Target = [i64; N];
    fn call(&mut self, op: &Op<[i64; N]>, last: &[i64; N]) -> Load {
        let start = match op {
            Op::MoveTo(t) => self.move_to(*t),
            Op::Again => self.move_to(*last),
            Op::Run(_) => unreachable!("axes do not run"),
            Op::Stop => {
                self.stop();
                return (None, None, 0);
            }
            Op::Cruise(pos) => {
                self.set_cruise(*pos);
                return (None, None, 0);
            }
            Op::CruisePeriod(p) => {
                self.set_cruise_period(*p);
                return (None, None, 0);
            }
            Op::Wait => return (None, None, 0),
        };
        (start.first, start.next, start.mask)
    }
    fn interrupt(&mut self, write: &mut dyn FnMut(u16)) -> u32 {
        self.step(write)
    }
    fn left(&self) -> u32 {
        self.remaining()
    }
    fn pin_directions(&self) -> [Direction; N] {
        self.directions()
    }
    fn pin_position(&self) -> [i64; N] {
        self.position()
    }
}

/// Moves the pins of the axes in `mask` one step each in `directions`.
fn take<const N: usize>(pins: &mut [i64; N], mask: u32, directions: [Direction; N]) {
    for (i, p) in pins.iter_mut().enumerate() {
        if mask >> i & 1 == 1 {
            *p += directions[i].sign();
        }
    }
}

/// Drives `stepper` on the timer model through `ops`, then to rest (a
/// stop after a few interrupts when the last call leaves a run): the
/// edges the pins take, and the calls as made.
fn drive<const N: usize, S: Stepper<N>>(
    stepper: &mut S,
    from: [i64; N],
    first_target: S::Target,
    ops: &[(When, Op<S::Target>)],
) -> Result<Driven<N, S::Target>, TestCaseError> {
    let mut edges: Vec<Edge<N>> = vec![];
    let mut made = vec![];
    let mut last = first_target.clone();
    let mut pins = from;
    // The timer: running, the interval it counts, the register, the time
    // of the last edge.
    let mut running = false;
    let (mut now, mut counting, mut reload, mut edge_at) = (0u64, 0u16, 0u16, 0u64);
    let mut handed = 0usize;
    let mut interrupts = 0u32;
    let mut all: Vec<(When, Op<S::Target>)> = vec![(When::After(0), Op::MoveTo(first_target))];
    all.extend(ops.iter().cloned());
    // To rest at the end, and to the end of that stop.
    all.push((When::After(5), Op::Stop));
    all.push((When::After(u32::MAX), Op::Wait));
    for (when, op) in &all {
        let mut waited = 0u32;
        while running {
            let due = match *when {
                When::After(n) => waited >= n,
                // (A run has no last intervals: a while, then.)
                When::Last(k) => stepper.left() <= k + 1 || waited >= 3000,
            };
            if due {
                break;
            }
            // The wrap: the interval ends, the counter loads the register.
            now += u64::from(counting);
            counting = reload;
            let mask = stepper.interrupt(&mut |p| {
                reload = p;
                handed += 1;
            });
            waited += 1;
            interrupts += 1;
            prop_assert!(interrupts < 200_000, "a move without end");
            if mask == 0 {
                running = false;
                break;
            }
            let directions = stepper.pin_directions();
            take(&mut pins, mask, directions);
            edges.push((
                Some(now - edge_at),
                mask,
                directions,
                stepper.pin_position(),
            ));
            edge_at = now;
            prop_assert_eq!(stepper.pin_position(), pins, "at edge {}", edges.len());
        }
        made.push((handed, !running, op.clone()));
        if let Op::MoveTo(t) = op {
            last = t.clone();
        }
        match stepper.call(op, &last) {
            (Some(first), next, mask) => {
                prop_assert!(!running, "a counter to start while it runs: {op:?}");
                handed += 1 + usize::from(next.is_some());
                (counting, reload, running) = (first, next.unwrap_or(first), true);
                let directions = stepper.pin_directions();
                take(&mut pins, mask, directions);
                edges.push((None, mask, directions, stepper.pin_position()));
                edge_at = now;
                prop_assert_eq!(stepper.pin_position(), pins, "at edge {}", edges.len());
            }
            (None, Some(next), mask) => {
                // The last interval counting: the register, for the edge
                // its end takes.
                prop_assert!(running, "a register to load at rest: {op:?}");
                prop_assert_eq!(mask, 0);
                handed += 1;
                reload = next;
            }
            (None, None, mask) => prop_assert_eq!(mask, 0),
        }
    }
    Ok((edges, made))
}

/// The rules from the table alone: a direction changes only at rest.
fn at_rest_turns<const N: usize>(edges: &[Edge<N>], slowest: u16) -> Result<(), TestCaseError> {
    let slowest = Some(u64::from(slowest));
    for (k, w) in edges.windows(2).enumerate() {
        let ((_, _, before, _), (interval, mask, now, _)) = (&w[0], &w[1]);
        for i in 0..N {
            // The axis steps on this edge in another direction than the one
            // its pin said last.
            if mask >> i & 1 == 1 && before[i] != now[i] && interval.is_some() {
                let after = edges.get(k + 2).map(|e| e.0);
                prop_assert_eq!(*interval, slowest, "a turn at speed at edge {}", k + 1);
                if let Some(Some(after)) = after {
                    prop_assert_eq!(Some(after), slowest, "a turn at speed at edge {}", k + 1);
                }
            }
        }
    }
    Ok(())
}

/// What the plain (unbuffered) steppers do that the replay needs.
trait Plain<const N: usize> {
    type Target;
    /// The next step: its period and the mask of the axes that take it.
    fn next(&mut self) -> Option<(u16, u32)>;
    /// Makes the call `op`, `last` the target sent last.
    fn apply(&mut self, op: &Op<Self::Target>, last: &Self::Target);
    fn directions(&self) -> [Direction; N];
    fn position(&self) -> [i64; N];
}

impl Plain<1> for Axis<'_, u16> {
    type Target = i64;
    fn next(&mut self) -> Option<(u16, u32)> {
        let mut period = 0;
        self.step(|p| period = p).then_some((period, 1))
    }
    fn apply(&mut self, op: &Op<i64>, last: &i64) {
        match op {
            Op::MoveTo(t) => {
                self.move_to(*t);
            }
            Op::Again => {
                self.move_to(*last);
            }
            Op::Run(forward) => {
                self.run(direction(*forward));
            }
            Op::Stop => self.stop(),
            Op::Cruise(pos) => self.set_cruise(*pos),
            Op::CruisePeriod(p) => self.set_cruise_period(*p),
            Op::Wait => {}
        }
    }
    fn directions(&self) -> [Direction; 1] {
        [self.direction()]
    }
    fn position(&self) -> [i64; 1] {
        [Axis::position(self)]
    }
}

impl<const N: usize> Plain<N> for Axes<'_, u16, N> {
    type Target = [i64; N];
    fn next(&mut self) -> Option<(u16, u32)> {
        self.next_step()
    }
    fn apply(&mut self, op: &Op<[i64; N]>, last: &[i64; N]) {
        match op {
            Op::MoveTo(t) => {
                self.move_to(*t);
            }
            Op::Again => {
                self.move_to(*last);
            }
            Op::Run(_) => unreachable!("axes do not run"),
            Op::Stop => self.stop(),
            Op::Cruise(pos) => self.set_cruise(*pos),
            Op::CruisePeriod(p) => self.set_cruise_period(*p),
            Op::Wait => {}
        }
    }
    fn directions(&self) -> [Direction; N] {
        Axes::directions(self)
    }
    fn position(&self) -> [i64; N] {
        Axes::position(self)
    }
}

/// The plain stepper `plain`, from `from`, with the same calls after the
/// same periods handed out: the edges it takes.
fn replay<const N: usize, P: Plain<N>>(
    mut plain: P,
    from: P::Target,
    made: &[Made<P::Target>],
) -> Result<Vec<Edge<N>>, TestCaseError>
where
    P::Target: Clone,
{
    let mut edges = vec![];
    let mut before: Option<u16> = None;
    let mut handed = 0usize;
    let mut last = from;
    let mut step = |plain: &mut P, edges: &mut Vec<Edge<N>>| match plain.next() {
        Some((period, mask)) => {
            edges.push((
                before.map(u64::from),
                mask,
                plain.directions(),
                plain.position(),
            ));
            before = Some(period);
            true
        }
        None => {
            before = None;
            false
        }
    };
    for (at, rest, op) in made {
        while handed < *at {
            prop_assert!(step(&mut plain, &mut edges), "ended before {at} periods");
            handed += 1;
        }
        if *rest {
            prop_assert!(!step(&mut plain, &mut edges), "at rest after {at} periods");
        }
        plain.apply(op, &last);
        if let Op::MoveTo(t) = op {
            last = t.clone();
        }
    }
    let mut n = 0;
    while step(&mut plain, &mut edges) {
        n += 1;
        prop_assert!(n < 200_000, "a move without end");
    }
    Ok(edges)
}

/// The plain axis with the same calls after the same periods handed out.
fn plain_axis(table: &[u16], from: i64, made: &[Made<i64>]) -> Result<Vec<Edge<1>>, TestCaseError> {
    replay(Axis::new(Player::new(Ramp::steps(table)), from), from, made)
}

/// The plain axes with the same calls after the same periods handed out.
fn plain_axes<const N: usize>(
    table: &[u16],
    from: [i64; N],
    made: &[Made<[i64; N]>],
) -> Result<Vec<Edge<N>>, TestCaseError> {
    replay(Axes::new(Player::new(Ramp::steps(table)), from), from, made)
}

/// The target the last calls leave, if they leave one: the last target
/// sent, when no stop or run came after it.
fn final_target<T: Clone>(first: &T, ops: &[(When, Op<T>)]) -> Option<T> {
    let mut target = Some(first.clone());
    let mut last = first.clone();
    for (_, op) in ops {
        match op {
            Op::MoveTo(t) => {
                last = t.clone();
                target = Some(t.clone());
            }
            Op::Again => target = Some(last.clone()),
            Op::Run(_) | Op::Stop => target = None,
            Op::Cruise(_) | Op::CruisePeriod(_) | Op::Wait => {}
        }
    }
    target
}

/// The same calls with each `Again` left out, nothing in its place:
/// sending the target again changes nothing.
fn without_again<T: Clone>(ops: &[(When, Op<T>)]) -> Vec<(When, Op<T>)> {
    ops.iter()
        .map(|(when, op)| match op {
            Op::Again => (*when, Op::Wait),
            _ => (*when, op.clone()),
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// An axis: the buffered pin takes the plain axis's steps one interval
    /// late, each in its own move's direction, and turns only at rest.
    #[test]
    fn a_buffered_axis_takes_every_step_of_the_plain_axis(
        table in falling(1usize..24, 900, 2),
        from in -200i64..200,
        first in -200i64..200,
        ops in ops(-200i64..200, true),
    ) {
        let mut stepper = Buffered::new(Axis::new(Player::new(Ramp::steps(&table)), from));
        let (edges, made) = drive::<1, _>(&mut stepper, [from], first, &ops)?;
        let plain = plain_axis(&table, from, &made)?;
        prop_assert_eq!(&edges, &plain);
        at_rest_turns(&edges, table[0])?;
        // The final stop has ended every move.
        prop_assert!(stepper.is_done() && stepper.inner().is_done());
    }

    /// Axes, two and three: the same, mask and directions per edge.
    #[test]
    fn buffered_axes_take_every_edge_of_the_plain_axes(
        table in falling(1usize..24, 900, 2),
        from in proptest::array::uniform3(-100i64..100),
        first in proptest::array::uniform3(-100i64..100),
        ops in ops(proptest::array::uniform3(-100i64..100), false),
        three in any::<bool>(),
    ) {
        if three {
            let mut stepper = Buffered::new(Axes::new(Player::new(Ramp::steps(&table)), from));
            let (edges, made) = drive(&mut stepper, from, first, &ops)?;
            prop_assert_eq!(&edges, &plain_axes(&table, from, &made)?);
            at_rest_turns(&edges, table[0])?;
        } else {
            let two = |a: [i64; 3]| [a[0], a[1]];
            let ops: Vec<_> = ops.iter().map(|(w, op)| (*w, match op {
                Op::MoveTo(t) => Op::MoveTo(two(*t)),
                Op::Again => Op::Again,
                Op::Run(f) => Op::Run(*f),
                Op::Stop => Op::Stop,
                Op::Cruise(p) => Op::Cruise(*p),
                Op::CruisePeriod(p) => Op::CruisePeriod(*p),
                Op::Wait => Op::Wait,
            })).collect();
            let mut stepper = Buffered::new(Axes::new(Player::new(Ramp::steps(&table)), two(from)));
            let (edges, made) = drive(&mut stepper, two(from), two(first), &ops)?;
            prop_assert_eq!(&edges, &plain_axes(&table, two(from), &made)?);
            at_rest_turns(&edges, table[0])?;
        }
    }

    /// Without a final stop, the axes arrive at the last target; sending a
    /// target again, anywhere, the last intervals included, changes no
    /// edge.
    #[test]
    fn the_last_target_is_reached_and_sending_it_again_changes_nothing(
        table in falling(1usize..24, 900, 2),
        from in proptest::array::uniform2(-100i64..100),
        first in proptest::array::uniform2(-100i64..100),
        ops in ops(proptest::array::uniform2(-100i64..100), false),
    ) {
        // No stop: every move plays to its end.
        let ops: Vec<_> = ops.into_iter().filter(|(_, op)| !matches!(op, Op::Stop)).collect();
        let run = |ops: &[(When, Op<[i64; 2]>)]| {
            let mut stepper = Buffered::new(Axes::new(Player::new(Ramp::steps(&table)), from));
            let mut all = ops.to_vec();
            // Long enough for the last move to end before the final stop.
            all.push((When::After(100_000), Op::Wait));
            drive(&mut stepper, from, first, &all).map(|(edges, _)| (edges, stepper.pin_position()))
        };
        let (edges, end) = run(&ops)?;
        if let Some(target) = final_target(&first, &ops) {
            prop_assert_eq!(end, target);
        }
        let (edges_once, end_once) = run(&without_again(&ops))?;
        prop_assert_eq!(end, end_once);
        let times = |e: &[Edge<2>]| e.iter().map(|e| (e.0, e.1, e.3)).collect::<Vec<_>>();
        prop_assert_eq!(times(&edges), times(&edges_once));
    }

    /// The same for one axis, runs among the calls.
    #[test]
    fn an_axis_reaches_its_last_target_and_sending_it_again_changes_nothing(
        table in falling(1usize..24, 900, 2),
        from in -200i64..200,
        first in -200i64..200,
        ops in ops(-200i64..200, false),
    ) {
        let ops: Vec<_> = ops.into_iter().filter(|(_, op)| !matches!(op, Op::Stop)).collect();
        let run = |ops: &[(When, Op<i64>)]| {
            let mut stepper = Buffered::new(Axis::new(Player::new(Ramp::steps(&table)), from));
            let mut all = ops.to_vec();
            all.push((When::After(100_000), Op::Wait));
            drive::<1, _>(&mut stepper, [from], first, &all).map(|(edges, _)| (edges, stepper.pin_position()))
        };
        let (edges, end) = run(&ops)?;
        if let Some(target) = final_target(&first, &ops) {
            prop_assert_eq!(end, [target]);
        }
        let (edges_once, end_once) = run(&without_again(&ops))?;
        prop_assert_eq!(end, end_once);
        prop_assert_eq!(edges, edges_once);
    }

    /// A retarget to the steps that remain changes nothing, at any step of
    /// any move, whatever comes after it.
    #[test]
    fn a_retarget_that_changes_nothing_is_a_no_op(
        table in falling(1usize..40, 900, 2),
        (steps, at) in prop_oneof![1u32..12, 1u32..200].prop_flat_map(|s| (Just(s), 0..=s)),
        later in prop_oneof![0u32..16, 0u32..300],
        stop in any::<bool>(),
        cruise in proptest::option::of(0u32..40),
    ) {
        let play = |noop: bool| {
            let mut player = Player::new(Ramp::steps(&table));
            player.start(steps);
            let mut out: Vec<u16> = (0..at).filter_map(|_| player.next_period()).collect();
            if noop {
                let remaining = player.remaining();
                assert!(player.retarget(remaining));
            }
            if let Some(pos) = cruise {
                player.set_cruise(pos);
            }
            let taken = if stop { player.stop(); true } else { player.retarget(later) };
            out.extend(core::iter::from_fn(|| player.next_period()));
            (taken, out)
        };
        prop_assert_eq!(play(true), play(false));
    }
}
