//! The followers' accumulators of [`Axes`](crate::player::Axes): which
//! axes step on each of the lead's steps, by Bresenham's rule, an addition
//! and a branch per follower.

use core::sync::atomic::{Ordering, compiler_fence};

/// Built for Armv6-M (the build script's cfg, on `thumbv6m` targets): eight
/// low registers and no `ldrd`/`strd`. There each follower's accumulator
/// is stored as soon as it is moved on, and a carry reads `L` and the bit
/// through one register, so that the step keeps every value in a register
/// and pushes an even number of them (no stack slot, no padding);
/// elsewhere a pair of accumulators is stored with one `strd`.
pub(crate) const LOW_REGISTERS: bool = cfg!(thumb_low_registers);

/// The followers' accumulators, laid out for the step path: the mask of an
/// edge where no follower's count changes first, then the followers
/// (`1..N`, in the order of their axes) in pairs, each follower's increment
/// beside its accumulator and the pair's two accumulators adjacent (one
/// load of a follower's two words, one store of a pair's accumulators),
/// then what a follower reads only on the edges where its count changes.
///
/// A follower of `d` steps of the lead's `L` has taken `n(s) = floor((d·s +
/// h) / L)` steps after the lead's `s`-th, with `h = floor((d - 1) / 2)`:
/// exactly `#{k : s_k <= s}` for the rule's `s_k = floor((2kL + d) / 2d)`.
/// With `a = (d·s + h) mod L`, it steps on the lead's next step exactly
/// when `a + d >= L`. A follower of at most `L / 2` steps keeps `a - L`
/// (modulo 2^32) and adds `d`: the addition carries out of 32 bits exactly
/// when it steps, and then `L` comes off. One of more steps keeps `L - 1 -
/// a`, less `L`, and adds `L - d`, its steps left out: the addition
/// carries exactly when it does not step (`L - 1 - a` grows by `L - d`
/// and reaches `L` exactly when `a + d < L`), and its bit is in the mask
/// unless it carries. Either way the edges where the accumulator carries
/// are at most half the lead's, and each of those flips the follower's
/// bit of the mask.
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub(crate) struct Edges<const N: usize> {
    /// The mask of an edge where no follower's accumulator carries: the
    /// lead's bit and the bits of the followers of more than `L / 2` steps.
    pub(crate) base: u32,
    /// `slot[j - 1]`: follower `j`'s increment and accumulator, in that order
    /// for an odd `j` and the other way round for an even one, so that
    /// the accumulators of followers `j` and `j + 1` (`j` odd) are
    /// adjacent (`slot[N - 1]` unused).
    pub(crate) slot: [[u32; 2]; N],
    /// `steps[j - 1]`: the lead's steps (`L`) and follower `j`'s bit of
    /// the mask, read on the edges where its accumulator carries.
    pub(crate) steps: [[u32; 2]; N],
}

impl<const N: usize> Edges<N> {
    pub(crate) const REST: Self = Edges {
        base: 0,
        slot: [[0; 2]; N],
        steps: [[0; 2]; N],
    };

    /// Where follower `j`'s accumulator is in its slot.
    const fn acc_at(j: usize) -> usize {
        j % 2
    }

    /// Follower `j`'s `(d·s + h) mod L` ([`Edges`]), the lead's steps
    /// being `l` and the follower's `d`.
    #[cfg(test)]
    pub(crate) fn held(&self, j: usize, d: u32, l: u32) -> u32 {
        let acc = self.slot[j - 1][Self::acc_at(j)];
        if Self::dense(d, l) {
            !acc
        } else {
            acc.wrapping_add(l)
        }
    }

    /// A follower of `d` steps of the lead's `l` counts the steps it leaves
    /// out.
    const fn dense(d: u32, l: u32) -> bool {
        d > l / 2
    }

