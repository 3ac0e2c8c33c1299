//! The figures of `docs/performance.md`'s table, on the core this is built
//! for: instructions per step of a step interrupt's work, counted in QEMU's
//! instruction trace between two marker functions (`measure.sh`).
//!
//! Each step function does what a step interrupt does (the next period into
//! the timer's reload register, here SysTick's) and is neither inlined nor
//! mangled, so that the trace names it. The loops that call them stand in
//! for the interrupt's entry and exit, which are not counted.
#![no_std]
#![no_main]

use core::hint::black_box;
use cortex_m::asm;
use cortex_m::peripheral::SYST;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;
use stepgen::Stepgen;
use stepper_profiles::player::{Axes, Axis, Buffered, Compressed, Direction, Layout, Player, Ramp};
use stepper_profiles::runs::RunIndex;

/// The tables of the root `profiles.toml`.
mod profiles {
    stepper_profiles::include_profiles!("../../profiles.toml");
}

mod handler;

// On the M3 and M4F the package depends on RTIC (src/bin/rtic.rs), whose
// runtime asks for a device's interrupt vectors: the LM3S6965's, unused.
#[cfg(rtic)]
use lm3s6965 as _;

use profiles::{exponential_segments, microstep_runs, sigmoid_exact, sigmoid_orange};

/// Steps of the measured move: up the ramp, cruise, down the ramp.
pub const UP: u32 = sigmoid_exact::LEN as u32;
pub const CRUISE: u32 = 3000;

/// Marks the start of a measured stretch in the instruction trace.
#[inline(never)]
#[unsafe(no_mangle)]
pub extern "C" fn measure_begin() {
    asm::nop();
}

/// Marks its end (another body, so that the two are not merged).
#[inline(never)]
#[unsafe(no_mangle)]
pub extern "C" fn measure_end() {
    asm::nop();
    asm::nop();
}

/// The baseline: `reload = PERIODS[i]; i += 1`, the index checked against
/// the table's length as safe Rust does.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn bare_step(next: &mut usize, timer: &mut SYST) {
    if let Some(&period) = sigmoid_exact::PERIODS.get(*next) {
        timer.set_reload(u32::from(period));
        *next += 1;
    }
}

/// The same load through a slice iterator.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn iter_step(periods: &mut core::slice::Iter<'_, u16>, timer: &mut SYST) {
    if let Some(&period) = periods.next() {
        timer.set_reload(u32::from(period));
    }
}

/// The player's next period into the reload register.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_step(player: &mut Player<'_, u16>, timer: &mut SYST) {
    player.step(|period| timer.set_reload(u32::from(period)));
}

/// The same for a player of compressed tables.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_runs_step(player: &mut Player<'_, u16, Compressed>, timer: &mut SYST) {
    player.step(|period| timer.set_reload(u32::from(period)));
}

/// [`Player::next_period`] into the reload register: the same step as
/// [`player_step`], its period returned as an `Option`.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_next_period(player: &mut Player<'_, u16>, timer: &mut SYST) {
    if let Some(period) = player.next_period() {
        timer.set_reload(u32::from(period));
    }
}

/// The same for a player of compressed tables.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_runs_next_period(player: &mut Player<'_, u16, Compressed>, timer: &mut SYST) {
    if let Some(period) = player.next_period() {
        timer.set_reload(u32::from(period));
    }
}

/// The axis's next step into the reload register: the player's, with the
/// position kept.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn axis_step(axis: &mut Axis<'_, u16>, timer: &mut SYST) {
    axis.step(|period| timer.set_reload(u32::from(period)));
}

/// Three axes on one ramp: the lead's next period into the reload
/// register, and the mask of the axes that step on the edge to the step
/// pins.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn axes_step(axes: &mut Axes<'_, u16, 3>, timer: &mut SYST, pins: &mut u32) {
    axes.step(|period, mask| {
        timer.set_reload(u32::from(period));
        *pins = mask;
    });
}

/// The next periods into a DMA buffer: [`Player::fill`].
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_fill(player: &mut Player<'_, u16>, buf: &mut [u16]) -> usize {
    player.fill(buf)
}

/// The same for a player of compressed tables.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_runs_fill(player: &mut Player<'_, u16, Compressed>, buf: &mut [u16]) -> usize {
    player.fill(buf)
}

// Buffered: the step functions of a player for a reload register that
// takes effect at the next wrap (SysTick's), and their moves.

