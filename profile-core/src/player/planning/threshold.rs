//! The last step of a compressed run whose period is at least a given one,
//! in closed form: no step read one by one.
//!
//! A run's step `k` plays `(frac_k + I_k) >> 16` ticks, its interval
//! `I_k = I_0 + k·add` (16 fractional bits) and `frac_k` the remainder the
//! steps before it left. Against `H` ticks the steps fall in three kinds,
//! told by the interval alone:
//!
//! - `I_k ≥ H·2^16`: the period is `H` or more;
//! - `I_k < (H - 1)·2^16`: the period is below `H`;
//! - in between, the period is `H - 1`, or `H` where the remainder wraps
//!   (`frac_k + I_k` carries past the tick).
//!
//! The intervals are monotonic along a run, so each kind is one stretch of
//! steps, found by a division. Within the middle stretch, going back from a
//! step `k`, the remainder falls by `g_j = I_j - (H - 1)·2^16` a step as
//! long as no step wraps: the last `n` steps hold a wrap exactly when
//! `g`'s sum over them exceeds the remainder after step `k`. That sum is
//! quadratic in `n` and grows with it, so the last wrap is found by
//! bisection.

use crate::base::timer::TableWord;
use crate::player::ramps::ramp::{Cursor, Ramp};
use crate::player::ramps::runs::run_at;
use crate::table::runs::{FRACTION_MASK, RUN_FRACTION_BITS, ahead, behind, triangle};

/// The intervals a run may reach for the closed form to hold: from 0 up
/// to a tick short of the word, so that no period's sum wraps.
const INTERVAL_END: i64 = (1 << 32) - (1 << RUN_FRACTION_BITS);

