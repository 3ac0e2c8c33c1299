//! Property tests of the ramp player over random tables and moves.
//!
//! `PROPTEST_CASES` sets the number of cases (default 256 per property here).

use profile_core::player::{Compressed, Player, Ramp};
use profile_core::runs::{Expand, RunIndex};
use proptest::prelude::*;

/// A non-increasing table (slow to fast), as generated tables are.
fn table() -> impl Strategy<Value = Vec<u16>> {
    (1usize..120, 100u16..=u16::MAX).prop_flat_map(|(len, start)| {
        proptest::collection::vec(0u16..400, len).prop_map(move |drops| {
            let mut p = start as u32;
            drops
                .iter()
                .map(|d| {
                    let v = p as u16;
                    p = p.saturating_sub(*d as u32).max(1);
                    v
                })
                .collect()
        })
    })
}

/// Largest difference between consecutive entries.
fn max_step(t: &[u16]) -> u32 {
    t.windows(2)
        .map(|w| (w[0] as i32 - w[1] as i32).unsigned_abs())
        .max()
        .unwrap_or(0)
}

/// Plays a move, calling `at(step, player)` before each step; `None` when
/// the player yields more than `limit` periods.
fn play(
    player: &mut Player<'_, u16>,
    limit: usize,
    mut at: impl FnMut(usize, &mut Player<'_, u16>),
) -> Option<Vec<u32>> {
    let mut out = Vec::new();
    loop {
        at(out.len(), player);
        match player.next_period() {
            Some(p) => out.push(p as u32),
            None => return Some(out),
        }
        if out.len() > limit {
            return None;
        }
    }
}

fn expand(t: &[u16], hold: u32) -> Vec<u32> {
    t.iter()
        .flat_map(|&p| std::iter::repeat_n(p as u32, hold.max(1) as usize))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Exactly S steps, never faster than the fastest entry, jumps no larger
    /// than the tables', ending at the deceleration table's slowest entry.
    #[test]
    fn moves_have_exactly_s_steps(
        accel in table(), decel in table(), symmetric in any::<bool>(),
        hold in 1u32..4, steps in 0u32..1500,
    ) {
        let decel = if symmetric { accel.clone() } else { decel };
        let mut player = Player::new(Ramp::held(&accel, hold)).with_decel(Ramp::held(&decel, hold));
        player.start(steps);
        let periods = play(&mut player, steps as usize, |_, _| {}).expect("move does not end");
        prop_assert_eq!(periods.len(), steps as usize);
        let fastest = accel.iter().chain(&decel).copied().min().unwrap() as u32;
        prop_assert!(periods.iter().all(|&p| p >= fastest));
        let bound = max_step(&accel).max(max_step(&decel));
        for w in periods.windows(2) {
            prop_assert!((w[0] as i64 - w[1] as i64).unsigned_abs() <= bound as u64, "{:?}", w);
        }
        // Ends at rest: no faster than the deceleration table's slowest entry.
        if let Some(&last) = periods.last() {
            prop_assert!(last >= decel[0] as u32);
        }
        // A move long enough plays both halves whole: the acceleration table
        // forwards, then the deceleration table backwards, each limited by the
        // other's top speed (the cruise speed is the slower of the two tops).
        let (a, d) = (expand(&accel, hold), expand(&decel, hold));
        if steps as usize >= a.len() + d.len() {
            let a_top = *a.last().unwrap();
            let d_top = *d.iter().min().unwrap();
            let head: Vec<u32> = a.iter().map(|&v| v.max(d_top)).collect();
            prop_assert_eq!(&periods[..a.len()], &head[..]);
            let tail: Vec<u32> = d.iter().rev().map(|&v| v.max(a_top)).collect();
            prop_assert_eq!(&periods[periods.len() - d.len()..], &tail[..]);
            prop_assert_eq!(*periods.last().unwrap(), (decel[0] as u32).max(a_top));
        }
    }

    /// A stop at any step ends at rest, with no jump larger than the tables'
    /// and no more steps than the move had.
    #[test]
    fn stop_ends_at_rest(
        accel in table(), decel in table(), hold in 1u32..3,
        steps in 1u32..1500, stop_at in 0usize..1500,
    ) {
        let mut player = Player::new(Ramp::held(&accel, hold)).with_decel(Ramp::held(&decel, hold));
        player.start(steps);
        let periods = play(&mut player, steps as usize, |i, p| if i == stop_at { p.stop() })
            .expect("move does not end");
        prop_assert!(periods.len() <= steps as usize);
        let bound = max_step(&accel).max(max_step(&decel));
        for w in periods.windows(2) {
            prop_assert!((w[0] as i64 - w[1] as i64).unsigned_abs() <= bound as u64, "{:?}", w);
        }
        // At rest: the deceleration table's slowest entry, or slower still
        // when the move never got that fast.
        if let Some(&last) = periods.last() {
            prop_assert!(last >= decel[0] as u32);
            prop_assert!(last == decel[0] as u32 || accel.contains(&(last as u16)));
        }
    }

    /// A new cruise speed mid-move walks the table to it.
    #[test]
    fn cruise_changes_walk_the_table(
        accel in table(), steps in 1u32..1500, at in 0usize..1500, cruise in 0u32..200,
    ) {
        let mut player = Player::new(Ramp::steps(&accel));
        player.start(steps);
        let periods = play(&mut player, steps as usize, |i, p| if i == at { p.set_cruise(cruise) })
            .expect("move does not end");
        prop_assert_eq!(periods.len(), steps as usize);
        let bound = max_step(&accel);
        for w in periods.windows(2) {
            prop_assert!((w[0] as i64 - w[1] as i64).unsigned_abs() <= bound as u64);
        }
        // Set before the first step: never faster than the cruise entry.
        let target = accel[(cruise as usize).min(accel.len() - 1)] as u32;
        if at == 0 {
            prop_assert!(periods.iter().all(|&p| p >= target));
        }
    }

    /// Segment tables play exactly as the per-step tables they stand for.
    #[test]
    fn segments_play_like_their_expansion(
        periods in table(), counts in proptest::collection::vec(0u16..5, 120),
        steps in 0u32..700, stop_at in 0usize..700,
    ) {
        let pairs: Vec<(u16, u16)> = periods.iter().zip(&counts).map(|(&p, &c)| (p, c)).collect();
        let expanded: Vec<u16> = pairs
            .iter()
            .flat_map(|&(p, c)| std::iter::repeat_n(p, c as usize))
            .collect();
        let mut seg = Player::new(Ramp::segments(&pairs));
        let mut flat = Player::new(Ramp::steps(&expanded));
        seg.start(steps);
        flat.start(steps);
        let a = play(&mut seg, steps as usize, |i, p| if i == stop_at { p.stop() });
        let b = play(&mut flat, steps as usize, |i, p| if i == stop_at { p.stop() });
        prop_assert_eq!(a, b);
    }
}

#[test]
fn empty_tables_play_nothing() {
    let empty: [u16; 0] = [];
    let mut player = Player::new(Ramp::steps(&empty));
    player.start(10);
    assert_eq!(player.next_period(), None);
    let none: [(u16, u16); 2] = [(100, 0), (50, 0)];
    let mut player = Player::new(Ramp::segments(&none));
    player.start(10);
    assert_eq!(player.next_period(), None);
}

#[test]
fn short_symmetric_move_is_a_triangle() {
    let table = [1000u16, 800, 600, 500, 400];
    let mut player = Player::new(Ramp::steps(&table));
    player.start(5);
    let periods: Vec<u16> = std::iter::from_fn(|| player.next_period()).collect();
    assert_eq!(periods, [1000, 800, 600, 800, 1000]);
}

#[test]
fn divider_holds_each_entry() {
    let table = [1000u16, 500];
    let mut player = Player::new(Ramp::held(&table, 3));
    player.start(14);
    let periods: Vec<u16> = std::iter::from_fn(|| player.next_period()).collect();
    assert_eq!(
        periods,
        [
            1000, 1000, 1000, 500, 500, 500, 500, 500, 500, 500, 500, 1000, 1000, 1000
        ]
    );
}

#[test]
fn stop_enters_the_deceleration_table_at_the_current_speed() {
    let accel = [1000u16, 800, 600, 500, 400];
    let decel = [2000u16, 1500, 1000, 700, 450, 300];
    let mut player = Player::new(Ramp::steps(&accel)).with_decel(Ramp::steps(&decel));
    player.start(100);
    let mut periods = Vec::new();
    for _ in 0..4 {
        periods.push(player.next_period().unwrap());
    }
    // Now at 500 ticks: the slowest decel entry not faster than 500 is 700.
    player.stop();
    periods.extend(std::iter::from_fn(|| player.next_period()));
    assert_eq!(periods, [1000, 800, 600, 500, 700, 1000, 1500, 2000]);
}

/// On a table that is not ordered slow to fast, a stop enters at the last
/// entry not shorter than the current period (a walk down from the top
/// finds it), not at the first boundary a bisection meets.
#[test]
fn stop_enters_at_the_last_entry_not_shorter() {
    let table = [900u16, 800, 700, 800, 800, 600];
    let mut player = Player::new(Ramp::steps(&table));
    player.start(20);
    let mut periods = vec![player.next_period().unwrap(), player.next_period().unwrap()];
    player.stop();
    periods.extend(std::iter::from_fn(|| player.next_period()));
    assert_eq!(periods, [900, 800, 800, 800, 700, 800, 900]);
}

/// Tables rounded by diffusion tie by a tick near the top (`..., 156, 157,
/// 156`): a long move must still play them exactly as written, up and down,
/// so their pulse edges keep their half-tick accuracy.
#[test]
fn diffused_tables_play_exactly() {
    use profile_core::{Curve, Sigmoid, Spec, Timer};
    let spec = Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        }),
        Timer::new(10_000_000),
    );
    let mut table = [0u16; 1000];
    let figures = spec.generate(&mut table).unwrap();
    assert!(
        table.windows(2).any(|w| w[1] > w[0]),
        "the table should have diffusion ties for this test to mean something"
    );
    let cruise = 500;
    let mut player = Player::new(Ramp::steps(&table));
    player.start(2000 + cruise);
    let played: Vec<u16> = std::iter::from_fn(|| player.next_period()).collect();
    assert_eq!(&played[..1000], &table[..]);
    let down: Vec<u16> = table.iter().rev().copied().collect();
    assert_eq!(&played[1000 + cruise as usize..], &down[..]);
    assert!(
        played[1000..1000 + cruise as usize]
            .iter()
            .all(|&p| p == table[999])
    );
    let total: u64 = played.iter().map(|&p| p as u64).sum();
    assert_eq!(
        total,
        2 * figures.total_ticks + cruise as u64 * table[999] as u64
    );
}