/// For a buffered reload register: the period after the interval now
/// starting into the reload register.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn buffered_step(player: &mut Buffered<Player<'_, u16>>, timer: &mut SYST) {
    player.step(|period| timer.set_reload(u32::from(period)));
}

/// The same for a player of compressed tables.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn buffered_runs_step(player: &mut Buffered<Player<'_, u16, Compressed>>, timer: &mut SYST) {
    player.step(|period| timer.set_reload(u32::from(period)));
}

/// The same for an axis.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn buffered_axis_step(axis: &mut Buffered<Axis<'_, u16>>, timer: &mut SYST) {
    axis.step(|period| timer.set_reload(u32::from(period)));
}

/// The moves of the player, the compressed player and the axis, each
/// wrapped in [`Buffered`]: two periods at the start, then one from each
/// interrupt, the last two interrupts without.
fn buffered_moves(timer: &mut SYST) {
    let mut buffered = Buffered::new(Player::new(Ramp::steps(&sigmoid_exact::PERIODS)));
    let _ = buffered.start(2 * UP + CRUISE);
    phases(
        "Buffered, per-step table (sigmoid_exact)",
        (UP, CRUISE),
        || buffered_step(&mut buffered, timer),
    );
    check(buffered.is_done(), "buffered player");
    let up = microstep_runs::LEN as u32;
    let mut buffered = Buffered::new(Player::new(&microstep_runs::RUNS));
    let _ = buffered.start(2 * up + 1000);
    phases(
        "Buffered compressed Player (microstep, compress = 1)",
        (up, 1000),
        || buffered_runs_step(&mut buffered, timer),
    );
    check(buffered.is_done(), "buffered compressed player");
    let axis = Axis::new(Player::new(Ramp::steps(&sigmoid_exact::PERIODS)), 0);
    let mut buffered = Buffered::new(axis);
    let moved = buffered.move_by(-i64::from(2 * UP + CRUISE));
    check(moved.0 == Direction::Backward, "buffered axis move");
    phases(
        "Buffered axis, per-step table (sigmoid_exact)",
        (UP, CRUISE),
        || buffered_axis_step(&mut buffered, timer),
    );
    check(
        buffered.is_done() && buffered.position() == -i64::from(2 * UP + CRUISE),
        "buffered axis position",
    );
}

/// The peer: stepgen computes each delay (16.8 fixed point, rounded).
#[inline(never)]
#[unsafe(no_mangle)]
pub fn stepgen_step(stepgen: &mut Stepgen, timer: &mut SYST) {
    if let Some(delay) = stepgen.next() {
        timer.set_reload((delay + 128) >> 8);
    }
}

/// Planning a move, stopping it, changing its cruise speed.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_start(player: &mut Player<'_, u16>, steps: u32) {
    player.start(steps);
}

#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_stop(player: &mut Player<'_, u16>) {
    player.stop();
}

#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_set_cruise(player: &mut Player<'_, u16>, pos: u32) {
    player.set_cruise(pos);
}

/// A player made on a per-step table: each ramp read once for its slack,
/// and once more, both together, for how far ahead the deceleration ramp
/// is faster. Not inlined and not mangled, as the planning calls.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_new(periods: &'static [u16]) -> Player<'static, u16> {
    Player::new(Ramp::steps(periods))
}

/// [`player_new`] on a compressed ramp.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_runs_new(runs: &'static [[u16; 5]]) -> Player<'static, u16, Compressed> {
    Player::new(runs)
}

/// [`player_new`] on a compressed ramp with its index.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn player_runs_new_indexed(
    index: &'static RunIndex<{ microstep_runs::RUNS.len() }>,
) -> Player<'static, u16, Compressed> {
    Player::new(index)
}

/// Planning calls, one set per kind of player: not inlined and not
/// mangled, so that the trace names them.
macro_rules! planning_calls {
    ($player:ty, $start:ident, $cruise:ident, $cruise_period:ident, $retarget:ident, $stop:ident) => {
        #[inline(never)]
        #[unsafe(no_mangle)]
        pub fn $start(player: &mut $player, steps: u32) {
            player.start(steps);
        }

        #[inline(never)]
        #[unsafe(no_mangle)]
        pub fn $cruise(player: &mut $player, pos: u32) {
            player.set_cruise(pos);
        }

        #[inline(never)]
        #[unsafe(no_mangle)]
        pub fn $cruise_period(player: &mut $player, period: u16) {
            player.set_cruise_period(period);
        }

        #[inline(never)]
        #[unsafe(no_mangle)]
        pub fn $retarget(player: &mut $player, steps: u32) -> bool {
            player.retarget(steps)
        }

        #[inline(never)]
        #[unsafe(no_mangle)]
        pub fn $stop(player: &mut $player) {
            player.stop();
        }
    };
}

