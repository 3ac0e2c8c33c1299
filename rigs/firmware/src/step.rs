//! The step interrupt: SysTick's exception handler plays the move, and a
//! clock the player does not drive times every step.
//!
//! SysTick's reload register takes effect at the next wrap, so the player is
//! wrapped in [`Buffered`]: the first two periods are loaded at the start,
//! and each interrupt loads the period after the interval now starting. As
//! in the README's step interrupt, the main program hands the stepper (the
//! player and the timer) to the handler for a move ([`Handover`]) and waits
//! for the move's end in a poll loop; the handler loads each period and
//! toggles the step pin, with no lock. For the checks the handler also
//! records every period it loads and applies the move's events (a stop, a
//! cruise change) before given periods.
//!
//! Every step is stamped by the MPS2's CMSDK APB timer 0, free-running on
//! the same 25 MHz clock as SysTick: the handler reads it first, at a fixed
//! number of instructions after the wrap, and the start reads it at a tick
//! and starts SysTick a few instructions later. Under QEMU's `-icount
//! shift=0,sleep=off` (one instruction a nanosecond, 40 a tick, and an idle
//! loop that spins, not `wfi`) both stay within the same tick of the
//! events they time, so each step's stamp is its time from the start, in
//! ticks, exactly.

use core::cell::{RefCell, UnsafeCell};
use core::mem::MaybeUninit;
use core::ptr;
use core::sync::atomic::{AtomicBool, Ordering};

use cortex_m::peripheral::SYST;
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::exception;
use critical_section::Mutex;
use stepper_profiles::player::{Axes, Axis, Buffered, Compressed, Direction, Player};

use crate::moves::Event;

/// The most steps a move may record.
pub const MAX_STEPS: usize = 15_000;

/// The step pins: the MPS2 FPGA's LEDs (the SCC's `CFG_REG1`), bit 0 for
/// a player, bit `i` for axis `i` of [`Players::Axes`].
pub const STEP_PINS: usize = 0x4002_F004;

/// CMSDK APB timer 0: control and current value. It counts down from its
/// reload value at 25 MHz, the MPS2's system clock.
const CLOCK_CTRL: usize = 0x4000_0000;
const CLOCK_VALUE: usize = 0x4000_0004;
const CLOCK_RELOAD: usize = 0x4000_0008;

/// SysTick counts the core clock, the stamping clock's: one tick each.
pub const CLOCK_PER_TICK: u32 = 1;

/// The direction pins: bits 4, 5 and 6 of the same register, one an axis
/// (set: backward).
const DIR_SHIFT: u32 = 4;

/// The driver's `dir_setup` the firmware keeps: 5 µs, a DM542's, in ticks
/// of the 25 MHz clock. The interrupt sets the direction pins for the next
/// step right after the step it pulses (the axes' own directions are one
/// step ahead of the pins'), so the step that takes a new direction comes a
/// whole period later: at a reversal, the ramp's slowest entry. A move from
/// rest sets them and waits this long before its first step.
pub const DIR_SETUP_TICKS: u32 = 125;

/// The most direction changes a move records.
pub const MAX_TURNS: usize = 16;

/// Direction changes: each as the step that takes the new direction and
/// the clock's value just after the pins were written; and how many.
type Turns = ([(usize, u32); MAX_TURNS], usize);

/// The direction changes of the move playing.
pub static TURNS: Mutex<RefCell<Turns>> = Mutex::new(RefCell::new(([(0, 0); MAX_TURNS], 0)));

/// Steps whose direction pins did not say the step's direction when it
/// was pulsed.
pub static WRONG_DIRECTION: Mutex<RefCell<u32>> = Mutex::new(RefCell::new(0));

/// The stamps of the steps of the move playing: the clock's value at each.
pub static STAMPS: Mutex<RefCell<[u32; MAX_STEPS]>> = Mutex::new(RefCell::new([0; MAX_STEPS]));

/// The step pins toggled at each step of the move playing (bit `i`: pin
/// `i`).
pub static PINS: Mutex<RefCell<[u8; MAX_STEPS]>> = Mutex::new(RefCell::new([0; MAX_STEPS]));

