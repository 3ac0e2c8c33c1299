//! A move's exact step edges as a logic analyzer's reference, and a
//! capture of the pin compared with them.
//!
//! [`Reference::of`] plays a move of a profile's table with the player
//! firmware uses (`player::Player`, its deceleration the same table) and
//! keeps the time of every step edge, in the timer's ticks from the move's
//! first edge, each edge starting the period the player handed out with it
//! or ending it ([`Timing`]). [`Reference::vcd`] writes it as a VCD file that PulseView and
//! `sigrok-cli` read; [`Capture::parse`] reads a capture (VCD, or the CSV
//! `sigrok-cli -O csv` writes) and [`Capture::compare`] lines its step
//! channel up with the reference, first edge on first edge, and gives each
//! step's error in ticks.
//!
//! ```
//! use profile_codegen::capture::{Capture, Edges, Reference, Timing};
//! use profile_codegen::profiles::Profiles;
//!
//! let profiles = Profiles::parse(
//!     "ramps.toml",
//!     "[profiles.x]\ncurve = \"linear\"\nfmin = 500\nfmax = 2000\nlen = 20\ntimer_hz = \"1 MHz\"\n",
//! )?;
//! let reference = Reference::of(&profiles.profiles()[0], 50, None, Timing::Starts)?;
//! // The reference read back as a capture: every step at its tick.
//! let capture = Capture::parse(&reference.vcd())?;
//! let result = capture.compare(&reference, None, Edges::Rising, 0.5)?;
//! assert_eq!((result.steps(), result.largest(), result.first_out()), (50, 0.0, None));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod csv;
mod vcd;

use std::format;
use std::string::String;
use std::vec::Vec;

use crate::profiles::Profile;
use crate::table::computed::Generated;
use profile_core::TableWord;
use profile_core::player::{Layout, Player, Ramp};

/// A capture or a move that cannot be read or compared, in words.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CaptureError(pub String);

impl core::fmt::Display for CaptureError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CaptureError {}

fn error<T>(message: impl Into<String>) -> Result<T, CaptureError> {
    Err(CaptureError(message.into()))
}

/// Where a step's edge falls in the period the player hands out with it,
/// as the firmware makes it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Timing {
    /// The edge starts its period: a step interrupt that pulses the pin and
    /// then hands the timer the period after it (`Player::step`, the guide's
    /// firmware, the PIO and RMT examples): step `k` at the sum of the
    /// first `k` periods.
    #[default]
    Starts,
    /// The edge ends its period: a timer's compare output that toggles at
    /// the match, each period written before it starts (the ATmega328P
    /// client of `rigs/avr`): step `k` at the sum of the first `k + 1`.
    Ends,
}

/// A move's step edges, exact: what the player hands the timer, summed.
#[derive(Clone, Debug, PartialEq)]
pub struct Reference {
    /// The profile's name.
    pub name: String,
    /// The timer's rate, ticks per second.
    pub timer_hz: u32,
    /// Each step's period, in ticks (a step's timer intervals summed:
    /// `ticks_per_step` of them), as the player hands them out.
    pub periods: Vec<u64>,
    /// Where each edge falls in its period.
    pub timing: Timing,
    /// The move's steps, as asked (a stop plays fewer: one edge each of
    /// [`Reference::edges`]).
    pub steps: u32,
    /// The steps after which a stop was asked for, if one was.
    pub stop_at: Option<u32>,
    /// The driver's shortest pulse in ticks, where the profile names it:
    /// the pulse the VCD draws.
    pub pulse_ticks: Option<u32>,
}

impl Reference {
    /// The move of `steps` steps that `profile`'s table plays from rest
    /// (up the table, at its top, down the same table), stopped after
    /// `stop_at` steps when given: each step's period as the player hands
    /// it out, times the timer's ticks per step (its `reload_offset` not
    /// counted: the periods themselves), each edge where `timing` puts it.
    /// A segment table plays each segment's period its count of times.
    pub fn of(
        profile: &Profile,
        steps: u32,
        stop_at: Option<u32>,
        timing: Timing,
    ) -> Result<Self, CaptureError> {
        if steps == 0 {
            return error("a move of 0 steps has no edges: give `--move` 1 or more");
        }
        let periods = match &profile.table {
            Generated::Steps(t) => play(Player::new(Ramp::steps(&t.periods)), steps, stop_at),
            Generated::Segments(t) => play(Player::new(Ramp::segments(&t.pairs)), steps, stop_at),
            Generated::Runs(t) => play(Player::<u16, _>::new(&t.runs[..]), steps, stop_at),
        };
        let spec = profile.table.spec();
        let per = u64::from(spec.timer.ticks_per_step);
        let pulse_ticks = profile
            .driver
            .as_ref()
            .map(|d| d.ticks(d.step_pulse, &spec.timer));
        Ok(Reference {
            name: profile.name.clone(),
            timer_hz: spec.timer.timer_hz,
            periods: periods.iter().map(|&p| u64::from(p) * per).collect(),
            timing,
            steps,
            stop_at,
            pulse_ticks,
        })
    }