planning_calls!(
    Player<'_, u16>,
    player_plan_start,
    player_plan_set_cruise,
    player_plan_set_cruise_period,
    player_plan_retarget,
    player_plan_stop
);
planning_calls!(
    Player<'_, u16, Compressed>,
    player_runs_plan_start,
    player_runs_plan_set_cruise,
    player_runs_plan_set_cruise_period,
    player_runs_plan_retarget,
    player_runs_plan_stop
);

/// Plays `n` steps of a player, not measured.
fn skip<L: Layout>(player: &mut Player<'_, u16, L>, n: u32) {
    for _ in 0..n {
        player.next_period();
    }
}

/// Planning on one ramp of `len` steps, each call measured once: a move of
/// `2 len + 3000` steps starts; cruising, it changes its cruise speed to
/// the ramp's middle, then to twice the top's period, takes a target 1000
/// steps farther, and stops. Before the stop, a copy takes a target 2000
/// steps nearer, and another one 300 steps past the stop's. With `after`, the step after each call is
/// measured too (a compressed player's call leaves its first run to it).
macro_rules! planning {
    (@after $label:expr, $player:expr, $call:expr, $step:ident, $timer:expr) => {
        hprintln!("measure: planning, {}, the step after {}: 1 call", $label, $call);
        measure_begin();
        $step($player, $timer);
        measure_end();
    };
    (@after $label:expr, $player:expr, $call:expr) => {
        skip($player, 1)
    };
    ($label:expr, $player:expr, $len:expr, $top:expr, $start:ident, $cruise:ident,
     $cruise_period:ident, $retarget:ident, $stop:ident $(, after $step:ident, $timer:expr)?) => {{
        let mut player = $player;
        let len: u32 = $len;
        let top: u16 = $top;
        once(concat!("planning, ", $label, ", start"), || {
            $start(&mut player, 2 * len + 3000)
        });
        planning!(@after $label, &mut player, "start" $(, $step, $timer)?);
        skip(&mut player, len + 99);
        once(concat!("planning, ", $label, ", set_cruise"), || {
            $cruise(&mut player, len / 2)
        });
        planning!(@after $label, &mut player, "set_cruise" $(, $step, $timer)?);
        skip(&mut player, 199);
        once(concat!("planning, ", $label, ", set_cruise_period"), || {
            $cruise_period(&mut player, 2 * top)
        });
        planning!(@after $label, &mut player, "set_cruise_period" $(, $step, $timer)?);
        skip(&mut player, 199);
        let steps = player.remaining() + 1000;
        let mut taken = false;
        once(concat!("planning, ", $label, ", retarget"), || {
            taken = $retarget(&mut player, steps)
        });
        check(taken, "retarget");
        planning!(@after $label, &mut player, "retarget" $(, $step, $timer)?);
        skip(&mut player, 99);
        // A target 2000 steps nearer, on a copy: the deceleration comes
        // into reach while the move walks down to its cruise position.
        let mut nearer = player.clone();
        let steps = nearer.remaining() - 2000;
        let mut taken = false;
        once(concat!("planning, ", $label, ", retarget nearer"), || {
            taken = $retarget(&mut nearer, steps)
        });
        check(taken, "retarget nearer");
        planning!(@after $label, &mut nearer, "retarget nearer" $(, $step, $timer)?);
        // A target 300 steps past the stop's, on another copy: the move
        // walks down all the way to its cruise position with the
        // deceleration ramp 300 steps ahead.
        let mut past_stop = player.clone();
        let steps = past_stop.steps_to_stop() + 300;
        once(concat!("planning, ", $label, ", retarget 300 past the stop"), || {
            taken = $retarget(&mut past_stop, steps)
        });
        check(taken, "retarget 300 past the stop");
        once(concat!("planning, ", $label, ", stop"), || {
            $stop(&mut player)
        });
        planning!(@after $label, &mut player, "stop" $(, $step, $timer)?);
        while player.next_period().is_some() {}
    }};
}

/// The lead's steps in the axes' move.
const AXES_LEAD: u32 = 2 * UP + CRUISE;

