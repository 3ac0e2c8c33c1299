//! ESP32-C3: RMT channel 0 plays a move, the step pin GPIO 2: the periods
//! `Player::fill` hands out, each turned into RMT symbols (`rmt_step.rs`:
//! the pin high for the pulse, then low for the rest of the period, split
//! over more symbols where a half's 15 bits do not hold it), the whole move
//! converted before it starts and sent by one transmission, which refills
//! the channel's memory as it plays.
//!
//! Why every step is exact: the RMT plays each symbol's two halves for
//! exactly their lengths in its clock's ticks (80 MHz over a divider of 8:
//! 10 MHz, the table's rate), one after the other, whatever the CPU does,
//! so step `k` rises at the sum of the first `k` periods; the halves of a
//! period add up to it, split or not.
#![no_std]
#![no_main]

use esp_hal::gpio::Level;
use esp_hal::main;
use esp_hal::rmt::{PulseCode, Rmt, TxChannelConfig, TxChannelCreator};
use esp_hal::time::Rate;
use stepper_profiles::player::{Player, Ramp};

#[path = "../rmt_step.rs"]
mod rmt_step;

use rmt_step::{PULSE, RAMP};

/// The move: 400 steps up, 1200 at the top, 400 down.
const STEPS: usize = 2000;
/// Symbols: at most two a step here (no period reaches 25 + 3 x 32 767
/// ticks), and the end.
const SYMBOLS: usize = 2 * STEPS + 1;

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {}
}

#[main]
fn main() -> ! {
    let peripherals = esp_hal::init(esp_hal::Config::default());
    let rmt = Rmt::new(peripherals.RMT, Rate::from_mhz(80)).unwrap();
    let channel = rmt
        .channel0
        .configure_tx(
            &TxChannelConfig::default()
                .with_clk_divider(8)
                .with_idle_output_level(Level::Low)
                .with_idle_output(true),
        )
        .unwrap()
        .with_pin(peripherals.GPIO2);

    // The move's symbols, from the player's periods 64 at a time.
    let mut player = Player::new(Ramp::steps(&RAMP));
    player.start(STEPS as u32);
    let mut symbols = [PulseCode(rmt_step::END); SYMBOLS];
    let mut n = 0;
    let mut periods = [0u16; 64];
    loop {
        let filled = player.fill(&mut periods);
        for &period in &periods[..filled] {
            rmt_step::step(u32::from(period), PULSE, |word| {
                symbols[n] = PulseCode(word);
                n += 1;
            })
            .unwrap();
        }
        if filled < periods.len() {
            break;
        }
    }
    // One transmission, ended by the symbol of length 0 after the last.
    let transaction = channel.transmit(&symbols[..=n]).unwrap();
    let _channel = transaction.wait().unwrap();
    loop {
        core::hint::spin_loop(); // the move has played
    }
}
