//! The step interrupt as an RTIC 2 task, measured from SysTick's vector to
//! its return: the guide's RTIC example (`rigs/firmware/examples/
//! rtic_step.rs`), its task owning the `Buffered` player and SysTick as
//! local resources. Built for the Cortex-M3 and M4F with each of RTIC's
//! backends there (features `rtic-masking`, the guide's, and
//! `rtic-basepri`); `measure.sh` counts it as it counts the hand-rolled
//! handler.
//!
//! `idle` pends SysTick once per step, so that the trace sees one task per
//! step whatever the emulated clock does: first to start the move (the
//! task finds the player at rest), then once a step, phase by phase
//! between the markers, and once more to end it.
#![no_std]
#![no_main]

use core::sync::atomic::{AtomicBool, AtomicU32};

use cortex_m::asm;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;

/// The tables of the root `profiles.toml`.
mod profiles {
    stepper_profiles::include_profiles!("../../profiles.toml");
}

use profiles::sigmoid_exact;

/// RTIC's backend, as the features chose it.
const BACKEND: &str = if cfg!(feature = "rtic-masking") {
    "source-masking"
} else {
    "BASEPRI"
};

/// Steps of the measured move: up the ramp, cruise, down the ramp.
const UP: u32 = sigmoid_exact::LEN as u32;
const CRUISE: u32 = 3000;

/// Stands for the step pin's toggle register, as in the main binary: the
/// LM3S6965's GPIO port B direction register, a word the MPS2's UART 1
/// ignores.
const STEP_PIN_TOGGLE: *mut u32 = 0x4000_5400 as *mut u32;
const STEP_PIN: u32 = 1;

/// The steps of the move `idle` asks for.
static NEXT: AtomicU32 = AtomicU32::new(0);
/// Set by `idle` when it asks for a move, cleared by the task at its end.
static MOVING: AtomicBool = AtomicBool::new(false);

/// Marks the start of a measured stretch in the instruction trace.
#[inline(never)]
#[unsafe(no_mangle)]
pub extern "C" fn measure_begin() {
    asm::nop();
}

/// Marks its end (another body, so that the two are not merged).
#[inline(never)]
#[unsafe(no_mangle)]
pub extern "C" fn measure_end() {
    asm::nop();
    asm::nop();
}

fn check(ok: bool, what: &str) {
    if !ok {
        hprintln!("FAIL {}", what);
        debug::exit(debug::EXIT_FAILURE);
    }
}

/// What the task owns: the registers a step writes, by address, beside
/// the player (the task loads the pin's register and bit with one `ldrd`,
/// where building each constant address takes two instructions, and the
/// reload register's with the player's first word in another: `reload`
/// sits just before the player, which is aligned to 8), and the timer, to
/// stop it at a move's end.
#[repr(C)]
pub struct Stepper {
    pin: usize,
    bit: u32,
    spare: u32,
    reload: usize,
    player: stepper_profiles::player::Buffered<stepper_profiles::player::Player<'static, u16>>,
    timer: cortex_m::peripheral::SYST,
}

#[rtic::app(device = lm3s6965, peripherals = false)]
mod app {
    use super::{
        BACKEND, CRUISE, MOVING, NEXT, STEP_PIN, STEP_PIN_TOGGLE, Stepper, UP, check,
        measure_begin, measure_end, sigmoid_exact,
    };
    use core::sync::atomic::Ordering;
    use cortex_m::peripheral::SCB;
    use cortex_m::peripheral::syst::SystClkSource;
    use cortex_m_semihosting::{debug, hprintln};
    use stepper_profiles::player::{Buffered, Player, Ramp};

    #[shared]
    struct Shared {}

    #[local]
    struct Local {
        stepper: Stepper,
    }

    #[init]
    fn init(cx: init::Context) -> (Shared, Local) {
        let mut timer = cx.core.SYST;
        timer.set_clock_source(SystClkSource::Core);
        let player = Buffered::new(Player::new(Ramp::steps(&sigmoid_exact::PERIODS)));
        let stepper = Stepper {
            pin: STEP_PIN_TOGGLE as usize,
            bit: STEP_PIN,
            spare: 0,
            reload: &raw const timer.rvr as usize,
            player,
            timer,
        };
        (Shared {}, Local { stepper })
    }

    #[idle]
    fn idle(_: idle::Context) -> ! {
        NEXT.store(2 * UP + CRUISE, Ordering::Relaxed);
        MOVING.store(true, Ordering::Release);
        SCB::set_pendst(); // the task starts the move: its first step
        for (phase, n) in [
            ("accelerating", UP),
            ("cruising", CRUISE),
            ("decelerating", UP),
        ] {
            hprintln!(
                "measure: handler, RTIC task ({} backend), Buffered per-step table (SysTick vector to return) {}: {} steps",
                BACKEND,
                phase,
                n
            );
            measure_begin();
            for _ in 0..n {
                SCB::set_pendst();
            }
            measure_end();
        }
        check(!MOVING.load(Ordering::Acquire), "RTIC task done");
        hprintln!("ok");
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::nop();
        }
    }

    /// A step at each wrap; at rest, the move `idle` asked for.
    #[task(binds = SysTick, local = [stepper])]
    fn step(cx: step::Context) {
        let Stepper {
            pin,
            bit,
            reload,
            player,
            ..
        } = cx.local.stepper;
        let reload = *reload as *mut u32;
        // SAFETY (both writes): the registers `init` put in the stepper.
        if !player.pulse_and_step(
            || unsafe { (*pin as *mut u32).write_volatile(*bit) },
            |value| unsafe { reload.write_volatile(u32::from(value)) },
        ) {
            rest(cx.local.stepper);
        }
    }

    /// The move has ended (or none was playing): the timer off, and the
    /// move `idle` asked for, if any, its first two periods loaded (the
    /// counter stays off: `idle` pends each step).
    #[cold]
    #[inline(never)]
    fn rest(stepper: &mut Stepper) {
        stepper.timer.disable_interrupt();
        stepper.timer.disable_counter();
        let steps = match NEXT.swap(0, Ordering::Relaxed) {
            0 => return MOVING.store(false, Ordering::Release),
            steps => steps,
        };
        let (Some(first), next) = stepper.player.start(steps) else {
            MOVING.store(false, Ordering::Release);
            return;
        };
        stepper.timer.set_reload(u32::from(first));
        if let Some(next) = next {
            stepper.timer.set_reload(u32::from(next));
        }
    }
}
