//! A plotter's polyline of six shallow lines, played twice on the host:
//! stopping at every vertex, and queued with `Axes::queue` so that the
//! lines join at speed. Prints both times.
//!
//! ```text
//! cargo run --example polyline
//! ```

use stepper_profiles::period_table;
use stepper_profiles::player::{Axes, Player};

/// The ramp: 500 Hz to 20 kHz in 200 steps, on a 1 MHz timer.
static RAMP: [u16; 200] = period_table!(
    curve = linear,
    len = 200,
    fmin = 500,
    fmax = 20kHz,
    timer_hz = 1MHz,
);

/// The timer's ticks a second.
const TIMER_HZ: f64 = 1e6;

/// The polyline's vertices after its start at (0, 0): lines 3 to 10°
/// off the x axis, bending by 3 to 7° (no axis reverses).
const VERTICES: [[i64; 2]; 6] = [
    [400, 40],
    [800, 60],
    [1200, 120],
    [1600, 150],
    [2000, 220],
    [2400, 240],
];

/// The junction deviation, in steps.
const DEVIATION: f32 = 2.0;

/// Plays the polyline: each line its own move from rest when `joined` is
/// false, else queued. The time in ticks, and the edges.
pub fn play(joined: bool) -> (u64, u32) {
    let mut axes = Axes::new(Player::new(&RAMP), [0, 0]).with_junction_deviation(DEVIATION);
    let (mut ticks, mut edges) = (0u64, 0u32);
    if joined {
        for v in VERTICES {
            axes.queue(v).expect("six lines fit the queue");
        }
        while let Some((period, _mask)) = axes.next_step() {
            ticks += u64::from(period);
            edges += 1;
        }
    } else {
        for v in VERTICES {
            axes.move_to(v);
            while let Some((period, _mask)) = axes.next_step() {
                ticks += u64::from(period);
                edges += 1;
            }
        }
    }
    assert_eq!(axes.position(), VERTICES[5]);
    (ticks, edges)
}

fn main() {
    let (stopping, edges) = play(false);
    let (joined, joined_edges) = play(true);
    assert_eq!(edges, joined_edges);
    let ms = |ticks: u64| ticks as f64 / TIMER_HZ * 1e3;
    println!(
        "polyline of 6 lines, {edges} lead steps, ramp 500 Hz to 20 kHz in 200 steps, \
         junction deviation {DEVIATION} steps:"
    );
    println!("  stopping at every vertex: {:>9.3} ms", ms(stopping));
    println!("  joined at speed (queued): {:>9.3} ms", ms(joined));
    println!(
        "  {:.1} % shorter",
        100.0 * (1.0 - joined as f64 / stopping as f64)
    );
}
