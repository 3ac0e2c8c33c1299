//! The step paths ([`Player::step`]'s, and [`Player::next_period`]'s,
//! which returns the period): the run being played, inline in the step
//! interrupt, and past its end the plan's next run, in cold functions; the
//! paths of a buffered register ([`Buffered`](crate::player::Buffered)).

use crate::base::timer::TableWord;
use crate::player::planning::plan::{Run, Source};
use crate::player::playing::buffered::Pulsed;
use crate::player::{Layout, Player, Ramp};
use core::sync::atomic::{Ordering, compiler_fence};

impl<'a, W: TableWord, L: Layout> Player<'a, W, L> {
    /// Plays the next step of the run being played, or hands `write` back
    /// when the run is played.
    #[inline(always)]
    pub(in crate::player) fn play_run<F: FnOnce(W)>(&mut self, write: F) -> Result<(), F> {
        self.play_run_counted::<false, F>(write)
    }

    /// [`Player::play_run`], a held run's count decremented before it is
    /// tested when `DECREMENT_FIRST`: the test is then on the count as
    /// loaded, which the compiler keeps in a low register (`cbz` on a
    /// Cortex-M3) where a longer write (`Axes`' mask and the period) would
    /// push it out, at two instructions more where the run ends (the
    /// decrement and its store). The count left when the run ends is
    /// `u32::MAX`, never read: the step past a run always replaces it
    /// ([`Player::refill`]).
    #[inline(always)]
    pub(in crate::player) fn play_run_counted<const DECREMENT_FIRST: bool, F: FnOnce(W)>(
        &mut self,
        write: F,
    ) -> Result<(), F> {
        match &mut self.run {
            Run::Down(periods) | Run::Ended(periods) => {
                if let Some(&p) = periods.next_back() {
                    write(p);
                    return Ok(());
                }
            }
            Run::Hold(p, n) if DECREMENT_FIRST => {
                let (left, ended) = n.overflowing_sub(1);
                *n = left;
                if !ended {
                    write(*p);
                    return Ok(());
                }
            }
            Run::Hold(p, n) => {
                if *n > 0 {
                    *n -= 1;
                    // Emits nothing; keeps the test a branch where the
                    // write is longer (`Axes`' mask and the period): made
                    // a conditional block, the path is an instruction
                    // longer on a Cortex-M3.
                    compiler_fence(Ordering::SeqCst);
                    write(*p);
                    return Ok(());
                }
            }
            Run::Up(periods) => {
                if let Some(&p) = periods.next() {
                    write(p);
                    return Ok(());
                }
            }
        }
        Err(write)
    }

    /// A buffered register's step ([`Buffered`](crate::player::Buffered)): `Pulsed::Ended` when the
    /// player has handed out nothing since it last returned `false` (no
    /// step is ahead of the pin); else calls `pulse`, then plays the next
    /// step of the run being played, or hands `write` back when the run is
    /// played. The run's kind is read once: whether a step is ahead and
    /// which path plays it.
    #[inline(always)]
    pub(in crate::player) fn play_pulsed<F: FnOnce(W)>(
        &mut self,
        pulse: impl FnOnce(),
        write: F,
    ) -> Pulsed<F> {
        if L::COMPRESSED {
            if let Run::Ended(_) = self.run {
                return Pulsed::Ended;
            }
            pulse();
            if let Some(ticks) = self.computed.next() {
                write(W::from_ticks(ticks));
                return Pulsed::Played;
            }
            return Pulsed::Empty(write);
        }
        match &mut self.run {
            Run::Down(periods) => {
                pulse();
                if let Some(&p) = periods.next_back() {
                    write(p);
                    return Pulsed::Played;
                }
            }
            Run::Hold(p, n) => {
                pulse();
                if *n > 0 {
                    *n -= 1;
                    write(*p);
                    return Pulsed::Played;
                }
            }
            Run::Up(periods) => {
                pulse();
                if let Some(&p) = periods.next() {
                    write(p);
                    return Pulsed::Played;
                }
            }
            Run::Ended(_) => return Pulsed::Ended,
        }
        Pulsed::Empty(write)
    }

    /// A buffered register's step without a pulse ([`Buffered::step`](crate::player::Buffered::step)):
    /// the run being played, then past it whether a step is ahead of the
    /// pin, so that the step path is the player's own.
    #[inline(always)]
    pub(in crate::player) fn step_buffered<F: FnOnce(W)>(&mut self, write: F) -> bool {
        match self.play(write) {
            Ok(()) => true,
            Err(write) => self.buffered_past_run(write),
        }
    }

