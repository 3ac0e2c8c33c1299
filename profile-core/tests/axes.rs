//! `player::Axes` over random moves of 1 to 4 axes, random ramps, stops and
//! cruise changes, against a model written here on its own: the lead is
//! the axis with the most steps (of equal ones the lowest index) and plays
//! what a single `Player` plays; an axis of `d` steps of the lead's `L`
//! takes its `k`-th step on the lead's step `floor((2kL + d) / 2d)`,
//! computed in 128-bit integers, never through an accumulator.
//!
//! `PROPTEST_CASES` sets the number of cases (default 256 per property).

use core_test_support as common;

use common::{Event, cases, events, falling};
use profile_core::player::{Axes, AxesStart, Buffered, Compressed, Direction, Player, Ramp};
use proptest::prelude::*;

/// 1 to 4 axes' moves; now and then two of them equal, for the lead's ties.
fn deltas() -> impl Strategy<Value = Vec<i64>> {
    (
        proptest::collection::vec(-400i64..400, 1..=4),
        any::<bool>(),
    )
        .prop_map(|(mut d, tie)| {
            if tie && d.len() > 1 {
                let last = d.len() - 1;
                d[last] = -d[0];
            }
            d
        })
}

/// The model of a move: which axes step on each of the lead's edges.
struct Model {
    lead: usize,
    /// The lead's steps.
    len: u32,
    /// Edge `e` (from 0, the lead's step `e + 1`): bit `i` when axis `i`
    /// steps there.
    masks: Vec<u32>,
}

/// The lead steps on which an axis of `d` steps of the lead's `l` takes its
/// steps: `floor((2kl + d) / 2d)` for `k = 1..=d`.
fn rule(d: u64, l: u64) -> Vec<u64> {
    (1..=u128::from(d))
        .map(|k| ((2 * k * u128::from(l) + u128::from(d)) / (2 * u128::from(d))) as u64)
        .collect()
}

fn model(deltas: &[i64]) -> Model {
    let steps: Vec<u64> = deltas.iter().map(|d| d.unsigned_abs()).collect();
    let len = steps.iter().copied().max().unwrap_or(0);
    let lead = steps.iter().position(|&s| s == len).unwrap_or(0);
    let mut masks = vec![1u32 << lead; len as usize];
    for (i, &d) in steps.iter().enumerate() {
        if i == lead {
            continue;
        }
        for s in rule(d, len) {
            // Lead steps 1..=len; never two steps of one axis on one edge.
            assert!(
                (1..=len).contains(&s),
                "the rule names lead step {s} of {len}"
            );
            let m = &mut masks[s as usize - 1];
            assert_eq!(*m & (1 << i), 0, "two steps on one edge");
            *m |= 1 << i;
        }
    }
    Model {
        lead,
        len: len as u32,
        masks,
    }
}

/// Positions after `edges` of the model's edges.
fn positions(from: &[i64], deltas: &[i64], masks: &[u32]) -> Vec<i64> {
    (0..from.len())
        .map(|i| {
            let steps = masks.iter().filter(|&&m| m & (1 << i) != 0).count() as i64;
            from[i] + deltas[i].signum() * steps
        })
        .collect()
}

/// The periods a single player hands out, with `events` applied before the
/// period of their index.
fn plain(accel: &[u16], steps: u32, events: &[(usize, Event)]) -> Vec<u16> {
    let mut player = Player::new(Ramp::steps(accel));
    player.start(steps);
    let mut out = Vec::new();
    loop {
        apply(events, out.len(), |e| match e {
            Event::Stop => player.stop(),
            Event::Cruise(pos) => player.set_cruise(pos),
        });
        match player.next_period() {
            Some(p) => out.push(p),
            None => return out,
        }
        assert!(out.len() < 100_000, "a move without end");
    }
}

fn apply(events: &[(usize, Event)], at: usize, mut f: impl FnMut(Event)) {
    for &(i, e) in events {
        if i == at {
            f(e);
        }
    }
}

fn array<const N: usize>(v: &[i64]) -> [i64; N] {
    v.try_into().expect("N values")
}