    /// The time of each step edge, in ticks from the first: one a step, the
    /// periods between them those that start at an edge (all but the last)
    /// or end at one (all but the first), as [`Reference::timing`] says.
    pub fn edges(&self) -> Vec<u64> {
        let between = match self.timing {
            Timing::Starts => &self.periods[..self.periods.len().saturating_sub(1)],
            Timing::Ends => self.periods.get(1..).unwrap_or(&[]),
        };
        let mut at = 0;
        let mut out = Vec::with_capacity(self.periods.len());
        out.push(0);
        for &p in between {
            at += p;
            out.push(at);
        }
        out
    }

    /// The move as a VCD file: the step pin `STEP` high at each step edge
    /// (for the driver's `step_pulse`, or half the shortest period without
    /// one, at least a tick), time 0 a pulse before the first, in the
    /// largest power-of-ten unit that holds every tick exactly (`1 ps`,
    /// rounded to it, where none does). Its header gives the move, the
    /// timer's rate and a tick in that unit. One 1-bit signal, as sigrok's
    /// VCD reader takes it.
    pub fn vcd(&self) -> String {
        vcd::write(self)
    }
}

/// Plays a move of `steps`, stopped after `stop_at`: every period.
fn play<W: TableWord, L: Layout>(
    mut player: Player<'_, W, L>,
    steps: u32,
    stop_at: Option<u32>,
) -> Vec<u32> {
    player.start(steps);
    let mut out = Vec::new();
    loop {
        if stop_at.is_some_and(|k| out.len() == k as usize) {
            player.stop();
        }
        match player.next_period() {
            Some(p) => out.push(p.into_ticks()),
            None => return out,
        }
    }
}

/// Which transitions of the step channel are steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edges {
    /// Low to high: a driver that steps on the rising edge.
    Rising,
    /// Both: a pin that toggles once a step (a timer's compare output; a
    /// driver that steps on both edges).
    Both,
}

/// A 1-bit channel of a capture: its level changes, in seconds from the
/// capture's start, each with the new level (changes from an unknown level
/// are not kept: the first known level is the channel's start).
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    /// Its name in the capture.
    pub name: String,
    /// The level at the start (the first known).
    pub initial: bool,
    /// Each change: the time in seconds and the new level.
    pub changes: Vec<(f64, bool)>,
}

/// A logic analyzer's capture: its 1-bit channels.
#[derive(Clone, Debug, PartialEq)]
pub struct Capture {
    /// The channels, in the order the capture declares them.
    pub channels: Vec<Channel>,
}

impl Capture {
    /// Reads a capture: a VCD file (any timescale, scopes, vectors
    /// skipped) or the CSV that `sigrok-cli -O csv` writes (one row a
    /// sample, the rate in its `META samplerate` or `; Samplerate` line,
    /// the channels named by its `; Channels` line or by a header row of
    /// names; a first column of times or sample numbers is skipped).
    pub fn parse(text: &str) -> Result<Self, CaptureError> {
        let trimmed = text.trim_start();
        if trimmed.starts_with('$') || text.contains("$enddefinitions") {
            vcd::read(text)
        } else {
            csv::read(text)
        }
    }

    /// The step channel: the one named `name`, or else the one whose name
    /// holds `step` (any case), or else the one that changes most.
    pub fn step_channel(&self, name: Option<&str>) -> Result<&Channel, CaptureError> {
        let names = || {
            self.channels
                .iter()
                .map(|c| format!("`{}`", c.name))
                .collect::<Vec<_>>()
                .join(", ")
        };
        if let Some(name) = name {
            return match self.channels.iter().find(|c| c.name == name) {
                Some(c) => Ok(c),
                None => error(format!(
                    "the capture has no channel `{name}`; its channels: {}",
                    names()
                )),
            };
        }
        let step = self
            .channels
            .iter()
            .find(|c| c.name.to_lowercase().contains("step"));
        match step.or_else(|| self.channels.iter().max_by_key(|c| c.changes.len())) {
            Some(c) => Ok(c),
            None => error("the capture has no 1-bit channel"),
        }
    }