use core_test_support as common;

use common::reference::Reference;
use common::{Shape, any_runs, cases, padded, shape};
use profile_core::TableWord;

/// What a random operation sequence does to a player.
#[derive(Clone, Debug)]
enum Op {
    Start(u32),
    Play(u32),
    Stop,
    Cruise(u32),
}

fn ops() -> impl Strategy<Value = Vec<Op>> {
    let op = prop_oneof![
        3 => prop_oneof![8 => 0u32..400, 1 => Just(0u32), 1 => Just(u32::MAX)].prop_map(Op::Start),
        6 => (0u32..200).prop_map(Op::Play),
        2 => Just(Op::Stop),
        2 => (0u32..120).prop_map(Op::Cruise),
    ];
    proptest::collection::vec(op, 1..12)
}

/// Plays `ops` on the planned player and on the reference model with the
/// same ramps, `W` wide; the periods played and the steps remaining must be
/// the same after every operation. Returns the steps compared.
fn compare<W: TableWord + core::fmt::Debug + PartialEq>(
    accel: &Shape,
    decel: &Shape,
    ops: &[Op],
) -> Result<u64, TestCaseError> {
    let words = |t: &[u32]| -> Vec<W> { t.iter().map(|&p| W::from_ticks(p)).collect() };
    let pairs = |t: &[(u32, u32)]| -> Vec<(W, W)> {
        t.iter()
            .map(|&(p, c)| (W::from_ticks(p), W::from_ticks(c)))
            .collect()
    };
    // The model plays a compressed ramp as its expansion: the player must
    // play the runs bit for bit as `runs::Expand` expands them.
    let steps_of = |shape: &Shape| -> Vec<W> {
        match shape {
            Shape::Steps(t, _) => words(t),
            Shape::Runs(r) => Expand::new(r).map(W::from_ticks).collect(),
            Shape::Segments(_) => vec![],
        }
    };
    let pairs_of = |shape: &Shape| match shape {
        Shape::Segments(t) => pairs(t),
        _ => vec![],
    };
    let (a_steps, a_pairs, d_steps, d_pairs) = (
        steps_of(accel),
        pairs_of(accel),
        steps_of(decel),
        pairs_of(decel),
    );
    fn ramp<'t, W: TableWord>(
        shape: &'t Shape,
        steps: &'t [W],
        pairs: &'t [(W, W)],
        planned: bool,
    ) -> Ramp<'t, W> {
        match shape {
            Shape::Steps(_, hold) => Ramp::held(steps, *hold),
            Shape::Segments(_) => Ramp::segments(pairs),
            Shape::Runs(r) if planned => Ramp::runs(r),
            Shape::Runs(_) => Ramp::steps(steps),
        }
    }
    // Compressed ramps indexed (padded to 12 runs with runs of no step).
    let pad = |shape: &Shape| match shape {
        Shape::Runs(r) => padded::<12>(r),
        _ => padded(&[]),
    };
    let (a_padded, d_padded) = (pad(accel), pad(decel));
    let (a_index, d_index) = (RunIndex::new(&a_padded), RunIndex::new(&d_padded));
    let mut planned = Player::new(ramp(accel, &a_steps, &a_pairs, true))
        .with_decel(ramp(decel, &d_steps, &d_pairs, true));
    // Every compressed ramp indexed, beside the other layouts.
    fn indexed<'t, W: TableWord>(
        shape: &'t Shape,
        index: &'t RunIndex<12>,
        steps: &'t [W],
        pairs: &'t [(W, W)],
    ) -> Ramp<'t, W> {
        match shape {
            Shape::Runs(_) => Ramp::indexed(index),
            _ => ramp(shape, steps, pairs, true),
        }
    }
    let mut any_indexed = Player::new(indexed(accel, &a_index, &a_steps, &a_pairs))
        .with_decel(indexed(decel, &d_index, &d_steps, &d_pairs));
    let mut model = Reference::with_decel(
        ramp(accel, &a_steps, &a_pairs, false),
        ramp(decel, &d_steps, &d_pairs, false),
    );
    let mut compressed: Vec<Player<'_, W, Compressed>> = match (accel, decel) {
        (Shape::Runs(a), Shape::Runs(d)) => vec![
            Player::new(&a[..]).with_decel(&d[..]),
            Player::new(&a_index).with_decel(&d_index),
        ],
        _ => vec![],
    };
    let mut steps = 0u64;
    for (i, op) in ops.iter().enumerate() {
        match *op {
            Op::Start(n) => {
                planned.start(n);
                any_indexed.start(n);
                model.start(n);
                compressed.iter_mut().for_each(|c| c.start(n));
            }
            Op::Stop => {
                planned.stop();
                any_indexed.stop();
                model.stop();
                compressed.iter_mut().for_each(|c| c.stop());
            }
            Op::Cruise(pos) => {
                planned.set_cruise(pos);
                any_indexed.set_cruise(pos);
                model.set_cruise(pos);
                compressed.iter_mut().for_each(|c| c.set_cruise(pos));
            }
            Op::Play(n) => {
                for k in 0..n {
                    let (got, want) = (planned.next_period(), model.next_period());
                    let got_indexed = any_indexed.next_period();
                    prop_assert_eq!(
                        got_indexed,
                        want,
                        "indexed: op {} ({:?}), step {}",
                        i,
                        op,
                        k
                    );
                    prop_assert_eq!(got, want, "op {} ({:?}), step {}", i, op, k);
                    for (which, c) in compressed.iter_mut().enumerate() {
                        let got = c.next_period();
                        prop_assert_eq!(
                            got,
                            want,
                            "compressed {}: op {} ({:?}), step {}",
                            which,
                            i,
                            op,
                            k
                        );
                    }
                    steps += 1;
                    if want.is_none() {
                        break;
                    }
                }
            }
        }
        prop_assert_eq!(
            any_indexed.remaining(),
            model.remaining(),
            "indexed: after op {}",
            i
        );
        prop_assert_eq!(
            planned.remaining(),
            model.remaining(),
            "after op {} ({:?})",
            i,
            op
        );
        for (which, c) in compressed.iter().enumerate() {
            prop_assert_eq!(
                c.remaining(),
                model.remaining(),
                "compressed {}: after op {}",
                which,
                i
            );
        }
    }
    Ok(steps)
}

