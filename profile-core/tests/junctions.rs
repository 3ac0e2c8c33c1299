//! Polylines queued on axes ([`Axes::queue`]) over random tables, random
//! lines and random junction deviations, checked step by step against
//! rules computed here from the table and the lines alone:
//!
//! - every line is straight: after the lead's `s`-th step of a line, an
//!   axis of `d` of its `L` steps has taken the steps `k` whose
//!   `floor((2kL + d) / 2d)` is at most `s`, so every vertex is passed
//!   exactly, and the axes end at the last target;
//! - within a line the lead's period moves by at most one table entry a
//!   step, a move from rest (the first line, a line after a reversal)
//!   starts at the slowest entry and the polyline ends there;
//! - where an axis reverses, the lead's periods on both sides are the
//!   slowest entry: a reversal passes through rest;
//! - the path speed at a vertex (the lead's rate over its line's
//!   `L / |d|`) is at most the junction's, grbl's `sqrt(a·δ·s / (1 − s))`
//!   (`s` the sine of half the angle between the line before reversed and
//!   the line after, `a` the table's mean acceleration), and it does not
//!   rise across the vertex (but to the slowest entry, a start from rest).
//!
//! `PROPTEST_CASES` sets the number of cases (default 256).

use core_test_support as common;

use common::watch::neighbours;
use common::{cases, falling};
use profile_core::player::{Axes, Player, QUEUE, Ramp};
use proptest::prelude::*;

/// The steps an axis of `d` has taken after the lead's `s`-th of `l`,
/// counted from the rule's definition.
fn taken(d: u64, l: u64, s: u64) -> u64 {
    (1..=d).filter(|&k| (2 * k * l + d) / (2 * d) <= s).count() as u64
}

/// The junction's path speed from the line `a` into the line `b`, in
/// steps a tick, for a deviation `delta` and a mean acceleration `accel`.
fn junction(a: [i64; 2], b: [i64; 2], delta: f64, accel: f64) -> f64 {
    if a.iter().zip(&b).any(|(x, y)| x * y < 0) {
        return 0.0;
    }
    let norm = |v: [i64; 2]| ((v[0] * v[0] + v[1] * v[1]) as f64).sqrt();
    let cos = (a[0] * b[0] + a[1] * b[1]) as f64 / (norm(a) * norm(b));
    // Half the angle between -a and b.
    let half = (-cos).clamp(-1.0, 1.0).acos() / 2.0;
    let s = half.sin();
    if s >= 1.0 - 1e-6 {
        return f64::INFINITY;
    }
    (accel * delta * s / (1.0 - s)).sqrt()
}

/// Lead steps over the line's length.
fn rho(d: [i64; 2]) -> f64 {
    let lead = d[0].abs().max(d[1].abs()) as f64;
    lead / ((d[0] * d[0] + d[1] * d[1]) as f64).sqrt()
}