/// Plays `deltas` from `from` with `events`; checks every edge and
/// position against the model and the lead's periods against `plain`.
fn play<const N: usize>(
    accel: &[u16],
    from: &[i64],
    deltas: &[i64],
    events: &[(usize, Event)],
) -> Result<(), TestCaseError> {
    let m = model(deltas);
    let periods = plain(accel, m.len, events);
    let mut axes = Axes::new(Player::new(Ramp::steps(accel)), array::<N>(from));
    let target: Vec<i64> = from.iter().zip(deltas).map(|(f, d)| f + d).collect();
    let directions = axes.move_to(array::<N>(&target));
    for (i, d) in directions.iter().enumerate() {
        let want = if deltas[i] < 0 {
            Direction::Backward
        } else {
            Direction::Forward
        };
        prop_assert_eq!(*d, want);
    }
    prop_assert_eq!(axes.lead(), m.lead);
    // A single player in step with the lead.
    let mut single = Player::new(Ramp::steps(accel));
    single.start(m.len);
    let mut edges: Vec<(u16, u32)> = Vec::new();
    loop {
        apply(events, edges.len(), |e| match e {
            Event::Stop => {
                axes.stop();
                single.stop();
            }
            Event::Cruise(pos) => {
                axes.set_cruise(pos);
                single.set_cruise(pos);
            }
        });
        prop_assert_eq!(axes.remaining(), single.remaining());
        let before = edges.len();
        let more = axes.step(|period, mask| edges.push((period, mask)));
        prop_assert_eq!(more, edges.len() == before + 1);
        prop_assert_eq!(
            edges.last().filter(|_| more).map(|e| e.0),
            single.next_period()
        );
        if !more {
            break;
        }
        // Exact after every step, stops included.
        let want = positions(from, deltas, &m.masks[..edges.len()]);
        prop_assert_eq!(
            &axes.position()[..],
            &want[..],
            "after edge {}",
            edges.len()
        );
        prop_assert!(edges.len() <= m.masks.len());
    }
    let got: Vec<u16> = edges.iter().map(|e| e.0).collect();
    prop_assert_eq!(&got, &periods, "the lead plays what a single player plays");
    let masks: Vec<u32> = edges.iter().map(|e| e.1).collect();
    prop_assert_eq!(
        &masks[..],
        &m.masks[..masks.len()],
        "every step where the rule puts it"
    );
    prop_assert!(axes.is_done());
    prop_assert_eq!(axes.next_step(), None);
    if events.is_empty() {
        prop_assert_eq!(masks.len(), m.masks.len());
        prop_assert_eq!(&axes.position()[..], &target[..]);
    }
    // At rest: the next move starts where this one ended; a move of no
    // steps keeps the directions.
    let here = axes.position();
    let directions = axes.directions();
    prop_assert_eq!(axes.move_by([0; N]), directions);
    prop_assert!(axes.is_done());
    prop_assert_eq!(axes.position(), here);
    Ok(())
}

