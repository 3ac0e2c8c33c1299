//! The moves: each is played through [`step_interrupt`] and checked step by
//! step against [`Model`], a plain reading of the tables, and as a whole
//! against the figures the macros emit.

use cortex_m::peripheral::SYST;
use cortex_m_semihosting::hprintln;
use stepper_profiles::player::{Axis, Buffered, Direction, Player, Ramp};

use crate::profiles::{
    exponential_segments, linear_estop, linear_exact, microstep_runs, sigmoid_exact, sigmoid_orange,
};
use crate::step::{self, Players, Stepper};
use crate::{DECEL, Report};

/// A ramp as the reference model reads it.
#[derive(Clone, Copy)]
pub enum Table<'a> {
    /// One entry per `hold` steps.
    Steps(&'a [u16], u32),
    /// `(period, steps)` per segment.
    Segments(&'a [(u16, u16)]),
    /// Compressed runs `[count, interval_hi, interval_lo, add_hi, add_lo]`.
    Runs(&'a [[u16; 5]]),
}

/// Edge `j` of a run that starts at the 16.16 remainder `frac`, in 16.16
/// ticks from the run's start, in closed form: `frac + j·interval +
/// add·j(j-1)/2` (period `j` is the difference of the whole ticks of edges
/// `j + 1` and `j`).
fn run_edge(run: &[u16; 5], frac: i64, j: i64) -> i64 {
    let interval = (i64::from(run[1]) << 16) | i64::from(run[2]);
    let add = i64::from(((u32::from(run[3]) << 16) | u32::from(run[4])) as i32);
    frac + j * interval + add * j * (j - 1) / 2
}

impl<'a> Table<'a> {
    /// The same ramp for the player.
    pub fn ramp(self) -> Ramp<'a, u16> {
        match self {
            Table::Steps(periods, 1) => Ramp::steps(periods),
            Table::Steps(periods, hold) => Ramp::held(periods, hold),
            Table::Segments(pairs) => Ramp::segments(pairs),
            Table::Runs(runs) => Ramp::runs(runs),
        }
    }

    /// Steps from rest to the top of the ramp.
    fn len_steps(self) -> u32 {
        match self {
            Table::Steps(periods, hold) => periods.len() as u32 * hold,
            Table::Segments(pairs) => pairs.iter().map(|&(_, n)| u32::from(n)).sum(),
            Table::Runs(runs) => runs.iter().map(|r| u32::from(r[0])).sum(),
        }
    }

    /// Period of step `pos` along the ramp (0 = slowest).
    fn at(self, pos: u32) -> u16 {
        match self {
            Table::Steps(periods, hold) => periods[(pos / hold) as usize],
            Table::Segments(pairs) => {
                let mut start = 0;
                for &(period, n) in pairs {
                    start += u32::from(n);
                    if pos < start {
                        return period;
                    }
                }
                panic!("step {} is past the segment table", pos)
            }
            Table::Runs(runs) => {
                // The first run starts half a tick in.
                let (mut frac, mut start) = (1i64 << 15, 0u32);
                for run in runs {
                    let count = u32::from(run[0]);
                    if pos < start + count {
                        let j = i64::from(pos - start);
                        let period =
                            (run_edge(run, frac, j + 1) >> 16) - (run_edge(run, frac, j) >> 16);
                        return period as u16;
                    }
                    frac = run_edge(run, frac, i64::from(count)) & 0xFFFF;
                    start += count;
                }
                panic!("step {} is past the runs", pos)
            }
        }
    }
}

/// Something that happens before a step of a move.
#[derive(Clone, Copy)]
pub enum Event {
    /// `Player::set_cruise(pos)`.
    Cruise(u32),
    /// `Player::stop()`.
    Stop,
    /// `Player::retarget(steps)`: the move ends `steps` periods later.
    Retarget(u32),
    /// `Player::run()`: the move goes on without an end, a lap of 2^31
    /// steps at a time.
    Run,
    /// `Axes::move_to(target)` while moving: a stop, then a straight line
    /// to `target`.
    Target([i64; 3]),
    /// `Axes::queue(target)`: a line joined at speed to the one before.
    Queue([i64; 3]),
    /// `Player::abort()`: a stop along the emergency ramp.
    Abort,
}

/// The move as the player's contract describes it, read off the tables with
/// no cursor. The acceleration ramp plays at its position (which walks one
/// step per step towards the cruise position), no faster than the
/// deceleration ramp's fastest entry, until the deceleration ramp at the
/// steps that remain is within reach and not faster; from then on the
/// deceleration ramp plays to the end. Both play exactly as their tables read.
pub struct Model<'a> {
    accel: Table<'a>,
    decel: Table<'a>,
    /// The emergency ramp an abort plays, if any.
    pub emergency: Option<Table<'a>>,
    pos: u32,
    cruise: u32,
    remaining: u32,
    last: u16,
    decelerating: bool,
    decel_fastest: u16,
}