/// Three axes on the move of the per-step player, the lead on axis 1; the
/// followers step on 4321 and 1234 of its 5000 steps, each on the lead
/// steps the rule of `Axes` names (checked after the move, from the edges
/// kept as bits). Not inlined, so that `main`'s frame (and with it where
/// the DMA buffers of the fills lie) stays as it is without it.
#[inline(never)]
fn axes_move(timer: &mut SYST) {
    let (lead, high, low) = (i64::from(AXES_LEAD), 4321, -1234);
    let mut axes = Axes::new(Player::new(Ramp::steps(&sigmoid_exact::PERIODS)), [0; 3]);
    check(
        axes.move_by([high, lead, low])
            == [Direction::Forward, Direction::Forward, Direction::Backward],
        "axes move",
    );
    let mut pins = 0u32;
    let mut stepped = [0i64; 3];
    // Bit `e % 32` of word `e / 32`: whether the axis stepped on edge `e`
    // (the followers', axes 0 and 2).
    let mut edges = [[0u32; AXES_LEAD as usize / 32 + 1]; 2];
    let mut edge = 0usize;
    phases(
        "axes, 3 (1 lead + 2 followers), per-step table",
        (UP, CRUISE),
        || {
            axes_step(&mut axes, timer, &mut pins);
            for (i, n) in stepped.iter_mut().enumerate() {
                *n += i64::from(pins >> i & 1);
            }
            for (bits, axis) in edges.iter_mut().zip([0, 2]) {
                bits[edge / 32] |= (pins >> axis & 1) << (edge % 32);
            }
            edge += 1;
        },
    );
    check(
        axes.position() == [high, lead, low] && stepped == [high, lead, -low],
        "axes positions",
    );
    // The rule: a follower of `d` steps takes its `k`-th on the lead's step
    // `floor((2kL + d) / 2d)` (numbered from 1), so on edge `e` (from 0)
    // it steps when some `k` names lead step `e + 1`.
    for (bits, d) in edges.iter().zip([high.unsigned_abs(), low.unsigned_abs()]) {
        let l = u64::from(AXES_LEAD);
        let mut k = 1;
        for e in 0..AXES_LEAD as usize {
            let names = k <= d && (2 * k * l + d) / (2 * d) == e as u64 + 1;
            if names {
                k += 1;
            }
            check(
                bits[e / 32] >> (e % 32) & 1 == u32::from(names),
                "axes rule",
            );
        }
        check(k == d + 1, "axes rule, every step");
    }
}

/// Queues a line on three axes ([`Axes::queue`]): the planning call of a
/// line that joins the one playing at speed.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn axes_queue(axes: &mut Axes<'_, u16, 3>, target: [i64; 3]) -> bool {
    axes.queue(target).is_ok()
}

/// Queues a target on an axis ([`Axis::queue`]): the planning call of a
/// target the same way, which the move playing goes on to at speed.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn axis_queue(axis: &mut Axis<'_, u16>, target: i64) -> bool {
    axis.queue(target).is_ok()
}

/// An axis's queue: a target the same way queued while the move plays at
/// its top (the move goes on to it, joined at speed), measured; the axis
/// ends there.
#[inline(never)]
fn axis_joined(timer: &mut SYST) {
    let mut axis = Axis::new(Player::new(Ramp::steps(&sigmoid_exact::PERIODS)), 0);
    check(axis_queue(&mut axis, 3000), "axis queue, first target");
    for _ in 0..1500 {
        axis_step(&mut axis, timer);
    }
    once(
        "planning, queue, axis, a target the same way joined to the move playing",
        || {
            check(axis_queue(&mut axis, 6000), "axis queue, joined");
        },
    );
    while !axis.is_done() {
        axis_step(&mut axis, timer);
    }
    check(axis.position() == 6000, "axis queue, position");
}

/// The vertices of the queued polyline: three lines of 3000, 3000 and
/// 3000 lead steps (axis 1 leads), bending by a few degrees, no axis
/// reversing.
const POLYLINE: [[i64; 3]; 3] = [[1200, 3000, -400], [2500, 6000, -700], [3700, 9000, -1200]];

