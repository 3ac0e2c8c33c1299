//! The step interrupt as an RTIC 2 task: SysTick's hardware task owns the
//! stepper (the `Buffered` player, the timer and the registers a step
//! writes) as a local resource, so that no lock, no `UnsafeCell` and no
//! check stand between a wrap and its step: 15 to 17 instructions a step
//! on a Cortex-M3 from the vector to the return with RTIC's source-masking
//! backend (`rigs/measure`). `idle`
//! asks for a move by storing its steps and pending SysTick; the task,
//! finding the player at rest, starts it, plays it step by step and says
//! when it has ended. The only `unsafe` is the registers' writes.
#![no_std]
#![no_main]

use core::sync::atomic::{AtomicBool, AtomicU32};

use panic_semihosting as _;
use stepper_profiles::period_table;

/// 1000 steps from 500 Hz to 64 kHz, S-shaped, for a 10 MHz timer, each
/// entry the period less one: what SysTick's reload register holds.
static RAMP: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64_000,
    flexible = 8,
    timer_hz = 10_000_000,
    reload_offset = -1,
);

/// The step pin, PA02 of a SAM D5x/E5x: PORT group 0's `OUTTGL` toggles
/// the pins whose bits are written (a driver stepping on both edges).
const OUTTGL: *mut u32 = 0x4100_801C as *mut u32;
const DIRSET: *mut u32 = 0x4100_8008 as *mut u32;
const STEP_PIN: u32 = 1 << 2;

/// The steps of the move `idle` asks for, taken by the task when it starts
/// it.
static NEXT: AtomicU32 = AtomicU32::new(0);
/// Set by `idle` when it asks for a move, cleared by the task at its end.
static MOVING: AtomicBool = AtomicBool::new(false);

/// What the task owns: the registers a step writes, by address, beside
/// the player (the task loads the pin's register and bit with one `ldrd`,
/// and the reload register's with the player's first word in another:
/// `reload` sits just before the player, which is aligned to 8), and the
/// timer, to start and stop it.
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
    use super::{DIRSET, MOVING, NEXT, OUTTGL, RAMP, STEP_PIN, Stepper};
    use core::sync::atomic::Ordering;
    use cortex_m::peripheral::syst::SystClkSource;
    use cortex_m::peripheral::{SCB, SYST};
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
        let stepper = Stepper {
            pin: OUTTGL as usize,
            bit: STEP_PIN,
            spare: 0,
            reload: &raw const timer.rvr as usize,
            player: Buffered::new(Player::new(Ramp::steps(&RAMP))),
            timer,
        };
        (Shared {}, Local { stepper })
    }

    #[idle]
    fn idle(_: idle::Context) -> ! {
        // SAFETY: the PORT's register: the step pin an output.
        unsafe { DIRSET.write_volatile(STEP_PIN) };
        loop {
            // 1000 steps up, 3000 at the top, 1000 down.
            NEXT.store(5000, Ordering::Relaxed);
            MOVING.store(true, Ordering::Release);
            SCB::set_pendst(); // the task starts it
            while MOVING.load(Ordering::Acquire) {
                cortex_m::asm::nop(); // the move plays from the task
            }
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
        // A step now: the pin first, at the same time after every wrap;
        // then the interval after the one now starting (loaded at the
        // last wrap). SAFETY (both writes): the registers `init` put in
        // the stepper.
        if !player.pulse_and_step(
            || unsafe { (*pin as *mut u32).write_volatile(*bit) },
            |value| unsafe { reload.write_volatile(u32::from(value)) },
        ) {
            rest(cx.local.stepper);
        }
    }

    /// The move has ended (or none was playing): the timer off, and the
    /// move `idle` asked for, if any: the first period loaded and the
    /// first step now, then the second period in the reload register.
    #[cold]
    #[inline(never)]
    fn rest(stepper: &mut Stepper) {
        let timer = &mut stepper.timer;
        timer.disable_interrupt();
        timer.disable_counter();
        let steps = match NEXT.swap(0, Ordering::Relaxed) {
            0 => return MOVING.store(false, Ordering::Release),
            steps => steps,
        };
        let (Some(first), next) = stepper.player.start(steps) else {
            return MOVING.store(false, Ordering::Release);
        };
        timer.set_reload(u32::from(first));
        timer.clear_current();
        timer.enable_counter(); // SysTick loads `first` at its next tick
        // SAFETY: the step pin's toggle register.
        unsafe { OUTTGL.write_volatile(STEP_PIN) }; // the first step, now
        while SYST::get_current() == 0 {} // `first` is loaded: the next may go in
        if let Some(next) = next {
            timer.set_reload(u32::from(next));
        }
        timer.enable_interrupt();
    }
}

// Not in the guide: the harness that times the step pin in QEMU.
#[path = "harness/step_interrupt.rs"]
mod harness;