/// Runs `cases` random operation sequences on the ramps `ramps` draws
/// (the deceleration ramp the acceleration ramp's when `None`), u16 and u32,
/// each through [`compare`]; prints the sequences and steps compared under
/// `what`.
fn compare_random(what: &str, cases: u32, ramps: impl Strategy<Value = (Shape, Option<Shape>)>) {
    use proptest::test_runner::{Config, TestRunner};
    let mut runner = TestRunner::new(Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    });
    let (sequences, steps) = (std::cell::Cell::new(0u64), std::cell::Cell::new(0u64));
    runner
        .run(
            &(ramps, ops(), any::<bool>()),
            |((accel, decel), ops, wide)| {
                let decel = decel.unwrap_or_else(|| accel.clone());
                let n = if wide {
                    compare::<u32>(&accel, &decel, &ops)?
                } else {
                    compare::<u16>(&accel, &decel, &ops)?
                };
                sequences.set(sequences.get() + 1);
                steps.set(steps.get() + n);
                Ok(())
            },
        )
        .unwrap_or_else(|e| panic!("{e}"));
    println!(
        "{what} == per-step model: {} random operation sequences, {} steps compared",
        sequences.get(),
        steps.get()
    );
}

/// The planned player plays every move exactly as the per-step model does:
/// random tables (falling with ties, arbitrary, one entry, held, segments
/// with empty ones, runs), u16 and u32, random operations (starts of 0 and
/// `u32::MAX` steps, stops, twice too, cruise changes mid-ramp). Prints the
/// sequences and steps compared (`-- --nocapture`); `PROPTEST_CASES` times 8
/// sequences.
#[test]
fn plays_exactly_as_the_per_step_model() {
    let decel = prop_oneof![1 => Just(None), 1 => shape(80, 6, 1).prop_map(Some)];
    compare_random("planned player", cases() * 8, (shape(80, 6, 1), decel));
}

