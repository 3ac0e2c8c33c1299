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

use crate::base::timer::TableWord;
use crate::player::planning::reader::RunWalk;
use crate::player::ramps::ramp::{Cursor, Ramp, ticks_at};

/// A run of steps, as the step path plays it. Its tag a word, so that
/// runs are copied word by word (with a 16-bit tag, a held period packs
/// beside it and a run is copied by `memcpy`).
#[derive(Clone, Debug)]
#[repr(u32)]
pub(crate) enum Run<'a, W> {
    /// Nothing to play (the iterator is empty), and the step has found
    /// so: the player returned `false` and has handed out nothing since.
    /// (A [`Buffered`](crate::player::Buffered) player has no step ahead of the
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

impl<'a, W: TableWord> Stretch<'a, W> {
    /// A stretch of `count` steps read from `source`, the deceleration
    /// ramp's if `decel`, from position `start` on, `dir` a step; the
    /// acceleration side at `acc` when it begins, moving `acc_dir` a step.
    #[inline(always)]
    pub(crate) fn new(
        source: Source<'a, W>,
        decel: bool,
        start: u32,
        dir: i8,
        count: u32,
        acc: u32,
        acc_dir: i8,
    ) -> Self {
        Stretch {
            source,
            decel,
            start,
            dir,
            count,
            total: count,
            acc,
            acc_dir,
            decelerating: decel && dir == -1,
        }
    }

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

/// What a player knows of its two ramps from when it was made, which its
/// planner reads through one reference.
#[derive(Clone, Debug)]
pub(crate) struct Known {
    /// Cursors at the tops of the acceleration and deceleration ramps,
    /// from which searches on compressed ramps seek positions near the
    /// top, a run at a time.
    pub(crate) tops: [Option<Cursor>; 2],
    /// How far ahead of the acceleration ramp the deceleration ramp is
    /// faster at every step ([`Fall`](crate::table::fall::Fall)).
    pub(crate) fall: crate::table::fall::Fall,
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
    /// No step after the cruise position is known to be as long as it.
    pub(crate) cruise_last: bool,
    /// The two ramps' slack ([`search::slack`](crate::player::planning::search::slack))
    /// added: a deceleration step that far faster than the acceleration
    /// side has every step before it faster too.
    pub(crate) slack: u32,
    /// The deceleration ramp's slack alone.
    pub(crate) decel_slack: u32,
    /// What planning knows of the two ramps: the cursors at their tops,
    /// and how far ahead the deceleration ramp is faster.
    pub(crate) known: &'t Known,
    /// The cursors placed last on each ramp: a plan's stretches begin near
    /// each other.
    pub(crate) recent: Cell<[Option<Cursor>; 2]>,
    /// Where a crossing's walk on an indexed deceleration ramp stood when
    /// it found the crossing.
    pub(crate) crossed: Cell<Option<Cursor>>,
    /// The cursor at the last position of an indexed acceleration ramp
    /// [`Sides::a`] read: the crossing's walk and a plan's stretch begin
    /// there or near.
    pub(crate) read_a: Cell<Option<Cursor>>,
}

impl<'a, W: TableWord> Sides<'_, 'a, W> {
    pub(crate) fn a(&self, pos: u32) -> u32 {
        if let Some(periods) = self.accel.per_step() {
            return ticks_at(periods, pos).unwrap_or(0);
        }
        if let Ramp::Indexed(index) = self.accel {
            let walk = RunWalk::at(index, pos);
            self.read_a.set(walk.map(|w| w.cursor()));
            return walk.map_or(0, |w| w.ticks());
        }
        self.cursor(false, pos)
            .map_or(0, |c| c.period(&self.accel).into_ticks())
    }

