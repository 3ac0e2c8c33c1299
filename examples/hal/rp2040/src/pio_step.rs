//! The PIO program that plays periods from its TX FIFO, and its cycle
//! arithmetic: shared by `bin/pio.rs`, which installs it on an RP2040, and
//! by the host test that runs its instructions (`tests/pio.rs` of the
//! `stepper-profiles` repository).
//!
//! ```text
//! .side_set 1                        ; the step pin
//! .wrap_target
//!     out x, 32        side 0        ; the next period (autopull): stalls, low, when none is left
//!     jmp y--, count   side 1 [9]    ; the step: high for 10 cycles; Y counts it down
//! count:
//!     jmp x--, count   side 0        ; low for X + 1 cycles
//! .wrap
//! ```
//!
//! A step takes `1 + PULSE + (X + 1)` cycles, from one rising edge to the
//! next: a period of `p` cycles is the word `p - OVERHEAD`, which a table
//! holds with `reload_offset = -12`; the shortest period is `OVERHEAD`
//! cycles (the word 0). Y starts at 0 and is decremented once a step: the
//! steps played are `0 - Y`.

use stepper_profiles::period_table;

/// The program's instructions, as `pio::pio_asm!` assembles the text above
/// (side-set of one bit, not optional; wrap from 2 to 0; jump targets
/// relative to the program's start, moved where it is installed).
pub const PROGRAM: [u16; 3] = [0x6020, 0x1982, 0x0042];
/// The wrap: from the last instruction back to the first.
pub const WRAP_SOURCE: u8 = 2;
pub const WRAP_TARGET: u8 = 0;

/// Cycles the step pin stays high: the `jmp y--` and its delay of 9.
pub const PULSE: u32 = 10;
/// Cycles of a step besides `X`: the `out`, the pulse, and the countdown's
/// last `jmp`.
pub const OVERHEAD: u32 = 1 + PULSE + 1;

/// The state machine's clock: 125 MHz (what `init_clocks_and_plls` sets on
/// a Pico) divided by 25, an integer, so that every cycle is the same.
pub const SYS_HZ: u32 = 125_000_000;
pub const DIVIDER: u16 = 25;
pub const PIO_HZ: u32 = SYS_HZ / DIVIDER as u32;

/// 400 steps from 500 Hz to 20 kHz, S-shaped, in cycles of the state
/// machine's 5 MHz clock, each stored as the word the program takes: the
/// period less `OVERHEAD` (a period under it is a compile error).
pub static RAMP: [u32; 400] = period_table!(
    curve = sigmoid,
    len = 400,
    fmin = 500,
    fmax = 20kHz,
    flexible = 8,
    timer_hz = 5MHz,
    word = u32,
    reload_offset = -12,
);

// The table's offset and rate are the program's.
const _: () = assert!(OVERHEAD == 12 && PIO_HZ == 5_000_000);
