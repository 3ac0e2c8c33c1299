//! The measured step loops: each is a loop of `n` calls of a step interrupt
//! between two marker functions. `measure.sh` runs them under QEMU's
//! instruction trace and counts the instructions between the markers.

use cortex_m::asm;
use cortex_m::peripheral::SYST;
use cortex_m_semihosting::hprintln;
use stepper_profiles::player::{Player, Ramp};

use crate::profiles::{exponential_segments, sigmoid_exact, sigmoid_orange};
use crate::{Report, step_interrupt};

/// Marks the start of a measured loop in the instruction trace.
#[inline(never)]
#[unsafe(no_mangle)]
pub extern "C" fn measure_begin() {
    asm::nop();
}

/// Marks the end of a measured loop (a different body, so that the two
/// markers are not merged into one function).
#[inline(never)]
#[unsafe(no_mangle)]
pub extern "C" fn measure_end() {
    asm::nop();
    asm::nop();
}

/// The baseline: a step interrupt that loads the next table entry into the
/// reload register, `reload = PERIODS[i]; i += 1`, and nothing else (the
/// index checked against the table's length, as safe Rust does).
#[inline(never)]
#[unsafe(no_mangle)]
pub fn bare_interrupt(next: &mut usize, timer: &mut SYST) {
    if let Some(&period) = sigmoid_exact::PERIODS.get(*next) {
        timer.set_reload(u32::from(period));
        *next += 1;
    }
}

/// The same load through a slice iterator: a pointer compared with the end
/// instead of an index checked against the length.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn iter_interrupt(periods: &mut core::slice::Iter<'_, u16>, timer: &mut SYST) {
    if let Some(&period) = periods.next() {
        timer.set_reload(u32::from(period));
    }
}

/// Plays a whole move, `up` steps accelerating, `cruise` at the top and
/// `up` decelerating, each phase between its own markers.
fn player_loops(
    report: &mut Report,
    label: &str,
    ramp: Ramp<'_, u16>,
    (up, cruise): (u32, u32),
    timer: &mut SYST,
) {
    let mut player = Player::new(ramp);
    player.start(2 * up + cruise);
    for (phase, steps) in [
        ("accelerating", up),
        ("cruising", cruise),
        ("decelerating", up),
    ] {
        hprintln!("measure: {}, {}: {} steps", label, phase, steps);
        measure_begin();
        for _ in 0..steps {
            step_interrupt(&mut player, timer);
        }
        measure_end();
    }
    report.equal(label, player.is_done().into(), 1);
}

/// Runs the measured loops.
pub fn run(timer: &mut SYST, report: &mut Report) {
    let n = sigmoid_exact::LEN;
    hprintln!(
        "measure: bare load, PERIODS[i] (sigmoid_exact): {} steps",
        n
    );
    let mut next = 0;
    measure_begin();
    for _ in 0..n {
        bare_interrupt(&mut next, timer);
    }
    measure_end();
    report.equal("bare table load", next as u64, n as u64);

    hprintln!(
        "measure: bare load, slice iterator (sigmoid_exact): {} steps",
        n
    );
    let mut periods = sigmoid_exact::PERIODS.iter();
    measure_begin();
    for _ in 0..n {
        iter_interrupt(&mut periods, timer);
    }
    measure_end();
    report.equal("bare load, slice iterator", periods.len() as u64, 0);

    player_loops(
        report,
        "player, trapezoid (sigmoid_exact)",
        Ramp::steps(&sigmoid_exact::PERIODS),
        (sigmoid_exact::LEN as u32, 1000),
        timer,
    );
    player_loops(
        report,
        "player, held x4 (sigmoid_orange)",
        Ramp::held(&sigmoid_orange::PERIODS, 4),
        (sigmoid_orange::LEN as u32 * 4, 1000),
        timer,
    );
    player_loops(
        report,
        "player, segments (exponential_segments)",
        Ramp::segments(&exponential_segments::SEGMENTS),
        (exponential_segments::LEN as u32, 60),
        timer,
    );
}
