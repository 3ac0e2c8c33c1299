//! STM32F411: TIM3 plays a move with its auto-reload preload on (`ARPE`),
//! from its update interrupt, through `player::Buffered`; channel 1 makes
//! the step pulse on PA6 (AF2) in hardware.
//!
//! Why every step is exact: with `ARPE = 1` a value written to `ARR` waits
//! in the preload register and takes effect at the next update event. When
//! the update interrupt runs, the counter has already loaded the interval
//! now starting, so the value written then is the period *after* it, which
//! is what `Buffered::step` hands out (less one: the counter runs from 0 to
//! `ARR`, `ARR + 1` ticks). The interrupt's latency moves nothing: it only
//! has to write `ARR` before the interval now starting ends. The pin is not
//! driven by the interrupt either: channel 1 in PWM mode 2 holds it low for
//! `PULSE_DELAY` ticks after each update event, then high until the next,
//! so each step's rising edge is `PULSE_DELAY` ticks after its interval
//! starts: step `k` at the sum of the first `k` periods, plus that constant.
//!
//! The end is made in hardware too: when the last interval starts there is
//! no period after it, and the interrupt writes 0 to `ARR`: the counter
//! stops at the next update event, at 0, with the pin low (a null `ARR`
//! blocks the counter; with the preload on, no update follows to release
//! it). No extra edge.
#![no_std]
#![no_main]

use core::cell::RefCell;

use cortex_m_rt::entry;
use critical_section::Mutex;
use panic_halt as _;
use stepper_profiles::player::{Buffered, Player, Ramp};
use stm32f4xx_hal::pac::{self, TIM3, interrupt};
use stm32f4xx_hal::prelude::*;
use stm32f4xx_hal::rcc::Config;
use stm32f4xx_hal::timer::FTimer;

/// The profiles of `profiles.toml`: `ramp::PERIODS`, `ramp::TIMER_HZ`, ...
mod profiles {
    stepper_profiles::include_profiles!("profiles.toml");
}
use profiles::ramp;

/// Ticks from each update event to the step's rising edge: the pin's low
/// time, 2 µs at 10 MHz (drivers ask for 1 to 2 µs). The high time is the
/// rest of the period, at least 136 ticks at the ramp's top (156).
const PULSE_DELAY: u16 = 20;

/// The player and the timer, shared by `main` and the update interrupt.
type Stepper = (Buffered<Player<'static, u16>>, TIM3);
static STEPPER: Mutex<RefCell<Option<Stepper>>> = Mutex::new(RefCell::new(None));

/// The value of `ARR` for a period: the period less one, or 0, which stops
/// the counter at the end of the interval playing, where there is no next.
fn reload(period: Option<u16>) -> u16 {
    period.map_or(0, |p| p - 1)
}

#[interrupt]
fn TIM3() {
    critical_section::with(|cs| {
        let mut stepper = STEPPER.borrow_ref_mut(cs);
        let Some((player, tim)) = stepper.as_mut() else {
            return;
        };
        tim.sr().write(|w| w.uif().clear_bit());
        // The interval now starting was loaded at this update event: hand
        // the one after it to the preload register.
        let mut next = None;
        if player.step(|period| next = Some(period)) {
            // A step now: channel 1 makes its edge, `PULSE_DELAY` ticks on.
            tim.arr().write(|w| w.arr().set(reload(next)));
        } else {
            // The last interval has elapsed; `ARR = 0` has stopped the
            // counter, at 0, the pin low.
            tim.dier().write(|w| w.uie().clear_bit());
            tim.cr1().modify(|_, w| w.cen().clear_bit());
        }
    });
}

#[entry]
fn main() -> ! {
    let dp = pac::Peripherals::take().unwrap();
    // 100 MHz from the internal oscillator; APB1 at 50 MHz, so its timers
    // count at 100 MHz.
    let mut rcc = dp
        .RCC
        .freeze(Config::hsi().sysclk(100.MHz()).pclk1(50.MHz()));
    let gpioa = dp.GPIOA.split(&mut rcc);
    let _step_pin = gpioa.pa6.into_alternate::<2>(); // TIM3_CH1

    // The HAL enables and resets TIM3 and sets its prescaler for the
    // table's rate (10 MHz); its registers are programmed directly below.
    let tim = FTimer::<TIM3, { ramp::TIMER_HZ }>::new(dp.TIM3, &mut rcc).release();
    // Channel 1 in PWM mode 2: low while CNT < CCR1, high from CCR1 on.
    tim.ccmr1_output()
        .write(|w| w.oc1m().pwm_mode2().oc1pe().set_bit());
    tim.ccr1().write(|w| w.ccr().set(PULSE_DELAY));
    tim.ccer().write(|w| w.cc1e().set_bit());
    // Preload on; only overflows raise the update flag (not UG below).
    tim.cr1().write(|w| w.arpe().set_bit().urs().set_bit());

    let mut player = Buffered::new(Player::new(Ramp::steps(&ramp::PERIODS)));
    // 1000 steps up, 3000 at the top, 1000 down.
    let (first, next) = player.start(5000);
    // The first period straight into the counter (UG copies ARR, PSC and
    // CCR1 to their shadows and clears CNT), the second into the preload.
    tim.arr().write(|w| w.arr().set(reload(first)));
    tim.egr().write(|w| w.ug().set_bit());
    tim.arr().write(|w| w.arr().set(reload(next)));
    tim.dier().write(|w| w.uie().set_bit());

    // The interrupt is taken once the handler's state is in place, at the
    // end of this critical section (the first update event is a period on).
    critical_section::with(|cs| {
        // Step 0 now: its edge `PULSE_DELAY` ticks after the counter starts.
        tim.cr1().modify(|_, w| w.cen().set_bit());
        STEPPER.borrow(cs).replace(Some((player, tim)));
        // SAFETY: no critical section relies on this interrupt being masked.
        unsafe { cortex_m::peripheral::NVIC::unmask(pac::Interrupt::TIM3) };
    });
    loop {
        cortex_m::asm::wfi(); // the move plays from the interrupt
    }
}