    /// The cursor at `pos` of the deceleration ramp (else the acceleration
    /// ramp), sought from the ramp's top when that is nearer.
    pub(crate) fn cursor(&self, decel: bool, pos: u32) -> Option<Cursor> {
        let (ramp, side) = if decel {
            (&self.decel, 1)
        } else {
            (&self.accel, 0)
        };
        // Held and segment tables place a cursor directly, and so does an
        // index, unless the crossing's walk left it there or it is the
        // ramp's top, whose cursor the player keeps.
        if !matches!(ramp, Ramp::Runs(_)) {
            if let (true, Ramp::Indexed(_)) = (decel, ramp) {
                if let Some(c) = self.crossed.get().filter(|c| c.pos == pos) {
                    return Some(c);
                }
            }
            let last = if decel {
                self.decel_last
            } else {
                self.accel_last
            };
            if pos == last {
                if let Some(top) = self.known.tops[side] {
                    return Some(top);
                }
            }
            return Cursor::at(ramp, pos);
        }
        let mut recent = self.recent.get();
        let hint = match (recent[side], self.known.tops[side]) {
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

    /// The cursor at `pos` of an indexed acceleration ramp if
    /// [`Sides::a`] read there last.
    pub(crate) fn read_at(&self, pos: u32) -> Option<Cursor> {
        self.read_a.get().filter(|c| c.pos == pos)
    }

    /// A cursor to begin a search on each ramp from: the one placed last.
    pub(crate) fn hints(&self) -> [Option<Cursor>; 2] {
        let recent = self.recent.get();
        [
            recent[0].or(self.known.tops[0]),
            recent[1].or(self.known.tops[1]),
        ]
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
        // stretch plays (on an indexed acceleration ramp, the one `a` left
        // at `pos` if it read there last).
        let source = match ramp.per_step() {
            Some(periods) => Run::over(periods, pos, dir, count).map_or(Source::Taken, Source::Run),
            None => Source::At(
                self.read_at(pos)
                    .filter(|_| !decel)
                    .or_else(|| self.cursor(decel, pos))
                    .unwrap_or(Cursor::ZERO),
            ),
        };
        Stretch::new(source, decel, pos, dir, count, acc, acc_dir)
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

    /// Lengthens the plan's last stretch by `n` steps if it walks the
    /// acceleration ramp `dir` and ends where a walk from `p` begins: a
    /// walk out of reach of the deceleration ramp and the one within it
    /// are one stretch, placed once.
    fn extend(&self, plan: &mut Plan<'a, W>, p: u32, dir: i8, n: u32) -> bool {
        let Some(last) = plan
            .len
            .checked_sub(1)
            .and_then(|i| plan.stretches.get_mut(i))
        else {
            return false;
        };
        if last.decel || last.dir != dir || last.acc_dir != dir || last.read_at(last.count) != p {
            return false;
        }
        let count = last.count + n;
        match last.source {
            // A per-step table's run, made again.
            Source::Run(_) => {
                let run = self.accel.per_step();
                match run.and_then(|periods| Run::over(periods, last.start, dir, count)) {
                    Some(run) => last.source = Source::Run(run),
                    None => return false,
                }
            }
            // A cursor at its first step.
            Source::At(_) => {}
            Source::Taken => return false,
        }
        (last.count, last.total) = (count, count);
        true
    }

    /// Plans `r` steps of a move that is not decelerating, the acceleration
    /// side at `p`, into `plan` (in place: a plan is large to copy).
    // Inlined into `Player::plan_steps`, its one caller, with the
    // fields `sides!` borrows.
    #[inline(always)]
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
    #[inline(always)]
    fn within_reach(&self, plan: &mut Plan<'a, W>, p: u32, r: u32) {
        let j = self.crossing(p, r);
        // The walk's steps towards the cruise position go on the walk
        // planned out of reach, if that one ends here.
        let dir = self.toward(p).1;
        let walked = j.min(p.abs_diff(self.cruise));
        let p = match walked > 0 && self.extend(plan, p, dir, walked) {
            true => {
                let q = self.walked_by(p, dir, walked);
                self.walk(plan, q, j - walked)
            }
            false => self.walk(plan, p, j),
        };
        if j < r {
            let after = r - 1 - j;
            plan.push(self.stretch(true, after, -1, after + 1, p, 0));
        }
    }
}
