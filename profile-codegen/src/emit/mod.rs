//! The one emitter: what a compiled table becomes in Rust and in C.
//!
//! This module holds what both languages share: [`Profile`], a table under
//! its name with its motor and torque figures; the figures every output
//! carries (the constants of a profile module, the `#define`s of a header);
//! [`doc_lines`], the lines that describe a table in docs and comments; and
//! [`start_note`], the remark on a table that starts far above `fmin`. Its
//! modules write the languages: [`rust`], tokens for the macros and for
//! build-script files alike; [`print`], those tokens as source text; [`c`],
//! a header (or a header and a source file) with the tables and the move
//! players.

use std::format;
use std::string::{String, ToString};
use std::vec;
use std::vec::Vec;

use crate::driver::Driver;
use crate::motor::{Motor, TorqueFigures};
use crate::numbers::Fixed;
use crate::pipeline::Compiled;
use crate::schema::describe;
use crate::table::computed::Generated;
use profile_core::Discretization;

pub mod c;
pub mod print;
pub mod rust;

/// A named table, as declared in `profiles.toml`.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    /// The profile's name: a Rust identifier, the module's name.
    pub name: String,
    /// Its table.
    pub table: Generated,
    /// Where its motor has the least torque to spare, when it names one.
    pub torque: Option<TorqueFigures>,
    /// The motor it drives, when it names one: for plots and simulations
    /// ([`Motor::check_with`](crate::motor::Motor::check_with),
    /// [`simulate::run`](crate::simulate::run)).
    pub motor: Option<Motor>,
    /// The step driver it plays into, when it names one: its times, in
    /// the table's ticks, are constants of the module and `#define`s of
    /// the C header.
    pub driver: Option<Driver>,
    /// The step interrupt's core and clock, when it names them: the report
    /// prints the CPU's load at the top speed.
    pub cpu: Option<crate::cpu::Cpu>,
    /// The speed bands it stays out of, when it names them: the report
    /// prints the time the ramp spends in each.
    pub avoid: Option<crate::bands::Bands>,
    /// Its emergency ramp, when it names one (`emergency` in a profiles
    /// file): the module's `STOP_STEPS` and the C header's
    /// `NAME_STOP_STEPS`.
    pub emergency: Option<Emergency>,
}

/// A profile's emergency ramp: another profile of its file, which
/// `Player::abort` plays down from the current speed.
#[derive(Clone, Debug, PartialEq)]
pub struct Emergency {
    /// The emergency ramp's profile.
    pub profile: String,
    /// For each step of the profile's ramp, the steps an abort plays when
    /// that step is the last played: the emergency ramp from its last
    /// step not shorter than that step, down to its first (0 when the
    /// motor already runs slower than every step of it).
    pub stop_steps: Vec<u32>,
}

impl Profile {
    /// A compiled table under its name.
    pub(crate) fn new(name: String, compiled: Compiled) -> Self {
        Profile {
            name,
            table: compiled.table,
            torque: compiled.torque,
            motor: compiled.motor,
            driver: compiled.driver,
            cpu: compiled.cpu,
            avoid: compiled.avoid,
            emergency: None,
        }
    }
}

/// A figure of a table, as a constant of its module and a `#define` in C.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Constant {
    pub(crate) name: &'static str,
    pub(crate) value: Number,
    pub(crate) doc: &'static str,
}

/// A constant's value and its type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Number {
    U8(u8),
    I32(i32),
    U32(u32),
    U64(u64),
    Usize(u64),
    /// Always finite: the pipeline refuses a table whose figures are not.
    F64(f64),
}