impl<'a> Model<'a> {
    pub fn new(accel: Table<'a>, decel: Table<'a>, steps: u32) -> Self {
        let top = accel.len_steps() - 1;
        let decel_fastest = (0..decel.len_steps())
            .map(|p| decel.at(p))
            .min()
            .unwrap_or(0);
        Model {
            accel,
            decel,
            emergency: None,
            pos: 0,
            cruise: top,
            remaining: steps,
            last: 0,
            decelerating: false,
            decel_fastest,
        }
    }

    /// Applies `event`; for a stop, `chosen` is the player's steps remaining
    /// after it. Returns `false` when the player's choice breaks the contract.
    pub fn apply(&mut self, event: Event, chosen: u32) -> bool {
        match event {
            Event::Cruise(pos) => {
                self.cruise = pos.min(self.accel.len_steps() - 1);
                true
            }
            // On, cruising: the same walk, to a farther end (the
            // scenarios retarget and run only before the deceleration).
            Event::Retarget(steps) => {
                self.remaining = steps;
                chosen == steps
            }
            Event::Run => {
                self.remaining = 1 << 31;
                chosen == 1 << 31
            }
            // The axes' new target: their player's stop, checked as a stop.
            Event::Target(_) => self.apply(Event::Stop, chosen),
            // A line queued: the axes' own rules, not this model's.
            Event::Queue(_) => true,
            // An abort: a stop on the emergency ramp, which plays from
            // then on when it shortens the move (else the move's own
            // deceleration stays).
            Event::Abort => match self.emergency.take() {
                None => self.apply(Event::Stop, chosen),
                Some(emergency) => {
                    let kept = (self.decel, self.decel_fastest);
                    self.decel = emergency;
                    self.decel_fastest = (0..emergency.len_steps())
                        .map(|p| emergency.at(p))
                        .min()
                        .unwrap_or(0);
                    let remaining = self.remaining;
                    let ok = self.apply(Event::Stop, chosen);
                    if chosen >= remaining {
                        (self.decel, self.decel_fastest) = kept;
                    }
                    ok
                }
            },
            Event::Stop if self.last == 0 => {
                self.remaining = 0;
                chosen == 0
            }
            Event::Stop if self.decel.at(0) < self.last => {
                // Already slower than the ramp's slowest entry: at rest now.
                self.remaining = 0;
                chosen == 0
            }
            Event::Stop => {
                // The deceleration ramp is entered at an entry not faster than
                // the current period whose next entry is faster (or at its
                // top). Diffused tables are not monotone (156, 157, 156, ...),
                // so several entries may qualify; the player's search picks
                // one, and a stop never lengthens the move.
                let top = self.decel.len_steps() - 1;
                let boundary = |pos: u32| {
                    self.decel.at(pos) >= self.last
                        && (pos == top || self.decel.at(pos + 1) < self.last)
                };
                let ok = if chosen < self.remaining {
                    chosen > 0 && boundary(chosen - 1)
                } else {
                    chosen == self.remaining && (self.remaining - 1..=top).any(boundary)
                };
                if chosen < self.remaining {
                    self.decelerating = true;
                }
                self.remaining = chosen;
                ok
            }
        }
    }

