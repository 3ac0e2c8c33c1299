//! Not in the README: runs the README's step interrupt, as written, in QEMU
//! (`mps2-an385`, `-icount shift=0,sleep=off`) and times every step edge by
//! a clock it does not drive.
//!
//! The MPU makes the step pin's registers fault: each write the README's
//! code makes to `OUTTGL` enters `MemoryManagement`, which stamps it with
//! the MPS2's CMSDK timer 0 (free-running on SysTick's 25 MHz clock: one
//! tick each) and steps past the store (the SAM's PORT is not on this
//! board). After two moves it checks each step's time against the table's
//! cumulative periods, and exits QEMU: status 0, or 1. The handler pulses
//! the pin before any other work, so every edge it makes comes the same
//! time after its wrap: from each move's second edge (the handler's first)
//! each must be at its time to the tick. The first edge is `main`'s, a
//! fixed few cycles less after the counter's start than the handler's
//! after a wrap: the first interval must be its period and at most the
//! one tick that difference rounds to here.

use core::arch::global_asm;
use core::ptr::{read_volatile, write_volatile};
use core::sync::atomic::{AtomicU32, AtomicUsize, Ordering};

use cortex_m_semihosting::{debug, hprintln};
// The examples share the rig's dev-dependencies: RTIC's (rtic_step.rs)
// turn on cortex-m-rt's `device` feature, which asks every example for a
// device's interrupt vectors: the LM3S6965's, unused.
use lm3s6965 as _;

/// Moves checked, and their steps (the README's moves of 5000).
const MOVES: usize = 2;
const STEPS: usize = 5000;

const CLOCK_CTRL: usize = 0x4000_0000;
const CLOCK_VALUE: usize = 0x4000_0004;
const CLOCK_RELOAD: usize = 0x4000_0008;
const SHPR3: usize = 0xE000_ED20;
const SHCSR: usize = 0xE000_ED24;
const CFSR: usize = 0xE000_ED28;
const MMFAR: usize = 0xE000_ED34;
const MPU_CTRL: usize = 0xE000_ED94;
const MPU_RNR: usize = 0xE000_ED98;
const MPU_RBAR: usize = 0xE000_ED9C;
const MPU_RASR: usize = 0xE000_EDA0;

static STAMPS: [AtomicU32; MOVES * STEPS] = [const { AtomicU32::new(0) }; MOVES * STEPS];
static TAKEN: AtomicUsize = AtomicUsize::new(0);

// Before the RAM is initialised and `main` runs: `arm`.
global_asm!(
    ".section .text.__pre_init,\"ax\",%progbits",
    ".global __pre_init",
    ".type __pre_init,%function",
    ".thumb_func",
    "__pre_init:",
    "b {arm}",
    arm = sym arm,
);

/// The clock running, SysTick below MemManage, and the PORT's 32 bytes out
/// of reach. No static touched: the RAM is not initialised yet.
unsafe extern "C" fn arm() {
    // SAFETY: the MPS2's timer and the core's system registers, written
    // before anything runs.
    unsafe {
        write_volatile(CLOCK_RELOAD as *mut u32, u32::MAX);
        write_volatile(CLOCK_VALUE as *mut u32, u32::MAX);
        write_volatile(CLOCK_CTRL as *mut u32, 1);
        write_volatile(SHPR3 as *mut u32, 0x80 << 24);
        write_volatile(MPU_RNR as *mut u32, 0);
        write_volatile(MPU_RBAR as *mut u32, 0x4100_8000);
        // Enabled, 32 bytes, no access, never executed.
        write_volatile(MPU_RASR as *mut u32, (1 << 28) | (4 << 1) | 1);
        // On, the default map elsewhere.
        write_volatile(MPU_CTRL as *mut u32, 0b101);
        write_volatile(SHCSR as *mut u32, 1 << 16);
    }
}

// The fault's stacked registers for `fault`: the main stack's top.
global_asm!(
    ".section .text.MemoryManagement,\"ax\",%progbits",
    ".global MemoryManagement",
    ".type MemoryManagement,%function",
    ".thumb_func",
    "MemoryManagement:",
    "mrs r0, msp",
    "b {fault}",
    fault = sym fault,
);

/// A write to the PORT: stamped (`OUTTGL`), and stepped past.
unsafe extern "C" fn fault(frame: *mut u32) {
    // SAFETY: the timer's value, and the fault's registers and stacked
    // frame, as the architecture lays them out.
    unsafe {
        let now = read_volatile(CLOCK_VALUE as *const u32);
        let address = read_volatile(MMFAR as *const u32);
        let status = read_volatile(CFSR as *const u32);
        if status & 0x80 == 0 || address & !0x1F != 0x4100_8000 {
            hprintln!("FAIL: a fault not on the step pin's registers");
            debug::exit(debug::EXIT_FAILURE);
        }
        write_volatile(CFSR as *mut u32, 0xFF);
        let pc = frame.add(6);
        let first = read_volatile(*pc as *const u16);
        *pc += if first >> 11 >= 0b11101 { 4 } else { 2 };
        if address == super::OUTTGL as u32 {
            let k = TAKEN.fetch_add(1, Ordering::Relaxed);
            if let Some(stamp) = STAMPS.get(k) {
                stamp.store(now, Ordering::Relaxed);
            }
            if k + 1 == MOVES * STEPS {
                check();
            }
        }
    }
}

/// Step `k`'s period of a move of 5000 on the README's ramp: up, 3000 at
/// the top, down; each entry the period less one.
fn period(k: usize) -> i64 {
    let top = super::RAMP.len() - 1;
    let entry = match k {
        k if k <= top => super::RAMP[k],
        k if k < STEPS - top => super::RAMP[top],
        k => super::RAMP[STEPS - 1 - k],
    };
    i64::from(entry) + 1
}

fn check() -> ! {
    let (mut exact, mut bad, mut first) = (0, 0, [0i64; MOVES]);
    for (m, first) in first.iter_mut().enumerate() {
        let stamp = |k: usize| i64::from(STAMPS[m * STEPS + k].load(Ordering::Relaxed));
        // The clock counts down. The first edge is `main`'s, a few
        // instructions after the counter starts; every later one the
        // handler's, its entry and a few instructions after a wrap. That
        // fixed difference is under a tick here (the core runs an
        // instruction a nanosecond, the clock ticks every 40), and the
        // stamps round it to 0 or 1 tick as the two clocks' phase falls:
        // the first interval is its period and at most a tick.
        *first = (stamp(0) - stamp(1)) - period(0);
        if !(0..=1).contains(first) {
            hprintln!("FAIL: move {}, its first interval {} ticks off", m, first);
            bad += 1;
        }
        // From the second edge on, each at its time to the tick.
        let mut time = 0;
        for k in 1..STEPS {
            let late = (stamp(1) - stamp(k)) - time;
            exact += usize::from(late == 0);
            if late != 0 {
                if bad == 0 {
                    hprintln!("FAIL: move {}, step {}: {} ticks off", m, k, late);
                }
                bad += 1;
            }
            time += period(k);
        }
    }
    hprintln!(
        "step_interrupt: {} steps timed at the pin, {} of the {} after each move's first at their time to the tick, {} off; each move's first interval its period and {:?} ticks",
        MOVES * STEPS,
        exact,
        MOVES * (STEPS - 1),
        bad,
        first
    );
    debug::exit(if bad == 0 {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    loop {
        cortex_m::asm::wfi();
    }
}
