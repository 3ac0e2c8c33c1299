//! A step interrupt that plays a ramp: SysTick's reload register takes
//! effect at the next wrap, so the player is `Buffered`: the first two
//! periods are loaded at the start, and each interrupt loads the period
//! after the interval now starting. `main` hands the stepper to the
//! interrupt for a move and takes it back when the move has ended: no lock
//! and no check in the interrupt, 16 to 18 instructions a step on a
//! Cortex-M3 from the vector to the return (`rigs/measure`); the pin
//! is pulsed first, so every edge comes the same time after its wrap.
#![no_std]
#![no_main]

use core::cell::UnsafeCell;
use core::mem::MaybeUninit;
use core::sync::atomic::{AtomicBool, Ordering};

use cortex_m::peripheral::SYST;
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::{entry, exception};
use panic_semihosting as _;
use stepper_profiles::period_table;
use stepper_profiles::player::{Buffered, Player, Ramp};

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

/// What the interrupt owns while a move plays. The registers' addresses
/// are held beside the player: the handler loads them with its first words.
#[repr(C)]
struct Stepper {
    pin: *mut u32,
    bit: u32,
    reload: *mut u32,
    player: Buffered<Player<'static, u16>>,
}

/// A value `main` lends to one interrupt handler: `main` uses it only while
/// the interrupt is disabled, the handler only while it is enabled.
struct Handover<T>(UnsafeCell<MaybeUninit<T>>);

// SAFETY: one context at a time uses the value (the contract of `get`).
unsafe impl<T> Sync for Handover<T> {}

impl<T> Handover<T> {
    /// # Safety
    /// After a `write` from `main`; from the handler while its interrupt is
    /// enabled, or from `main` while it is disabled; one reference at a time.
    #[allow(clippy::mut_from_ref)]
    unsafe fn get(&self) -> &mut T {
        unsafe { (*self.0.get()).assume_init_mut() }
    }
}

static STEPPER: Handover<Stepper> = Handover(UnsafeCell::new(MaybeUninit::uninit()));
/// Set by `main` to start a move, cleared by the handler at its end.
static MOVING: AtomicBool = AtomicBool::new(false);

#[exception]
fn SysTick() {
    // SAFETY: the interrupt is enabled: the stepper is the handler's.
    let Stepper {
        pin,
        bit,
        reload,
        player,
    } = unsafe { STEPPER.get() };
    let reload = *reload;
    // SAFETY (both writes): the registers `main` put in the stepper.
    // A step now: the pin first, at the same time after every wrap; then
    // the interval after the one now starting (loaded at the last wrap).
    if !player.pulse_and_step(
        || unsafe { pin.write_volatile(*bit) },
        |value| unsafe { reload.write_volatile(u32::from(value)) },
    ) {
        // The last interval has elapsed: give the stepper back.
        // SAFETY: SysTick's control register, cleared: counter and
        // interrupt off.
        unsafe { (*SYST::PTR).csr.write(0) };
        MOVING.store(false, Ordering::Release);
    }
}

#[entry]
fn main() -> ! {
    let mut timer = cortex_m::Peripherals::take().unwrap().SYST;
    // SAFETY: the PORT's register; SysTick's interrupt is not enabled yet,
    // so `main` owns the stepper.
    unsafe {
        DIRSET.write_volatile(STEP_PIN);
        (*STEPPER.0.get()).write(Stepper {
            pin: OUTTGL,
            bit: STEP_PIN,
            reload: &raw const (*SYST::PTR).rvr as *mut u32,
            player: Buffered::new(Player::new(Ramp::steps(&RAMP))),
        });
    }
    loop {
        // SAFETY: SysTick's interrupt is disabled: the stepper is `main`'s.
        let stepper = unsafe { STEPPER.get() };
        // 1000 steps up, 3000 at the top, 1000 down.
        let (Some(first), next) = stepper.player.start(5000) else {
            unreachable!("a move of 5000 steps")
        };
        timer.set_clock_source(SystClkSource::Core);
        timer.set_reload(u32::from(first));
        timer.clear_current();
        timer.enable_counter(); // SysTick loads `first` at its next tick
        // SAFETY: the step pin's toggle register.
        unsafe { OUTTGL.write_volatile(STEP_PIN) }; // the first step, now
        while SYST::get_current() == 0 {} // `first` is loaded: the next may go in
        if let Some(next) = next {
            timer.set_reload(u32::from(next));
        }
        // Hand the stepper to the interrupt, and wait for the move's end.
        MOVING.store(true, Ordering::Release);
        timer.enable_interrupt();
        while MOVING.load(Ordering::Acquire) {
            cortex_m::asm::nop(); // the move plays from the interrupt
        }
    }
}

// Not in the guide: the harness that times the step pin in QEMU.
#[path = "harness/step_interrupt.rs"]
mod harness;