/// The timer of `tests/buffered.rs`: a counter and a reload register
/// loaded at each wrap, when the interrupt runs. Returns each step the
/// pins take, `(time, mask)`, the first at the start.
fn buffered<const N: usize>(
    stepper: &mut Buffered<Axes<'_, u16, N>>,
    begin: AxesStart<u16, N>,
    events: &[(usize, Event)],
    mut at_step: impl FnMut(&Buffered<Axes<'_, u16, N>>, usize),
) -> Vec<(u64, u32)> {
    let Some(first) = begin.first else {
        assert_eq!(begin.mask, 0);
        return Vec::new();
    };
    let mut reload = begin.next.unwrap_or(first);
    let mut handed = 1 + usize::from(begin.next.is_some());
    let (mut now, mut counting) = (0u64, first);
    let mut steps = vec![(0, begin.mask)];
    at_step(stepper, 1);
    loop {
        now += u64::from(counting);
        counting = reload;
        apply(events, handed, |e| match e {
            Event::Stop => stepper.stop(),
            Event::Cruise(pos) => stepper.set_cruise(pos),
        });
        handed += 1;
        let mask = stepper.step(|p| reload = p);
        if mask == 0 {
            return steps;
        }
        steps.push((now, mask));
        at_step(stepper, steps.len());
        assert!(steps.len() < 100_000, "a move without end");
    }
}

/// `Buffered<Axes>`: each step the pins take at the sum of the periods
/// before it, on the axes the model names, the positions at the pins
/// exact after each.
fn play_buffered<const N: usize>(
    accel: &[u16],
    from: &[i64],
    deltas: &[i64],
    events: &[(usize, Event)],
) -> Result<(), TestCaseError> {
    // Events where the interrupt hands out periods: from the third on.
    let events: Vec<(usize, Event)> = events.iter().map(|&(at, e)| (at + 2, e)).collect();
    let events = &events[..];
    let m = model(deltas);
    let periods = plain(accel, m.len, events);
    let axes = Axes::new(Player::new(Ramp::steps(accel)), array::<N>(from));
    let mut stepper = Buffered::new(axes);
    let begin = stepper.move_by(array::<N>(deltas));
    prop_assert_eq!(begin.first, periods.first().copied());
    prop_assert_eq!(begin.next, periods.get(1).copied());
    let mut wrong = None;
    let steps = buffered(&mut stepper, begin, events, |s, taken| {
        let want = positions(from, deltas, &m.masks[..taken]);
        if s.position()[..] != want[..] && wrong.is_none() {
            wrong = Some((taken, s.position().to_vec(), want));
        }
    });
    prop_assert_eq!(wrong, None);
    let mut t = 0u64;
    let want: Vec<(u64, u32)> = periods
        .iter()
        .zip(&m.masks)
        .map(|(&p, &mask)| {
            let at = t;
            t += u64::from(p);
            (at, mask)
        })
        .collect();
    prop_assert_eq!(steps, want);
    prop_assert!(stepper.is_done());
    Ok(())
}

/// `f::<N>(args)` for the `N` of `deltas.len()`.
macro_rules! by_len {
    ($f:ident, $len:expr, $($arg:expr),*) => {
        match $len {
            1 => $f::<1>($($arg),*),
            2 => $f::<2>($($arg),*),
            3 => $f::<3>($($arg),*),
            _ => $f::<4>($($arg),*),
        }
    };
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Whole moves: every axis's steps where the rule puts them, its
    /// count and its final position; the lead's periods a single player's.
    #[test]
    fn every_axis_steps_where_the_rule_says(
        accel in falling(1usize..80, 600, 2),
        from in proptest::collection::vec(-1000i64..1000, 4),
        deltas in deltas(),
    ) {
        let n = deltas.len();
        by_len!(play, n, &accel, &from[..n], &deltas, &[])?;
    }

    /// Stops and cruise changes mid-move: the lead plays what a single
    /// player plays, the followers step where the rule says and no more,
    /// the positions exact after every step.
    #[test]
    fn stops_and_cruise_changes_keep_the_positions_exact(
        accel in falling(1usize..80, 600, 2),
        from in proptest::collection::vec(-1000i64..1000, 4),
        deltas in deltas(),
        events in events(0usize..400),
    ) {
        let n = deltas.len();
        by_len!(play, n, &accel, &from[..n], &deltas, &events)?;
    }

    /// Through `Buffered`: the mask of the edge now starting with the
    /// period after it, each step at its time.
    #[test]
    fn buffered_axes_step_on_their_edges(
        accel in falling(1usize..80, 600, 2),
        from in proptest::collection::vec(-1000i64..1000, 4),
        deltas in deltas(),
        events in events(0usize..400),
    ) {
        let n = deltas.len();
        by_len!(play_buffered, n, &accel, &from[..n], &deltas, &events)?;
    }

    /// The player of compressed tables leads the same edges.
    #[test]
    fn a_compressed_lead_gives_the_same_edges(
        accel in falling(1usize..80, 600, 2),
        deltas in proptest::collection::vec(-300i64..300, 3),
    ) {
        let runs: Vec<[u16; 5]> = accel.iter().map(|&p| [1, p, 0, 0, 0]).collect();
        let m = model(&deltas);
        let mut axes = Axes::new(Player::<u16, _>::new(&runs[..]), [0; 3]);
        axes.move_by(array::<3>(&deltas));
        let mut edges = Vec::new();
        while let Some(e) = axes.next_step() {
            edges.push(e);
        }
        let want: Vec<(u16, u32)> = plain(&accel, m.len, &[]).into_iter().zip(m.masks).collect();
        prop_assert_eq!(edges, want);
        prop_assert_eq!(axes.position(), array::<3>(&deltas));
        let _: &Player<'_, u16, Compressed> = axes.player();
    }
}

/// The rule on moves small enough to read: 3 of 10 steps land nearest
/// 3.33, 6.67 and 10; 2 of 4 on the ties 2 and 4 (later of equals: none
/// here); 1 of 2 on the tie 1 or 2: the later, 2.
#[test]
fn the_rule_by_hand() {
    static RAMP: [u16; 3] = [3000, 2000, 1500];
    let masks = |deltas: [i64; 2]| {
        let mut axes = Axes::new(Player::new(Ramp::steps(&RAMP)), [0; 2]);
        axes.move_by(deltas);
        std::iter::from_fn(|| axes.next_step().map(|e| e.1)).collect::<Vec<_>>()
    };
    assert_eq!(masks([10, 3]), [1, 1, 3, 1, 1, 1, 3, 1, 1, 3]);
    assert_eq!(masks([4, -2]), [1, 3, 1, 3]);
    assert_eq!(masks([2, 1]), [1, 3]);
    // The lead need not be axis 0; equal axes step together.
    assert_eq!(masks([-1, 2]), [2, 3]);
    assert_eq!(masks([5, 5]), [3; 5]);
    // A move where no axis moves has no steps.
    assert_eq!(masks([0, 0]), [0u32; 0]);
}

/// On an empty ramp a move has no steps, and no axis moves.
#[test]
fn an_empty_ramp_moves_nothing() {
    let mut axes = Axes::new(Player::new(Ramp::steps(&[] as &[u16])), [1, 2]);
    axes.move_by([5, -3]);
    assert!(axes.is_done());
    assert_eq!(axes.next_step(), None);
    assert_eq!(axes.position(), [1, 2]);
}

/// A new target while a move plays: a stop, then the way to it from rest,
/// the directions changing at its first edge; the positions can be set
/// only at rest.
#[test]
fn a_new_target_stops_and_goes_on_from_rest() {
    static RAMP: [u16; 3] = [3000, 2000, 1500];
    let mut axes = Axes::new(Player::new(Ramp::steps(&RAMP)), [5, 6, 7]);
    axes.move_by([30, 0, -10]);
    for _ in 0..4 {
        assert!(axes.next_step().is_some());
    }
    assert_eq!(axes.position(), [9, 6, 6]);
    // From 1500 ticks a stop takes 3 steps: the lead ends at 12.
    assert_eq!(
        axes.move_to([0, 6, 7]),
        [Direction::Forward, Direction::Forward, Direction::Backward]
    );
    assert!(axes.set_position([0; 3]).is_err());
    let mut edges = vec![];
    while let Some((period, mask)) = axes.next_step() {
        edges.push((period, mask, axes.directions()[0], axes.position()));
    }
    let (f, b) = (Direction::Forward, Direction::Backward);
    // The stop: 1500, 2000, 3000 on the lead (axis 0), the third axis on
    // the rule's steps; then the way back from (12, 6, 6) to (0, 6, 7).
    assert_eq!(
        edges[..3],
        [
            (1500, 0b001, f, [10, 6, 6]),
            (2000, 0b101, f, [11, 6, 5]),
            (3000, 0b001, f, [12, 6, 5]),
        ]
    );
    assert_eq!(edges[3], (3000, 0b001, b, [11, 6, 5]));
    assert_eq!(edges.len(), 3 + 12);
    assert_eq!(axes.position(), [0, 6, 7]);
    assert!(axes.set_position([1, 2, 3]).is_ok());
    assert_eq!(axes.position(), [1, 2, 3]);
}

/// New targets at pseudo-random edges, reversing some axes through rest:
/// the directions `next_directions` gives before each edge are those the
/// axes that step on it take.
#[test]
fn the_next_directions_are_the_next_edges() {
    static ACCEL: [u16; 12] = [900, 700, 560, 460, 390, 340, 300, 270, 250, 235, 225, 220];
    let mut next = common::xorshift(0x2545_f491_4f6c_dd1du64);
    let mut reversals = 0;
    for _ in 0..200 {
        let mut axes = Axes::new(Player::new(Ramp::steps(&ACCEL)), [0i64; 3]);
        let target = |next: &mut dyn FnMut(u64) -> u64| [0, 1, 2].map(|_| next(401) as i64 - 200);
        axes.move_to(target(&mut next));
        let (mut edges, mut last) = (0, [None; 3]);
        let retarget_at = next(150) as usize;
        loop {
            if edges == retarget_at {
                axes.move_to(target(&mut next));
            }
            let pins = axes.next_directions();
            let mut mask = 0;
            if !axes.step(|_, m| mask = m) {
                break;
            }
            edges += 1;
            let now = axes.directions();
            for i in 0..3 {
                if mask >> i & 1 == 1 {
                    assert_eq!(now[i], pins[i], "axis {i} at edge {edges}");
                    if last[i].is_some_and(|d| d != now[i]) {
                        reversals += 1;
                    }
                    last[i] = Some(now[i]);
                }
            }
        }
    }
    // The new targets reverse axes: the asserts hold at those steps.
    assert!(reversals > 100, "{reversals} reversals");
}