/// The figures of a table: the constants of a profile module and the
/// `#define`s of a C header.
pub(crate) fn constants(profile: &Profile) -> Vec<Constant> {
    let table = &profile.table;
    let spec = table.spec();
    let mut c = vec![
        Constant {
            name: "TIMER_HZ",
            value: Number::U32(spec.timer.timer_hz),
            doc: "Timer tick rate after the prescaler, in Hz.",
        },
        Constant {
            name: "TICKS_PER_STEP",
            value: Number::U8(spec.timer.ticks_per_step),
            doc: "Timer reloads per step (2: each entry is a half period).",
        },
        Constant {
            name: "RELOAD_OFFSET",
            value: Number::I32(spec.reload_offset),
            doc: "Added to every period the table stores (-1: the period less one, as an \
                  `ARR`-style reload register holds it); the figures are the periods'.",
        },
    ];
    match table {
        Generated::Steps(t) => {
            let f = &t.figures;
            c.extend([
                Constant {
                    name: "LEN",
                    value: Number::Usize(f.len.into()),
                    doc: "Entries in `PERIODS`: steps of the ramp.",
                },
                Constant {
                    name: "TOTAL_TICKS",
                    value: Number::U64(f.total_ticks),
                    doc: "Sum of the periods, in ticks.",
                },
                Constant {
                    name: "FIRST_TICKS",
                    value: Number::U32(f.first_ticks),
                    doc: "First (slowest) period, in ticks.",
                },
                Constant {
                    name: "LAST_TICKS",
                    value: Number::U32(f.last_ticks),
                    doc: "Last (fastest) period, in ticks.",
                },
                Constant {
                    name: "DURATION_S",
                    value: Number::F64(f.duration_s),
                    doc: "Ramp duration as played, in s.",
                },
                Constant {
                    name: "START_HZ",
                    value: Number::F64(f.start_hz),
                    doc: "Step frequency of the first entry, in Hz.",
                },
                Constant {
                    name: "FINAL_HZ",
                    value: Number::F64(f.final_hz),
                    doc: "Step frequency of the last entry, in Hz.",
                },
            ]);
        }
        Generated::Segments(t) => c.extend(compact_constants(&t.figures)),
        Generated::Runs(t) => c.extend(compact_constants(&t.figures)),
    }
    if let Some(t) = &profile.torque {
        c.extend(torque_constants(t));
    }
    if let Some(d) = &profile.driver {
        c.extend(driver_constants(d, &spec.timer));
    }
    c
}

/// A profile's bands as the periods that play in them, stored as its table
/// stores periods, when it names bands: what both emitters write.
pub(crate) fn avoid_periods(profile: &Profile) -> Option<Vec<(u32, u32)>> {
    let spec = profile.table.spec();
    Some(profile.avoid?.periods(&spec.timer, spec.reload_offset))
}

/// The step driver's times in ticks of the table's timer, rounded up.
fn driver_constants(d: &Driver, timer: &profile_core::Timer) -> [Constant; 3] {
    let ticks = |s: f64| Number::U32(d.ticks(s, timer));
    [
        Constant {
            name: "STEP_PULSE_TICKS",
            value: ticks(d.step_pulse),
            doc: "The driver's shortest STEP high time, in ticks (rounded up).",
        },
        Constant {
            name: "STEP_SPACE_TICKS",
            value: ticks(d.step_space),
            doc: "The driver's shortest STEP low time, in ticks (rounded up).",
        },
        Constant {
            name: "DIR_SETUP_TICKS",
            value: ticks(d.dir_setup),
            doc: "Ticks (rounded up) from a change of DIR to the step edge that takes it, at \
                  least: set the direction pin that long before a move's first step.",
        },
    ]
}

/// Where a motor has the least torque to spare.
fn torque_constants(t: &TorqueFigures) -> [Constant; 2] {
    [
        Constant {
            name: "TORQUE_MARGIN_NM",
            value: Number::F64(t.min_margin_nm),
            doc: "Smallest torque the motor has to spare over the ramp, in N·m.",
        },
        Constant {
            name: "TORQUE_MARGIN_STEP",
            value: Number::Usize(t.step.into()),
            doc: "The step where the torque margin is smallest.",
        },
    ]
}

/// The figures of a compact layout: a segment table, or a compressed one
/// (with its largest edge error).
fn compact_constants(f: &profile_core::CompactFigures) -> Vec<Constant> {
    let runs = f.tolerance_ticks.is_some();
    let (count, entries, len, ticks) = if runs {
        (
            "RUN_COUNT",
            "Entries in `RUNS`.",
            "Steps of the ramp: the sum of the runs' counts.",
            "Sum of the periods the runs play, in ticks.",
        )
    } else {
        (
            "SEGMENT_COUNT",
            "Entries in `SEGMENTS`.",
            "Steps of the ramp: the sum of the segments' counts.",
            "Sum of period times count, in ticks.",
        )
    };
    let mut c = Vec::from([
        Constant {
            name: count,
            value: Number::Usize(f.entries.into()),
            doc: entries,
        },
        Constant {
            name: "LEN",
            value: Number::Usize(f.steps.into()),
            doc: len,
        },
        Constant {
            name: "TOTAL_TICKS",
            value: Number::U64(f.total_ticks),
            doc: ticks,
        },
        Constant {
            name: "DURATION_S",
            value: Number::F64(f.duration_s),
            doc: "Ramp duration as played, in s.",
        },
    ]);
    if runs {
        c.push(Constant {
            name: "MAX_EDGE_ERROR_TICKS",
            value: Number::F64(f.max_edge_error_ticks),
            doc: "Largest distance of a played pulse edge from the curve's, in ticks.",
        });
    }
    c
}