    /// The step channel's steps (`channel`, or found as
    /// [`Capture::step_channel`] finds it) against `reference`: the first
    /// step edge on the reference's first, each later one's error in ticks
    /// of the reference's timer; `tolerance` in ticks.
    pub fn compare(
        &self,
        reference: &Reference,
        channel: Option<&str>,
        edges: Edges,
        tolerance: f64,
    ) -> Result<Comparison, CaptureError> {
        let channel = self.step_channel(channel)?;
        let steps: Vec<f64> = channel
            .changes
            .iter()
            .filter(|&&(_, high)| edges == Edges::Both || high)
            .map(|&(t, _)| t)
            .collect();
        let Some(&first) = steps.first() else {
            return error(format!(
                "the channel `{}` has no step edges ({})",
                channel.name,
                match edges {
                    Edges::Rising => "no rising edge: try `--edges both` for a pin that toggles",
                    Edges::Both => "it never changes",
                }
            ));
        };
        let hz = f64::from(reference.timer_hz);
        let want = reference.edges();
        // To a millionth of a tick: a capture's times are decimal fractions
        // of a second, its ticks rarely whole in binary (and a zero is +0).
        let micro = |x: f64| libm::round(x * 1e6) / 1e6 + 0.0;
        let errors: Vec<f64> = steps
            .iter()
            .zip(&want)
            .map(|(&t, &w)| micro((t - first) * hz - w as f64))
            .collect();
        Ok(Comparison {
            channel: channel.name.clone(),
            reference: want,
            captured: steps.iter().map(|&t| micro((t - first) * hz)).collect(),
            errors,
            tolerance,
        })
    }
}

/// A capture's steps against a reference's.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// The step channel compared.
    pub channel: String,
    /// The reference's step edges, ticks from its first.
    pub reference: Vec<u64>,
    /// The capture's step edges, ticks from its first (all of them, more
    /// than the reference's when the capture goes on).
    pub captured: Vec<f64>,
    /// Each step's error, captured minus reference, in ticks (to a
    /// millionth), for the steps both have.
    pub errors: Vec<f64>,
    /// The tolerance, ticks.
    pub tolerance: f64,
}

impl Comparison {
    /// The steps compared: those both have.
    pub fn steps(&self) -> usize {
        self.errors.len()
    }

    /// The largest error, in ticks (absolute).
    pub fn largest(&self) -> f64 {
        self.errors.iter().fold(0.0, |m, e| f64::max(m, e.abs()))
    }

    /// The first step whose error passes the tolerance.
    pub fn first_out(&self) -> Option<usize> {
        self.errors.iter().position(|e| e.abs() > self.tolerance)
    }

    /// The reference's steps the capture lacks.
    pub fn missing(&self) -> usize {
        self.reference.len().saturating_sub(self.captured.len())
    }

    /// The capture's step edges past the reference's last.
    pub fn extra(&self) -> usize {
        self.captured.len().saturating_sub(self.reference.len())
    }

    /// Every step within the tolerance and none missing.
    pub fn passes(&self) -> bool {
        self.first_out().is_none() && self.missing() == 0
    }

    /// The summary: steps compared, the largest error and where, the first
    /// step out of tolerance, steps missing or extra.
    pub fn summary(&self) -> String {
        let at = self
            .errors
            .iter()
            .position(|e| e.abs() == self.largest())
            .unwrap_or(0);
        let mut out = format!(
            "{} steps compared on `{}`: the largest error {:.3} ticks, at step {at}; ",
            self.steps(),
            self.channel,
            self.largest()
        );
        out.push_str(&match self.first_out() {
            Some(k) => format!(
                "step {k} is the first out of the tolerance of {} ticks ({:+.3})",
                self.tolerance, self.errors[k]
            ),
            None => format!(
                "every step within the tolerance of {} ticks",
                self.tolerance
            ),
        });
        if self.missing() > 0 {
            out.push_str(&format!(
                "; the capture ends {} steps short of the move",
                self.missing()
            ));
        }
        if self.extra() > 0 {
            out.push_str(&format!(
                "; {} more step edges after the move, not compared",
                self.extra()
            ));
        }
        out
    }

    /// Every step compared, a line each: the step, the reference's tick,
    /// the captured tick, the error.
    pub fn table(&self) -> String {
        let mut out = String::from("step  reference  captured  error (ticks)\n");
        for (k, e) in self.errors.iter().enumerate() {
            out.push_str(&format!(
                "{k:>4} {:>10} {:>9.3} {e:>+8.3}{}\n",
                self.reference[k],
                self.captured[k],
                if e.abs() > self.tolerance {
                    "  out"
                } else {
                    ""
                }
            ));
        }
        out
    }
}

impl core::fmt::Display for Comparison {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(&self.summary())
    }
}
