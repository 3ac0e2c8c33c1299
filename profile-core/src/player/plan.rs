//! Planning a move: the stretches of steps it is made of, found once when the
//! move starts, stops or changes its cruise speed.
//!
//! A move is the acceleration side walking one step per step towards the
//! cruise position, no faster than the deceleration ramp's fastest entry
//! while that ramp is out of reach, until the deceleration ramp read
//! backwards by the steps that remain is not faster than it; from then on
//! the deceleration ramp plays to the end. The planner finds where each of
//! these changes happens, so that playing is a countdown and a load.

use core::cell::Cell;
use core::slice;

use super::ramp::{Cursor, Ramp, ticks_at};
use super::reader::{Reader, RunWalk};
use super::search;
use crate::base::timer::TableWord;
use crate::table::runs::IndexedRun;

/// A run of steps, as the step path plays it. Its tag a word, so that
/// runs are copied word by word (with a 16-bit tag, a held period packs
/// beside it and a run is copied by `memcpy`).
#[derive(Clone, Debug)]
#[repr(u32)]
pub(crate) enum Run<'a, W> {
    /// Nothing to play (the iterator is empty), and the step has found
    /// so: the player returned `false` and has handed out nothing since.
    /// (A [`Buffered`](super::Buffered) player has no step ahead of the
    /// pin.) The step path plays it as the empty `Down` it holds, so that
    /// it adds no kind to the step's dispatch: its tag and `Down`'s are
    /// one test.
    Ended(slice::Iter<'a, W>),
    /// Periods played last to first.
    Down(slice::Iter<'a, W>),
    /// One period, played `n` more times.
    Hold(W, u32),
    /// Periods played first to last.
    Up(slice::Iter<'a, W>),
}

impl<'a, W: TableWord> Run<'a, W> {
    /// A run with nothing to play.
    pub(crate) fn empty() -> Self {
        Run::Up([].iter())
    }

    /// Nothing to play, and the step has found so.
    pub(crate) fn ended() -> Self {
        Run::Ended([].iter())
    }

    /// Steps left in the run.
    pub(crate) fn left(&self) -> u32 {
        match self {
            Run::Up(s) | Run::Down(s) | Run::Ended(s) => s.len() as u32,
            Run::Hold(_, n) => *n,
        }
    }

    /// The run of a stretch of a per-step table, whole.
    fn over(periods: &'a [W], pos: u32, dir: i8, count: u32) -> Option<Self> {
        let (pos, n) = (pos as usize, count as usize);
        Some(match dir {
            1 => Run::Up(periods.get(pos..pos + n)?.iter()),
            -1 => Run::Down(periods.get((pos + 1).checked_sub(n)?..=pos)?.iter()),
            _ => Run::Hold(*periods.get(pos)?, count),
        })
    }
}

/// The most stretches a plan holds: a move is at most a capped walk down, a
/// walk, a cruise (out of reach of the deceleration ramp), then a walk, a
/// cruise and the deceleration (within reach).
pub(crate) const MAX_STRETCHES: usize = 8;

/// What a stretch plays from.
#[derive(Clone, Debug)]
pub(crate) enum Source<'a, W> {
    /// The stretch as one run, made when the move is planned: a per-step
    /// table.
    Run(Run<'a, W>),
    /// That run, handed to the step path.
    Taken,
    /// Where it reads next, read as it plays: a held or segment table
    /// entry by entry, compressed runs run by run.
    At(Cursor),
}

/// Steps that read one ramp at positions moving the same way.
#[derive(Clone, Debug)]
#[repr(C)]
pub(crate) struct Stretch<'a, W> {
    /// What it plays from.
    pub(crate) source: Source<'a, W>,
    /// Steps not yet handed to a run.
    pub(crate) count: u32,
    // The four bytes together: one word.
    /// Reads the deceleration ramp (else the acceleration ramp).
    pub(crate) decel: bool,
    /// Positions per step: -1, 0 or 1.
    pub(crate) dir: i8,
    /// How the acceleration side moves per step: -1, 0 or 1.
    pub(crate) acc_dir: i8,
    /// The deceleration ramp has taken over.
    pub(crate) decelerating: bool,
    /// The position it reads first.
    pub(crate) start: u32,
    /// Steps in all.
    pub(crate) total: u32,
    /// Where the acceleration side stands when the stretch begins.
    pub(crate) acc: u32,
}

impl<W: TableWord> Stretch<'_, W> {
    /// The position read by its step `k` (from 0).
    pub(crate) fn read_at(&self, k: u32) -> u32 {
        match self.dir {
            1 => self.start + k,
            -1 => self.start - k,
            _ => self.start,
        }
    }

    /// Where the acceleration side stands after `played` of its steps.
    pub(crate) fn acc_after(&self, played: u32) -> u32 {
        match self.acc_dir {
            1 => self.acc + played,
            -1 => self.acc - played,
            _ => self.acc,
        }
    }
}