    pub fn next(&mut self) -> Option<u16> {
        if self.remaining == 0 {
            return None;
        }
        let last = self.decel.len_steps() - 1;
        let after = self.remaining - 1;
        self.remaining = after;
        let pd = self.decel.at(after.min(last));
        let period = if self.decelerating {
            pd
        } else {
            let pa = self.accel.at(self.pos);
            if after <= last && pd >= pa {
                self.decelerating = true;
                pd
            } else if after > last && self.decel_fastest > pa {
                pd
            } else {
                if self.pos < self.cruise {
                    self.pos += 1;
                } else if self.pos > self.cruise {
                    self.pos -= 1;
                }
                pa
            }
        };
        self.last = period;
        Some(period)
    }
}

/// A move: ramps, length and events (`(step index, event)`, in order).
pub struct Move<'a> {
    /// Printed in the summary.
    pub name: &'a str,
    /// Acceleration ramp.
    pub accel: Table<'a>,
    /// Deceleration ramp.
    pub decel: Table<'a>,
    /// Steps asked of `Player::start`.
    pub steps: u32,
    /// Events before given steps.
    pub events: &'static [(u32, Event)],
    /// Played by `Player::new(&RUNS)` (both ramps are runs), else by
    /// `Player::new(..).with_decel(..)`.
    pub compressed: bool,
    /// Played by a `Buffered<Axis>` at the first position, moved to the
    /// second (`steps` apart).
    pub axis: Option<(i64, i64)>,
    /// The emergency ramp (`Player::with_emergency`) an `Event::Abort`
    /// plays.
    pub emergency: Option<Table<'a>>,
}

/// What a move amounted to.
#[derive(Clone, Copy, Default)]
pub struct Played {
    /// Steps played.
    pub steps: u32,
    /// Sum of the periods, in ticks.
    pub ticks: u64,
    /// Period of the last step: the speed the move ends at.
    pub last: u16,
    /// Shortest period: the top speed reached.
    pub min: u16,
    /// Steps whose period differs from the model's.
    pub mismatches: u32,
    /// `true` when the step after each stop was not faster than the step
    /// before it, and each stop entered the deceleration ramp as the
    /// player's contract says.
    pub stop_ok: bool,
}

/// Plays `m` from the step interrupt and compares every step with the model.
pub fn play(
    m: &Move<'static>,
    timer: SYST,
    log: &'static mut [u16; step::MAX_STEPS],
    report: &mut Report,
) -> (Played, SYST, &'static mut [u16; step::MAX_STEPS]) {
    let player = match (m.compressed, m.accel, m.decel) {
        _ if m.axis.is_some() => {
            let (from, to) = m.axis.unwrap_or_default();
            let player = Player::new(m.accel.ramp()).with_decel(m.decel.ramp());
            Players::Axis(Buffered::new(Axis::new(player, from)), to)
        }
        (true, Table::Runs(a), Table::Runs(d)) => {
            Players::Compressed(Buffered::new(Player::new(a).with_decel(d)))
        }
        _ => {
            let player = Player::new(m.accel.ramp()).with_decel(m.decel.ramp());
            Players::Any(Buffered::new(match m.emergency {
                Some(emergency) => player.with_emergency(emergency.ramp()),
                None => player,
            }))
        }
    };
    let s = step::run(Stepper::new(player, timer, m.events, log), m.steps);
    // The model, step by step, with the events where the handler applied them.
    let mut model = Model::new(m.accel, m.decel, m.steps);
    model.emergency = m.emergency;
    let mut out = Played {
        min: u16::MAX,
        stop_ok: true,
        ..Played::default()
    };
    let mut stopped = false;
    for (k, &got) in s.log[..s.steps.min(step::MAX_STEPS)].iter().enumerate() {
        for (i, &(_, event)) in m.events.iter().enumerate().filter(|(_, e)| e.0 == k as u32) {
            out.stop_ok &= model.apply(event, s.after_events[i]);
            stopped |= matches!(event, Event::Stop | Event::Abort);
        }
        let want = model.next();
        if Some(got) != want {
            if out.mismatches == 0 {
                hprintln!(
                    "FAIL {}: step {}: player {}, model {:?}",
                    m.name,
                    k,
                    got,
                    want
                );
            }
            out.mismatches += 1;
        }
        if stopped && out.steps > 0 && got < out.last {
            out.stop_ok = false;
        }
        stopped = false;
        out.steps += 1;
        out.ticks += u64::from(got);
        out.last = got;
        out.min = out.min.min(got);
    }
    if model.next().is_some() {
        out.mismatches += 1;
    }
    report.equal(m.name, u64::from(out.mismatches), 0);
    report.equal(
        "player done after the move",
        u64::from(s.player.is_done()),
        1,
    );
    report.equal(
        "a step pin toggle per step",
        u64::from(s.toggles),
        u64::from(out.steps),
    );
    check_axis(m, &s.player, out.steps, report);
    check_pin(
        m.name,
        &s.log[..s.steps.min(step::MAX_STEPS)],
        s.taken,
        report,
    );
    if m.axis.is_some() {
        check_turns(m.name, s.taken, report);
    }
    hprintln!(
        "  {:<34} {:>6} steps {:>9} ticks  top {:>5}  end {:>5}",
        m.name,
        out.steps,
        out.ticks,
        out.min,
        out.last
    );
    (out, s.timer, s.log)
}

