//! The step interrupt itself, measured from SysTick's vector to its
//! exception return: the README's step interrupt (its handler compiles to
//! the same instructions).
//!
//! `main` hands the stepper (the [`Buffered`] player and SysTick) to the
//! handler by enabling SysTick's interrupt, and takes it back once the
//! handler has disabled it at the move's end ([`Handover`]); while the
//! move plays the handler alone touches it, with no lock and no check. The
//! handler takes the next period (the player's step path, inlined), loads
//! it and toggles the step pin with one store. Here SysTick's exception is
//! pended by software, once per step, so that the trace sees one handler
//! per step whatever the emulated clock does.

use core::cell::UnsafeCell;
use core::mem::MaybeUninit;
use core::sync::atomic::{AtomicBool, Ordering};

use cortex_m::peripheral::{SCB, SYST};
use cortex_m_rt::exception;
use stepper_profiles::player::{Buffered, Player, Ramp};

use crate::profiles::sigmoid_exact;
use crate::{CRUISE, UP, check, phases};

/// A value `main` hands to one interrupt handler. `main` uses it only while
/// the handler's interrupt is disabled, the handler only while it is
/// enabled: one of them at a time, with no lock.
pub struct Handover<T>(UnsafeCell<MaybeUninit<T>>);

// SAFETY: one context at a time uses the value, by the contracts of `put`
// and `get`; the value moves between contexts, so it must be `Send`.
unsafe impl<T: Send> Sync for Handover<T> {}

impl<T> Handover<T> {
    /// Empty: `put` before the handler's interrupt is first enabled.
    pub const fn new() -> Self {
        Handover(UnsafeCell::new(MaybeUninit::uninit()))
    }

    /// Stores the value (an earlier one is forgotten, not dropped).
    ///
    /// # Safety
    ///
    /// Only from `main` while the handler's interrupt is disabled, with no
    /// reference from [`get`](Self::get) alive.
    pub unsafe fn put(&self, value: T) {
        // SAFETY: the caller owns the cell now (the contract above).
        unsafe { (*self.0.get()).write(value) };
    }

    /// The value.
    ///
    /// # Safety
    ///
    /// After [`put`](Self::put); from the handler while its interrupt is
    /// enabled, or from `main` while it is disabled, and no other reference
    /// from `get` alive.
    #[allow(clippy::mut_from_ref)]
    pub unsafe fn get(&self) -> &mut T {
        // SAFETY: initialised by `put`, and used by one context at a time
        // (the contract above).
        unsafe { (*self.0.get()).assume_init_mut() }
    }
}

/// What the step interrupt owns while a move plays.
///
/// The registers' addresses are held with the player, the reload
/// register's just before it: the handler loads it with the player's first
/// word in one `ldrd`, and the pin's register and bit in another, where
/// building each constant address takes two instructions.
#[repr(C)]
pub struct Stepper {
    /// The step pin's toggle register and the pin's bit.
    pin: *mut u32,
    bit: u32,
    /// SysTick's reload register.
    reload: *mut u32,
    player: Buffered<Player<'static, u16>>,
    timer: SYST,
}

// SAFETY: the registers are the board's, used by one context at a time.
unsafe impl Send for Stepper {}

static STEPPER: Handover<Stepper> = Handover::new();

/// `true` from the move's start until the handler has disabled its
/// interrupt: then the stepper is `main`'s again.
static MOVING: AtomicBool = AtomicBool::new(false);

/// Stands for the step pin's toggle register (a SAM's `OUTTGL`, a Kinetis
/// `PTOR`, the RP2040's `GPIO_OUT_XOR`): one store of the pin's bit toggles
/// it. Here an address whose store changes nothing the measurement reads:
/// the LM3S6965's GPIO port B direction register, a word the MPS2's UART 1
/// ignores.
const STEP_PIN_TOGGLE: *mut u32 = 0x4000_5400 as *mut u32;

#[exception]
fn SysTick() {
    // SAFETY: SysTick's interrupt is enabled: the handler owns the stepper.
    let Stepper {
        pin,
        bit,
        reload,
        player,
        timer,
    } = unsafe { STEPPER.get() };
    // The reload register's address before the player's loads.
    let reload = *reload;
    // SAFETY (both writes): the registers `main` put in the stepper.
    // A step now: the pin first, at the same time after every wrap; then
    // the period after the interval now starting.
    if !player.pulse_and_step(
        || unsafe { pin.write_volatile(*bit) },
        |period| unsafe { reload.write_volatile(u32::from(period)) },
    ) {
        timer.disable_interrupt();
        MOVING.store(false, Ordering::Release);
    }
}

/// The handler on a move of `sigmoid_exact`, phase by phase, SysTick pended
/// once per step.
pub fn measure() {
    // SAFETY: the measurements before are done with SysTick; this is its
    // only owner from now on.
    let mut timer = unsafe { cortex_m::Peripherals::steal() }.SYST;
    let mut player = Buffered::new(Player::new(Ramp::steps(&sigmoid_exact::PERIODS)));
    let (first, next) = player.start(2 * UP + CRUISE);
    check(first.is_some() && next.is_some(), "handler move");
    timer.enable_interrupt();
    // SAFETY: SysTick's exception is not pended yet; `main` owns the cell.
    unsafe {
        STEPPER.put(Stepper {
            pin: STEP_PIN_TOGGLE,
            bit: 1,
            reload: &raw const (*SYST::PTR).rvr as *mut u32,
            player,
            timer,
        })
    };
    MOVING.store(true, Ordering::Release);
    // The first step was at the start: one exception per step after it,
    // and the one that ends the move.
    phases(
        "handler, Buffered per-step table (SysTick vector to return)",
        (UP, CRUISE),
        SCB::set_pendst,
    );
    check(!MOVING.load(Ordering::Acquire), "handler done");
}
