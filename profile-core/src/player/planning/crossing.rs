//! Where a plan's deceleration takes over ([`Sides::crossing`]): the
//! steps searched where the ramps' order allows, or passed a block at a
//! time where it does not, then read one by one, on cursors, on ramps
//! read by position, or on two indexed ramps each walked a step at a
//! time.

use crate::base::timer::TableWord;
use crate::player::planning::plan::Sides;
use crate::player::planning::reader::{Reader, RunRead, RunWalk};
use crate::player::planning::search;
use crate::player::planning::threshold;
use crate::player::ramps::ramp::{Cursor, Ramp};
use crate::table::runs::IndexedRuns;

impl<W: TableWord> Sides<'_, '_, W> {
    /// The first of the last `r` steps at which the deceleration ramp, read
    /// at the steps that remain, is not faster than the acceleration side
    /// (walking from `p` towards the cruise position); `r` if none is.
    ///
    /// Once the acceleration side walks up or holds, the deceleration ramp
    /// read at the steps that remain only gets slower and the acceleration
    /// side only faster, but for the ramps' slack: the step is searched
    /// ([`search`]). Walking down, both get slower: those steps are passed
    /// a block at a time where the two ramps' bounds show no crossing in
    /// it, and read one by one in the blocks they do not clear
    /// ([`Sides::crossing_down`]).
    pub(crate) fn crossing(&self, p: u32, r: u32) -> u32 {
        if let (Some(a), Some(d)) = (self.accel.per_step(), self.decel.per_step()) {
            return self.crossing_direct(a, d, p, r);
        }
        // Walking down, a block at a time; then the search.
        let (walked_down, slack) = match self.toward(p).1 {
            -1 => ((p - self.cruise).min(r), self.slack),
            1 => (0, self.slack),
            // Held: only the deceleration ramp's order counts.
            _ => (0, self.decel_slack),
        };
        if walked_down > 0 && !self.falls_ahead(p, r, walked_down) {
            if let Some(j) = self.crossing_down(p, r, walked_down) {
                return j;
            }
        }
        // Often the first: a long move's deceleration ramp joins at its
        // top. (Elsewhere the search below finds that step as well.)
        if walked_down < r && r - 1 - walked_down == self.decel_last {
            if let Some(j) = self.scan(p, r, walked_down, 1) {
                return j;
            }
        }
        // A step more than `slack` ticks short of not faster has every
        // step before it faster: the last of those is searched, and the
        // steps from there read one by one.
        let dir = self.toward(p).1;
        if dir <= 0 {
            // Held from `walked_down` on: one period to compare with.
            let q = self.walked_by(p, dir, walked_down);
            let held = self.a(q);
            if let Ramp::Indexed(index) = self.decel {
                // The last step of the ramp at least that long, in closed
                // form; the crossing's cursor where it stands. On one ramp
                // both ways, no step after the held one's run is searched
                // for before it: the held step itself is that long; and
                // none at all when no later step is known to be as long as
                // the cruise position's, which is then the entry.
                let (runs, top) = (index.runs(), (r - 1).checked_sub(walked_down));
                let from = match (self.accel, self.read_at(q), top) {
                    (Ramp::Indexed(a), Some(c), Some(top))
                        if core::ptr::eq(a.runs(), runs) && q <= top =>
                    {
                        if self.cruise_last && q == self.cruise {
                            self.crossed.set(Some(c));
                            return r - 1 - q;
                        }
                        c.entry + 1
                    }
                    _ => 0,
                };
                let mut read = RunRead::new(index);
                let found =
                    top.and_then(|top| read.last_at_least(top, held, self.decel_slack, from));
                let Some(pos) = found else {
                    return r;
                };
                self.crossed.set(read.cursor(pos));
                return r - 1 - pos;
            }
            let from = self
                .reader(true)
                .past_shorter(r, walked_down, r, slack, held);
            if let (Ramp::Runs(_), Some(top)) = (self.decel, (r - 1).checked_sub(from)) {
                // Plain runs: down from there each run in closed form.
                let Some(c) = self.cursor(true, top) else {
                    return r;
                };
                return match threshold::last_at_least_from(c, &self.decel, held) {
                    Some(pos) => r - 1 - pos,
                    None => r,
                };
            }
            return self.scan(p, r, from, r - from).unwrap_or(r);
        }
        let (mut a, mut d) = (self.reader(false), self.reader(true));
        let from = search::past(walked_down, r, &mut |j| match (
            d.ticks(r - 1 - j),
            a.ticks(self.walked_by(p, dir, j)),
        ) {
            (Some(dp), Some(ap)) => search::faster_by(dp, slack, ap),
            _ => false,
        });
        self.scan(p, r, from, r - from).unwrap_or(r)
    }

