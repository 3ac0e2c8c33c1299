//! The step interrupt: SysTick's exception handler plays the move.
//!
//! The player and the timer live in a `critical_section::Mutex`, shared by
//! the main program (which starts moves and waits) and the handler (which
//! writes each period to SysTick's reload register and toggles the step
//! pin). For the checks the handler also records every period it plays and
//! applies the move's events (a stop, a cruise change) before given steps.

use core::cell::RefCell;
use core::ptr;

use cortex_m::peripheral::SYST;
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::exception;
use critical_section::Mutex;
use stepper_profiles::player::{Compressed, Player};

use crate::moves::Event;

/// The most steps a move may record.
pub const MAX_STEPS: usize = 15_000;

/// The step pin: GPIO port F, pin 0, on the LM3S6965 (the evaluation
/// board's user LED).
const GPIO_F: usize = 0x4002_5000;
const GPIO_DATA_PIN0: usize = GPIO_F + (1 << 2);
const GPIO_DIR: usize = GPIO_F + 0x400;
const GPIO_DEN: usize = GPIO_F + 0x51C;
const SYSCTL_RCGC2: usize = 0x400F_E108;

/// The player the interrupt plays from: of any layout, or of compressed
/// tables only.
pub enum Players {
    Any(Player<'static, u16>),
    Compressed(Player<'static, u16, Compressed>),
}

/// `$body` on whichever player `$players` holds, bound to `$p`.
macro_rules! with_player {
    ($players:expr, $p:ident => $body:expr) => {
        match $players {
            Players::Any($p) => $body,
            Players::Compressed($p) => $body,
        }
    };
}

impl Players {
    pub fn start(&mut self, steps: u32) {
        with_player!(self, p => p.start(steps))
    }

    pub fn remaining(&self) -> u32 {
        with_player!(self, p => p.remaining())
    }

    pub fn is_done(&self) -> bool {
        with_player!(self, p => p.is_done())
    }

    fn next_period(&mut self) -> Option<u16> {
        with_player!(self, p => p.next_period())
    }
}

/// What the step interrupt plays and records.
pub struct Stepper {
    pub player: Players,
    pub timer: SYST,
    /// Events before given steps, in order.
    pub events: &'static [(u32, Event)],
    /// The periods played.
    pub log: &'static mut [u16; MAX_STEPS],
    pub steps: usize,
    /// Steps left in the move after each event.
    pub after_events: [u32; 4],
    /// Times the step pin was toggled.
    pub toggles: u32,
    /// The handler found the move done and stopped the timer.
    pub finished: bool,
}

/// Shared by the main program and the step interrupt.
pub static STEPPER: Mutex<RefCell<Option<Stepper>>> = Mutex::new(RefCell::new(None));

/// Turns the step pin's port on and makes pin 0 an output.
pub fn init_step_pin() {
    // SAFETY: the LM3S6965's system control and GPIO port F registers, at
    // their documented addresses; written once, before any interrupt.
    unsafe {
        ptr::write_volatile(SYSCTL_RCGC2 as *mut u32, 1 << 5);
        ptr::write_volatile(GPIO_DIR as *mut u32, 1);
        ptr::write_volatile(GPIO_DEN as *mut u32, 1);
    }
}

fn toggle_step_pin() {
    // SAFETY: GPIO port F's data register, masked to pin 0.
    unsafe {
        let pin = GPIO_DATA_PIN0 as *mut u32;
        ptr::write_volatile(pin, ptr::read_volatile(pin) ^ 1);
    }
}

/// The step interrupt.
#[exception]
fn SysTick() {
    critical_section::with(|cs| {
        let mut stepper = STEPPER.borrow_ref_mut(cs);
        let Some(s) = stepper.as_mut() else {
            return;
        };
        let k = s.steps as u32;
        for (i, &(at, event)) in s.events.iter().enumerate() {
            if at == k {
                match event {
                    Event::Cruise(pos) => with_player!(&mut s.player, p => p.set_cruise(pos)),
                    Event::Stop => with_player!(&mut s.player, p => p.stop()),
                }
                if let Some(slot) = s.after_events.get_mut(i) {
                    *slot = s.player.remaining();
                }
            }
        }
        let (timer, log, steps) = (&mut s.timer, &mut *s.log, &mut s.steps);
        // SysTick counts from its reload value down to 0: a period of n
        // ticks is a reload of n - 1.
        let write = |period: u16| {
            timer.set_reload(u32::from(period) - 1);
            if let Some(slot) = log.get_mut(*steps) {
                *slot = period;
            }
            *steps += 1;
        };
        let stepped = with_player!(&mut s.player, p => p.step(write));
        if stepped {
            toggle_step_pin();
            s.toggles += 1;
        } else {
            timer.disable_interrupt();
            timer.disable_counter();
            s.finished = true;
        }
    });
}

/// Plays a move from the interrupt: starts the timer on the first period
/// and waits for the handler to end the move. Returns the stepper, with
/// what it recorded.
pub fn run(mut stepper: Stepper) -> Stepper {
    let first = stepper.player.next_period();
    let Some(first) = first else {
        stepper.finished = true;
        return stepper;
    };
    // The first step is taken at once: its period times the first interval.
    stepper.log[0] = first;
    stepper.steps = 1;
    toggle_step_pin();
    stepper.toggles = 1;
    stepper.timer.set_clock_source(SystClkSource::Core);
    stepper.timer.set_reload(u32::from(first) - 1);
    stepper.timer.clear_current();
    critical_section::with(|cs| STEPPER.borrow(cs).replace(Some(stepper)));
    critical_section::with(|cs| {
        if let Some(s) = STEPPER.borrow_ref_mut(cs).as_mut() {
            s.timer.enable_interrupt();
            s.timer.enable_counter();
        }
    });
    loop {
        let done =
            critical_section::with(|cs| STEPPER.borrow_ref(cs).as_ref().is_none_or(|s| s.finished));
        if done {
            break;
        }
        cortex_m::asm::wfi();
    }
    // The handler has stopped the timer; take the stepper back.
    critical_section::with(|cs| STEPPER.borrow(cs).replace(None)).expect("the stepper was set")
}
