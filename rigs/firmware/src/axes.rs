//! Three axes on one ramp, from the step interrupt: `Buffered<Axes>` hands
//! the handler, per interrupt, the pins that step on the edge now starting
//! and the period to load next; the handler toggles those pins and the
//! clock stamps the edge.
//!
//! Checked here against a reading of its own: the lead's periods against
//! [`Model`] (the tables as the player's contract reads them), every edge
//! of the lead at the sum of the periods loaded before it ([`check_pin`]),
//! and every edge of every axis at the time of the lead's step the rule
//! names: an axis of `d` steps of the lead's `L` takes its `k`-th step on
//! the lead's step `floor((2kL + d) / 2d)`, computed here in 64 bits. The
//! pins' levels at the end are the parity of their toggles.

use cortex_m::peripheral::SYST;
use cortex_m_semihosting::hprintln;
use stepper_profiles::player::{Axes, Buffered, Player};

use crate::Report;
use crate::moves::{Event, Model, Table, check_pin, check_turns};
use crate::profiles::{linear_exact, sigmoid_exact};
use crate::step::{self, Players, Stepper};

/// A move of the three axes.
struct AxesMove {
    name: &'static str,
    /// Steps on each axis (negative: backward).
    delta: [i64; 3],
    /// Events on the lead's steps; a new target (`Event::Target`) stops the
    /// axes and moves them there in a straight line.
    events: &'static [(u32, Event)],
}

const MOVES: [AxesMove; 3] = [
    AxesMove {
        name: "3 axes (2500, -1234, 2999)",
        delta: [2500, -1234, 2999],
        events: &[],
    },
    AxesMove {
        name: "3 axes, stop while cruising",
        delta: [-4000, 4000, 777],
        events: &[(1800, Event::Stop)],
    },
    AxesMove {
        name: "3 axes, a new target while cruising",
        delta: [3000, -2000, 1000],
        events: &[(1500, Event::Target([-700, 900, 1400]))],
    },
];

/// Plays every move of the three axes and checks each edge.
pub fn run(
    mut timer: SYST,
    mut log: &'static mut [u16; step::MAX_STEPS],
    report: &mut Report,
) -> SYST {
    hprintln!("three axes on one ramp (sigmoid_exact), from the step interrupt:");
    for m in &MOVES {
        (timer, log) = play(m, timer, log, report);
    }
    polyline(timer, log, report)
}

/// The polyline's vertices from (0, 0, 0): four lines bending by a few
/// degrees, no axis reversing.
const VERTICES: [[i64; 3]; 4] = [
    [600, 200, -130],
    [1200, 470, -230],
    [1800, 600, -400],
    [2400, 870, -470],
];

/// The lines after the first, queued at the move's first interrupt.
const QUEUED: [(u32, Event); 3] = [
    (2, Event::Queue(VERTICES[1])),
    (2, Event::Queue(VERTICES[2])),
    (2, Event::Queue(VERTICES[3])),
];

/// A queued polyline (`Buffered<Axes>::queue`, junction deviation 4
/// steps) on `linear_exact` (500 Hz to 5 kHz): each line's edges at the
/// times and on the lead's steps its own rule names, from its vertex; every
/// edge at the sum of the periods before it; the interior vertices passed
/// at speed (the lead's period there shorter than the ramp's slowest
/// entry); the axes at the last vertex. The step at a vertex plans the next
/// line in the interrupt (3270 to 4763 instructions on the M3,
/// `docs/performance.md`): its period must be longer, as it is here (a
/// vertex at the S-curve's 64 kHz is not: its edge comes late).
fn polyline(timer: SYST, log: &'static mut [u16; step::MAX_STEPS], report: &mut Report) -> SYST {
    let name = "3 axes, a queued polyline of 4 lines";
    let table = Table::Steps(&linear_exact::PERIODS, 1);
    let axes = Axes::new(Player::new(table.ramp()), [0; 3]).with_junction_deviation(4.0);
    let pins_before = step::step_pins();
    let s = step::run(
        Stepper::new(
            Players::Axes(Buffered::new(axes), VERTICES[0]),
            timer,
            &QUEUED,
            log,
        ),
        0,
    );
    let loaded = &s.log[..s.steps.min(step::MAX_STEPS)];
    let (mut from, mut first, mut toggles) = ([0i64; 3], 0usize, [0u32; 3]);
    let mut joined = 0u32;
    for (k, vertex) in VERTICES.iter().enumerate() {
        let delta = [0, 1, 2].map(|i| vertex[i] - from[i]);
        let steps = delta.map(|d| d.unsigned_abs());
        let lead = steps.iter().copied().max().unwrap_or(0) as usize;
        let line = Line {
            first,
            end: first + lead,
            steps,
            events: &[],
        };
        let more = check_line(name, table, &line, loaded, &[], false, report);
        for i in 0..3 {
            toggles[i] += more[i];
        }
        // Each interior vertex at speed: the line's last period shorter
        // than the ramp's slowest entry.
        if k + 1 < VERTICES.len() && loaded.get(line.end - 1) < Some(&linear_exact::PERIODS[0]) {
            joined += 1;
        }
        (from, first) = (*vertex, line.end);
    }
    report.equal("polyline edges", s.taken as u64, first as u64);
    report.equal("polyline vertices joined at speed", joined.into(), 3);
    check_pin(name, loaded, s.taken, report);
    check_turns(name, s.taken, report);
    check_end(&s.player, VERTICES[3], toggles, pins_before, report);
    report.equal("axes done after the polyline", s.player.is_done().into(), 1);
    hprintln!(
        "  {:<40} {:>6} edges, {} of 3 vertices joined at speed",
        name,
        s.taken,
        joined
    );
    s.timer
}

