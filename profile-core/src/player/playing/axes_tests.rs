//! Tests of the followers' accumulators ([`Edges`]).

use super::*;
use crate::player::Ramp;

/// The follower steps `k` whose lead step `floor((2kL + d) / 2d)` is at
/// most `s`: the largest such `k`, found by bisection in 128 bits.
fn taken(d: u64, l: u64, s: u64) -> u64 {
    let at = |k: u64| (2 * u128::from(k) * u128::from(l) + u128::from(d)) / (2 * u128::from(d));
    let (mut lo, mut hi) = (0u64, d);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if at(mid) <= u128::from(s) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    lo
}

/// The followers' accumulators moved on in both orders of their stores
/// ([`LOW_REGISTERS`]) for the first `n` lead steps of a move by
/// `delta`: the same masks and accumulators on every step.
fn both_orders<const N: usize>(delta: [i64; N], n: u32) {
    static RAMP: [u16; 2] = [3000, 2000];
    let mut axes = Axes::new(Player::new(Ramp::steps(&RAMP)), [0; N]);
    axes.move_by(delta);
    let (mut each, mut pairs) = (axes.edges, axes.edges);
    for s in 0..n {
        let masks = (each.next_ordered::<true>(), pairs.next_ordered::<false>());
        assert_eq!(masks.0, masks.1, "{delta:?} at {s}");
        assert_eq!(each.slot, pairs.slot, "{delta:?} at {s}");
    }
}

/// An odd number of followers leaves the last pair's second out, an
/// even number fills it: both orders agree on each.
#[test]
fn both_orders_of_the_stores_step_alike() {
    both_orders([7, 5], 7);
    both_orders([1000, -999, 501, -3], 1000);
    both_orders([-300, 299, 150, 149, 1], 300);
    both_orders([17, 2, 100, 99, 50, 33, 0], 100);
}

/// Moves of up to `u32::MAX` steps, too long to play here: the
/// accumulators as `move_by` sets them, and `next` from any lead step,
/// step where the rule says.
#[test]
fn the_longest_moves_follow_the_rule() {
    static RAMP: [u16; 2] = [3000, 2000];
    let max = u32::MAX;
    let moves: [[u32; 3]; 5] = [
        [max, max - 1, 1],
        // Either side of half the lead's steps.
        [1001, 500, 501],
        [max, 2, max / 2 + 1],
        [3_000_000_001, 1_999_999_999, 7],
        [max - 4, max - 4, 123_456_789],
    ];
    for steps in moves {
        let l = u64::from(steps[0]);
        let mut axes = Axes::new(Player::new(Ramp::steps(&RAMP)), [0; 3]);
        axes.move_by(steps.map(i64::from));
        for j in 1..3 {
            let d = u64::from(steps[j]);
            // What the accumulator stands for after `s` lead steps.
            let held = |s: u64| ((d * s + (d - 1) / 2) % l) as u32;
            assert_eq!(axes.edges.held(j, steps[j], steps[0]), held(0), "{steps:?}");
            let probes = [0, 1, 2, l / 3, l / 2, l - 2, l - 1];
            for s in probes
                .into_iter()
                .chain((0..200).map(|i| i * (l / 200) + i))
            {
                let s = s.min(l - 1);
                let mut edges = axes.edges;
                edges.set(j, steps[j], held(s), 1 << j, steps[0]);
                // The stores in the other order (the other targets'),
                // to the same mask and accumulators.
                let mut other = edges;
                let other_mask = other.next_ordered::<{ !LOW_REGISTERS }>();
                let mask = edges.next();
                assert_eq!((mask, edges.slot), (other_mask, other.slot));
                let steps_now = taken(d, l, s + 1) - taken(d, l, s);
                assert_eq!(u64::from(mask >> j & 1), steps_now, "{steps:?} at {s}");
                let after = edges.held(j, steps[j], steps[0]);
                assert_eq!(after, held(s + 1), "{steps:?} at {s}");
                assert_eq!(
                    u64::from(follower_steps(steps[j], s as u32, steps[0])),
                    taken(d, l, s)
                );
            }
        }
    }
}