/// An axis's move: at its target after the move, having turned the way
/// from its start to the target, one position per step.
fn check_axis(m: &Move<'static>, player: &Players, steps: u32, report: &mut Report) {
    let (Some((from, to)), Some((position, direction))) = (m.axis, player.axis()) else {
        return;
    };
    let want = if to < from {
        Direction::Backward
    } else {
        Direction::Forward
    };
    report.equal("axis position after the move", position as u64, to as u64);
    report.equal("axis direction", (direction == want).into(), 1);
    report.equal("axis steps", steps.into(), from.abs_diff(to));
}

/// The driver's `dir_setup` at the pins: every change of the direction
/// pins at least [`step::DIR_SETUP_TICKS`] before the step that takes it
/// (the clock read after the write, the step's stamp before its pulse), and
/// every step pulsed with its own direction on the pins. Prints the changes:
/// the one before the first step (the start waits `dir_setup`) and those
/// of reversals while moving (a whole period of the ramp's slowest entry).
pub fn check_turns(name: &str, taken: usize, report: &mut Report) {
    let (mut start, mut turns, mut shortest, mut first_short) = (None, 0u32, u32::MAX, None);
    let wrong = step::turns(taken, |k, setup| {
        if k == 0 {
            start = Some(setup);
        } else {
            turns += 1;
            shortest = shortest.min(setup);
        }
        if setup < step::DIR_SETUP_TICKS {
            first_short.get_or_insert((k, setup));
        }
    });
    if let Some((k, setup)) = first_short {
        hprintln!(
            "FAIL {}: the direction pins changed {} ticks before step {} ({} needed)",
            name,
            setup,
            k,
            step::DIR_SETUP_TICKS
        );
    }
    report.equal(
        "direction changes too late for dir_setup",
        first_short.map_or(0, |_| 1),
        0,
    );
    report.equal("steps pulsed in the wrong direction", u64::from(wrong), 0);
    match start {
        Some(setup) => hprintln!(
            "  {:<34} DIR set {} ticks before the first step (dir_setup {})",
            name,
            setup,
            step::DIR_SETUP_TICKS
        ),
        None => hprintln!("  {:<34} DIR unchanged at the start", name),
    }
    if turns > 0 {
        hprintln!(
            "  {:<34} DIR turned {} time(s) while moving, at least {} ticks before its step",
            name,
            turns,
            shortest
        );
    }
}

/// Every step, timed at the pin by the clock the player does not drive: step
/// `k` at the sum of the first `k` periods loaded, from the move's start,
/// exact to the tick; one step per period.
pub fn check_pin(name: &str, loaded: &[u16], taken: usize, report: &mut Report) {
    report.equal("steps timed at the pin", taken as u64, loaded.len() as u64);
    let (mut expected, mut off, mut first) = (0u64, 0u32, None);
    step::step_times(taken, |k, time| {
        if u64::from(time) != expected * u64::from(step::CLOCK_PER_TICK) {
            off += 1;
            first.get_or_insert((k, u64::from(time), expected));
        }
        expected += u64::from(loaded.get(k).copied().unwrap_or(0));
    });
    if let Some((k, time, want)) = first {
        let per = u64::from(step::CLOCK_PER_TICK);
        hprintln!(
            "FAIL {}: step {} at {}/{} ticks, expected {}",
            name,
            k,
            time,
            per,
            want
        );
    }
    report.equal("steps off their time at the pin", off.into(), 0);
}