/// Markdown lines describing a table: parameters and figures.
pub fn doc_lines(table: &Generated) -> std::vec::Vec<String> {
    let spec = table.spec();
    let mut lines = std::vec![
        "| parameter | value |".to_string(),
        "| --- | --- |".to_string(),
    ];
    for (key, value) in describe(spec) {
        lines.push(format!("| `{key}` | {value} |"));
    }
    lines.push(String::new());
    match table {
        Generated::Steps(t) => {
            let f = &t.figures;
            lines.push(format!(
                "{} entries, {} to {} ticks ({:.2} Hz to {:.2} Hz), {} ticks in all ({:.6} s); \
                 step edges within {:.3} tick of the unrounded curve, drift {:.3} tick; \
                 acceleration up to {} Hz/s between windows long enough that rounding reads \
                 under 5% of the curve's acceleration (the curve's own peak: {} Hz/s).",
                f.len,
                f.first_ticks,
                f.last_ticks,
                f.start_hz,
                f.final_hz,
                f.total_ticks,
                f.duration_s,
                f.max_edge_error_ticks,
                f.total_error_ticks,
                Fixed(f.max_accel_hz_s, 0),
                Fixed(f.curve_max_accel_hz_s, 0)
            ));
            if let Some(note) = start_note(table) {
                lines.push(String::new());
                lines.push(format!("Note: {note}"));
            }
        }
        Generated::Segments(t) => {
            let f = &t.figures;
            lines.push(format!(
                "{} segments for {} steps, {} bytes instead of {} per step; {} ticks in all \
                 ({:.6} s); pulse edges within {:.1} ticks of the curve.",
                f.entries,
                f.steps,
                f.flash_bytes,
                f.per_step_flash_bytes,
                f.total_ticks,
                f.duration_s,
                f.max_edge_error_ticks
            ));
        }
        Generated::Runs(t) => {
            // Runs are always fitted to a tolerance (`Some`).
            let f = &t.figures;
            lines.push(format!(
                "{} runs for {} steps, {} bytes instead of {} per step; {} ticks in all \
                 ({:.6} s); pulse edges within {:.3} ticks of the curve (`compress = {}`).",
                f.entries,
                f.steps,
                f.flash_bytes,
                f.per_step_flash_bytes,
                f.total_ticks,
                f.duration_s,
                f.max_edge_error_ticks,
                f.tolerance_ticks.unwrap_or(0.0)
            ));
        }
    }
    lines
}

/// How far above `fmin` a table may start before it is worth saying.
const START_NOTE_RATIO: f64 = 1.5;

/// A sentence for a per-step table whose first entry is far above the
/// curve's `fmin`, or `None`. An exact table's first period is the time the
/// curve takes for the first step, which a fast start covers well above
/// `fmin`; an index table's first entry is the curve at index 0.
pub fn start_note(table: &Generated) -> Option<String> {
    let Generated::Steps(t) = table else {
        return None;
    };
    let (fmin, _) = t.spec.curve.frequencies();
    let start = t.figures.start_hz;
    if !(fmin > 0.0 && start >= START_NOTE_RATIO * fmin) {
        return None;
    }
    let fmin_text = crate::schema::units::show(profile_core::Key::FMIN, fmin);
    let (start, ratio) = (Fixed(start, 1), Fixed(start / fmin, 1));
    let why = match t.spec.discretization {
        Discretization::Exact => format!(
            "the curve starts at `fmin` but covers the first step at {start} Hz on \
             average (`discretization = exact`); `discretization = left_endpoint` starts \
             at `fmin` itself"
        ),
        d => format!(
            "the curve is already at {start} Hz where the first step begins \
             (`discretization = {}`)",
            d.name()
        ),
    };
    Some(format!(
        "the first entry runs at {start} Hz, {ratio} times `fmin` = {fmin_text}: {why}."
    ))
}
