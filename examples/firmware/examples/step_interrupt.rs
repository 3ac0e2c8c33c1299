//! A step interrupt that plays a ramp: SysTick's reload register takes
//! effect at the next wrap, so the player is `Buffered`: the first two
//! periods are loaded at the start, and each interrupt loads the period
//! after the interval now starting. The main program starts a move and
//! waits.
#![no_std]
#![no_main]

use core::cell::RefCell;

use cortex_m::peripheral::SYST;
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::{entry, exception};
use critical_section::Mutex;
use panic_semihosting as _;
use stepper_profiles::period_table;
use stepper_profiles::player::{Buffered, Player, Ramp};

/// 1000 steps from 500 Hz to 64 kHz, S-shaped, in ticks of a 10 MHz timer.
static RAMP: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64_000,
    flexible = 8,
    timer_hz = 10_000_000,
);

/// The player and its timer, shared by `main` and the step interrupt.
type Stepper = (Buffered<Player<'static, u16>>, SYST);
static STEPPER: Mutex<RefCell<Option<Stepper>>> = Mutex::new(RefCell::new(None));

#[exception]
fn SysTick() {
    critical_section::with(|cs| {
        if let Some((player, timer)) = STEPPER.borrow_ref_mut(cs).as_mut() {
            // The interval now starting was loaded at the last wrap: load the
            // one after it (a period of n ticks is a reload of n - 1).
            if player.step(|period| timer.set_reload(u32::from(period) - 1)) {
                // A step now: pulse the driver's step pin here.
            } else {
                timer.disable_interrupt(); // the last interval has elapsed
                timer.disable_counter();
            }
        }
    });
}

#[entry]
fn main() -> ! {
    let mut timer = cortex_m::Peripherals::take().unwrap().SYST;
    let mut player = Buffered::new(Player::new(Ramp::steps(&RAMP)));
    // 1000 steps up, 3000 at the top, 1000 down.
    let (Some(first), next) = player.start(5000) else {
        unreachable!("a move of 5000 steps")
    };
    timer.set_clock_source(SystClkSource::Core);
    timer.set_reload(u32::from(first) - 1);
    timer.clear_current();
    timer.enable_interrupt();
    timer.enable_counter(); // the first step now; SysTick loads `first` at its next tick
    // Pulse the step pin here for the first step.
    while SYST::get_current() == 0 {} // `first` is loaded: the next may go in
    if let Some(next) = next {
        timer.set_reload(u32::from(next) - 1);
    }
    critical_section::with(|cs| STEPPER.borrow(cs).replace(Some((player, timer))));
    loop {
        cortex_m::asm::wfi(); // the move plays from the interrupt
    }
}