    /// [`Sides::crossing`] over the first `walked_down` of the last `r`
    /// steps, the acceleration side walking down from `p`: the step found,
    /// `Some(r)` when a ramp ends, `None` when none of them is.
    #[inline(never)]
    fn crossing_down(&self, p: u32, r: u32, walked_down: u32) -> Option<u32> {
        // Walking down, the acceleration side is never faster than at `p`
        // but for its slack: a deceleration step more than both ramps'
        // slack faster than that has every step before it faster than
        // the acceleration side. On indexed ramps the buckets tell it of
        // the last of those steps, and so of every one.
        if self.bucket_faster(r - walked_down, p) {
            return None;
        }
        // Away from an index, first past the steps where the deceleration
        // ramp is that much faster: one bisection.
        let from = match self.decel {
            Ramp::Indexed(_) => 0,
            _ => {
                let (mut d, ap) = (self.reader(true), self.a(p));
                // Often the deceleration ramp is that much faster at the
                // last of those steps, and so at every one before.
                match d.ticks(r - walked_down) {
                    Some(t) if search::faster_by(t, self.slack, ap) => walked_down,
                    _ => d.past_shorter(r, 0, walked_down, self.slack, ap),
                }
            }
        };
        self.scan_down(p, r, from, walked_down)
    }

    /// [`Sides::crossing`] over the walked-down steps `from..to` of the
    /// last `r`, the acceleration side walking down from `p`: the step
    /// found, `Some(r)` when a ramp ends, `None` when none of them is.
    ///
    /// A block at a time ([`blocks_down`], each as long as the one passed
    /// before it): the deceleration ramp at a block's last step is
    /// its slowest there but for its slack, and the acceleration side at
    /// its first step its fastest but for its slack; more than both
    /// slacks faster at the first, the deceleration ramp is faster at
    /// every step of the block, which has no crossing. The index's
    /// buckets are asked first; from [`READ_BLOCK`] steps down the two
    /// periods are read. A block they do not clear is halved, and one of
    /// [`SCAN_BLOCK`] steps or fewer is read step by step
    /// ([`Sides::scan`]).
    fn scan_down(&self, p: u32, r: u32, from: u32, to: u32) -> Option<u32> {
        let (mut d, mut a) = (self.reader(true), self.reader(false));
        let mut found = None;
        blocks_down(from, to, to - from, false, |j, end| {
            let (x, y) = (r - end, p - j);
            let clear = self.bucket_faster(x, y)
                || (end - j <= READ_BLOCK
                    && match (d.ticks(x), a.ticks(y)) {
                        (Some(dx), Some(ay)) => search::faster_by(dx, self.slack, ay),
                        _ => false,
                    });
            if clear {
                return Block::Pass;
            }
            if end - j > SCAN_BLOCK {
                return Block::Split;
            }
            found = self.scan(p, r, j, end - j);
            match found {
                Some(_) => Block::Stop,
                None => Block::Pass,
            }
        });
        found
    }

    /// On two indexed ramps, `true` when their buckets' periods show the
    /// deceleration ramp's step `x` more than both ramps' slack faster
    /// than the acceleration ramp's step `p` (as [`Sides::crossing`]'s
    /// walk down asks of the two periods), without reading either
    /// ([`buckets_faster`]).
    fn bucket_faster(&self, x: u32, p: u32) -> bool {
        let (Ramp::Indexed(a), Ramp::Indexed(d)) = (self.accel, self.decel) else {
            return false;
        };
        x <= self.decel_last && buckets_faster(a, d, x, p, self.slack, self.decel_slack)
    }

    /// The first `walked_down` of the last `r` steps walking down from
    /// `p` (both sides a step lower each step), `true` when the
    /// deceleration ramp, within its steps, stands far enough ahead of the
    /// acceleration side to be faster at each of them ([`Fall::clears`](crate::table::fall::Fall::clears)):
    /// the walk has no crossing.
    #[inline(never)]
    pub(crate) fn falls_ahead(&self, p: u32, r: u32, walked_down: u32) -> bool {
        let top = r.saturating_sub(1);
        top <= self.decel_last
            && top
                .checked_sub(p)
                .is_some_and(|ahead| self.known.fall.clears(p + 1 - walked_down, p, ahead))
    }

    /// A reader of the deceleration ramp (else the acceleration ramp),
    /// its first read sought from the cursor placed last on it; an index
    /// needs no hint, and none is copied for it.
    fn reader(&self, decel: bool) -> Reader<'_, '_, W> {
        let (ramp, side) = if decel {
            (&self.decel, 1)
        } else {
            (&self.accel, 0)
        };
        match ramp {
            Ramp::Indexed(index) => Reader::Indexed(RunRead::new(*index)),
            _ => Reader::new(ramp, self.hints()[side]),
        }
    }

