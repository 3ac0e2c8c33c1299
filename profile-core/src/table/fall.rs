//! How far ahead of one ramp another is faster at every step, kept for
//! each sixteenth of the first ([`Fall`]): what planning asks before it
//! searches a walk down for a crossing. An index computes its own at
//! compile time ([`RunIndex`](super::runs::RunIndex)); a player computes
//! it for other ramps when it is made.

/// Parts of the first ramp [`Fall`] keeps a figure for.
pub(crate) const FALL_PARTS: usize = 16;

/// How far ahead of a first ramp (a player's acceleration ramp) a second
/// (its deceleration ramp) is read where it is faster at every step, for
/// each sixteenth of the first: at a step `y` of the first in part `i`,
/// and any step `z >= y + ahead[i]` of the second, the second's period
/// is shorter. A part's figure is kept where the ramp falls steeply as
/// where it is nearly flat, so that a walk in the steep parts is not held
/// to the flat ones' figure.
///
/// A plan that walks the acceleration side down while the deceleration
/// ramp, read at the steps that remain, stands at least that far ahead
/// has no crossing in the walk, however long: a comparison a part
/// instead of a search ([`Fall::clears`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Fall {
    /// Steps a part spans: `1 << shift`.
    shift: u8,
    /// Each part's figure; `u16::MAX` when not known to be less.
    ahead: [u16; FALL_PARTS],
    /// The largest figure: ahead that far, every part is cleared at once.
    most: u16,
}

impl Fall {
    /// No figure: held and segment tables, whose planning reads entries,
    /// not steps.
    pub(crate) const UNKNOWN: Fall = Fall {
        shift: 31,
        ahead: [u16::MAX; FALL_PARTS],
        most: u16::MAX,
    };

    /// No figure yet, for a first ramp of `steps` steps: parts of the
    /// fewest steps, a power of two, that [`FALL_PARTS`] of cover it.
    pub(crate) const fn empty(steps: u32) -> Self {
        let mut shift = 0u8;
        while shift < 31 && steps >> shift > FALL_PARTS as u32 {
            shift += 1;
        }
        Fall {
            shift,
            ahead: [0; FALL_PARTS],
            most: 0,
        }
    }

    /// Takes in the first ramp's step `y`: the second is faster than it
    /// from `ahead` steps ahead on.
    #[inline(always)]
    pub(crate) const fn take(&mut self, y: u32, ahead: u32) {
        let ahead = if ahead > u16::MAX as u32 {
            u16::MAX
        } else {
            ahead as u16
        };
        let part = (y >> self.shift) as usize;
        if part < FALL_PARTS && self.ahead[part] < ahead {
            self.ahead[part] = ahead;
        }
        if self.most < ahead {
            self.most = ahead;
        }
    }

    /// [`Fall`] of two ramps' periods, `steps` the first's,
    /// `decel_slack` the second's (the most a step's period exceeds the
    /// shortest before it): each part's largest `t(y) - y` (0 at least),
    /// where `t(y)` is the first step of the second more than its slack
    /// faster than the fastest of the first's steps up to `y` (one past
    /// its last when none is). From `t(y)` on, the second is no slower
    /// than at `t(y)` but for its slack, so faster than every one of those
    /// steps, `y`'s among them. The fastest step so far only gets faster
    /// as `y` grows, so `t(y)` only moves on: one pass over each ramp.
    pub(crate) fn of(
        accel: impl Iterator<Item = u32>,
        mut decel: impl Iterator<Item = u32>,
        steps: u32,
        decel_slack: u32,
    ) -> Self {
        let mut fall = Fall::empty(steps);
        let mut fastest = u32::MAX;
        let (mut t, mut at_t) = (0u32, decel.next());
        for (y, period) in (0u32..).zip(accel) {
            fastest = fastest.min(period);
            while at_t.is_some_and(|d| d.saturating_add(decel_slack) >= fastest) {
                (t, at_t) = (t + 1, decel.next());
            }
            fall.take(y, t.saturating_sub(y));
        }
        fall
    }

