//! A step interrupt that plays a ramp: SysTick's handler writes each period
//! to the reload register; the main program starts a move and waits.
#![no_std]
#![no_main]

use core::cell::RefCell;

use cortex_m::peripheral::SYST;
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::{entry, exception};
use critical_section::Mutex;
use panic_semihosting as _;
use stepper_profiles::period_table;
use stepper_profiles::player::{Player, Ramp};

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
type Stepper = (Player<'static, u16>, SYST);
static STEPPER: Mutex<RefCell<Option<Stepper>>> = Mutex::new(RefCell::new(None));

#[exception]
fn SysTick() {
    critical_section::with(|cs| {
        if let Some((player, timer)) = STEPPER.borrow_ref_mut(cs).as_mut() {
            // SysTick counts reload..=0: a period of n ticks is a reload of n - 1.
            let stepped = player.step(|period| timer.set_reload(u32::from(period) - 1));
            if stepped {
                // Pulse the driver's step pin here.
            } else {
                timer.disable_interrupt(); // the move is done
            }
        }
    });
}

#[entry]
fn main() -> ! {
    let mut timer = cortex_m::Peripherals::take().unwrap().SYST;
    let mut player = Player::new(Ramp::steps(&RAMP));
    player.start(5000); // 1000 steps up, 3000 at the top, 1000 down
    timer.set_clock_source(SystClkSource::Core);
    // The first step now: its period times the first interval.
    player.step(|period| timer.set_reload(u32::from(period) - 1));
    timer.clear_current();
    timer.enable_interrupt();
    timer.enable_counter();
    critical_section::with(|cs| STEPPER.borrow(cs).replace(Some((player, timer))));
    loop {
        cortex_m::asm::wfi(); // the move plays from the interrupt
    }
}