fn sum(periods: &[u16]) -> u64 {
    periods.iter().map(|&p| u64::from(p)).sum()
}

/// Ticks of a ramp played while the other side of the player holds `floor`:
/// entries faster than `floor` are played at `floor`.
fn floored(periods: &[u16], floor: u16) -> u64 {
    periods.iter().map(|&p| u64::from(p.max(floor))).sum()
}

/// What a move must amount to.
#[derive(Clone, Copy)]
struct Expect {
    /// Steps played, at least and at most.
    steps: (u32, u32),
    /// Sum of the periods, when it follows from the emitted figures.
    ticks: Option<u64>,
    /// The top speed's period, when it is known.
    top: Option<u16>,
    /// The period the move ends at: the deceleration ramp's slowest entry.
    end: u16,
    /// Whether the move stops, and so must enter the ramp as the contract says.
    stops: bool,
}

/// A move and what it must amount to.
struct Scenario<'a> {
    play: Move<'a>,
    expect: Expect,
}

impl Expect {
    /// Exactly `steps` steps of `ticks` ticks, ending at rest at `end`.
    fn exact(steps: u32, ticks: u64, end: u16) -> Self {
        Expect {
            steps: (steps, steps),
            ticks: Some(ticks),
            top: None,
            end,
            stops: false,
        }
    }
}