    /// Plays the next step of the run being played (a compressed run for
    /// a [`Compressed`](crate::player::Compressed) player), or hands `write` back when it is played.
    #[inline(always)]
    pub(in crate::player) fn play<F: FnOnce(W)>(&mut self, write: F) -> Result<(), F> {
        if L::COMPRESSED {
            return match self.computed.next() {
                Some(ticks) => {
                    write(W::from_ticks(ticks));
                    Ok(())
                }
                None => Err(write),
            };
        }
        self.play_run(write)
    }

    /// [`Player::step_buffered`] past the run: `true` when a step is taken
    /// now, the next period handed to `write` if there is one.
    #[cold]
    #[inline(never)]
    fn buffered_past_run<F: FnOnce(W)>(&mut self, write: F) -> bool {
        if self.is_ended() {
            // No step ahead of the pin: the interval that ended was the
            // move's last.
            return self.step_past_run(write) || self.rest();
        }
        self.step_past_run(write);
        true
    }

    /// The buffered step has found the move over: at rest. `false`.
    #[cold]
    pub(in crate::player) fn rest(&mut self) -> bool {
        self.rested = true;
        false
    }

    /// For [`Buffered`](crate::player::Buffered): at rest, or nothing has played
    /// ([`Player::rest`]).
    pub(in crate::player) fn is_rested(&self) -> bool {
        self.rested
    }

    /// For [`Buffered`](crate::player::Buffered): a move has begun (`false`), or
    /// the stepper is at rest (`true`).
    pub(in crate::player) fn set_rested(&mut self, rested: bool) {
        self.rested = rested;
    }

    /// The step past the end of the run being played, for
    /// [`Player::play_pulsed`]: `false`, the run [`Run::Ended`], when the
    /// move is done: a call to the refill of any layout, the loop over
    /// compressed runs inline (it calls their refill).
    #[inline(always)]
    pub(in crate::player) fn step_past_run<F: FnOnce(W)>(&mut self, write: F) -> bool {
        if L::COMPRESSED {
            self.step_runs(write)
        } else {
            self.step_refilled(write)
        }
    }

    /// The step path past the end of a run: the plan's next runs until one
    /// plays.
    #[cold]
    #[inline(never)]
    pub(in crate::player) fn step_refilled<F: FnOnce(W)>(&mut self, mut write: F) -> bool {
        // `refill` hands the player back, so that the loop keeps no
        // register across its call.
        let mut this = self;
        loop {
            // A compressed ramp's run, behind an empty `Down`: here, so that
            // the per-step table's paths are the step's only ones.
            if let Some(ticks) = this.computed.next() {
                write(W::from_ticks(ticks));
                return true;
            }
            match this.refill() {
                Some(player) => this = player,
                None => return false,
            }
            match this.play_run(write) {
                Ok(()) => return true,
                Err(w) => write = w,
            }
        }
    }

    /// [`Player::next_period`]: the step path of [`Player::step`], the
    /// period returned.
    #[inline(always)]
    pub(in crate::player) fn next_played(&mut self) -> Option<W> {
        // The step's paths, each returning its period: written through a
        // closure, as `step` writes, the period lay in a stack slot whose
        // address the refill's call took (5 or 6 instructions more per
        // step). The run being played is tried before the loop, so that
        // the loop's blocks are not laid out between its arms and the
        // caller's code; `inline(always)`, as `inline` alone left the loop
        // a call. `refill` hands the player back, so that the loops keep
        // no register across its call.
        let mut this = self;
        if L::COMPRESSED {
            loop {
                if let Some(ticks) = this.computed.next() {
                    return Some(W::from_ticks(ticks));
                }
                this = this.refill_runs()?;
            }
        }
        if let Some(p) = this.next_in_run() {
            return Some(p);
        }
        loop {
            // A compressed ramp's run, behind an empty `Down`.
            if let Some(ticks) = this.computed.next() {
                return Some(W::from_ticks(ticks));
            }
            this = this.refill()?;
            if let Some(p) = this.next_in_run() {
                return Some(p);
            }
        }
    }

