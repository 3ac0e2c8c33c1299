//! RP2040: the timer's alarm 0 plays a move, scheduled at absolute times
//! with `Player::step`; the alarm's interrupt pulses the step pin, GPIO 2.
//!
//! Why every step is exact: the RP2040's timer counts microseconds from
//! boot, and an alarm fires when it reaches a given count. Each interrupt
//! schedules the next step at `last + period`, where `last` is the time the
//! step now playing was scheduled for, not the time the handler runs: an
//! alarm at an absolute time is a register that takes effect at once, so
//! `Player::step` hands out the period of the interval that starts now.
//! The interrupt's latency (its entry, and the few instructions before the
//! pin is set) delays each edge by about the same, and never adds to a
//! period: step `k` is at the sum of the first `k` periods from the start.
//! (`alarm.schedule(period)` would count from the moment it is called, and
//! add each interrupt's latency to every period.) A handler that ran past
//! the next step's time would find its alarm already due: the HAL then
//! raises the interrupt at once, and the step after that is on time again.
#![no_std]
#![no_main]

use core::cell::RefCell;

use critical_section::Mutex;
use embedded_hal::digital::OutputPin;
use fugit::MicrosDurationU32;
use panic_halt as _;
use rp2040_hal as hal;
use stepper_profiles::period_table;
use stepper_profiles::player::{Player, Ramp};

use hal::gpio::{FunctionSioOutput, Pin, PullDown, bank0::Gpio2};
use hal::pac::{self, interrupt};
use hal::timer::{Alarm, Alarm0, Instant};

/// The second-stage boot loader, at the start of flash, where the boot ROM
/// expects it (for the Raspberry Pi Pico's W25Q080 flash).
#[unsafe(link_section = ".boot2")]
#[used]
pub static BOOT2: [u8; 256] = rp2040_boot2::BOOT_LOADER_W25Q080;

/// The Raspberry Pi Pico's crystal.
const XTAL_FREQ_HZ: u32 = 12_000_000;

/// 400 steps from 500 Hz to 20 kHz, S-shaped, in microseconds: the
/// RP2040's timer counts at 1 MHz.
static RAMP: [u16; 400] = period_table!(
    curve = sigmoid,
    len = 400,
    fmin = 500,
    fmax = 20kHz,
    flexible = 8,
    timer_hz = 1MHz,
);

/// Cycles the step pin stays high: at least 2 µs at 125 MHz, the clock
/// `init_clocks_and_plls` sets (drivers ask for 1 to 2 µs).
const PULSE_CYCLES: u32 = 250;

type StepPin = Pin<Gpio2, FunctionSioOutput, PullDown>;

/// What the alarm's interrupt plays with: the player, the alarm, the step
/// pin and the time the alarm is set for.
struct Stepper {
    player: Player<'static, u16>,
    alarm: Alarm0,
    pin: StepPin,
    at: Instant,
}

static STEPPER: Mutex<RefCell<Option<Stepper>>> = Mutex::new(RefCell::new(None));

#[interrupt]
fn TIMER_IRQ_0() {
    critical_section::with(|cs| {
        let mut stepper = STEPPER.borrow_ref_mut(cs);
        let Some(Stepper {
            player,
            alarm,
            pin,
            at,
        }) = stepper.as_mut()
        else {
            return;
        };
        alarm.clear_interrupt();
        if player.is_done() {
            // The move's last period has elapsed: it is over.
            alarm.disable_interrupt();
            return;
        }
        // A step now, at `at`.
        let _ = pin.set_high();
        player.step(|period| {
            *at += MicrosDurationU32::from_ticks(u32::from(period));
            let _ = alarm.schedule_at(*at);
        });
        cortex_m::asm::delay(PULSE_CYCLES);
        let _ = pin.set_low();
    });
}

#[hal::entry]
fn main() -> ! {
    let mut pac = pac::Peripherals::take().unwrap();
    let mut watchdog = hal::Watchdog::new(pac.WATCHDOG);
    let clocks = hal::clocks::init_clocks_and_plls(
        XTAL_FREQ_HZ,
        pac.XOSC,
        pac.CLOCKS,
        pac.PLL_SYS,
        pac.PLL_USB,
        &mut pac.RESETS,
        &mut watchdog,
    )
    .unwrap();
    let sio = hal::Sio::new(pac.SIO);
    let pins = hal::gpio::Pins::new(
        pac.IO_BANK0,
        pac.PADS_BANK0,
        sio.gpio_bank0,
        &mut pac.RESETS,
    );
    let pin: StepPin = pins.gpio2.reconfigure();

    let mut timer = hal::Timer::new(pac.TIMER, &mut pac.RESETS, &clocks);
    let mut alarm = timer.alarm_0().unwrap();
    let mut player = Player::new(Ramp::steps(&RAMP));
    // 400 steps up, 1200 at the top, 400 down.
    player.start(2000);
    // Step 0 in 100 µs, from the alarm's interrupt like every other.
    let at = timer.get_counter() + MicrosDurationU32::from_ticks(100);
    alarm.enable_interrupt();
    // The interrupt is taken once the handler's state is in place, at the
    // end of this critical section.
    critical_section::with(|cs| {
        let _ = alarm.schedule_at(at);
        STEPPER.borrow(cs).replace(Some(Stepper {
            player,
            alarm,
            pin,
            at,
        }));
        // SAFETY: no critical section relies on this interrupt being masked.
        unsafe { pac::NVIC::unmask(pac::Interrupt::TIMER_IRQ_0) };
    });
    loop {
        cortex_m::asm::wfi(); // the move plays from the interrupt
    }
}
