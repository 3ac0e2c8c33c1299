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
use crate::moves::{Event, Model, Table, check_pin};
use crate::profiles::sigmoid_exact;
use crate::step::{self, Players, Stepper};

/// A move of the three axes.
struct AxesMove {
    name: &'static str,
    /// Steps on each axis (negative: backward).
    delta: [i64; 3],
    events: &'static [(u32, Event)],
}

const MOVES: [AxesMove; 2] = [
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
    timer
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
        Stepper {
            player: Players::Axes(Buffered::new(axes), m.delta),
            timer,
            events: m.events,
            log,
            steps: 0,
            taken: 0,
            after_events: [0; 4],
            toggles: 0,
            finished: false,
        },
        0,
    );
    let loaded = &s.log[..s.steps.min(step::MAX_STEPS)];
    // The lead: the axis with the most steps, the lowest of equals.
    let steps = m.delta.map(|d| d.unsigned_abs());
    let lead_steps = steps.iter().copied().max().unwrap_or(0);
    // Its periods: the model's, with the events where the handler applied them.
    let mut model = Model::new(table, table, lead_steps as u32);
    let mut mismatches = 0u32;
    for (k, &got) in loaded.iter().enumerate() {
        for (i, &(_, event)) in m.events.iter().enumerate().filter(|(_, e)| e.0 == k as u32) {
            report.equal(m.name, model.apply(event, s.after_events[i]).into(), 1);
        }
        if model.next() != Some(got) {
            mismatches += 1;
        }
    }
    mismatches += u32::from(model.next().is_some());
    report.equal("the lead's periods against the model", mismatches.into(), 0);
    check_pin(m.name, loaded, s.taken, report);
    // Each edge's time from the start, and the pins it toggled.
    let taken = s.taken.min(step::MAX_STEPS);
    let position = s.player.axes_position();
    let pins_now = step::step_pins() ^ pins_before;
    let (mut off, mut toggles) = (0u32, [0u32; 3]);
    critical_section::with(|cs| {
        let stamps = step::STAMPS.borrow_ref(cs);
        let pins = step::PINS.borrow_ref(cs);
        for (i, &d) in steps.iter().enumerate() {
            // The rule, edge by edge: the k-th step on the lead's step s_k
            // (numbered from 1), at the sum of the first s_k - 1 periods.
            let mut edges = (0..taken).filter(|&e| pins[e] >> i & 1 == 1);
            for k in 1..=d {
                let s_k = ((2 * k * lead_steps + d) / (2 * d)) as usize;
                if s_k > taken {
                    break;
                }
                let want: u64 = loaded[..s_k - 1].iter().map(|&p| u64::from(p)).sum();
                let time = |e: usize| u64::from(stamps[0].wrapping_sub(stamps[e]));
                match edges.next() {
                    Some(e) if e == s_k - 1 && time(e) == want => {}
                    got => {
                        if off == 0 {
                            hprintln!(
                                "FAIL {}: axis {} step {} on edge {:?}, the rule says edge {} at {} ticks",
                                m.name,
                                i,
                                k,
                                got.map(|e| (e, time(e))),
                                s_k - 1,
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
    for i in 0..3 {
        let want = m.delta[i].signum() * i64::from(toggles[i]);
        report.check(
            position[i] == want,
            "axis position at the pins",
            position[i] as u64,
            want as u64,
        );
        report.equal(
            "axis pin level",
            u64::from(pins_now >> i & 1),
            u64::from(toggles[i] & 1),
        );
    }
    report.equal("axis edges off the rule or their time", off.into(), 0);
    report.equal("player done after the move", s.player.is_done().into(), 1);
    hprintln!(
        "  {:<34} {:>6} edges, steps {} {} {}",
        m.name,
        taken,
        toggles[0],
        toggles[1],
        toggles[2]
    );
    (s.timer, s.log)
}