    /// The next period of the run being played, `None` when it is played:
    /// [`Player::play_run`] for [`Player::next_period`]. Each arm loads
    /// the period before it moves the run on, so that no arm ends with the
    /// load: three arms ending with one were merged into a load after
    /// them, an instruction or two more per step than the step's own loads.
    #[inline(always)]
    pub(in crate::player) fn next_in_run(&mut self) -> Option<W> {
        match &mut self.run {
            Run::Down(periods) | Run::Ended(periods) => {
                let mut rest = periods.clone();
                if let Some(&p) = rest.next_back() {
                    *periods = rest;
                    return Some(p);
                }
            }
            Run::Hold(p, n) => {
                if *n > 0 {
                    let p = *p;
                    *n -= 1;
                    // Emits nothing; keeps the count's store in this arm:
                    // merged with the `Down` arm's store of its end, the
                    // path is a branch longer on a Cortex-M4F.
                    compiler_fence(Ordering::SeqCst);
                    return Some(p);
                }
            }
            Run::Up(periods) => {
                let mut rest = periods.clone();
                if let Some(&p) = rest.next() {
                    *periods = rest;
                    return Some(p);
                }
            }
        }
        None
    }

    /// The step path of a player of compressed tables: its run first.
    #[inline(always)]
    pub(in crate::player) fn step_runs(&mut self, write: impl FnOnce(W)) -> bool {
        let mut this = self;
        loop {
            if let Some(ticks) = this.computed.next() {
                write(W::from_ticks(ticks));
                return true;
            }
            match this.refill_runs() {
                Some(player) => this = player,
                None => return false,
            }
        }
    }

    /// Begins the plan's next run of a compressed table; `None`, the run
    /// [`Run::Ended`], when the plan is played (or a ramp is not
    /// compressed, which the constructors of a [`Compressed`](crate::player::Compressed) player rule
    /// out).
    #[cold]
    #[inline(never)]
    pub(in crate::player) fn refill_runs(&mut self) -> Option<&mut Self> {
        if self.begin_runs().is_none() {
            self.run = Run::ended();
            return None;
        }
        Some(self)
    }

    /// [`Player::refill_runs`]: `None` when the plan is played.
    #[inline(always)]
    fn begin_runs(&mut self) -> Option<()> {
        let next = self.next_stretch()?;
        let s = self.plan.stretches.get_mut(next)?;
        let ramp = if s.decel { &self.decel } else { &self.accel };
        let Source::At(at) = &mut s.source else {
            return None;
        };
        self.computed = match *ramp {
            Ramp::Runs(runs) => at.take_run(runs, s.dir, s.count),
            Ramp::Indexed(index) => at.take_run(index.runs(), s.dir, s.count),
            _ => return None,
        };
        s.count -= self.computed.left;
        Some(())
    }

    /// Begins the plan's next run; `None`, the run [`Run::Ended`], when
    /// the plan is played.
    #[cold]
    #[inline(never)]
    pub(in crate::player) fn refill(&mut self) -> Option<&mut Self> {
        // Most stretches of a per-step table are a whole run, made when the
        // move was planned: taken at once.
        let next = self.plan.next;
        if next < self.plan.len {
            if let Some(s) = self.plan.stretches.get_mut(next) {
                if matches!(s.source, Source::Run(_)) && !(self.endless && s.decelerating) {
                    let Source::Run(run) = core::mem::replace(&mut s.source, Source::Taken) else {
                        return None;
                    };
                    self.run = run;
                    s.count = 0;
                    self.plan.at = next;
                    self.plan.next = next + 1;
                    return Some(self);
                }
            }
        }
        match self.next_run() {
            Some(run) => self.run = run,
            None => {
                self.run = Run::ended();
                return None;
            }
        }
        Some(self)
    }

    /// The next stretch with steps not yet handed out, now the one being
    /// played; `None` when the plan is played.
    #[inline(always)]
    pub(in crate::player) fn next_stretch(&mut self) -> Option<usize> {
        loop {
            let next = self.plan.next;
            if next >= self.plan.len {
                return None;
            }
            let s = self.plan.stretches.get(next)?;
            if s.count > 0 {
                if self.endless && s.decelerating {
                    self.next_lap();
                    continue;
                }
                self.plan.at = next;
                return Some(next);
            }
            self.plan.next = next + 1;
        }
    }