/// Three axes on a queued polyline: the queue call that joins the second
/// line to the first, the steps of each line but its first, and the step
/// at each vertex (the next line's first, which starts it), measured on
/// their own; the axes end at the last vertex.
#[inline(never)]
fn axes_polyline(timer: &mut SYST) {
    let player = Player::new(Ramp::steps(&sigmoid_exact::PERIODS));
    let mut axes = Axes::new(player, [0; 3]).with_junction_deviation(4.0);
    let mut pins = 0u32;
    check(axes_queue(&mut axes, POLYLINE[0]), "polyline, first line");
    once(
        "planning, queue, axes 3, a line joined to the one playing",
        || {
            check(axes_queue(&mut axes, POLYLINE[1]), "polyline, second line");
        },
    );
    check(axes_queue(&mut axes, POLYLINE[2]), "polyline, third line");
    let label = "axes, 3, queued polyline (per-step table)";
    steps(label, "line 1", 3000, || {
        axes_step(&mut axes, timer, &mut pins)
    });
    for line in 2..=3 {
        once("axes, 3, queued polyline, the step at a vertex", || {
            axes_step(&mut axes, timer, &mut pins)
        });
        let phase = if line == 2 {
            "line 2 after its first step"
        } else {
            "line 3 after its first step"
        };
        steps(label, phase, 2999, || {
            axes_step(&mut axes, timer, &mut pins)
        });
    }
    check(
        axes.position() == POLYLINE[2] && axes.is_done(),
        "polyline positions",
    );
}

/// Runs `steps` calls of a step function between the markers.
fn steps(label: &str, phase: &str, n: u32, mut step: impl FnMut()) {
    hprintln!("measure: {} {}: {} steps", label, phase, n);
    measure_begin();
    for _ in 0..n {
        step();
    }
    measure_end();
}

/// A move's three phases, `up` steps accelerating, `cruise` cruising and
/// `up` decelerating, each measured on its own.
pub fn phases(label: &str, (up, cruise): (u32, u32), mut step: impl FnMut()) {
    for (phase, n) in [
        ("accelerating", up),
        ("cruising", cruise),
        ("decelerating", up),
    ] {
        steps(label, phase, n, &mut step);
    }
}

/// A move of the player on `ramp`, phase by phase.
fn player_move(label: &str, ramp: Ramp<'_, u16>, (up, cruise): (u32, u32), timer: &mut SYST) {
    let mut player = Player::new(ramp);
    player.start(2 * up + cruise);
    phases(label, (up, cruise), || player_step(&mut player, timer));
    check(player.is_done(), label);
}

/// A DMA buffer of `B` periods (`B` even) at a word's boundary, and one
/// half a word past it.
#[repr(C, align(4))]
struct Buffers<const B: usize> {
    word: [u16; B],
    pad: u16,
    half: [u16; B],
}

/// Periods of DMA buffers (ping-pong halves) filled per phase of a move of
/// `up`, `cruise`, `up` steps, `B` periods a call; each phase a whole
/// number of buffers. The buffer is read back, so that the writes count;
/// it starts at a word's boundary, or half a word past it (`half`).
// Not inlined, so that the trace sees the loop (the buffer's sum included)
// as the caller's own lines, not counted.
#[inline(never)]
fn fill_phases<const B: usize>(
    label: &str,
    (up, cruise): (u32, u32),
    half: bool,
    mut fill: impl FnMut(&mut [u16]) -> usize,
) -> u32 {
    let mut buffers = Buffers {
        word: [0u16; B],
        pad: 0,
        half: [0u16; B],
    };
    let buf = if half {
        &mut buffers.half
    } else {
        &mut buffers.word
    };
    let mut sum = u32::from(buffers.pad);
    for (phase, n) in [
        ("accelerating", up),
        ("cruising", cruise),
        ("decelerating", up),
    ] {
        check(n % B as u32 == 0, "whole buffers");
        hprintln!("measure: {} {}: {} periods", label, phase, n);
        measure_begin();
        for _ in 0..n / B as u32 {
            let filled = fill(buf);
            for &p in &buf[..filled] {
                sum = sum.wrapping_add(u32::from(p));
            }
        }
        measure_end();
    }
    sum
}

/// One call, between the markers.
fn once(label: &str, call: impl FnOnce()) {
    hprintln!("measure: {}: 1 call", label);
    measure_begin();
    call();
    measure_end();
}

/// The period of a compressed ramp's top: its last step.
fn last_run(runs: &[[u16; 5]]) -> u32 {
    stepper_profiles::runs::Expand::new(runs)
        .last()
        .unwrap_or(0)
}