fn check(table: &[u16], vertices: &[[i64; 2]], delta: f32) -> Result<(), String> {
    let mut axes =
        Axes::new(Player::new(Ramp::steps(table)), [0, 0]).with_junction_deviation(delta);
    let mut targets: Vec<[i64; 2]> = vec![];
    for &v in vertices {
        // The line playing and QUEUE after it.
        let full = targets.len() > QUEUE;
        match axes.queue(v) {
            Ok(_) if targets.last().copied().unwrap_or([0, 0]) == v => {}
            Ok(_) if !full => targets.push(v),
            Err(refused) if full && refused.target == v => {}
            other => return Err(format!("queue({v:?}) after {targets:?}: {other:?}")),
        }
    }
    // The lines: consecutive distinct targets.
    let mut lines: Vec<([i64; 2], [i64; 2])> = vec![];
    let mut from = [0, 0];
    for &t in &targets {
        if t != from {
            lines.push((from, t));
            from = t;
        }
    }
    let (slowest, top) = (f64::from(table[0]), f64::from(table[table.len() - 1]));
    let accel = if table.len() > 1 {
        (1.0 / (top * top) - 1.0 / (slowest * slowest)) / (2.0 * (table.len() - 1) as f64)
    } else {
        0.0
    };
    let mut last: Option<u16> = None;
    for (k, &(a, b)) in lines.iter().enumerate() {
        let d = [b[0] - a[0], b[1] - a[1]];
        let l = d[0].unsigned_abs().max(d[1].unsigned_abs());
        let mut first = None;
        for s in 1..=l {
            let Some((period, _mask)) = axes.next_step() else {
                return Err(format!("line {k} ended after {} of {l} steps", s - 1));
            };
            let want =
                [0, 1].map(|i| a[i] + d[i].signum() * taken(d[i].unsigned_abs(), l, s) as i64);
            if axes.position() != want {
                return Err(format!(
                    "line {k} step {s}: at {:?}, not {want:?}",
                    axes.position()
                ));
            }
            match (last, s) {
                (None, _) if period != table[0] => {
                    return Err(format!("line {k}: from rest at {period}"));
                }
                (Some(p), 2..) if !neighbours(table, p, period) => {
                    return Err(format!("line {k} step {s}: a jump from {p} to {period}"));
                }
                _ => {}
            }
            first.get_or_insert(period);
            last = Some(period);
        }
        // The vertex after the line: its speed, and the next line's start.
        let Some(&(_, c)) = lines.get(k + 1) else {
            break;
        };
        let next = [c[0] - b[0], c[1] - b[1]];
        let end = last.unwrap();
        let speed = 1.0 / (f64::from(end) * rho(d));
        let allowed = junction(d, next, f64::from(delta), accel);
        let reverses = d.iter().zip(&next).any(|(x, y)| x * y < 0);
        if reverses && end != table[0] {
            return Err(format!(
                "vertex {k}: an axis reverses at {end}, not at rest"
            ));
        }
        if speed > allowed * 1.001 + 1e-12 && end != table[0] {
            return Err(format!(
                "vertex {k}: {speed} steps a tick, the junction allows {allowed}"
            ));
        }
        // The next line's first step: no faster along the path.
        let Some((after, _)) = axes.clone().next_step() else {
            return Err(format!("nothing after vertex {k}"));
        };
        let speed_after = 1.0 / (f64::from(after) * rho(next));
        // (The slowest entry is a start from rest, always allowed.)
        if after != table[0] && speed_after > speed * 1.000_001 {
            return Err(format!(
                "vertex {k}: faster after ({speed_after} > {speed})"
            ));
        }
        // At rest there (a reversal, or a start from the slowest entry):
        // the next line starts as a move from rest does.
        if end == table[0] && (reverses || after == table[0]) {
            last = None;
        }
    }
    if axes.next_step().is_some() {
        return Err("steps past the last line".into());
    }
    if let Some(p) = last {
        if p != table[0] {
            return Err(format!("ended at {p}, not at rest"));
        }
    }
    let end = lines.last().map_or([0, 0], |l| l.1);
    if axes.position() != end || !axes.is_done() {
        return Err(format!("at {:?}, not done at {end:?}", axes.position()));
    }
    Ok(())
}