/// The axes at the end of a move: at `want` at the pins, each step pin at
/// the parity of its `toggles` since `pins_before`.
fn check_end(
    player: &Players,
    want: [i64; 3],
    toggles: [u32; 3],
    pins_before: u32,
    report: &mut Report,
) {
    let position = player.axes_position();
    let pins_now = step::step_pins() ^ pins_before;
    for i in 0..3 {
        report.check(
            position[i] == want[i],
            "axis position at the pins",
            position[i] as u64,
            want[i] as u64,
        );
        report.equal(
            "axis pin level",
            u64::from(pins_now >> i & 1),
            u64::from(toggles[i] & 1),
        );
    }
}

/// One straight line of a move: its edges `first..end`, each axis's
/// steps, and the events on its lead from its first edge.
struct Line<'e> {
    first: usize,
    end: usize,
    steps: [u64; 3],
    events: &'e [(u32, Event)],
}

/// Where the rule has taken each axis of a line of `steps` after the
/// lead's first `n` steps, signed.
fn rule_positions(steps: &[u64; 3], signs: &[i64; 3], n: usize) -> [i64; 3] {
    let lead = steps.iter().copied().max().unwrap_or(0);
    [0, 1, 2].map(|i| {
        let d = steps[i];
        let taken = (1..=d)
            .take_while(|&k| ((2 * k * lead + d) / (2 * d)) as usize <= n)
            .count();
        signs[i] * taken as i64
    })
}

fn play(
    m: &AxesMove,
    timer: SYST,
    log: &'static mut [u16; step::MAX_STEPS],
    report: &mut Report,
) -> (SYST, &'static mut [u16; step::MAX_STEPS]) {
    let table = Table::Steps(&sigmoid_exact::PERIODS, 1);
    let axes = Axes::new(Player::new(table.ramp()), [0; 3]);
    let pins_before = step::step_pins();
    let s = step::run(
        Stepper::new(
            Players::Axes(Buffered::new(axes), m.delta),
            timer,
            m.events,
            log,
        ),
        0,
    );
    let loaded = &s.log[..s.steps.min(step::MAX_STEPS)];
    let taken = s.taken.min(step::MAX_STEPS);
    let (steps, signs) = (m.delta.map(|d| d.unsigned_abs()), m.delta.map(i64::signum));
    // A new target: the first line ends where its stop ends (the periods
    // loaded before it and the stop's), the second goes on from there.
    let target = m
        .events
        .iter()
        .enumerate()
        .find_map(|(i, &(at, e))| match e {
            Event::Target(t) => Some((i, at, t)),
            _ => None,
        });
    let first_end = target.map_or(taken, |(i, at, _)| at as usize + s.after_events[i] as usize);
    let first = Line {
        first: 0,
        end: first_end,
        steps,
        events: m.events,
    };
    let mut want = [0i64; 3];
    let mut toggles = check_line(m.name, table, &first, loaded, &s.after_events, true, report);
    if let Some((_, _, target)) = target {
        let at_stop = rule_positions(&steps, &signs, first_end);
        let delta = [0, 1, 2].map(|i| target[i] - at_stop[i]);
        let second = Line {
            first: first_end,
            end: taken,
            steps: delta.map(|d| d.unsigned_abs()),
            events: &[],
        };
        let more = check_line(m.name, table, &second, loaded, &[], true, report);
        for i in 0..3 {
            toggles[i] += more[i];
        }
        want = target;
    } else {
        for i in 0..3 {
            want[i] = signs[i] * i64::from(toggles[i]);
        }
    }
    check_pin(m.name, loaded, s.taken, report);
    check_turns(m.name, s.taken, report);
    check_end(&s.player, want, toggles, pins_before, report);
    report.equal("player done after the move", s.player.is_done().into(), 1);
    hprintln!(
        "  {:<40} {:>6} edges, steps {} {} {}",
        m.name,
        taken,
        toggles[0],
        toggles[1],
        toggles[2]
    );
    (s.timer, s.log)
}

