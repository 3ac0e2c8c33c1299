//! Plays the period tables of the root `profiles.toml` on a Cortex-M3 (QEMU's
//! `lm3s6965evb`) and checks every step.
//!
//! A loop stands in for the step interrupt: each call of [`step_interrupt`]
//! asks the [`Player`] for the next period and writes it to the SysTick
//! reload register, as a step timer's interrupt writes its reload register.
//! The moves cover a trapezoid, a triangle, an asymmetric ramp pair, stops,
//! cruise changes, a held (divider) ramp and a segment table; each is compared
//! step by step with a plain reference reading of the tables and with the
//! figures the macros emit (`TOTAL_TICKS`, `LAST_TICKS`, ...). Then the tables
//! are generated again on the target with `Spec::generate` and compared bit
//! for bit with the ones the macros put in flash.
//!
//! `cargo run --release` prints a summary over semihosting and exits QEMU with
//! status 0, or 1 on any mismatch or panic. With `--features measure` only the
//! measured step loops run (see `measure.sh`).
#![no_std]
#![no_main]

mod measure;
mod moves;
mod regen;
mod stack;

use cortex_m::peripheral::SYST;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;
use stepper_profiles::period_table;
use stepper_profiles::player::Player;

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

/// The step interrupt's work: the next period into the timer's reload
/// register (here SysTick's), `None` when the move is over. Not inlined and
/// not mangled, so that `measure.sh` finds it in QEMU's instruction trace.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn step_interrupt(player: &mut Player<'_, u16>, timer: &mut SYST) -> Option<u16> {
    let period = player.next_period()?;
    timer.set_reload(u32::from(period));
    Some(period)
}

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
    let mut timer = cortex_m::Peripherals::take()
        .expect("peripherals are taken once")
        .SYST;
    let mut report = Report::default();

    if cfg!(feature = "measure") {
        measure::run(&mut timer, &mut report);
    } else {
        hprintln!("stepper-profiles firmware: Cortex-M3, tables from profiles.toml");
        moves::run(&mut timer, &mut report);
        regen::run(&mut report);
        measure::run(&mut timer, &mut report);
        hprintln!(
            "stack: {} bytes at most, of {} free",
            stack::peak(),
            stack::size()
        );
    }

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