fn vertices() -> impl Strategy<Value = Vec<[i64; 2]>> {
    proptest::collection::vec((-120i64..120, -120i64..120), 1..12).prop_map(|v| {
        // Mostly onward, now and then back: a polyline wandering.
        let mut at = [0i64, 0];
        v.into_iter()
            .map(|(x, y)| {
                at = [at[0] + x, at[1] + y / 3];
                at
            })
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn queued_lines_are_straight_exact_and_join_within_the_junction(
        table in falling(1usize..40, 400, 1),
        vertices in vertices(),
        delta in prop_oneof![Just(0.0f32), 0.0f32..30.0],
    ) {
        check(&table, &vertices, delta).map_err(TestCaseError::fail)?;
    }
}

/// The lead's period at a right-angle corner (its last step on the first
/// line), for a junction deviation of `delta` steps.
fn corner_period(table: &[u16], delta: f32) -> u16 {
    let mut axes =
        Axes::new(Player::new(Ramp::steps(table)), [0, 0]).with_junction_deviation(delta);
    axes.queue([300, 0]).unwrap();
    axes.queue([300, 300]).unwrap();
    let periods: Vec<u16> = core::iter::from_fn(|| axes.next_step().map(|s| s.0)).collect();
    assert_eq!((periods.len(), axes.position()), (600, [300, 300]));
    periods[299]
}

/// A corner joins faster the larger the deviation: at rest without one,
/// up to the top of the ramp.
#[test]
fn a_corner_joins_faster_the_larger_the_deviation() {
    // 2000 ticks a step down to 100, at a constant acceleration.
    let table: Vec<u16> = (0..200)
        .map(|i| (2000.0 / (1.0 + f64::from(i) * 2.0).sqrt()).max(100.0) as u16)
        .collect();
    let periods: Vec<u16> = [0.0, 2.0, 20.0, 80.0, 5000.0]
        .iter()
        .map(|&d| corner_period(&table, d))
        .collect();
    assert_eq!(periods[0], table[0]);
    assert!(periods.windows(2).all(|w| w[0] > w[1]), "{periods:?}");
    assert_eq!(periods[4], 100);
}

/// Lines that go on straight join at the top whatever the deviation.
#[test]
fn a_straight_line_cut_in_pieces_plays_as_one_move() {
    static RAMP: [u16; 5] = [5000, 3000, 2300, 1900, 1700];
    let mut pieces = Axes::new(Player::new(&RAMP), [0, 0, 0]);
    let mut whole = Axes::new(Player::new(&RAMP), [0, 0, 0]);
    for k in 1..=4 {
        pieces.queue([30 * k, -20 * k, 10 * k]).unwrap();
    }
    whole.move_to([120, -80, 40]);
    let played = |axes: &mut Axes<'_, u16, 3>| -> Vec<(u16, u32)> {
        core::iter::from_fn(|| axes.next_step()).collect()
    };
    assert_eq!(played(&mut pieces), played(&mut whole));
}

/// Through a buffered register, queued lines hand out the edges the axes
/// hand out, lines queued while they play included, and the pins end at
/// the last vertex.
#[test]
fn buffered_queued_lines_hand_out_the_same_edges() {
    use profile_core::player::Buffered;
    static RAMP: [u16; 6] = [4000, 3000, 2400, 2000, 1700, 1500];
    let vertices = [[100, 10], [200, 30], [300, 35], [400, 60]];
    let make = || Axes::new(Player::new(&RAMP), [0, 0]).with_junction_deviation(3.0);
    let mut axes = make();
    for v in vertices {
        axes.queue(v).unwrap();
    }
    let want: Vec<(u16, u32)> = core::iter::from_fn(|| axes.next_step()).collect();
    let mut buffered = Buffered::new(make());
    let start = buffered.queue(vertices[0]).unwrap();
    let mut got = vec![(start.first.unwrap(), start.mask)];
    let mut pending = start.next.unwrap();
    // The rest queued while the first line plays.
    for v in &vertices[1..] {
        buffered.queue(*v).unwrap();
    }
    loop {
        let mut next = None;
        let mask = buffered.step(|p| next = Some(p));
        if mask == 0 {
            break;
        }
        got.push((pending, mask));
        if let Some(p) = next {
            pending = p;
        }
    }
    assert_eq!(got, want);
    assert_eq!(buffered.position(), [400, 60]);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Queued lines on compressed runs, plain and indexed, hand out the
    /// edges the same lines hand out on the runs' expansion, lines queued
    /// while others play included: a line cut to end at speed, and the
    /// next begun at it, alike on every layout.
    #[test]
    fn queued_lines_on_runs_play_as_on_their_expansion(
        runs in common::falling_runs(3 << 16),
        vertices in vertices(),
        delta in 0.0f32..30.0,
        at in 0usize..300,
    ) {
        use profile_core::runs::{Expand, RunIndex};
        let steps: Vec<u16> = Expand::new(&runs).map(|p| p as u16).collect();
        let all = common::padded::<40>(&runs);
        let index = RunIndex::new(&all);
        let mut expanded = Axes::new(Player::new(Ramp::steps(&steps)), [0, 0]).with_junction_deviation(delta);
        let mut plain = Axes::new(Player::<u16, _>::new(&runs[..]), [0, 0]).with_junction_deviation(delta);
        let mut indexed = Axes::new(Player::<u16, _>::new(&index), [0, 0]).with_junction_deviation(delta);
        let mut k = 0;
        // Two lines, some steps, then the rest queued while they play.
        for (i, v) in vertices.iter().take(QUEUE + 1).enumerate() {
            if i == 2 {
                for _ in 0..at {
                    let want = expanded.next_step();
                    prop_assert_eq!(plain.next_step(), want, "edge {}", k);
                    prop_assert_eq!(indexed.next_step(), want, "edge {}", k);
                    k += 1;
                }
            }
            let want = expanded.queue(*v).is_ok();
            prop_assert_eq!(plain.queue(*v).is_ok(), want);
            prop_assert_eq!(indexed.queue(*v).is_ok(), want);
        }
        while let Some(want) = expanded.next_step() {
            prop_assert_eq!(plain.next_step(), Some(want), "edge {}", k);
            prop_assert_eq!(indexed.next_step(), Some(want), "edge {}", k);
            k += 1;
        }
        prop_assert_eq!(plain.next_step(), None);
        prop_assert_eq!(indexed.next_step(), None);
        prop_assert_eq!(plain.position(), expanded.position());
    }
}