    /// Where the acceleration side stands `j` steps after `p`.
    fn walked(&self, p: u32, j: u32) -> u32 {
        self.walked_by(p, self.toward(p).1, j)
    }

    /// [`Sides::walked`], the side moving `dir` (`toward(p)`'s).
    #[inline]
    pub(crate) fn walked_by(&self, p: u32, dir: i8, j: u32) -> u32 {
        match dir {
            1 => p.saturating_add(j).min(self.cruise),
            -1 => p.saturating_sub(j).max(self.cruise),
            _ => p,
        }
    }

    /// [`Sides::crossing`] read step by step over `n` of the last `r`
    /// steps from step `from`: the step found, `Some(r)` when the steps
    /// read reach the last or a ramp ends, `None` when none of those is.
    fn scan(&self, p: u32, r: u32, from: u32, n: u32) -> Option<u32> {
        if n == 0 {
            return None;
        }
        let to_end = (from + n == r).then_some(r);
        let q = self.walked(p, from);
        // One step, both ramps read at their tops (a long move's
        // deceleration joining at its top, cruising at the acceleration
        // ramp's): the tops' cursors, no search.
        if let (1, [Some(a), Some(d)]) = (n, self.known.tops) {
            if a.pos == q && d.pos == r - 1 - from {
                let joins =
                    d.period(&self.decel).into_ticks() >= a.period(&self.accel).into_ticks();
                return joins.then_some(from).or(to_end);
            }
        }
        if read_directly(&self.accel) && read_directly(&self.decel) {
            return self.scan_read(q, r, from, n).or(to_end);
        }
        // (Two per-step tables are read by `crossing_direct`.)
        let mut d = self.cursor(true, r - 1 - from).unwrap_or(Cursor::ZERO);
        let mut a = self.cursor(false, q).unwrap_or(Cursor::ZERO);
        let (mut j, to) = (from, from + n);
        // A held or segment deceleration table: the steps where neither
        // period changes at once, however many an entry holds, the
        // acceleration side in an entry of such a table or holding at
        // the cruise position (runs change every step).
        let entries = !matches!(self.decel, Ramp::Runs(_) | Ramp::Indexed(_));
        while j < to {
            if d.period(&self.decel).into_ticks() >= a.period(&self.accel).into_ticks() {
                return Some(j);
            }
            if entries {
                let same = self.skip_entries(&mut d, &mut a, to - 1 - j);
                if same > 0 {
                    j += same;
                    continue;
                }
            }
            let dir = self.toward(a.pos).1;
            d.backward(&self.decel);
            match dir {
                1 => {
                    a.forward(&self.accel, self.accel_last);
                }
                -1 => {
                    a.backward(&self.accel);
                }
                _ => {}
            }
            j += 1;
        }
        to_end
    }

    /// [`Sides::scan`]'s steps, at most `most`, where the deceleration
    /// ramp's cursor `d` walking down and the acceleration side's `a`
    /// walking towards the cruise position stay in their entries of held
    /// or segment tables, so that neither period changes: both moved past
    /// them; how many.
    #[inline(never)]
    fn skip_entries(&self, d: &mut Cursor, a: &mut Cursor, most: u32) -> u32 {
        let dir = self.toward(a.pos).1;
        let to_cruise = match dir {
            0 => u32::MAX,
            _ => a.pos.abs_diff(self.cruise),
        };
        let same = d
            .room_in_entry(&self.decel, -1)
            .min(a.room_in_entry(&self.accel, dir))
            .min(to_cruise)
            .min(most);
        d.skip_in_entry(-1, same);
        a.skip_in_entry(dir, same);
        same
    }

    /// [`Sides::scan`] on ramps read by position ([`read_directly`]), the
    /// acceleration side at `q` on step `from`: the step found, `Some(r)`
    /// when a ramp ends, `None` when none of the `n` steps is.
    fn scan_read(&self, q: u32, r: u32, from: u32, n: u32) -> Option<u32> {
        if let (Ramp::Indexed(a), Ramp::Indexed(d)) = (self.accel, self.decel) {
            return self.scan_runs(a, d, q, r, from, n);
        }
        let (mut a, mut d) = (
            Reader::new(&self.accel, None),
            Reader::new(&self.decel, None),
        );
        let mut q = q;
        for j in from..from + n {
            let (Some(x), Some(y)) = (d.ticks(r - 1 - j), a.ticks(q)) else {
                return Some(r);
            };
            if x >= y {
                return Some(j);
            }
            q = self.toward(q).0;
        }
        None
    }