/// The player of compressed tables (`Player::new(&RUNS)`) plays every
/// move exactly as the per-step model plays the runs' expansion (and as the
/// player of any layout does): random runs (empty ones included), one ramp
/// or two, u16 and u32, random operations. `PROPTEST_CASES` times 4
/// sequences.
#[test]
fn the_compressed_player_plays_exactly_as_the_per_step_model() {
    let runs = || any_runs().prop_map(Shape::Runs);
    let decel = prop_oneof![1 => Just(None), 1 => runs().prop_map(Some)];
    compare_random("compressed player", cases() * 4, (runs(), decel));
}

/// The two faults of the per-step player, pinned.
#[test]
fn a_slower_cruise_is_followed_while_the_deceleration_ramp_caps_the_speed() {
    static ACCEL: [u16; 4] = [4000, 3000, 2000, 1000];
    static DECEL: [u16; 2] = [4000, 2500];
    let mut player = Player::new(Ramp::steps(&ACCEL)).with_decel(Ramp::steps(&DECEL));
    player.start(40);
    let mut played = Vec::new();
    for step in 0..40 {
        if step == 10 {
            player.set_cruise(0);
        }
        played.extend(player.next_period());
    }
    // Up to the cap (2500, the deceleration ramp's fastest), then down to
    // 4000 and cruising there; the move ends on the deceleration ramp.
    assert_eq!(&played[..5], [4000, 3000, 2500, 2500, 2500]);
    assert_eq!(&played[10..13], [2500, 3000, 4000]);
    assert!(played[13..38].iter().all(|&p| p == 4000), "{played:?}");
    assert_eq!(&played[38..], [4000, 4000]);
}