/// A move's stretches, in order.
// The fields a refill reads come first.
#[derive(Clone, Debug)]
#[repr(C)]
pub(crate) struct Plan<'a, W> {
    /// The next stretch to hand steps out of.
    pub(crate) next: usize,
    /// The stretch being played.
    pub(crate) at: usize,
    pub(crate) len: usize,
    pub(crate) stretches: [Stretch<'a, W>; MAX_STRETCHES],
}

impl<'a, W: TableWord> Plan<'a, W> {
    pub(crate) const EMPTY: Self = Plan {
        next: 0,
        at: 0,
        len: 0,
        stretches: [const {
            Stretch {
                source: Source::Taken,
                decel: false,
                start: 0,
                dir: 0,
                count: 0,
                total: 0,
                acc: 0,
                acc_dir: 0,
                decelerating: false,
            }
        }; MAX_STRETCHES],
    };

    /// No stretches: nothing to play.
    pub(crate) fn clear(&mut self) {
        self.next = 0;
        self.at = 0;
        self.len = 0;
    }

    #[inline(always)]
    pub(crate) fn push(&mut self, stretch: Stretch<'a, W>) {
        if let Some(slot) = self.stretches.get_mut(self.len) {
            *slot = stretch;
            self.len += 1;
        }
    }

    /// Steps of the plan not yet handed to a run.
    pub(crate) fn steps(&self) -> u32 {
        self.stretches[..self.len].iter().map(|s| s.count).sum()
    }
}

/// What the planner knows of a player.
pub(crate) struct Sides<'t, 'a, W> {
    pub(crate) accel: Ramp<'a, W>,
    pub(crate) decel: Ramp<'a, W>,
    pub(crate) accel_last: u32,
    pub(crate) decel_last: u32,
    pub(crate) decel_fastest: u32,
    /// The first acceleration step faster than `decel_fastest`.
    pub(crate) cap: u32,
    pub(crate) cruise: u32,
    /// The two ramps' slack ([`search::slack`]) added: a deceleration step
    /// that far faster than the acceleration side has every step before it
    /// faster too.
    pub(crate) slack: u32,
    /// The deceleration ramp's slack alone.
    pub(crate) decel_slack: u32,
    /// Cursors at the tops of the acceleration and deceleration ramps.
    pub(crate) tops: &'t [Option<Cursor>; 2],
    /// The cursors placed last on each ramp: a plan's stretches begin near
    /// each other.
    pub(crate) recent: Cell<[Option<Cursor>; 2]>,
    /// Where a crossing's walk on an indexed deceleration ramp stood when
    /// it found the crossing.
    pub(crate) crossed: Cell<Option<Cursor>>,
}