    /// [`Sides::scan_read`] on two indexed ramps, each walked a step at a
    /// time: the steps within both walks' runs compared in one loop
    /// ([`RunWalk::first_not_shorter`]), a step into another run through
    /// the index.
    fn scan_runs(
        &self,
        a: IndexedRuns<'_>,
        d: IndexedRuns<'_>,
        mut q: u32,
        r: u32,
        from: u32,
        n: u32,
    ) -> Option<u32> {
        let a = match self.read_at(q) {
            Some(c) => RunWalk::from_cursor(a, c),
            None => RunWalk::at(a, q),
        };
        let (Some(mut a), Some(mut d)) = (a, RunWalk::at(d, r - 1 - from)) else {
            return Some(r);
        };
        let (to, mut j) = (from + n, from);
        loop {
            let (next, dir) = self.toward(q);
            // The steps both walks take within their runs, the acceleration
            // side's direction holding, compared in one loop.
            let to_cruise = match dir {
                1 => self.cruise - q,
                -1 => q - self.cruise,
                _ => u32::MAX,
            };
            let moves = (to - 1 - j).min(to_cruise).min(a.room(dir)).min(d.room(-1));
            if moves > 0 {
                if let Some(k) = a.first_not_shorter(dir, &mut d, moves) {
                    return Some(self.found(&d, j + k));
                }
                j += moves;
                q = self.walked_by(q, dir, moves);
                continue;
            }
            // A step into another run, or the last.
            if d.ticks() >= a.ticks() {
                return Some(self.found(&d, j));
            }
            if j + 1 == to {
                return None;
            }
            let moved = match dir {
                1 => a.forward(),
                -1 => a.backward(),
                _ => Some(()),
            };
            if moved.and(d.backward()).is_none() {
                return Some(r);
            }
            (q, j) = (next, j + 1);
        }
    }

    /// The crossing `j` found by the deceleration ramp's walk `d` standing
    /// at it: kept, for the deceleration's stretch begins there.
    fn found(&self, d: &RunWalk<'_>, j: u32) -> u32 {
        self.crossed.set(Some(d.cursor()));
        j
    }
}

/// What [`blocks_down`] does with a block of steps.
pub(crate) enum Block {
    /// Passed: on to the next block.
    Pass,
    /// Not passed: its first half next.
    Split,
    /// Done: the walk stops here.
    Stop,
}

/// Steps `from..to` of a walk down passed a block at a time, in order,
/// the first block `size` steps long: `ask(j, end)` says what to do with
/// steps `j..end` ([`Block`]), and a block of one step is never split.
/// A block passed, the next is as long, or twice as long if `grow`.
/// `true` when every step was passed, `false` when `ask` stopped the walk.
#[inline(always)]
pub(crate) fn blocks_down(
    from: u32,
    to: u32,
    size: u32,
    grow: bool,
    mut ask: impl FnMut(u32, u32) -> Block,
) -> bool {
    let (mut j, mut size) = (from, size.max(1));
    while j < to {
        let end = j.saturating_add(size).min(to);
        match ask(j, end) {
            Block::Pass if grow => (j, size) = (end, size.saturating_mul(2)),
            Block::Pass => j = end,
            Block::Split if end - j > 1 => size = (end - j) / 2,
            _ => return false,
        }
    }
    true
}

/// The longest block of walked-down steps [`Sides::scan_down`] reads
/// two periods to clear, where the index's buckets do not.
const READ_BLOCK: u32 = 256;

/// The longest block [`Sides::scan_down`] (and the crossing of two
/// per-step tables) reads step by step.
pub(crate) const SCAN_BLOCK: u32 = 32;

/// A ramp whose periods are read by position at little cost: a per-step
/// table or an indexed compressed one.
fn read_directly<W: TableWord>(ramp: &Ramp<'_, W>) -> bool {
    ramp.per_step().is_some() || matches!(ramp, Ramp::Indexed(_))
}

/// [`Sides::crossing`]'s test of two indexed ramps' buckets: `true` when
/// they show the deceleration ramp's step `x` more than `slack` (both
/// ramps' slack added; `decel_slack` the deceleration ramp's alone)
/// faster than the acceleration ramp's step `p`, without reading either.
/// The first is at most its bucket's first period and the deceleration
/// ramp's slack, the second at least the next bucket's first period less
/// the acceleration ramp's. `false` when they do not show it.
pub(crate) fn buckets_faster(
    a: IndexedRuns<'_>,
    d: IndexedRuns<'_>,
    x: u32,
    p: u32,
    slack: u32,
    decel_slack: u32,
) -> bool {
    // Both slacks, exact unless their sum saturated.
    if slack == u32::MAX {
        return false;
    }
    let accel_slack = slack - decel_slack;
    d.buckets()
        .at_most(x, decel_slack)
        .is_some_and(|dx| search::faster_by(dx, slack, a.buckets().at_least(p, accel_slack)))
}