/// Empty segments are passed when the move is planned and at the few
/// refills, never walked step by step: a table of 20 000 empty segments
/// between two real ones plays as its expansion.
#[test]
fn empty_segments_play_as_their_expansion() {
    let mut pairs = vec![(900u16, 3u16)];
    pairs.extend(std::iter::repeat_n((500u16, 0u16), 20_000));
    pairs.push((300, 2));
    let mut player = Player::new(Ramp::segments(&pairs));
    player.start(9);
    let played: Vec<u16> = std::iter::from_fn(|| player.next_period()).collect();
    assert_eq!(played, [900, 900, 900, 300, 300, 300, 900, 900, 900]);
}

/// Entries of any count are planned entry by entry, never step by step: a
/// player of a held table of 4 294 967 298 steps, not ordered, or of a
/// segment of `u32::MAX` steps, is made, starts, stops and changes speed at
/// once, and plays as its entries say.
#[test]
fn entries_of_any_count_are_planned_entry_by_entry() {
    static T: [u16; 3] = [3000, 1000, 2000];
    let hold = 1_431_655_766;
    let mut player = Player::new(Ramp::held(&T, hold));
    player.start(u32::MAX);
    for _ in 0..1000 {
        assert_eq!(player.next_period(), Some(3000));
    }
    assert_eq!(player.remaining(), u32::MAX - 1000);
    // The last step of at least 2500 ticks is entry 0's last: on to it.
    player.set_cruise_period(2500);
    assert_eq!(player.next_period(), Some(3000));
    // The last step of at least 3000 ticks: entry 0's last.
    player.stop();
    assert_eq!(player.remaining(), hold);

    // A segment of 2e9 steps plays as one of 100 while the move is far
    // from its end: up, a slower cruise walked down to, a stop.
    let play = |count: u32, steps: u32| {
        let pairs = [(3000u32, 2u32), (1000, count)];
        let mut player = Player::new(Ramp::segments(&pairs));
        player.start(steps);
        let up: Vec<u32> = (0..20).filter_map(|_| player.next_period()).collect();
        player.set_cruise_period(2000);
        let down: Vec<u32> = (0..20).filter_map(|_| player.next_period()).collect();
        player.stop();
        (up, down, player.remaining())
    };
    let (up, down, left) = play(2_000_000_000, u32::MAX);
    // Walked down to step 1 (3000 ticks): two steps to rest.
    assert_eq!(left, 2);
    assert_eq!(up[..3], [3000, 3000, 1000]);
    assert_eq!(down[..20 - 3], [1000; 17]);
    assert_eq!(play(100, 1000), (up, down, left));
}