/// The player the interrupt plays from, for SysTick's buffered reload: of
/// any layout, or of compressed tables only, or an axis with the position
/// its move goes to. One at a time, moved into the stepper and back: the
/// axes' variant, with their queue of lines, is the largest, and no other
/// is kept beside it.
#[allow(clippy::large_enum_variant)]
pub enum Players {
    Any(Buffered<Player<'static, u16>>),
    Compressed(Buffered<Player<'static, u16, Compressed>>),
    /// Three axes and the move they make (steps on each).
    Axes(Buffered<Axes<'static, u16, 3>>, [i64; 3]),
    /// An axis and the position its move goes to.
    Axis(Buffered<Axis<'static, u16>>, i64),
}

/// `$body` on whichever player `$players` holds, bound to `$p`.
macro_rules! with_player {
    ($players:expr, $p:ident => $body:expr) => {
        match $players {
            Players::Any($p) => $body,
            Players::Compressed($p) => $body,
            Players::Axes($p, _) => $body,
            Players::Axis($p, _) => $body,
        }
    };
}

impl Players {
    /// Starts a move (of `steps` steps; the axes make theirs): the first
    /// two periods, the pins the first step toggles and the direction pins
    /// it takes.
    pub fn start(&mut self, steps: u32) -> (Option<u16>, Option<u16>, u32, u32) {
        let (first, next, dirs) = match self {
            Players::Any(p) => {
                let (first, next) = p.start(steps);
                (first, next, 0)
            }
            Players::Compressed(p) => {
                let (first, next) = p.start(steps);
                (first, next, 0)
            }
            Players::Axes(p, delta) => {
                let s = p.move_by(*delta);
                return (s.first, s.next, s.mask, dir_bits(&s.directions));
            }
            Players::Axis(p, target) => {
                let (direction, first, next) = p.move_to(*target);
                (first, next, dir_bits(&[direction]))
            }
        };
        (first, next, u32::from(first.is_some()), dirs)
    }

    /// The direction pins of the step the pins take now.
    fn directions_now(&self) -> u32 {
        match self {
            Players::Axes(p, _) => dir_bits(&p.directions()),
            Players::Axis(p, _) => dir_bits(&[p.direction()]),
            _ => 0,
        }
    }

    /// The direction pins of the next step: the axes' own, one step ahead
    /// of the pins'.
    fn directions_next(&self) -> u32 {
        match self {
            Players::Axes(p, _) => dir_bits(&p.inner().directions()),
            Players::Axis(p, _) => dir_bits(&[p.inner().direction()]),
            _ => 0,
        }
    }

    /// From the interrupt: the pins that step now (0: the move is over),
    /// the period after the interval now starting to `load`.
    fn step(&mut self, load: impl FnMut(u16)) -> u32 {
        match self {
            Players::Any(p) => u32::from(p.step(load)),
            Players::Compressed(p) => u32::from(p.step(load)),
            Players::Axes(p, _) => p.step(load),
            Players::Axis(p, _) => u32::from(p.step(load)),
        }
    }

    /// An axis's position at the pin and direction.
    pub fn axis(&self) -> Option<(i64, Direction)> {
        match self {
            Players::Axis(p, _) => Some((p.position(), p.direction())),
            _ => None,
        }
    }

    /// Periods of the move not yet loaded: what the model counts.
    pub fn to_load(&self) -> u32 {
        with_player!(self, p => p.inner().remaining())
    }

    /// The axes' positions at the pins (zeros for a player).
    pub fn axes_position(&self) -> [i64; 3] {
        match self {
            Players::Axes(p, _) => p.position(),
            _ => [0; 3],
        }
    }

    pub fn is_done(&self) -> bool {
        with_player!(self, p => p.is_done())
    }
}

/// What the step interrupt plays and records.
pub struct Stepper {
    pub player: Players,
    pub timer: SYST,
    /// Events before given steps, in order.
    pub events: &'static [(u32, Event)],
    /// The periods loaded, in order: the pin plays them so.
    pub log: &'static mut [u16; MAX_STEPS],
    pub steps: usize,
    /// Steps taken (and stamped in [`STAMPS`]).
    pub taken: usize,
    /// Steps left in the move after each event.
    pub after_events: [u32; 4],
    /// Times the step pin was toggled.
    pub toggles: u32,
    /// The handler found the move done and stopped the timer.
    pub finished: bool,
}

/// A value the main program lends to the step interrupt: the main program
/// uses it only while SysTick's interrupt is disabled, the handler only
/// while it is enabled.
pub struct Handover<T>(UnsafeCell<MaybeUninit<T>>);

// SAFETY: one context at a time uses the value (the contracts below).
unsafe impl<T: Send> Sync for Handover<T> {}

impl<T> Handover<T> {
    /// # Safety
    /// From the main program while the interrupt is disabled, after `take`
    /// (or before any `put`).
    unsafe fn put(&self, value: T) {
        unsafe { (*self.0.get()).write(value) };
    }

    /// # Safety
    /// After `put`, from the handler while its interrupt is enabled; one
    /// reference at a time.
    #[allow(clippy::mut_from_ref)]
    unsafe fn get(&self) -> &mut T {
        unsafe { (*self.0.get()).assume_init_mut() }
    }

    /// # Safety
    /// After `put`, from the main program while the interrupt is disabled;
    /// the value is moved out (`put` again before the next `get`).
    unsafe fn take(&self) -> T {
        unsafe { (*self.0.get()).assume_init_read() }
    }
}

impl Stepper {
    /// A stepper for a move of `player` on `timer`, `events` before given
    /// steps, recording into `log`: nothing played yet.
    pub fn new(
        player: Players,
        timer: SYST,
        events: &'static [(u32, Event)],
        log: &'static mut [u16; MAX_STEPS],
    ) -> Self {
        Stepper {
            player,
            timer,
            events,
            log,
            steps: 0,
            taken: 0,
            after_events: [0; 4],
            toggles: 0,
            finished: false,
        }
    }
}

// SAFETY: SysTick and the log are the program's, used by one context at a
// time.
unsafe impl Send for Stepper {}

/// The stepper while a move plays: the step interrupt's.
static STEPPER: Handover<Stepper> = Handover(UnsafeCell::new(MaybeUninit::uninit()));

/// Set by the main program to start a move, cleared by the handler when it
/// has disabled its interrupt at the move's end.
static MOVING: AtomicBool = AtomicBool::new(false);

/// Starts the free-running clock that stamps the steps.
pub fn init_clock() {
    // SAFETY: CMSDK APB timer 0's registers, at the MPS2 AN385's documented
    // addresses; written once, before any interrupt.
    unsafe {
        ptr::write_volatile(CLOCK_RELOAD as *mut u32, u32::MAX);
        ptr::write_volatile(CLOCK_VALUE as *mut u32, u32::MAX);
        ptr::write_volatile(CLOCK_CTRL as *mut u32, 1);
    }
}

/// The free-running clock, in ticks (it counts down).
#[inline(always)]
fn clock() -> u32 {
    // SAFETY: CMSDK APB timer 0's current value, read only.
    unsafe { ptr::read_volatile(CLOCK_VALUE as *const u32) }
}

fn toggle_step_pins(pins: u32) {
    // SAFETY: the SCC's LED register, read and written back with the bits
    // of `pins` flipped.
    unsafe {
        let reg = STEP_PINS as *mut u32;
        ptr::write_volatile(reg, ptr::read_volatile(reg) ^ pins);
    }
}

/// The step pins as they are now.
pub fn step_pins() -> u32 {
    // SAFETY: the SCC's LED register, read only.
    unsafe { ptr::read_volatile(STEP_PINS as *const u32) }
}

/// Directions as the direction pins' bits.
fn dir_bits(directions: &[Direction]) -> u32 {
    directions
        .iter()
        .enumerate()
        .map(|(i, d)| u32::from(*d == Direction::Backward) << (DIR_SHIFT + i as u32))
        .fold(0, |a, b| a | b)
}

/// Writes the direction pins (bits 4 to 6) to `dirs`; `true` if they
/// changed.
fn set_dir_pins(dirs: u32) -> bool {
    const MASK: u32 = 0b111 << DIR_SHIFT;
    // SAFETY: the SCC's LED register, its direction bits replaced.
    unsafe {
        let reg = STEP_PINS as *mut u32;
        let was = ptr::read_volatile(reg);
        if was & MASK == dirs {
            return false;
        }
        ptr::write_volatile(reg, (was & !MASK) | dirs);
    }
    true
}

/// Records that the direction pins changed for step `step`.
fn record_turn(step: usize) {
    let stamp = clock();
    critical_section::with(|cs| {
        let mut turns = TURNS.borrow_ref_mut(cs);
        let n = turns.1;
        if let Some(slot) = turns.0.get_mut(n) {
            *slot = (step, stamp);
        }
        turns.1 = n + 1;
    });
}

/// The step interrupt.
#[exception]
fn SysTick() {
    // First, at a fixed distance from the wrap: the time of this step.
    let now = clock();
    // The interrupt is enabled before the stepper is handed over (to start
    // SysTick at a tick of the clock): nothing to do until then. The first
    // interval is far longer than the handover; a step missed would show
    // at the pin.
    if !MOVING.load(Ordering::Acquire) {
        return;
    }
    // SAFETY: `MOVING` is set: the stepper is the handler's.
    let s = unsafe { STEPPER.get() };
    {
        let k = s.steps as u32;
        for (i, &(at, event)) in s.events.iter().enumerate() {
            if at == k {
                match event {
                    Event::Cruise(pos) => with_player!(&mut s.player, p => p.set_cruise(pos)),
                    Event::Stop => with_player!(&mut s.player, p => p.stop()),
                    Event::Retarget(steps) => match &mut s.player {
                        Players::Any(p) => _ = p.retarget(steps),
                        Players::Compressed(p) => _ = p.retarget(steps),
                        _ => {}
                    },
                    Event::Target(target) => {
                        if let Players::Axes(p, _) = &mut s.player {
                            p.move_to(target);
                        }
                    }
                    Event::Queue(target) => {
                        if let Players::Axes(p, _) = &mut s.player {
                            _ = p.queue(target);
                        }
                    }
                    Event::Abort => with_player!(&mut s.player, p => p.abort()),
                    Event::Run => match &mut s.player {
                        Players::Any(p) => _ = p.run(),
                        Players::Compressed(p) => _ = p.run(),
                        _ => {}
                    },
                }
                if let Some(slot) = s.after_events.get_mut(i) {
                    *slot = s.player.to_load();
                }
            }
        }
        let (timer, log, steps) = (&mut s.timer, &mut *s.log, &mut s.steps);
        // SysTick counts from its reload value down to 0: a period of n
        // ticks is a reload of n - 1, loaded at the next wrap.
        let load = |period: u16| {
            timer.set_reload(u32::from(period) - 1);
            if let Some(slot) = log.get_mut(*steps) {
                *slot = period;
            }
            *steps += 1;
        };
        let pins = s.player.step(load);
        if pins != 0 {
            let dirs = step_pins() & (0b111 << DIR_SHIFT);
            toggle_step_pins(pins);
            // Only the axes that step now: the others' pins may already
            // say their next step's direction.
            let stepping = (pins & 0b111) << DIR_SHIFT;
            if (dirs ^ s.player.directions_now()) & stepping != 0 {
                critical_section::with(|cs| *WRONG_DIRECTION.borrow_ref_mut(cs) += 1);
            }
            // The next step's directions, a whole period ahead of it.
            if set_dir_pins(s.player.directions_next()) {
                record_turn(s.taken + 1);
            }
            critical_section::with(|cs| {
                if let Some(stamp) = STAMPS.borrow_ref_mut(cs).get_mut(s.taken) {
                    *stamp = now;
                }
                if let Some(slot) = PINS.borrow_ref_mut(cs).get_mut(s.taken) {
                    *slot = pins as u8;
                }
            });
            s.taken += 1;
            s.toggles += 1;
        } else {
            timer.disable_interrupt();
            timer.disable_counter();
            s.finished = true;
            // The stepper is the main program's again.
            MOVING.store(false, Ordering::Release);
        }
    }
}

/// Plays a move the stepper's player has not started: starts it, loads the
/// first period, starts SysTick at a tick of the clock (the first step,
/// stamped with that tick), loads the second, and waits, spinning, for the
/// handler to end the move. Returns the stepper, with what it recorded.
pub fn run(mut stepper: Stepper, steps: u32) -> Stepper {
    critical_section::with(|cs| {
        TURNS.borrow_ref_mut(cs).1 = 0;
        *WRONG_DIRECTION.borrow_ref_mut(cs) = 0;
    });
    let (first, next, pins, dirs) = stepper.player.start(steps);
    let Some(first) = first else {
        stepper.finished = true;
        return stepper;
    };
    // The first step's directions, `dir_setup` ahead of it.
    if set_dir_pins(dirs) {
        record_turn(0);
    }
    let set = clock();
    while set.wrapping_sub(clock()) < DIR_SETUP_TICKS {}
    stepper.log[0] = first;
    stepper.steps = 1;
    stepper.timer.set_clock_source(SystClkSource::Core);
    stepper.timer.set_reload(u32::from(first) - 1);
    stepper.timer.clear_current();
    stepper.timer.enable_interrupt();
    // Wait for a tick of the clock, and start at once after it.
    let before = clock();
    let mut start = clock();
    while start == before {
        start = clock();
    }
    stepper.timer.enable_counter();
    toggle_step_pins(pins);
    // SysTick loads its reload register at its first tick, at most one of
    // its own after the enable: the second period goes in after that.
    while start.wrapping_sub(clock()) <= CLOCK_PER_TICK {}
    if let Some(next) = next {
        stepper.timer.set_reload(u32::from(next) - 1);
        stepper.log[1] = next;
        stepper.steps = 2;
    }
    critical_section::with(|cs| {
        STAMPS.borrow_ref_mut(cs)[0] = start;
        PINS.borrow_ref_mut(cs)[0] = pins as u8;
    });
    stepper.taken = 1;
    stepper.toggles = 1;
    // Hand the stepper to the interrupt.
    // SAFETY: the handler returns at once while `MOVING` is clear, so the
    // main program owns the stepper.
    unsafe { STEPPER.put(stepper) };
    MOVING.store(true, Ordering::Release);
    // Spin: under `-icount`, `wfi` would let the clock run past interrupts
    // (and QEMU leaves its loop at every `yield` of a spin loop hint).
    while MOVING.load(Ordering::Acquire) {
        cortex_m::asm::nop();
    }
    // SAFETY: the handler has disabled its interrupt and given the stepper
    // back.
    unsafe { STEPPER.take() }
}

/// The direction changes of the last move, each as the step that took the
/// new direction and the time from the change to that step, in ticks of
/// the stamping clock; and the steps pulsed with the wrong direction.
pub fn turns(taken: usize, mut each: impl FnMut(usize, u32)) -> u32 {
    critical_section::with(|cs| {
        let stamps = STAMPS.borrow_ref(cs);
        let turns = TURNS.borrow_ref(cs);
        for &(step, at) in &turns.0[..turns.1.min(MAX_TURNS)] {
            if step < taken.min(MAX_STEPS) {
                each(step, at.wrapping_sub(stamps[step]));
            }
        }
        *WRONG_DIRECTION.borrow_ref(cs)
    })
}

/// Each step's time from the move's start, in ticks of the stamping clock:
/// `each(k, time)` for step `k`.
pub fn step_times(taken: usize, mut each: impl FnMut(usize, u32)) {
    critical_section::with(|cs| {
        let stamps = STAMPS.borrow_ref(cs);
        for (k, &stamp) in stamps[..taken.min(MAX_STEPS)].iter().enumerate() {
            each(k, stamps[0].wrapping_sub(stamp));
        }
    });
}