/// Every move the firmware plays, with what it must amount to: a
/// trapezoid, a triangle, stops, a held ramp, the diffused default table,
/// an asymmetric move, cruise changes, a segment table and compressed runs
/// played by both players.
fn scenarios() -> [Scenario<'static>; 20] {
    // Monotone tables first: the C-compatible orange S-curve (truncated, so
    // its periods never rise).
    let o: &'static [u16] = &sigmoid_orange::PERIODS;
    let (len, top, rest) = (
        sigmoid_orange::LEN as u32,
        sigmoid_orange::LAST_TICKS as u16,
        sigmoid_orange::FIRST_TICKS as u16,
    );
    let orange = Table::Steps(o, 1);
    let mv = |name, accel, decel, steps, events| Move {
        name,
        accel,
        decel,
        steps,
        events,
        compressed: false,
        axis: None,
        emergency: None,
    };
    // The default mode: diffused rounding keeps every pulse edge within half
    // a tick, so the table is not monotone near the top (156, 157, 156, ...);
    // the player still plays it exactly as written.
    let a: &'static [u16] = &sigmoid_exact::PERIODS;
    let (a_len, a_top, a_rest) = (
        sigmoid_exact::LEN as u32,
        sigmoid_exact::LAST_TICKS as u16,
        sigmoid_exact::FIRST_TICKS as u16,
    );
    let a_ticks = sigmoid_exact::TOTAL_TICKS;
    let exact = Table::Steps(a, 1);
    // Stop while accelerating the orange ramp: down from the speed reached.
    let (at, half, hold) = (300u32, 300u32, 4u32);
    let reached = o[at as usize - 1];
    let down = o.iter().rposition(|&x| x >= reached).unwrap_or(0) as u32 + 1;
    // Asymmetric: up the S-curve no faster than DECEL's fastest entry, cruise,
    // then DECEL backwards.
    let (d_min, d_len) = (DECEL.iter().copied().min().unwrap_or(0), DECEL.len() as u32);
    let asymmetric = match a.iter().position(|&x| x < d_min) {
        Some(cap) => {
            sum(&a[..cap])
                + u64::from(2000 - cap as u32 - d_len) * u64::from(DECEL[DECEL.len() - 1])
                + sum(&DECEL)
        }
        None => {
            sum(a) + u64::from(2000 - a_len - d_len) * u64::from(a_top) + floored(&DECEL, a_top)
        }
    };
    // Cruise changes: slow down to entry 500 while cruising, then back up:
    // up, top, walk down 500 entries, cruise at entry 500, walk up, top, down.
    let (slow, at_slow, at_fast, steps) = (500u32, 1500u32, 3000u32, 6000u32);
    let walk = a_len - slow;
    let at_500 = at_fast - at_slow - walk;
    let at_top = steps - 2 * a_len - 2 * walk - at_500;
    let cruises = 2 * a_ticks
        + 2 * sum(&a[slow as usize..])
        + u64::from(at_500) * u64::from(a[slow as usize])
        + u64::from(at_top) * u64::from(a_top);
    // Segment table: 8 (period, count) pairs for the 120-step exponential ramp.
    let pairs: &'static [(u16, u16)] = &exponential_segments::SEGMENTS;
    let segments = Table::Segments(pairs);
    let s_len = exponential_segments::LEN as u32;
    let fastest = pairs[exponential_segments::SEGMENT_COUNT - 1].0;
    // Compressed runs: the 1/16-step ramp, 97 runs for 7 192 steps.
    let runs = Table::Runs(&microstep_runs::RUNS);
    let r_len = microstep_runs::LEN as u32;
    let r_top = (0..r_len).map(|p| runs.at(p)).min().unwrap_or(0);
    let runs_move = Expect {
        top: Some(r_top),
        ..Expect::exact(
            2 * r_len + 200,
            2 * microstep_runs::TOTAL_TICKS + 200 * u64::from(r_top),
            runs.at(0),
        )
    };
    let runs_stop = Expect {
        steps: (STOP_RUNS_AT + 1, 2 * r_len),
        ticks: None,
        top: None,
        end: runs.at(0),
        stops: true,
    };
    [
        Scenario {
            play: mv(
                "trapezoid (sigmoid_orange)",
                orange,
                orange,
                2 * len + 3000,
                &[],
            ),
            expect: Expect {
                top: Some(top),
                ..Expect::exact(
                    2 * len + 3000,
                    2 * sigmoid_orange::TOTAL_TICKS + 3000 * u64::from(top),
                    rest,
                )
            },
        },
        // Too short to reach the top: the ramps cross in the middle.
        Scenario {
            play: mv(
                "triangle (sigmoid_orange)",
                orange,
                orange,
                2 * half + 1,
                &[],
            ),
            expect: Expect {
                top: Some(o[half as usize]),
                ..Expect::exact(
                    2 * half + 1,
                    2 * sum(&o[..half as usize]) + u64::from(o[half as usize]),
                    rest,
                )
            },
        },
        Scenario {
            play: mv(
                "stop while accelerating (orange)",
                orange,
                orange,
                100_000,
                &[(300, Event::Stop)],
            ),
            expect: Expect {
                stops: true,
                ..Expect::exact(
                    at + down,
                    sum(&o[..at as usize]) + sum(&o[..down as usize]),
                    rest,
                )
            },
        },
        // Every entry of the orange table held for 4 steps (a divider).
        Scenario {
            play: mv(
                "held x4 (sigmoid_orange)",
                Table::Steps(o, hold),
                Table::Steps(o, hold),
                2 * len * hold + 1000,
                &[],
            ),
            expect: Expect::exact(
                2 * len * hold + 1000,
                2 * u64::from(hold) * sigmoid_orange::TOTAL_TICKS + 1000 * u64::from(top),
                rest,
            ),
        },
        Scenario {
            play: mv(
                "trapezoid (sigmoid_exact)",
                exact,
                exact,
                2 * a_len + 3000,
                &[],
            ),
            expect: Expect::exact(
                2 * a_len + 3000,
                2 * a_ticks + 3000 * u64::from(a_top),
                a_rest,
            ),
        },
        // S-curve up, constant deceleration (DECEL) down.
        Scenario {
            play: mv(
                "asymmetric (sigmoid_exact, DECEL)",
                exact,
                Table::Steps(&DECEL, 1),
                2000,
                &[],
            ),
            expect: Expect::exact(2000, asymmetric, DECEL[0]),
        },
        // Stop while cruising: down the whole ramp from the top.
        Scenario {
            play: mv(
                "stop while cruising (exact)",
                exact,
                exact,
                100_000,
                &[(2500, Event::Stop)],
            ),
            expect: Expect {
                stops: true,
                ..Expect::exact(
                    2500 + a_len,
                    2 * a_ticks + u64::from(2500 - a_len) * u64::from(a_top),
                    a_rest,
                )
            },
        },
        // Stop while accelerating, where the table is not monotone: the player
        // may enter the ramp at any entry that qualifies (the model checks it).
        Scenario {
            play: mv(
                "stop while accelerating (exact)",
                exact,
                exact,
                100_000,
                &[(400, Event::Stop)],
            ),
            expect: Expect {
                steps: (401, 400 + a_len),
                ticks: None,
                top: None,
                end: a_rest,
                stops: true,
            },
        },
        Scenario {
            play: mv(
                "cruise changes (999 -> 500 -> 999)",
                exact,
                exact,
                steps,
                &[(1500, Event::Cruise(500)), (3000, Event::Cruise(999))],
            ),
            expect: Expect::exact(steps, cruises, a_rest),
        },
        // A new end while cruising: 5000 steps, at step 2500 the move is
        // to end 4000 steps later, 6500 in all.
        Scenario {
            play: mv(
                "a farther end while cruising (5000 -> 6500)",
                exact,
                exact,
                5000,
                &[(2500, Event::Retarget(4000))],
            ),
            expect: Expect::exact(
                6500,
                2 * a_ticks + u64::from(6500 - 2 * a_len) * u64::from(a_top),
                a_rest,
            ),
        },
        // A jog: at step 1200 the move no longer ends; a stop at step 6000
        // decelerates it to rest from the top.
        Scenario {
            play: mv(
                "a run, then a stop (a jog)",
                exact,
                exact,
                3000,
                &[(1200, Event::Run), (6000, Event::Stop)],
            ),
            expect: Expect {
                steps: (6001, 6000 + a_len),
                ticks: None,
                top: None,
                end: a_rest,
                stops: true,
            },
        },
        // A cancel: at step 600, cruising, an abort plays the emergency
        // ramp from the top, its `STOP_STEPS` at the top: every entry.
        Scenario {
            play: Move {
                emergency: Some(Table::Steps(&linear_estop::PERIODS, 1)),
                ..mv(
                    "abort while cruising (linear_exact, emergency linear_estop)",
                    Table::Steps(&linear_exact::PERIODS, 1),
                    Table::Steps(&linear_exact::PERIODS, 1),
                    2000,
                    &[(600, Event::Abort)],
                )
            },
            expect: Expect {
                stops: true,
                ..Expect::exact(
                    600 + u32::from(linear_exact::STOP_STEPS[linear_exact::LEN - 1]),
                    linear_exact::TOTAL_TICKS
                        + 400 * u64::from(linear_exact::LAST_TICKS)
                        + linear_estop::TOTAL_TICKS,
                    linear_estop::PERIODS[0],
                )
            },
        },
        // An axis through `Buffered`: to 2500 from 0 (forward), then from
        // there to -1500 (backward).
        Scenario {
            play: Move {
                axis: Some((0, 2500)),
                ..mv("axis forward (0 -> 2500)", exact, exact, 2500, &[])
            },
            expect: Expect::exact(2500, 2 * a_ticks + 500 * u64::from(a_top), a_rest),
        },
        Scenario {
            play: Move {
                axis: Some((2500, -1500)),
                ..mv("axis backward (2500 -> -1500)", exact, exact, 4000, &[])
            },
            expect: Expect::exact(4000, 2 * a_ticks + 2000 * u64::from(a_top), a_rest),
        },
        Scenario {
            play: mv(
                "segments (exponential_segments)",
                segments,
                segments,
                2 * s_len + 200,
                &[],
            ),
            expect: Expect::exact(
                2 * s_len + 200,
                2 * exponential_segments::TOTAL_TICKS + 200 * u64::from(fastest),
                pairs[0].0,
            ),
        },
        Scenario {
            play: mv(
                "segments, stop while accelerating",
                segments,
                segments,
                10_000,
                &[(60, Event::Stop)],
            ),
            expect: Expect {
                steps: (61, 10_000),
                ticks: None,
                top: None,
                end: pairs[0].0,
                stops: true,
            },
        },
        Scenario {
            play: Move {
                compressed: true,
                ..mv(RUNS_MOVE, runs, runs, 2 * r_len + 200, &[])
            },
            expect: runs_move,
        },
        Scenario {
            play: mv(
                "runs, Player::new(Ramp::runs)",
                runs,
                runs,
                2 * r_len + 200,
                &[],
            ),
            expect: runs_move,
        },
        Scenario {
            play: Move {
                compressed: true,
                ..mv(
                    "compressed, stop accelerating",
                    runs,
                    runs,
                    2 * r_len,
                    &[(STOP_RUNS_AT, Event::Stop)],
                )
            },
            expect: runs_stop,
        },
        Scenario {
            play: mv(
                "runs, stop while accelerating",
                runs,
                runs,
                2 * r_len,
                &[(STOP_RUNS_AT, Event::Stop)],
            ),
            expect: runs_stop,
        },
    ]
}