/// A run on compressed runs, decelerating along a held table not ordered
/// of `u32::MAX` steps an entry, plays as on the runs' expansion into a
/// per-step table: its crossing is scanned an entry at a time once the
/// acceleration side holds (step by step, the scan took seconds).
#[test]
fn a_run_onto_a_held_table_scans_it_entry_by_entry() {
    use profile_core::runs::LinearRun;
    let runs: Vec<[u16; 5]> = [(20, 3000u32, 0), (30, 2400, -9000), (40, 1900, -2000)]
        .iter()
        .map(|&(count, ticks, add)| {
            LinearRun {
                count,
                interval: ticks << 16,
                add,
            }
            .encode()
        })
        .collect();
    let expanded: Vec<u32> = Expand::new(&runs).collect();
    // Moves whose deceleration takes over once the runs are climbed (at
    // about 1900 ticks), within the slow entries' steps, as on the
    // expansions of both ramps (read directly).
    let moves = [3000u32, 5000, 1000, 1200, 1100];
    let decel_expanded: Vec<u32> = moves.iter().flat_map(|&p| [p; 40]).collect();
    for steps in [50, 120, 150, 170, 190, 200, 230, 400] {
        let mut a = Player::new(Ramp::runs(&runs)).with_decel(Ramp::held(&moves, 40));
        let mut c = Player::new(Ramp::steps(&expanded)).with_decel(Ramp::steps(&decel_expanded));
        a.start(steps);
        c.start(steps);
        let all = |p: &mut Player<'_, u32>| -> Vec<u32> {
            core::iter::from_fn(|| p.next_period()).collect()
        };
        assert_eq!(all(&mut a), all(&mut c), "{steps}");
    }
    let decel = [1000u32, 5000, 1500, 4000, 2500];
    let mut a = Player::new(Ramp::runs(&runs)).with_decel(Ramp::held(&decel, u32::MAX));
    let mut b = Player::new(Ramp::steps(&expanded)).with_decel(Ramp::held(&decel, u32::MAX));
    for player in [&mut a, &mut b] {
        player.run();
    }
    let played = |p: &mut Player<'_, u32>| -> Vec<u32> {
        (0..300).filter_map(|_| p.next_period()).collect()
    };
    let (up, expected) = (played(&mut a), played(&mut b));
    assert_eq!(up, expected);
    assert_eq!(up[..3], expanded[..3]);
    a.stop();
    b.stop();
    assert_eq!(a.remaining(), b.remaining());
    assert_eq!(played(&mut a), played(&mut b));
}

