//! STM32F411: TIM3 plays a move with no instruction per step. DMA1 stream 2
//! copies the values of `ARR` into it at each update event, from two
//! buffers in turn (the stream's double-buffer mode) that the stream's
//! transfer-complete interrupt refills from `Player::fill`; channel 1 makes
//! the step pulse on PA6 (AF2), as in `tim_preload`.
//!
//! Why every step is exact: the table is made with `reload_offset = -1`
//! (`profiles.toml`, `ramp_arr`), so each value the player hands out is the
//! period less one, what `ARR` holds for it. With the preload on (`ARPE`),
//! `ARR` holds the period after the interval playing; at each update event
//! the counter loads it and the timer requests the DMA (`UDE`), which
//! writes the next value to `ARR`: the period after the interval now
//! starting, as `player::Buffered` hands out in `tim_preload`, by hardware
//! at every update, so neither interrupt latency nor the refill's timing
//! touches a period. The first two values go into the counter and its
//! preload before it starts; the buffers hold the move from the third on.
//!
//! The move ends in hardware: after its last value a buffer holds zeros,
//! and `ARR = 0` stops the counter at the update event that ends the last
//! interval, at 0, the pin low: no extra edge.
//!
//! (A ramp could be copied by DMA straight from flash on the way up, but
//! the way down reads it backwards, which DMA cannot: the player writes
//! both into the buffers, about 4 instructions a period on a Cortex-M3.)
#![no_std]
#![no_main]

use core::cell::RefCell;

use cortex_m_rt::entry;
use critical_section::Mutex;
use panic_halt as _;
use stepper_profiles::player::{Player, Ramp};
use stm32f4xx_hal::dma::config::{DmaConfig, Priority};
use stm32f4xx_hal::dma::traits::{DMASet, PeriAddress};
use stm32f4xx_hal::dma::{MemoryToPeripheral, Stream2, StreamsTuple, Transfer};
use stm32f4xx_hal::pac::{self, DMA1, TIM3, interrupt};
use stm32f4xx_hal::prelude::*;
use stm32f4xx_hal::rcc::Config;
use stm32f4xx_hal::timer::FTimer;

/// The profiles of `profiles.toml`: `ramp_arr::PERIODS` holds `ARR`'s
/// values (`ramp_arr::RELOAD_OFFSET` is -1).
mod profiles {
    stepper_profiles::include_profiles!("profiles.toml");
}
use profiles::ramp_arr;

/// Ticks from each update event to the step's rising edge (see
/// `tim_preload`).
const PULSE_DELAY: u16 = 20;

/// Values in each of the two buffers: one buffer plays while the other is
/// refilled, so the refill has `HALF` periods, at least 64 × 15.6 µs here,
/// to run.
const HALF: usize = 64;

/// TIM3's auto-reload register as the stream's destination; it owns the
/// timer.
struct Arr(TIM3);

// SAFETY: the address is TIM3's `ARR`, a 16-bit register.
unsafe impl PeriAddress for Arr {
    type MemSize = u16;
    fn address(&self) -> u32 {
        self.0.arr().as_ptr() as u32
    }
}

// SAFETY: TIM3's update request is DMA1 stream 2, channel 5 (RM0383, DMA1
// request mapping), as the HAL's own map has it for `TIM3_UP`.
unsafe impl DMASet<Stream2<DMA1>, 5, MemoryToPeripheral> for Arr {}

type ArrTransfer = Transfer<Stream2<DMA1>, 5, Arr, MemoryToPeripheral, &'static mut [u16; HALF]>;

/// The player and the transfer, shared by `main` and the DMA interrupt.
type Stepper = (Player<'static, u16>, ArrTransfer);
static STEPPER: Mutex<RefCell<Option<Stepper>>> = Mutex::new(RefCell::new(None));

/// Writes the next values of the move into `buf`, and 0 after its end:
/// `ARR = 0` stops the counter at the update event that ends the last
/// interval.
fn refill(player: &mut Player<'static, u16>, buf: &mut [u16]) {
    let n = player.fill(buf);
    if let Some(rest) = buf.get_mut(n..) {
        rest.fill(0);
    }
}

#[interrupt]
fn DMA1_STREAM2() {
    critical_section::with(|cs| {
        if let Some((player, transfer)) = STEPPER.borrow_ref_mut(cs).as_mut() {
            // SAFETY: the buffer handed over is the one the stream has just
            // left; the stream comes back to it `HALF` update events later,
            // long after this refill.
            let refilled = unsafe {
                transfer.next_transfer_with(|buf, _| {
                    refill(player, &mut buf[..]);
                    (buf, ())
                })
            };
            // Not ready: the interrupt was not the transfer's end; nothing
            // to refill.
            let _ = refilled;
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
    let tim = FTimer::<TIM3, { ramp_arr::TIMER_HZ }>::new(dp.TIM3, &mut rcc).release();
    // Channel 1 in PWM mode 2: low while CNT < CCR1, high from CCR1 on.
    tim.ccmr1_output()
        .write(|w| w.oc1m().pwm_mode2().oc1pe().set_bit());
    tim.ccr1().write(|w| w.ccr().set(PULSE_DELAY));
    tim.ccer().write(|w| w.cc1e().set_bit());
    // Preload on; only overflows raise update events' requests (not UG).
    tim.cr1().write(|w| w.arpe().set_bit().urs().set_bit());

    let mut player = Player::new(Ramp::steps(&ramp_arr::PERIODS));
    // 1000 steps up, 3000 at the top, 1000 down.
    player.start(5000);
    // The first value straight into the counter (UG copies ARR, PSC and CCR1
    // to their shadows and clears CNT), the second into the preload; 0 for
    // none.
    tim.arr()
        .write(|w| w.arr().set(player.next_period().unwrap_or(0)));
    tim.egr().write(|w| w.ug().set_bit());
    tim.arr()
        .write(|w| w.arr().set(player.next_period().unwrap_or(0)));
    // A DMA request at each update event.
    tim.dier().write(|w| w.ude().set_bit());

    // The rest of the move, from the third value, in two buffers.
    let first = cortex_m::singleton!(: [u16; HALF] = [0; HALF]).unwrap();
    let second = cortex_m::singleton!(: [u16; HALF] = [0; HALF]).unwrap();
    refill(&mut player, first);
    refill(&mut player, second);
    let streams = StreamsTuple::new(dp.DMA1, &mut rcc);
    let config = DmaConfig::default()
        .priority(Priority::VeryHigh)
        .memory_increment(true)
        .double_buffer(true)
        .transfer_complete_interrupt(true);
    let mut transfer =
        Transfer::init_memory_to_peripheral(streams.2, Arr(tim), first, Some(second), config);

    // The interrupt is taken once the handler's state is in place, at the
    // end of this critical section (the first buffer ends `HALF` periods on).
    critical_section::with(|cs| {
        // The stream waits for the first update event; step 0 now, its edge
        // `PULSE_DELAY` ticks after the counter starts.
        transfer.start(|arr| {
            arr.0.cr1().modify(|_, w| w.cen().set_bit());
        });
        STEPPER.borrow(cs).replace(Some((player, transfer)));
        // SAFETY: no critical section relies on this interrupt being masked.
        unsafe { cortex_m::peripheral::NVIC::unmask(pac::Interrupt::DMA1_STREAM2) };
    });
    loop {
        cortex_m::asm::wfi(); // the move plays by DMA
    }
}