/// Where the compressed ramp's moves stop while accelerating. The stop is
/// planned in the step interrupt, which must end within the step it runs
/// in for the next to be on time at the pin: on this emulated core (one
/// instruction a nanosecond, 40 per tick) step 7000's 211 ticks are 8440
/// instructions, and the stop on runs by the player of either layout ends
/// within them (the pin's check).
const STOP_RUNS_AT: u32 = 7000;

/// The move whose accelerating edges are also checked against the curve.
const RUNS_MOVE: &str = "runs, compressed Player";

/// Every accelerating pulse edge of the compressed move against the exact
/// curve's, computed here on the target: within the `compress` the table
/// was built for.
fn check_edges(log: &[u16], report: &mut Report) {
    let spec = crate::regen::microstep_spec();
    report.equal(
        "microstep_runs timer",
        spec.timer.timer_hz.into(),
        microstep_runs::TIMER_HZ.into(),
    );
    let scale = spec.timer.frequency_scale();
    let (mut played, mut worst, mut edges) = (0u64, 0.0f64, 0u32);
    let result = spec.for_each_exact_edge(|k, t| {
        if let Some(&p) = log.get(k as usize - 1) {
            played += u64::from(p);
            let error = played as f64 - t * scale;
            worst = worst.max(if error < 0.0 { -error } else { error });
            edges += 1;
        }
    });
    report.equal("exact edges of microstep_runs", result.is_ok().into(), 1);
    report.equal("edges checked", edges.into(), microstep_runs::LEN as u64);
    let bound = microstep_runs::MAX_EDGE_ERROR_TICKS;
    report.check(
        worst <= bound,
        "largest edge error, millitick",
        (worst * 1000.0) as u64,
        (bound * 1000.0) as u64,
    );
    hprintln!(
        "  {:<34} {:>6} edges, largest error {} millitick (bound {})",
        "runs against the exact curve",
        edges,
        (worst * 1000.0) as u32,
        (bound * 1000.0) as u32
    );
}