/// A held acceleration table not ordered, its entries of any count, takes
/// a new target while decelerating, and a slower cruise, as its expansion
/// into a per-step table does (read by another path): its entry of the
/// current speed is found an entry at a time (step by step, a run taken
/// while decelerating took 24 s on entries of `u32::MAX` steps).
#[test]
fn a_held_table_retargets_as_its_expansion() {
    let held = [3000u32, 2000, 2500, 1000, 1500];
    let expanded: Vec<u32> = held.iter().flat_map(|&p| [p; 30]).collect();
    let decel: Vec<u32> = (0..60).map(|i| 3000 - 20 * i).collect();
    // The held table and its expansion, `played` steps into a move of
    // `steps`, then changed alike: the rest of each move.
    let both = |steps: u32, played: u32, change: &dyn Fn(&mut Player<'_, u32>) -> bool| {
        let mut a = Player::new(Ramp::held(&held, 30)).with_decel(Ramp::steps(&decel));
        let mut b = Player::new(Ramp::steps(&expanded)).with_decel(Ramp::steps(&decel));
        a.start(steps);
        b.start(steps);
        for _ in 0..played {
            assert_eq!(a.next_period(), b.next_period(), "{steps} {played}");
        }
        assert_eq!(change(&mut a), change(&mut b), "{steps} {played}");
        let rest = |p: &mut Player<'_, u32>| -> Vec<u32> {
            core::iter::from_fn(|| p.next_period()).collect()
        };
        assert_eq!(rest(&mut a), rest(&mut b), "{steps} {played}");
    };
    // Targets taken while decelerating: the acceleration ramp entered at
    // its first step not slower than the speed.
    for (steps, played, target) in [
        (200, 160, 300),
        (300, 280, 100),
        (120, 100, 90),
        (400, 350, 500),
        (400, 380, 200),
    ] {
        both(steps, played, &|p| p.retarget(target));
    }
    for (steps, played, cruise) in [(400, 130, 0), (400, 100, 40), (1000, 140, 70)] {
        both(steps, played, &|p| {
            p.set_cruise(cruise);
            true
        });
    }
    // Entries of `u32::MAX` steps: a run stopped, then run again while
    // decelerating.
    let mut player = Player::new(Ramp::held(&held, u32::MAX)).with_decel(Ramp::steps(&decel));
    player.run();
    assert_eq!(player.next_period(), Some(3000));
    player.stop();
    player.run();
    assert!(player.is_running());
    assert_eq!(player.next_period(), Some(3000));
}

