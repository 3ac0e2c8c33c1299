//! RP2040: PIO 0's state machine 0 plays a move, the step pin GPIO 2 its
//! side-set, one period a word from its TX FIFO, which DMA fills from
//! `Player::fill` in two buffers; the state machine counts the steps.
//!
//! Why every step is exact: the state machine runs the program of
//! `pio_step.rs` at 5 MHz (125 MHz over an integer divider), a step exactly
//! `word + OVERHEAD` of its cycles whatever the CPU and the DMA do, as long
//! as the FIFO never runs dry: DMA writes a word as soon as a slot is free
//! (the FIFO's DREQ), from one buffer while the CPU fills the other, 64
//! words (at least 64 periods of the move) ahead. The table holds each
//! period less `OVERHEAD` (`reload_offset = -12`), so the words are the
//! player's output as it is. At the move's end the player fills fewer
//! words than a buffer holds: the CPU writes them to the FIFO itself after
//! the last transfer, and the program stalls, the pin low, when none is
//! left. Then it has decremented Y once a step: the steps played are
//! `0 - Y`, read back through the RX FIFO.
#![no_std]
#![no_main]

use panic_halt as _;
use rp2040_hal as hal;
use stepper_profiles::player::{Player, Ramp};

use hal::dma::{DMAExt, double_buffer};
use hal::gpio::{FunctionPio0, Pin, PullDown, bank0::Gpio2};
use hal::pac;
use hal::pio::{PIOBuilder, PIOExt, PinDir, ShiftDirection};
use pio::{Instruction, InstructionOperands, MovDestination, MovOperation, MovSource};

#[path = "../pio_step.rs"]
mod pio_step;

use pio_step::{DIVIDER, PROGRAM, RAMP, WRAP_SOURCE, WRAP_TARGET};

/// The second-stage boot loader, at the start of flash, where the boot ROM
/// expects it (for the Raspberry Pi Pico's W25Q080 flash).
#[unsafe(link_section = ".boot2")]
#[used]
pub static BOOT2: [u8; 256] = rp2040_boot2::BOOT_LOADER_W25Q080;

/// The Raspberry Pi Pico's crystal.
const XTAL_FREQ_HZ: u32 = 12_000_000;
/// The step pin.
const STEP: u8 = 2;
/// Words per DMA buffer.
const BUFFER: usize = 64;
/// The move: 400 steps up, 1200 at the top, 400 down.
const STEPS: u32 = 2000;

#[hal::entry]
fn main() -> ! {
    let mut pac = pac::Peripherals::take().unwrap();
    let mut watchdog = hal::Watchdog::new(pac.WATCHDOG);
    let _clocks = hal::clocks::init_clocks_and_plls(
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
    let _step: Pin<Gpio2, FunctionPio0, PullDown> = pins.gpio2.into_function();

    // The program, side-set of one bit, wrapping from its last instruction
    // to its first.
    let program = pio::Program {
        code: PROGRAM.into_iter().collect(),
        origin: None,
        side_set: pio::SideSet::new(false, 1, false),
        wrap: pio::Wrap {
            source: WRAP_SOURCE,
            target: WRAP_TARGET,
        },
        version: pio::PioVersion::V0,
    };
    let (mut pio, sm0, _, _, _) = pac.PIO0.split(&mut pac.RESETS);
    let installed = pio.install(&program).unwrap();
    let (mut sm, mut rx, tx) = PIOBuilder::from_installed_program(installed)
        .side_set_pin_base(STEP)
        .autopull(true)
        .pull_threshold(32)
        .out_shift_direction(ShiftDirection::Right)
        .clock_divisor_fixed_point(DIVIDER, 0)
        .build(sm0);
    sm.set_pindirs([(STEP, PinDir::Output)]);
    let mut sm = sm.start();

    // The move's first two buffers, then one buffer refilled while DMA
    // sends the other.
    let mut player = Player::new(Ramp::steps(&RAMP));
    player.start(STEPS);
    let buffers = (
        cortex_m::singleton!(: [u32; BUFFER] = [0; BUFFER]).unwrap(),
        cortex_m::singleton!(: [u32; BUFFER] = [0; BUFFER]).unwrap(),
    );
    let dma = pac.DMA.split(&mut pac.RESETS);
    let (first, second) = buffers;
    let filled = (player.fill(&mut first[..]), player.fill(&mut second[..]));
    assert!(
        filled == (BUFFER, BUFFER),
        "a move of STEPS fills two buffers"
    );
    let mut transfer = double_buffer::Config::new((dma.ch0, dma.ch1), first, tx)
        .start()
        .read_next(second);
    let (last, n, mut tx) = loop {
        // The buffer DMA has sent, and the one it sends now.
        let (sent, sending) = transfer.wait();
        let n = player.fill(&mut sent[..]);
        if n < BUFFER {
            // The move's last words, after the transfer under way.
            let (_, _, _, tx) = sending.wait();
            break (sent, n, tx);
        }
        transfer = sending.read_next(sent);
    };
    for &word in &last[..n] {
        while !tx.write(word) {}
    }
    // The last step: the program stalls at `out`, the FIFO empty.
    while !tx.is_empty() || !sm.stalled() {}
    // The steps played: 0 - Y, through the ISR and the RX FIFO.
    sm.exec_instruction(Instruction {
        operands: InstructionOperands::MOV {
            destination: MovDestination::ISR,
            op: MovOperation::None,
            source: MovSource::Y,
        },
        delay: 0,
        side_set: Some(0),
    });
    sm.exec_instruction(Instruction {
        operands: InstructionOperands::PUSH {
            if_full: false,
            block: false,
        },
        delay: 0,
        side_set: Some(0),
    });
    let played = loop {
        if let Some(y) = rx.read() {
            break 0u32.wrapping_sub(y);
        }
    };
    if played != STEPS {
        panic!("{} steps played of {}", played, STEPS);
    }
    loop {
        cortex_m::asm::wfi(); // the move has played
    }
}