/// The last of steps `0..=top` of a run (remainder `frac` and interval
/// `interval` at its step 0, `add` added to the interval a step) whose
/// period is at least `ticks`: `Some(Some(k))`, or `Some(None)` when no
/// step is. `None` when the closed form does not hold (the run's
/// intervals leave `0..2^32 - 2^16` over those steps): the caller reads
/// them.
pub(crate) fn last_at_least(
    frac: u32,
    interval: u32,
    add: u32,
    top: u32,
    ticks: u32,
) -> Option<Option<u32>> {
    let slope = i64::from(add as i32);
    let last = i64::from(interval) + slope * i64::from(top);
    if !(0..INTERVAL_END).contains(&last) || i64::from(interval) >= INTERVAL_END {
        return None;
    }
    // Every interval of steps `0..=top` in range: the sums below are
    // exact in 32 bits.
    let at = |k: u32| interval.wrapping_add(k.wrapping_mul(add));
    let Some(low) = ticks.checked_sub(1) else {
        return Some(Some(top));
    };
    if low > FRACTION_MASK {
        // No period of an interval in range reaches a word.
        return Some(None);
    }
    // The middle kind's intervals: `low_edge..low_edge + 2^16`.
    let low_edge = low << RUN_FRACTION_BITS;
    let above = |i: u32| (i - low_edge) >> RUN_FRACTION_BITS != 0;
    let falling = slope < 0;
    let step = slope.unsigned_abs() as u32;
    let mut k = top;
    if at(k) < low_edge {
        // Below `H` here; going back the intervals fall too, or rise to
        // the last step of the middle kind.
        if !falling || interval < low_edge {
            return Some(None);
        }
        k = (interval - low_edge) / step;
    }
    if above(at(k)) {
        return Some(Some(k));
    }
    // The middle kind's first step: where the intervals rise to it going
    // back when they grow along the run, else the step after the last of
    // the first kind.
    let first = if !falling {
        match low_edge.checked_sub(interval) {
            Some(short) if short > 0 => short.div_ceil(step),
            _ => 0,
        }
    } else if above(interval) {
        (interval - low_edge - (1 << RUN_FRACTION_BITS)) / step + 1
    } else {
        0
    };
    // The remainder after step `k`, and `g` at it.
    let (after, _) = ahead(frac, interval, add, k + 1);
    let g = at(k) - low_edge;
    // `g`'s sum over the last `n` steps up to `k`: step `k - m` has
    // `g - m·add`.
    let sum = |n: u32| {
        n.wrapping_mul(g)
            .wrapping_sub(triangle(n).wrapping_mul(add))
    };
    let span = k - first + 1;
    if sum(span) <= after {
        // No wrap in the middle kind: the step before it, of the first
        // kind, if the run has one.
        return Some(if falling { first.checked_sub(1) } else { None });
    }
    // The fewest steps back that hold a wrap: the wrap is the last of them.
    let (mut lo, mut hi) = (1u32, span);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if sum(mid) > after {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    Some(Some(k + 1 - lo))
}

/// The last position up to `at`'s whose period is at least `ticks`,
/// `None` when none is, walking down from `at`: on plain runs each run in
/// closed form ([`last_at_least`]), a step at a time where it does not
/// hold, and on held and segment tables an entry at a time.
pub(crate) fn last_at_least_from<W: TableWord>(
    mut at: Cursor,
    ramp: &Ramp<'_, W>,
    ticks: u32,
) -> Option<u32> {
    loop {
        if let Ramp::Runs(runs) = *ramp {
            let run = run_at(runs, at.entry);
            let add = run.map_or(0, |r| r.add as u32);
            let (frac, interval) = behind(at.frac, at.interval, add, at.within);
            if let Some(found) = last_at_least(frac, interval, add, at.within, ticks) {
                let first = at.pos - at.within;
                if let Some(k) = found {
                    return Some(first + k);
                }
                // None in this run: on from the last step of the one
                // before.
                (at.pos, at.within, at.frac, at.interval) = (first, 0, frac, interval);
                if !at.backward(ramp) {
                    return None;
                }
                continue;
            }
        }
        if at.period(ramp).into_ticks() >= ticks {
            return Some(at.pos);
        }
        // A held or segment table: the entry's steps before are as short.
        at.skip_in_entry(-1, at.room_in_entry(ramp, -1));
        if !at.backward(ramp) {
            return None;
        }
    }
}

/// The last position up to `last` of `ramp` (not a per-step table) whose
/// period is at least `ticks`, `slack` the ramp's; `None` when none is.
/// Probes near each other: one cursor, from `top` (the ramp's top), moves
/// between the probes of the search past the steps the slack rules out
/// ([`search::short_above`](crate::player::planning::search::short_above)), and walks down
/// from the last ([`last_at_least_from`]: plain runs in closed form, held
/// and segment tables an entry at a time).
pub(crate) fn last_at_least_on<W: TableWord>(
    ramp: &Ramp<'_, W>,
    top: Option<Cursor>,
    last: u32,
    slack: u32,
    ticks: u32,
) -> Option<u32> {
    let mut at = top;
    let mut read = |pos| {
        at = Cursor::near(at, ramp, pos);
        at.map(|c| c.period(ramp).into_ticks())
    };
    let k = crate::player::planning::search::short_above(&mut read, last, slack, ticks);
    let c = Cursor::near(at, ramp, last.saturating_sub(k))?;
    last_at_least_from(c, ramp, ticks)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use proptest::prelude::*;

    /// The periods of steps `0..n` of a run, each from the running sum of
    /// the intervals in 64 bits: the tick count the edges reach, step by
    /// step, less the one before.
    fn periods(frac: u32, interval: u32, add: u32, n: u32) -> std::vec::Vec<u32> {
        let (interval, add) = (i64::from(interval), i64::from(add as i32));
        let mut total = i64::from(frac);
        (0..i64::from(n))
            .map(|k| {
                let before = total >> 16;
                total += interval + add * k;
                ((total >> 16) - before) as u32
            })
            .collect()
    }

    proptest! {
        // The cases that tell a step off by one are a few in a thousand.
        #![proptest_config(ProptestConfig::with_cases(8192))]

        /// On runs of either slope, the step found is the last up to the
        /// top whose period, from the intervals' running sum, is at least
        /// the one asked; none when no step is.
        #[test]
        fn the_last_step_at_least_a_period_is_the_walks(
            // No remainder before the run: going back to its first step
            // without a wrap leaves exactly none.
            frac in prop_oneof![Just(0u32), 0u32..65_536],
            ticks in 1u32..3000,
            // Intervals just above a tick and slopes of a few 1/65 536
            // ticks too: many steps in a row that do not wrap; and half
            // and quarter ticks, whose remainders come back to none.
            sub in prop_oneof![0u32..64, Just(1 << 15), Just(3 << 14), 0u32..65_536],
            add in prop_oneof![Just(0), -64i32..64, -300_000i32..300_000],
            count in 1u32..400,
            top in any::<prop::sample::Index>(),
            offset in -3i64..=3,
            from_step in any::<prop::sample::Index>(),
        ) {
            let interval = (ticks << 16) | sub;
            let end = i64::from(interval) + i64::from(add) * i64::from(count - 1);
            // The last step a tick at least.
            let add = if end >= 1 << 16 { add as u32 } else { 0 };
            let steps = periods(frac, interval, add, count);
            let top = top.index(count as usize) as u32;
            // Near a period the run plays, or any.
            let asked = (i64::from(steps[from_step.index(count as usize)]) + offset).max(0) as u32;
            let walk = (0..=top).rev().find(|&k| steps[k as usize] >= asked);
            prop_assert_eq!(last_at_least(frac, interval, add, top, asked), Some(walk));
        }
    }
}