impl<'a, W: TableWord> Sides<'_, 'a, W> {
    fn a(&self, pos: u32) -> u32 {
        if let Some(periods) = self.accel.per_step() {
            return ticks_at(periods, pos).unwrap_or(0);
        }
        if let Ramp::Indexed(index) = self.accel {
            return RunWalk::at(index.runs(), pos).map_or(0, |w| w.ticks());
        }
        self.cursor(false, pos)
            .map_or(0, |c| c.period(&self.accel).into_ticks())
    }

    /// The cursor at `pos` of the deceleration ramp (else the acceleration
    /// ramp), sought from the ramp's top when that is nearer.
    fn cursor(&self, decel: bool, pos: u32) -> Option<Cursor> {
        let (ramp, side) = if decel {
            (&self.decel, 1)
        } else {
            (&self.accel, 0)
        };
        // Held and segment tables place a cursor directly, and so does an
        // index, unless the crossing's walk left it there.
        if !matches!(ramp, Ramp::Runs(_)) {
            if let (true, Ramp::Indexed(_)) = (decel, ramp) {
                if let Some(c) = self.crossed.get().filter(|c| c.pos == pos) {
                    return Some(c);
                }
            }
            return Cursor::at(ramp, pos);
        }
        let mut recent = self.recent.get();
        let hint = match (recent[side], self.tops[side]) {
            (Some(r), Some(t)) if r.pos.abs_diff(pos) < t.pos.abs_diff(pos) => Some(r),
            (r, None) => r,
            (_, t) => t,
        };
        let c = Cursor::near(hint, ramp, pos);
        if c.is_some() {
            recent[side] = c;
            self.recent.set(recent);
        }
        c
    }

    /// A cursor to begin a search on each ramp from: the one placed last.
    fn hints(&self) -> [Option<Cursor>; 2] {
        let recent = self.recent.get();
        [recent[0].or(self.tops[0]), recent[1].or(self.tops[1])]
    }

    /// One step of the acceleration side towards the cruise position.
    pub(crate) fn toward(&self, p: u32) -> (u32, i8) {
        match p.cmp(&self.cruise) {
            core::cmp::Ordering::Less => (p + 1, 1),
            core::cmp::Ordering::Greater => (p - 1, -1),
            core::cmp::Ordering::Equal => (p, 0),
        }
    }

    /// The deceleration ramp from `pos` down to rest, the acceleration side
    /// standing at `acc`.
    pub(crate) fn decelerate(&self, pos: u32, acc: u32) -> Stretch<'a, W> {
        self.stretch(true, pos, -1, pos + 1, acc, 0)
    }

    #[inline(always)]
    fn stretch(
        &self,
        decel: bool,
        pos: u32,
        dir: i8,
        count: u32,
        acc: u32,
        acc_dir: i8,
    ) -> Stretch<'a, W> {
        let ramp = if decel { &self.decel } else { &self.accel };
        // A per-step table: one run, made now; else a cursor, read as the
        // stretch plays.
        let source = match ramp.per_step() {
            Some(periods) => Run::over(periods, pos, dir, count).map_or(Source::Taken, Source::Run),
            None => Source::At(self.cursor(decel, pos).unwrap_or(Cursor::ZERO)),
        };
        Stretch {
            source,
            decel,
            start: pos,
            dir,
            count,
            total: count,
            acc,
            acc_dir,
            decelerating: decel && dir == -1,
        }
    }

    /// The acceleration side walking from `p` for `n` steps (towards the
    /// cruise position, reaching it at most), then holding.
    fn walk(&self, plan: &mut Plan<'a, W>, p: u32, n: u32) -> u32 {
        let distance = p.abs_diff(self.cruise);
        let walked = n.min(distance);
        let dir = self.toward(p).1;
        if walked > 0 {
            plan.push(self.stretch(false, p, dir, walked, p, dir));
        }
        let p = if dir > 0 { p + walked } else { p - walked };
        if n > walked {
            plan.push(self.stretch(false, p, 0, n - walked, p, 0));
        }
        p
    }

    /// Plans `r` steps of a move that is not decelerating, the acceleration
    /// side at `p`, into `plan` (in place: a plan is large to copy).
    pub(crate) fn plan(&self, plan: &mut Plan<'a, W>, mut p: u32, mut r: u32) {
        plan.clear();
        let l = self.decel_last;
        while r > 0 && r - 1 > l {
            // The deceleration ramp is out of reach for `far` more steps.
            let far = r - (l + 1);
            // Before `cap` no step is faster than that entry: no read.
            let n = if p >= self.cap && self.a(p) < self.decel_fastest {
                // No faster than the deceleration ramp's fastest entry: its
                // top plays; the acceleration side only walks down.
                let n = if self.cruise < p {
                    self.capped_walk(p, far)
                } else {
                    far
                };
                let acc_dir = if self.cruise < p { -1 } else { 0 };
                plan.push(self.stretch(true, l, 0, n, p, acc_dir));
                if acc_dir < 0 {
                    p -= n;
                }
                n
            } else if p < self.cruise {
                // Up to the cruise position or the first capped step.
                let n = far
                    .min(self.cruise - p)
                    .min(self.cap.saturating_sub(p).max(1));
                p = self.walk(plan, p, n);
                n
            } else {
                p = self.walk(plan, p, far);
                far
            };
            r -= n;
        }
        if r > 0 {
            self.within_reach(plan, p, r);
        }
    }

    /// Steps in a row, from `p` walking down to the cruise position, whose
    /// acceleration period is faster than the deceleration ramp's fastest.
    fn capped_walk(&self, p: u32, far: u32) -> u32 {
        let mut c = self.cursor(false, p).unwrap_or(Cursor::ZERO);
        let mut n = 0;
        while n < far
            && c.pos > self.cruise
            && c.period(&self.accel).into_ticks() < self.decel_fastest
        {
            n += 1;
            c.backward(&self.accel);
        }
        n.max(1)
    }

    /// The last `r` steps, the deceleration ramp within reach: the
    /// acceleration side plays until the deceleration ramp, read at the steps
    /// that remain, is not faster; then the deceleration ramp plays to the end.
    fn within_reach(&self, plan: &mut Plan<'a, W>, p: u32, r: u32) {
        let j = self.crossing(p, r);
        let p = self.walk(plan, p, j);
        if j < r {
            let after = r - 1 - j;
            plan.push(self.stretch(true, after, -1, after + 1, p, 0));
        }
    }

    /// The first of the last `r` steps at which the deceleration ramp, read
    /// at the steps that remain, is not faster than the acceleration side
    /// (walking from `p` towards the cruise position); `r` if none is.
    ///
    /// Once the acceleration side walks up or holds, the deceleration ramp
    /// read at the steps that remain only gets slower and the acceleration
    /// side only faster, but for the ramps' slack: the step is searched
    /// ([`search`]). Walking down, both get slower: those steps are read
    /// one by one.
    pub(crate) fn crossing(&self, p: u32, r: u32) -> u32 {
        if let (Some(a), Some(d)) = (self.accel.per_step(), self.decel.per_step()) {
            return self.crossing_direct(a, d, p, r);
        }
        // Walking down, the steps one by one; then the search.
        let (walked_down, slack) = match self.toward(p).1 {
            -1 => ((p - self.cruise).min(r), self.slack),
            1 => (0, self.slack),
            // Held: only the deceleration ramp's order counts.
            _ => (0, self.decel_slack),
        };
        if walked_down > 0 {
            // Walking down, the acceleration side is never faster than at
            // `p` but for its slack: a deceleration step more than both
            // ramps' slack faster than that has every step before it faster
            // than the acceleration side.
            let [_, d] = self.hints();
            let mut d = Reader::new(&self.decel, d);
            let ap = self.a(p);
            // Often the deceleration ramp is that much faster at the last
            // of those steps, and so at every one before: no search.
            let last = d.ticks(r - walked_down);
            let from = match last {
                Some(t) if search::faster_by(t, self.slack, ap) => walked_down,
                _ => d.past_shorter(r, 0, walked_down, self.slack, ap),
            };
            if let Some(j) = self.scan(p, r, from, walked_down - from) {
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
        let [a, d] = self.hints();
        let dir = self.toward(p).1;
        if dir <= 0 {
            // Held from `walked_down` on: one period to compare with.
            let held = self.a(self.walked_by(p, dir, walked_down));
            let from = Reader::new(&self.decel, d).past_shorter(r, walked_down, r, slack, held);
            return self.scan(p, r, from, r - from).unwrap_or(r);
        }
        let (mut a, mut d) = (Reader::new(&self.accel, a), Reader::new(&self.decel, d));
        let from = search::past(walked_down, r, &mut |j| match (
            d.ticks(r - 1 - j),
            a.ticks(self.walked_by(p, dir, j)),
        ) {
            (Some(dp), Some(ap)) => search::faster_by(dp, slack, ap),
            _ => false,
        });
        self.scan(p, r, from, r - from).unwrap_or(r)
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
        if let (1, [Some(a), Some(d)]) = (n, self.tops) {
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
        for j in from..from + n {
            if d.period(&self.decel).into_ticks() >= a.period(&self.accel).into_ticks() {
                return Some(j);
            }
            d.backward(&self.decel);
            match self.toward(a.pos).1 {
                1 => {
                    a.forward(&self.accel, self.accel_last);
                }
                -1 => {
                    a.backward(&self.accel);
                }
                _ => {}
            }
        }
        to_end
    }

    /// [`Sides::scan`] on ramps read by position ([`read_directly`]), the
    /// acceleration side at `q` on step `from`: the step found, `Some(r)`
    /// when a ramp ends, `None` when none of the `n` steps is.
    fn scan_read(&self, q: u32, r: u32, from: u32, n: u32) -> Option<u32> {
        if let (Ramp::Indexed(a), Ramp::Indexed(d)) = (self.accel, self.decel) {
            return self.scan_runs(a.runs(), d.runs(), q, r, from, n);
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
        a: &[IndexedRun],
        d: &[IndexedRun],
        mut q: u32,
        r: u32,
        from: u32,
        n: u32,
    ) -> Option<u32> {
        let (Some(mut a), Some(mut d)) = (RunWalk::at(a, q), RunWalk::at(d, r - 1 - from)) else {
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

/// A ramp whose periods are read by position at little cost: a per-step
/// table or an indexed compressed one.
fn read_directly<W: TableWord>(ramp: &Ramp<'_, W>) -> bool {
    ramp.per_step().is_some() || matches!(ramp, Ramp::Indexed(_))
}
