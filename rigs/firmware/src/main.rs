//! Plays the period tables of the root `profiles.toml` on a Cortex-M3 (QEMU's
//! `mps2-an385`) and checks every step, at the pin.
//!
//! The moves play from a real step interrupt: SysTick's exception handler
//! (`step.rs`) takes each period from a [`Buffered`](stepper_profiles::player::Buffered)
//! player (SysTick's reload register takes effect at the next wrap) handed
//! to it for each move, loads it and toggles the step pin; the main program
//! starts each move and waits in a poll loop. Every step is stamped by a clock the
//! player does not drive (the MPS2's CMSDK timer 0, on SysTick's 25 MHz
//! clock), and each step's time from the move's start must be the sum of
//! the periods loaded before it, to the tick. The moves cover a trapezoid,
//! a triangle, an asymmetric ramp pair, stops, cruise changes, a held
//! (divider) ramp, a segment table and a compressed (runs) table, played by
//! `Player::new(&RUNS)` and by the player of any layout, whose every
//! accelerating pulse edge is also checked against the exact curve computed
//! on the target; each is compared step by step with a plain reference
//! reading of the tables and with the figures the macros emit
//! (`TOTAL_TICKS`, `LAST_TICKS`, ...). Then the tables are generated again on
//! the target with `Spec::generate` and compared bit for bit with the ones
//! the macros put in flash.
//!
//! `cargo run --release` (QEMU with `-icount shift=0,sleep=off`: one
//! instruction a nanosecond, so that the stamps are exact) prints a summary
//! over semihosting and exits QEMU with status 0, or 1 on any mismatch or
//! panic. Instructions per step are measured on three cores by
//! `rigs/measure`.
#![no_std]
#![no_main]

mod axes;
mod moves;
mod regen;
mod stack;
mod step;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;
use stepper_profiles::period_table;

/// Every profile of the root `profiles.toml`, compiled into flash: one module
/// per profile with `PERIODS` (or `SEGMENTS`), `LEN`, `TIMER_HZ`,
/// `TOTAL_TICKS`, ...
pub mod profiles {
    stepper_profiles::include_profiles!("../../profiles.toml");
}

/// A deceleration ramp of its own for asymmetric moves: constant deceleration
/// from 64 kHz to 500 Hz in 400 steps, on the same 10 MHz timer as
/// `sigmoid_exact` (ordered slow to fast, as every ramp).
pub static DECEL: [u16; 400] = period_table!(
    curve = linear,
    fmin = 500,
    fmax = 64_000,
    len = 400,
    timer_hz = 10_000_000,
);

/// The sigmoid article's orange curve through `period_table!` instead of the
/// TOML file: the same bits as `profiles::sigmoid_orange::PERIODS`.
pub static SEED: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64_000,
    flexible = 8,
    timer_hz = 10_000_000,
    discretization = index,
    rounding = truncate,
    arithmetic = f32,
);

/// Counts failed checks and prints each one.
#[derive(Default)]
pub struct Report {
    /// Checks run.
    pub checks: u32,
    /// Checks failed.
    pub failures: u32,
}

impl Report {
    /// Records one check; prints `what` with the values when it fails.
    pub fn check(&mut self, ok: bool, what: &str, got: u64, want: u64) {
        self.checks += 1;
        if !ok {
            self.failures += 1;
            hprintln!("FAIL {}: got {}, expected {}", what, got, want);
        }
    }

    /// Records `got == want`.
    pub fn equal(&mut self, what: &str, got: u64, want: u64) {
        self.check(got == want, what, got, want);
    }

    /// Records `ok` for one figure of `what`; prints both when it fails.
    pub fn figure(&mut self, ok: bool, what: &str, figure: &str, got: u64, want: u64) {
        self.checks += 1;
        if !ok {
            self.failures += 1;
            hprintln!("FAIL {} ({}): got {}, expected {}", what, figure, got, want);
        }
    }
}

#[entry]
fn main() -> ! {
    stack::paint();
    let timer = cortex_m::Peripherals::take()
        .expect("peripherals are taken once")
        .SYST;
    let mut report = Report::default();

    hprintln!("stepper-profiles firmware: Cortex-M3 (MPS2 AN385), tables from profiles.toml");
    let (timer, log) = moves::run(timer, &mut report);
    axes::run(timer, log, &mut report);
    regen::run(&mut report);
    hprintln!(
        "stack: {} bytes at most, of {} free",
        stack::peak(),
        stack::size()
    );

    if report.failures == 0 {
        hprintln!("ok: {} checks passed", report.checks);
        debug::exit(debug::EXIT_SUCCESS);
    } else {
        hprintln!("FAILED: {} of {} checks", report.failures, report.checks);
        debug::exit(debug::EXIT_FAILURE);
    }
    loop {
        cortex_m::asm::wfi();
    }
}