/// A held table stops as its expansion into a per-step table (read by
/// another path), where the stop's walk down a deceleration table not
/// ordered passes an entry's steps at once.
#[test]
fn a_held_table_stops_as_its_expansion() {
    let held = [3000u16, 2000, 1000, 800];
    let expanded: Vec<u16> = held.iter().flat_map(|&p| [p; 50]).collect();
    let decel = [3000u16, 2000, 2500, 1500];
    let decel_expanded: Vec<u16> = decel.iter().flat_map(|&p| [p; 40]).collect();
    for played in [10, 70, 120, 180] {
        let mut a = Player::new(Ramp::held(&held, 50)).with_decel(Ramp::held(&decel, 40));
        let mut b = Player::new(Ramp::steps(&expanded)).with_decel(Ramp::steps(&decel_expanded));
        a.start(1000);
        b.start(1000);
        for _ in 0..played {
            assert_eq!(a.next_period(), b.next_period(), "{played}");
        }
        a.stop();
        b.stop();
        assert_eq!(a.remaining(), b.remaining(), "{played}");
        let rest: Vec<u16> = std::iter::from_fn(|| a.next_period()).collect();
        let expected: Vec<u16> = std::iter::from_fn(|| b.next_period()).collect();
        assert_eq!(rest, expected, "{played}");
    }
}

/// The axis: positions after random moves, stops and cruise changes are the
/// sum of the steps played, signed by the direction each move reported.
#[test]
fn the_axis_knows_where_the_motor_is() {
    use profile_core::player::{Axis, Direction};
    use proptest::test_runner::{Config, TestRunner};
    let mut runner = TestRunner::new(Config {
        cases: cases(),
        failure_persistence: None,
        ..Config::default()
    });
    let moves = proptest::collection::vec((-500i64..500, 0u32..600, any::<bool>()), 1..8);
    runner
        .run(&(table(), moves), |(table, moves)| {
            let mut axis = Axis::new(Player::new(Ramp::steps(&table)), 7);
            let mut position = 7i64;
            for (delta, stop_at, stop) in moves {
                let before = axis.direction();
                let direction = axis.move_by(delta);
                // A move of no steps keeps the direction.
                match delta {
                    0 => prop_assert_eq!(direction, before),
                    _ => prop_assert_eq!(direction == Direction::Backward, delta < 0),
                }
                // The position cannot be set while a move plays.
                if axis.remaining() > 0 {
                    prop_assert!(axis.set_position(0).is_err());
                }
                let mut k = 0;
                while axis.step(|_| {}) {
                    position += direction.sign();
                    k += 1;
                    prop_assert_eq!(axis.position(), position);
                    if stop && k == stop_at {
                        axis.stop();
                    }
                }
                prop_assert_eq!(axis.position(), position);
            }
            axis.move_to(-3);
            while axis.step(|_| {}) {}
            prop_assert_eq!(axis.position(), -3);
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
}