/// Checks one line: the lead's periods against [`Model`] (when `model`:
/// a line that starts and ends at rest), and every edge of every axis at
/// the time of the lead's step the rule names. Returns each axis's steps.
fn check_line(
    name: &str,
    table: Table<'static>,
    line: &Line<'_>,
    loaded: &[u16],
    after_events: &[u32],
    model: bool,
    report: &mut Report,
) -> [u32; 3] {
    let lead_steps = line.steps.iter().copied().max().unwrap_or(0);
    let periods = &loaded[line.first..line.end.min(loaded.len())];
    if model {
        check_lead(name, table, line, periods, after_events, report);
    }
    check_rule(name, line, loaded, lead_steps, report)
}

/// The lead's periods of a line against [`Model`], with the events where
/// the handler applied them (a new target is the model's stop).
fn check_lead(
    name: &str,
    table: Table<'static>,
    line: &Line<'_>,
    periods: &[u16],
    after_events: &[u32],
    report: &mut Report,
) {
    let lead_steps = line.steps.iter().copied().max().unwrap_or(0);
    // The lead's periods: the model's, with the events where the handler
    // applied them (a new target is the model's stop).
    let mut model = Model::new(table, table, lead_steps as u32);
    let mut mismatches = 0u32;
    for (k, &got) in periods.iter().enumerate() {
        let here = line
            .events
            .iter()
            .enumerate()
            .filter(|(_, e)| e.0 == k as u32);
        for (i, &(_, event)) in here {
            let event = match event {
                Event::Target(_) => Event::Stop,
                e => e,
            };
            let chosen = after_events.get(i).copied().unwrap_or(0);
            report.equal(name, model.apply(event, chosen).into(), 1);
        }
        if model.next() != Some(got) {
            mismatches += 1;
        }
    }
    mismatches += u32::from(model.next().is_some());
    report.equal("the lead's periods against the model", mismatches.into(), 0);
}

/// Every edge of every axis of a line at the time of the lead's step the
/// rule names, and no other. Returns each axis's steps.
fn check_rule(
    name: &str,
    line: &Line<'_>,
    loaded: &[u16],
    lead_steps: u64,
    report: &mut Report,
) -> [u32; 3] {
    let (mut off, mut toggles) = (0u32, [0u32; 3]);
    critical_section::with(|cs| {
        let stamps = step::STAMPS.borrow_ref(cs);
        let pins = step::PINS.borrow_ref(cs);
        for (i, &d) in line.steps.iter().enumerate() {
            // The rule, edge by edge: the k-th step on the lead's step s_k
            // (numbered from 1 in the line), at the sum of the periods
            // before it from the move's first edge.
            let mut edges = (line.first..line.end).filter(|&e| pins[e] >> i & 1 == 1);
            for k in 1..=d {
                let s_k = ((2 * k * lead_steps + d) / (2 * d)) as usize;
                if line.first + s_k > line.end {
                    break;
                }
                let edge = line.first + s_k - 1;
                let want: u64 = loaded[..edge].iter().map(|&p| u64::from(p)).sum();
                let time = |e: usize| u64::from(stamps[0].wrapping_sub(stamps[e]));
                match edges.next() {
                    Some(e) if e == edge && time(e) == want => {}
                    got => {
                        if off == 0 {
                            hprintln!(
                                "FAIL {}: axis {} step {} on edge {:?}, the rule says edge {} at {} ticks",
                                name,
                                i,
                                k,
                                got.map(|e| (e, time(e))),
                                edge,
                                want
                            );
                        }
                        off += 1;
                    }
                }
                toggles[i] += 1;
            }
            // No step the rule does not name.
            off += edges.count() as u32;
        }
    });
    report.equal("axis edges off the rule or their time", off.into(), 0);
    toggles
}