/// Plays every move from the step interrupt and checks what it amounts to;
/// hands back the timer and the log of periods.
pub fn run(mut timer: SYST, report: &mut Report) -> (SYST, &'static mut [u16; step::MAX_STEPS]) {
    hprintln!("moves (ticks of each table's timer):");
    report.equal(
        "sigmoid_exact ramp = TOTAL_TICKS",
        sum(&sigmoid_exact::PERIODS),
        sigmoid_exact::TOTAL_TICKS,
    );
    step::init_clock();
    let mut log = cortex_m::singleton!(: [u16; step::MAX_STEPS] = [0; step::MAX_STEPS])
        .expect("the log is taken once");
    for Scenario { play: m, expect } in scenarios() {
        let (p, t, l) = play(&m, timer, log, report);
        (timer, log) = (t, l);
        let (lo, hi) = expect.steps;
        report.check(
            (lo..=hi).contains(&p.steps),
            m.name,
            p.steps.into(),
            hi.into(),
        );
        if let Some(ticks) = expect.ticks {
            report.equal(m.name, p.ticks, ticks);
        }
        if let Some(top) = expect.top {
            report.equal(m.name, p.min.into(), top.into());
        }
        report.equal(m.name, p.last.into(), expect.end.into());
        if expect.stops {
            report.equal(m.name, p.stop_ok.into(), 1);
        }
        if m.name == RUNS_MOVE {
            check_edges(
                &log[..p.steps.min(microstep_runs::LEN as u32) as usize],
                report,
            );
        }
    }
    // Tables from both front ends agree.
    report.equal(
        "period_table! == include_profiles! (sigmoid_orange)",
        u64::from(*core::hint::black_box(&crate::SEED) == sigmoid_orange::PERIODS),
        1,
    );
    (timer, log)
}