pub fn check(ok: bool, what: &str) {
    if !ok {
        hprintln!("FAIL {}", what);
        debug::exit(debug::EXIT_FAILURE);
    }
}

#[entry]
fn main() -> ! {
    let mut timer = cortex_m::Peripherals::take()
        .expect("peripherals are taken once")
        .SYST;
    let timer = &mut timer;

    let mut next = 0;
    steps("bare load, PERIODS[i]", "(sigmoid_exact)", UP, || {
        bare_step(&mut next, timer)
    });
    check(next == UP as usize, "bare load");
    let mut periods = sigmoid_exact::PERIODS.iter();
    steps("bare load, slice iterator", "(sigmoid_exact)", UP, || {
        iter_step(&mut periods, timer)
    });

    player_move(
        "player, per-step table (sigmoid_exact)",
        Ramp::steps(&sigmoid_exact::PERIODS),
        (UP, CRUISE),
        timer,
    );
    player_move(
        "player, held x4 (sigmoid_orange)",
        Ramp::held(&sigmoid_orange::PERIODS, 4),
        (4 * sigmoid_orange::LEN as u32, 1000),
        timer,
    );
    player_move(
        "player, compressed runs (microstep, compress = 1)",
        Ramp::runs(&microstep_runs::RUNS),
        (microstep_runs::LEN as u32, 1000),
        timer,
    );
    // The player of compressed tables on the same move.
    let mut player = Player::new(&microstep_runs::RUNS);
    let up = microstep_runs::LEN as u32;
    player.start(2 * up + 1000);
    phases(
        "compressed Player (microstep, compress = 1)",
        (up, 1000),
        || player_runs_step(&mut player, timer),
    );
    check(player.is_done(), "compressed player");
    // The same two moves by `next_period`: CI holds each phase within the
    // step's + 1.
    let mut player = Player::new(Ramp::steps(&sigmoid_exact::PERIODS));
    player.start(2 * UP + CRUISE);
    phases(
        "next_period, per-step table (sigmoid_exact)",
        (UP, CRUISE),
        || player_next_period(&mut player, timer),
    );
    check(player.is_done(), "next_period");
    let mut player = Player::new(&microstep_runs::RUNS);
    player.start(2 * up + 1000);
    phases(
        "next_period, compressed Player (microstep, compress = 1)",
        (up, 1000),
        || player_runs_next_period(&mut player, timer),
    );
    check(player.is_done(), "compressed next_period");
    player_move(
        "player, segments (exponential_segments)",
        Ramp::segments(&exponential_segments::SEGMENTS),
        (exponential_segments::LEN as u32, 60),
        timer,
    );

    buffered_moves(timer);

    // The same moves into DMA buffers: 40 periods a fill on the per-step
    // table, 62 on the runs (whole buffers in every phase), each filled
    // sum checked against the move's.
    let mut player = Player::new(Ramp::steps(&sigmoid_exact::PERIODS));
    player.start(2 * UP + CRUISE);
    let sum = fill_phases::<40>(
        "Player::fill, per-step table (sigmoid_exact)",
        (UP, CRUISE),
        false,
        |b| player_fill(&mut player, b),
    );
    let whole = 2 * sigmoid_exact::TOTAL_TICKS as u32 + CRUISE * sigmoid_exact::LAST_TICKS;
    check(
        player.is_done() && sum == whole,
        "fill of the per-step table",
    );
    // The same with the buffer half a word further: the copy does not
    // depend on how the table and the buffer are aligned.
    let mut player = Player::new(Ramp::steps(&sigmoid_exact::PERIODS));
    player.start(2 * UP + CRUISE);
    let sum = fill_phases::<40>(
        "Player::fill, per-step table, the buffer half a word on",
        (UP, CRUISE),
        true,
        |b| player_fill(&mut player, b),
    );
    check(player.is_done() && sum == whole, "fill half a word on");
    let (up, cruise) = (microstep_runs::LEN as u32, 992);
    let whole = 2 * microstep_runs::TOTAL_TICKS as u32 + cruise * last_run(&microstep_runs::RUNS);
    let mut player = Player::new(&microstep_runs::RUNS);
    player.start(2 * up + cruise);
    let sum = fill_phases::<62>(
        "Player::fill, compressed (microstep, compress = 1)",
        (up, cruise),
        false,
        |b| player_runs_fill(&mut player, b),
    );
    check(
        player.is_done() && sum == whole,
        "fill of the compressed runs",
    );
    let mut player = Player::new(Ramp::runs(&microstep_runs::RUNS));
    player.start(2 * up + cruise);
    let sum = fill_phases::<62>(
        "Player::fill, Ramp::runs (the same runs)",
        (up, cruise),
        false,
        |b| player_fill(&mut player, b),
    );
    check(player.is_done() && sum == whole, "fill of Ramp::runs");

    // The axis on the same move as the per-step player, backwards.
    let mut axis = Axis::new(Player::new(Ramp::steps(&sigmoid_exact::PERIODS)), 0);
    check(
        axis.move_by(-i64::from(2 * UP + CRUISE)) == Direction::Backward,
        "axis move",
    );
    phases("axis, per-step table (sigmoid_exact)", (UP, CRUISE), || {
        axis_step(&mut axis, timer)
    });
    check(
        axis.position() == -i64::from(2 * UP + CRUISE),
        "axis position",
    );

    axes_move(timer);
    axes_polyline(timer);
    axis_joined(timer);

    // The peer on a move of the same shape: 1000 steps to 64 kHz (the top of
    // sigmoid_exact, 156 ticks of 10 MHz) at constant acceleration, 3000 at
    // the top, 1000 down.
    let top = sigmoid_exact::FINAL_HZ as u32;
    let mut stepgen = Stepgen::new(sigmoid_exact::TIMER_HZ);
    let accel = top * top / (2 * UP);
    let set = stepgen.set_acceleration(accel << 8).is_ok()
        && stepgen.set_target_speed(top << 8).is_ok()
        && stepgen.set_target_step(2 * UP + CRUISE).is_ok();
    check(set, "stepgen settings");
    phases("stepgen 0.1.3", (UP, CRUISE), || {
        stepgen_step(&mut stepgen, timer)
    });

    // Planning: a move starts, changes its cruise speed, stops.
    let mut player = Player::new(Ramp::steps(&sigmoid_exact::PERIODS));
    once("player, start (a 5000-step move)", || {
        player_start(&mut player, 2 * UP + CRUISE)
    });
    for _ in 0..UP + 100 {
        player_step(&mut player, timer);
    }
    once("player, set_cruise (while cruising, to entry 500)", || {
        player_set_cruise(&mut player, 500)
    });
    for _ in 0..200 {
        player_step(&mut player, timer);
    }
    once("player, stop (at entry 500)", || player_stop(&mut player));
    while player.next_period().is_some() {}

    // Making a player, once per kind: work done at boot, not per move.
    once("made, per-step table (sigmoid_exact, 1000 entries)", || {
        black_box(player_new(&sigmoid_exact::PERIODS));
    });
    once("made, compressed ramp (microstep_runs, 7192 steps)", || {
        black_box(player_runs_new(&microstep_runs::RUNS));
    });
    once(
        "made, indexed compressed ramp (microstep_runs, 7192 steps)",
        || {
            black_box(player_runs_new_indexed(&microstep_runs::RUN_INDEX));
        },
    );

    // Planning on the per-step table and on the compressed microstep ramp.
    planning!(
        "per-step table (sigmoid_exact, 1000 entries)",
        Player::new(Ramp::steps(&sigmoid_exact::PERIODS)),
        UP,
        sigmoid_exact::PERIODS[sigmoid_exact::LEN - 1],
        player_plan_start,
        player_plan_set_cruise,
        player_plan_set_cruise_period,
        player_plan_retarget,
        player_plan_stop
    );
    // The compressed microstep ramp, plain and indexed.
    macro_rules! planning_runs {
        ($label:expr, $player:expr) => {
            planning!(
                $label,
                $player,
                microstep_runs::LEN as u32,
                last_run(&microstep_runs::RUNS) as u16,
                player_runs_plan_start,
                player_runs_plan_set_cruise,
                player_runs_plan_set_cruise_period,
                player_runs_plan_retarget,
                player_runs_plan_stop,
                after player_runs_step, &mut *timer
            )
        };
    }
    planning_runs!(
        "compressed ramp (microstep_runs, 7192 steps)",
        Player::<u16, _>::new(&microstep_runs::RUNS)
    );
    planning_runs!(
        "indexed compressed ramp (microstep_runs, 7192 steps)",
        Player::<u16, _>::new(&microstep_runs::RUN_INDEX)
    );

    handler::measure();

    hprintln!("ok");
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        asm::wfi();
    }
}
