//! The moves: each is played through [`step_interrupt`] and checked step by
//! step against [`Model`], a plain reading of the tables, and as a whole
//! against the figures the macros emit.

use cortex_m::peripheral::SYST;
use cortex_m_semihosting::hprintln;
use stepper_profiles::player::{Player, Ramp};

use crate::profiles::{exponential_segments, sigmoid_exact, sigmoid_orange};
use crate::{DECEL, Report, step_interrupt};

/// A ramp as the reference model reads it.
#[derive(Clone, Copy)]
pub enum Table<'a> {
    /// One entry per `hold` steps.
    Steps(&'a [u16], u32),
    /// `(period, steps)` per segment.
    Segments(&'a [(u16, u16)]),
}

impl<'a> Table<'a> {
    /// The same ramp for the player.
    pub fn ramp(self) -> Ramp<'a, u16> {
        match self {
            Table::Steps(periods, 1) => Ramp::steps(periods),
            Table::Steps(periods, hold) => Ramp::held(periods, hold),
            Table::Segments(pairs) => Ramp::segments(pairs),
        }
    }

    /// Steps from rest to the top of the ramp.
    fn len_steps(self) -> u32 {
        match self {
            Table::Steps(periods, hold) => periods.len() as u32 * hold,
            Table::Segments(pairs) => pairs.iter().map(|&(_, n)| u32::from(n)).sum(),
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
}

/// The move as the player's contract describes it, read off the tables with
/// no cursor. The acceleration ramp plays at its position (which walks one
/// step per step towards the cruise position), no faster than the
/// deceleration ramp's fastest entry, until the deceleration ramp at the
/// steps that remain is within reach and not faster; from then on the
/// deceleration ramp plays to the end. Both play exactly as their tables read.
struct Model<'a> {
    accel: Table<'a>,
    decel: Table<'a>,
    pos: u32,
    cruise: u32,
    remaining: u32,
    last: u16,
    decelerating: bool,
    decel_fastest: u16,
}

impl<'a> Model<'a> {
    fn new(accel: Table<'a>, decel: Table<'a>, steps: u32) -> Self {
        let top = accel.len_steps() - 1;
        let decel_fastest = (0..decel.len_steps())
            .map(|p| decel.at(p))
            .min()
            .unwrap_or(0);
        Model {
            accel,
            decel,
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
    fn apply(&mut self, event: Event, chosen: u32) -> bool {
        match event {
            Event::Cruise(pos) => {
                self.cruise = pos.min(self.accel.len_steps() - 1);
                true
            }
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

    fn next(&mut self) -> Option<u16> {
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
    pub events: &'a [(u32, Event)],
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

/// Plays `m` through the step interrupt and compares every step with the model.
pub fn play(m: &Move<'_>, timer: &mut SYST, report: &mut Report) -> Played {
    let mut player = Player::with_decel(m.accel.ramp(), m.decel.ramp());
    let mut model = Model::new(m.accel, m.decel, m.steps);
    player.start(m.steps);
    let mut out = Played {
        min: u16::MAX,
        stop_ok: true,
        ..Played::default()
    };
    let mut stopped = false;
    let mut k = 0u32;
    loop {
        for &(_, event) in m.events.iter().filter(|&&(at, _)| at == k) {
            match event {
                Event::Cruise(pos) => player.set_cruise(pos),
                Event::Stop => {
                    player.stop();
                    stopped = true;
                }
            }
            out.stop_ok &= model.apply(event, player.remaining());
        }
        let got = step_interrupt(&mut player, timer);
        let want = model.next();
        if got != want {
            if out.mismatches == 0 {
                hprintln!(
                    "FAIL {}: step {}: player {:?}, model {:?}",
                    m.name,
                    k,
                    got,
                    want
                );
            }
            out.mismatches += 1;
        }
        let Some(period) = got else { break };
        if stopped && out.steps > 0 && period < out.last {
            out.stop_ok = false;
        }
        stopped = false;
        out.steps += 1;
        out.ticks += u64::from(period);
        out.last = period;
        out.min = out.min.min(period);
        k += 1;
        if k > m.steps {
            break;
        }
    }
    report.equal(m.name, u64::from(out.mismatches), 0);
    report.equal("player done after the move", u64::from(player.is_done()), 1);
    hprintln!(
        "  {:<34} {:>6} steps {:>9} ticks  top {:>5}  end {:>5}",
        m.name,
        out.steps,
        out.ticks,
        out.min,
        out.last
    );
    out
}

fn sum(periods: &[u16]) -> u64 {
    periods.iter().map(|&p| u64::from(p)).sum()
}

/// Ticks of a ramp played while the other side of the player holds `floor`:
/// entries faster than `floor` are played at `floor`.
fn floored(periods: &[u16], floor: u16) -> u64 {
    periods.iter().map(|&p| u64::from(p.max(floor))).sum()
}

/// Plays every move and checks the figures.
pub fn run(timer: &mut SYST, report: &mut Report) {
    hprintln!("moves (ticks of each table's timer):");

    // Monotone tables first: the C-compatible orange S-curve (truncated, so
    // its periods never rise) played as a trapezoid and as a triangle.
    let o = &sigmoid_orange::PERIODS;
    let len = sigmoid_orange::LEN as u32;
    let top = sigmoid_orange::LAST_TICKS as u16;
    let rest = sigmoid_orange::FIRST_TICKS as u16;
    let orange = Table::Steps(o, 1);
    let cruise = 3000;
    let p = play(
        &Move {
            name: "trapezoid (sigmoid_orange)",
            accel: orange,
            decel: orange,
            steps: 2 * len + cruise,
            events: &[],
        },
        timer,
        report,
    );
    report.equal("trapezoid steps", p.steps.into(), (2 * len + cruise).into());
    report.equal(
        "trapezoid ticks = 2 TOTAL_TICKS + cruise LAST_TICKS",
        p.ticks,
        2 * sigmoid_orange::TOTAL_TICKS + u64::from(cruise) * u64::from(top),
    );
    report.equal("trapezoid top speed", p.min.into(), top.into());
    report.equal("trapezoid ends at rest", p.last.into(), rest.into());

    // Triangle: too short to reach the top; the ramps cross in the middle.
    let half = 300;
    let p = play(
        &Move {
            name: "triangle (sigmoid_orange)",
            accel: orange,
            decel: orange,
            steps: 2 * half + 1,
            events: &[],
        },
        timer,
        report,
    );
    report.equal("triangle steps", p.steps.into(), (2 * half + 1).into());
    report.equal(
        "triangle ticks",
        p.ticks,
        2 * sum(&o[..half as usize]) + u64::from(o[half as usize]),
    );
    report.equal("triangle top speed", p.min.into(), o[half as usize].into());
    report.equal("triangle ends at rest", p.last.into(), rest.into());

    // Stop while accelerating: down the ramp from the speed reached.
    let at = 300;
    let p = play(
        &Move {
            name: "stop while accelerating (orange)",
            accel: orange,
            decel: orange,
            steps: 100_000,
            events: &[(at, Event::Stop)],
        },
        timer,
        report,
    );
    let reached = o[at as usize - 1];
    let down = o.iter().rposition(|&x| x >= reached).unwrap_or(0) as u32 + 1;
    report.equal("stop: steps", p.steps.into(), (at + down).into());
    report.equal(
        "stop: ticks",
        p.ticks,
        sum(&o[..at as usize]) + sum(&o[..down as usize]),
    );
    report.equal("stop ends at rest", p.last.into(), rest.into());
    report.equal("stop enters the ramp", p.stop_ok.into(), 1);

    // Held ramp: every entry of the orange table for 4 steps (a divider).
    let hold = 4;
    let held = Table::Steps(o, hold);
    let cruise = 1000;
    let ramp = len * hold;
    let p = play(
        &Move {
            name: "held x4 (sigmoid_orange)",
            accel: held,
            decel: held,
            steps: 2 * ramp + cruise,
            events: &[],
        },
        timer,
        report,
    );
    report.equal("held steps", p.steps.into(), (2 * ramp + cruise).into());
    report.equal(
        "held ticks = 2 hold TOTAL_TICKS + cruise LAST_TICKS",
        p.ticks,
        2 * u64::from(hold) * sigmoid_orange::TOTAL_TICKS + u64::from(cruise) * u64::from(top),
    );
    report.equal("held ends at rest", p.last.into(), rest.into());

    // The default mode: diffused rounding keeps every pulse edge within half
    // a tick, so the table is not monotone near the top (156, 157, 156, ...);
    // the player still plays it exactly as written.
    let a = &sigmoid_exact::PERIODS;
    let len = sigmoid_exact::LEN as u32;
    let top = sigmoid_exact::LAST_TICKS as u16;
    let rest = sigmoid_exact::FIRST_TICKS as u16;
    let exact = Table::Steps(a, 1);
    let ramp_ticks = sigmoid_exact::TOTAL_TICKS;
    report.equal("sigmoid_exact ramp = TOTAL_TICKS", sum(a), ramp_ticks);
    let cruise = 3000;
    let p = play(
        &Move {
            name: "trapezoid (sigmoid_exact)",
            accel: exact,
            decel: exact,
            steps: 2 * len + cruise,
            events: &[],
        },
        timer,
        report,
    );
    report.equal("trapezoid steps", p.steps.into(), (2 * len + cruise).into());
    report.equal(
        "trapezoid ticks = 2 TOTAL_TICKS + cruise LAST_TICKS",
        p.ticks,
        2 * ramp_ticks + u64::from(cruise) * u64::from(top),
    );
    report.equal("trapezoid ends at rest", p.last.into(), rest.into());

    // Asymmetric: S-curve up, constant deceleration (DECEL) down.
    let steps = 2000;
    let d_top = DECEL[DECEL.len() - 1];
    let p = play(
        &Move {
            name: "asymmetric (sigmoid_exact, DECEL)",
            accel: exact,
            decel: Table::Steps(&DECEL, 1),
            steps,
            events: &[],
        },
        timer,
        report,
    );
    // Up the S-curve no faster than DECEL's fastest entry, cruise, then
    // DECEL backwards.
    let d_min = DECEL.iter().copied().min().unwrap_or(0);
    let d_len = DECEL.len() as u32;
    let expected = match a.iter().position(|&x| x < d_min) {
        Some(cap) => {
            sum(&a[..cap]) + u64::from(steps - cap as u32 - d_len) * u64::from(d_top) + sum(&DECEL)
        }
        None => sum(a) + u64::from(steps - len - d_len) * u64::from(top) + floored(&DECEL, top),
    };
    report.equal("asymmetric steps", p.steps.into(), steps.into());
    report.equal("asymmetric ticks", p.ticks, expected);
    report.equal("asymmetric ends at rest", p.last.into(), DECEL[0].into());

    // Stop while cruising: down the whole ramp from the top.
    let at = 2500;
    let p = play(
        &Move {
            name: "stop while cruising (exact)",
            accel: exact,
            decel: exact,
            steps: 100_000,
            events: &[(at, Event::Stop)],
        },
        timer,
        report,
    );
    report.equal(
        "stop while cruising: steps",
        p.steps.into(),
        (at + len).into(),
    );
    report.equal(
        "stop while cruising: ticks",
        p.ticks,
        2 * ramp_ticks + u64::from(at - len) * u64::from(top),
    );
    report.equal(
        "stop while cruising ends at rest",
        p.last.into(),
        rest.into(),
    );
    report.equal("stop while cruising enters the ramp", p.stop_ok.into(), 1);

    // Stop while accelerating, where the table is not monotone: the player
    // may enter the ramp at any entry that qualifies (the model checks it).
    let at = 400;
    let p = play(
        &Move {
            name: "stop while accelerating (exact)",
            accel: exact,
            decel: exact,
            steps: 100_000,
            events: &[(at, Event::Stop)],
        },
        timer,
        report,
    );
    report.check(
        p.steps > at && p.steps <= at + len,
        "stop while accelerating: steps",
        p.steps.into(),
        (at + len).into(),
    );
    report.equal(
        "stop while accelerating ends at rest",
        p.last.into(),
        rest.into(),
    );
    report.equal(
        "stop while accelerating enters the ramp",
        p.stop_ok.into(),
        1,
    );

    // Cruise changes: slow down to entry 500 while cruising, then back up.
    let (slow, at_slow, at_fast, steps) = (500u32, 1500u32, 3000u32, 6000u32);
    let p = play(
        &Move {
            name: "cruise changes (999 -> 500 -> 999)",
            accel: exact,
            decel: exact,
            steps,
            events: &[
                (at_slow, Event::Cruise(slow)),
                (at_fast, Event::Cruise(len - 1)),
            ],
        },
        timer,
        report,
    );
    // Up, top, walk down 500 entries, cruise at entry 500, walk up, top, down.
    let walk = len - slow;
    let at_500 = at_fast - at_slow - walk;
    let at_top = steps - 2 * len - 2 * walk - at_500;
    report.equal("cruise changes: steps", p.steps.into(), steps.into());
    report.equal(
        "cruise changes: ticks",
        p.ticks,
        2 * ramp_ticks
            + 2 * sum(&a[slow as usize..])
            + u64::from(at_500) * u64::from(a[slow as usize])
            + u64::from(at_top) * u64::from(top),
    );
    report.equal("cruise changes end at rest", p.last.into(), rest.into());

    // Segment table: 8 (period, count) pairs for the 120-step exponential ramp.
    let pairs = &exponential_segments::SEGMENTS;
    let segments = Table::Segments(pairs);
    let ramp = exponential_segments::LEN as u32;
    let cruise = 200;
    let p = play(
        &Move {
            name: "segments (exponential_segments)",
            accel: segments,
            decel: segments,
            steps: 2 * ramp + cruise,
            events: &[],
        },
        timer,
        report,
    );
    let fastest = u64::from(pairs[exponential_segments::SEGMENT_COUNT - 1].0);
    report.equal("segments steps", p.steps.into(), (2 * ramp + cruise).into());
    report.equal(
        "segments ticks = 2 TOTAL_TICKS + cruise last period",
        p.ticks,
        2 * exponential_segments::TOTAL_TICKS + u64::from(cruise) * fastest,
    );
    report.equal("segments ends at rest", p.last.into(), pairs[0].0.into());

    // Segment table, stopped while accelerating.
    let p = play(
        &Move {
            name: "segments, stop while accelerating",
            accel: segments,
            decel: segments,
            steps: 10_000,
            events: &[(60, Event::Stop)],
        },
        timer,
        report,
    );
    report.equal(
        "segments stop ends at rest",
        p.last.into(),
        pairs[0].0.into(),
    );
    report.equal("segments stop enters the ramp", p.stop_ok.into(), 1);

    // Tables from both front ends agree.
    report.equal(
        "period_table! == include_profiles! (sigmoid_orange)",
        u64::from(*core::hint::black_box(&crate::SEED) == sigmoid_orange::PERIODS),
        1,
    );
}