    /// The plan's next run, or `None` when the plan is played.
    pub(in crate::player) fn next_run(&mut self) -> Option<Run<'a, W>> {
        let next = self.next_stretch()?;
        let s = self.plan.stretches.get_mut(next)?;
        // A whole run made when the move was planned.
        if let Source::Run(_) = s.source {
            let Source::Run(run) = core::mem::replace(&mut s.source, Source::Taken) else {
                return None;
            };
            s.count = 0;
            self.plan.next = next + 1;
            return Some(run);
        }
        let Source::At(at) = &mut s.source else {
            return None;
        };
        let ramp = if s.decel { &self.decel } else { &self.accel };
        // A held or segment table: one entry at a time. A compressed table:
        // one run at a time, played by the step path from `computed`
        // (behind an empty `Down` for any layout).
        self.computed = match *ramp {
            Ramp::Steps { .. } | Ramp::Segments(_) => {
                let (period, n) = at.take_entry(ramp, s.dir, s.count)?;
                s.count -= n;
                return Some(Run::Hold(*period, n));
            }
            Ramp::Runs(runs) => at.take_run(runs, s.dir, s.count),
            Ramp::Indexed(index) => at.take_run(index.runs(), s.dir, s.count),
        };
        s.count -= self.computed.left;
        Some(Run::Down([].iter()))
    }
}

#[cfg(test)]
mod tests {
    //! Tests of [`Player::next_period`]'s path against [`Player::step`]'s.

    extern crate std;
    use super::*;
    use crate::table::runs::RunIndex;
    use std::vec::Vec;

    /// How a player is played: by `next_period`, by `step`, or the two in
    /// turn.
    #[derive(Clone, Copy)]
    enum By {
        NextPeriod,
        Step,
        Alternating,
    }

    /// One move's periods, `by` one path or the other, the same planning calls
    /// at the same steps (a new cruise, a new target, a stop, a run and its
    /// stop, each where `calls` says), then a call past the end; with the steps
    /// left after each period.
    fn play<L: Layout>(mut player: Player<'_, u16, L>, by: By, calls: [u32; 4]) -> Vec<(u16, u32)> {
        let mut out = Vec::new();
        for (i, steps) in [40, 7, 1].into_iter().enumerate() {
            player.start(steps);
            if i == 2 {
                player.run();
            }
            for k in 0.. {
                match k {
                    _ if k == calls[0] => player.set_cruise(1),
                    _ if k == calls[1] => {
                        player.retarget(player.remaining() + 5);
                    }
                    _ if k == calls[2] && i == 0 => player.stop(),
                    _ if k == calls[3].min(50) && i == 2 => player.stop(),
                    _ => {}
                }
                let next = match (by, k % 2) {
                    (By::NextPeriod, _) | (By::Alternating, 0) => player.next_period(),
                    _ => {
                        let mut period = None;
                        let played = player.step(|p| period = Some(p));
                        assert_eq!(played, period.is_some());
                        period
                    }
                };
                match next {
                    Some(p) => out.push((p, player.remaining())),
                    None => break,
                }
            }
            // Past the end, again and again: nothing, either way.
            assert_eq!(player.next_period(), None);
            assert!(!player.step(|_| panic!("no period past the end")));
            assert_eq!(player.next_period(), None);
        }
        out
    }

    /// The three ways hand out the same periods, every layout, every call.
    fn same<L: Layout + Clone>(player: Player<'_, u16, L>) {
        for calls in [[u32::MAX; 4], [5, 12, 20, 30], [0, 1, 2, 3], [9, 3, 15, 60]] {
            let stepped = play(player.clone(), By::Step, calls);
            assert!(!stepped.is_empty());
            assert_eq!(play(player.clone(), By::NextPeriod, calls), stepped);
            assert_eq!(play(player.clone(), By::Alternating, calls), stepped);
        }
    }

    #[test]
    fn next_period_hands_out_what_step_does() {
        static STEPS: [u16; 6] = [5000, 4000, 3200, 2600, 2200, 2000];
        static DECEL: [u16; 3] = [4500, 3000, 2100];
        static SEGMENTS: [(u16, u16); 3] = [(4000, 3), (3000, 2), (2000, 4)];
        static RUNS: [[u16; 5]; 2] = [[3, 4000, 0x8000, 0xFE0C, 0], [2, 2000, 0, 0, 0]];
        static INDEX: RunIndex<2> = RunIndex::new(&RUNS);
        same(Player::new(Ramp::steps(&STEPS)));
        same(Player::new(Ramp::steps(&STEPS)).with_decel(Ramp::steps(&DECEL)));
        same(Player::new(Ramp::held(&STEPS, 3)));
        same(Player::new(Ramp::segments(&SEGMENTS)));
        same(Player::new(Ramp::runs(&RUNS)));
        same(Player::new(Ramp::runs(&RUNS)).with_decel(Ramp::steps(&DECEL)));
        same(Player::<u16, _>::new(&RUNS));
        same(Player::<u16, _>::new(&INDEX));
    }
}