    /// Sets follower `j` (`1..N`) of `d` steps, the lead's being `l`, to
    /// `held = (d·s + h) mod L` after the lead's `s`-th step, its bit of
    /// the mask `bit`.
    pub(crate) fn set(&mut self, j: usize, d: u32, held: u32, bit: u32, l: u32) {
        // `L - 1 - a`, less `L`, is `!a`.
        let (inc, acc) = if Self::dense(d, l) {
            self.base |= bit;
            (l - d, !held)
        } else {
            self.base &= !bit;
            (d, held.wrapping_sub(l))
        };
        self.slot[j - 1][Self::acc_at(j)] = acc;
        self.slot[j - 1][1 - Self::acc_at(j)] = inc;
        self.steps[j - 1] = [l, bit];
    }

    /// The mask of the axes that step on the lead's next step, the
    /// followers' accumulators moved on by it. Written out pair of
    /// followers by pair (the followers past `N` vanish): a loop costs more
    /// than its body.
    #[inline(always)]
    pub(crate) fn next(&mut self) -> u32 {
        self.next_ordered::<LOW_REGISTERS>()
    }

    /// [`Edges::next`], each accumulator stored as soon as it has moved on
    /// if `EACH` ([`LOW_REGISTERS`]), else in pairs.
    #[inline(always)]
    pub(crate) fn next_ordered<const EACH: bool>(&mut self) -> u32 {
        let mut mask = self.base;
        // Follower `j`'s accumulator moved on, its bit of the mask flipped
        // when it carries: an addition and a branch, and where it carries
        // a load of its bit and `L`, an exclusive or and a subtraction. The
        // fence, which emits no instruction, keeps the branch: without it
        // the follower becomes a conditional block of at least 4
        // instructions on every step.
        let mut follow = |acc: u32, inc: u32, j: usize| {
            let (sum, carry) = acc.overflowing_add(inc);
            if carry {
                compiler_fence(Ordering::SeqCst);
                let steps = |j: usize| self.steps.get(j - 1).copied().unwrap_or([0; 2]);
                if EACH {
                    // `L` and the bit through one register, one after
                    // the other.
                    let sum = sum.wrapping_sub(steps(j)[0]);
                    compiler_fence(Ordering::SeqCst);
                    mask ^= steps(j)[1];
                    return sum;
                }
                let [lead_steps, bit] = steps(j);
                mask ^= bit;
                return sum.wrapping_sub(lead_steps);
            }
            sum
        };
        macro_rules! pair {
            ($($j:literal)*) => {$(
                if let (true, Some(&[inc, acc])) = ($j < N, self.slot.get($j - 1)) {
                    let first = follow(acc, inc, $j);
                    let store_first = |slot: &mut [[u32; 2]; N]| {
                        if let Some(slot) = slot.get_mut($j - 1) {
                            slot[1] = first;
                        }
                    };
                    // At once on eight low registers; else beside the
                    // second's, one `strd`.
                    if EACH {
                        store_first(&mut self.slot);
                    }
                    let second = match self.slot.get($j) {
                        Some(&[acc, inc]) if $j + 1 < N => Some(follow(acc, inc, $j + 1)),
                        _ => None,
                    };
                    if !EACH {
                        store_first(&mut self.slot);
                    }
                    if let (Some(slot), Some(acc)) = (self.slot.get_mut($j), second) {
                        slot[0] = acc;
                    }
                }
            )*};
        }
        pair!(1 3 5 7 9 11 13 15 17 19 21 23 25 27 29 31);
        mask
    }
}

/// Steps a follower of `d` steps has taken after the lead's `s`-th of `l`:
/// `floor((d·s + floor((d - 1) / 2)) / l)` (the lead's own: `s`).
pub(crate) fn follower_steps(d: u32, s: u32, l: u32) -> u32 {
    if d == 0 || l == 0 {
        return 0;
    }
    let n = (u64::from(d) * u64::from(s) + u64::from((d - 1) / 2)) / u64::from(l);
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// Axis `i`'s bit of the mask (`i` below 32).
pub(crate) fn bit(i: usize) -> u32 {
    1u32.wrapping_shl(i as u32)
}

#[cfg(test)]
mod tests {
    //! Tests of the followers' accumulators ([`Edges`]).

    use super::*;
    use crate::player::{Axes, Player, Ramp};

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
}