    /// `true` when the deceleration ramp, read `ahead` steps ahead of the
    /// acceleration ramp, is faster than it at each of the latter's steps
    /// `from..=to`: at least each of their parts' figures ahead.
    #[inline]
    pub(crate) fn clears(&self, from: u32, to: u32, ahead: u32) -> bool {
        // `u16::MAX` is never cleared.
        let ahead = ahead.min(u32::from(u16::MAX) - 1) as u16;
        if ahead >= self.most {
            return true;
        }
        // From the top down: a ramp is flattest near its top.
        let part = |y: u32| (y >> self.shift) as usize;
        self.ahead
            .get(part(from)..=part(to))
            .is_some_and(|parts| parts.iter().rev().all(|&f| ahead >= f))
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec;

    /// [`Fall::of`] two ramps' periods, parts as for a first ramp of
    /// `steps` steps.
    fn fall_on(accel: &[u32], decel: &[u32], decel_slack: u32, steps: u32) -> Fall {
        Fall::of(
            accel.iter().copied(),
            decel.iter().copied(),
            steps,
            decel_slack,
        )
    }

    /// The slack of periods, by its definition: the most a period exceeds
    /// the shortest before it.
    fn rise_of(periods: &[u32]) -> u32 {
        (0..periods.len())
            .map(|i| {
                let before = periods[..i].iter().min().copied().unwrap_or(u32::MAX);
                periods[i].saturating_sub(before)
            })
            .max()
            .unwrap_or(0)
    }

    /// Read as far ahead as [`Fall::clears`] takes, or farther, the
    /// second ramp is faster than the first at every pair of steps
    /// (checked pair by pair): on every ramp of up to 6 steps of periods
    /// 1 to 4, one ramp both ways or two, parts of 1, 2 and 4 steps, any
    /// steps of the first and any distance; on ramps ordered strictly,
    /// a step ahead clears them all.
    #[test]
    fn the_deceleration_read_far_enough_ahead_is_faster() {
        let ramps: Vec<Vec<u32>> = (0..7u32)
            .flat_map(|len| (0..4u32.pow(len)).map(move |n| (len, n)))
            .map(|(len, n)| (0..len).map(|i| n / 4u32.pow(i) % 4 + 1).collect())
            .collect();
        let (mut checked, mut cleared) = (0u32, 0u32);
        for (i, a) in ramps.iter().enumerate() {
            let n = a.len() as u32;
            // One ramp both ways, and a few others.
            for d in [a]
                .into_iter()
                .chain(ramps.iter().skip(i % 97).step_by(301))
            {
                // Parts of 1, 2 and 4 steps.
                for steps in [16, 32, 64] {
                    let fall = fall_on(a, d, rise_of(d), steps);
                    for (from, to) in (0..n).flat_map(|f| (f..n).map(move |t| (f, t))) {
                        for ahead in 0..=d.len() as u32 {
                            if !fall.clears(from, to, ahead) {
                                continue;
                            }
                            cleared += 1;
                            for y in from..=to {
                                for z in (y + ahead) as usize..d.len() {
                                    assert!(
                                        d[z] < a[y as usize],
                                        "{a:?} {d:?} {fall:?}: {from}..={to} {ahead} ahead, {y} -> {z}"
                                    );
                                    checked += 1;
                                }
                            }
                        }
                    }
                    let strict = d.windows(2).all(|w| w[1] < w[0]);
                    if core::ptr::eq(a, d) && strict && n > 0 {
                        assert!(fall.clears(0, n - 1, 1), "{a:?}: {fall:?}");
                    }
                }
            }
        }
        assert!(
            checked > 100_000 && cleared > 100_000,
            "{checked} {cleared}"
        );
        // Flat for three steps from step 2: read three ahead there, and
        // a step ahead elsewhere.
        let f = [9, 8, 5, 5, 5, 4, 2];
        let fall = fall_on(&f, &f, 0, 7);
        assert!(fall.clears(0, 1, 1) && fall.clears(4, 6, 1) && fall.clears(2, 2, 3));
        assert!(!fall.clears(2, 2, 2) && !fall.clears(0, 6, 2) && fall.clears(0, 6, 3));
    }
}
