//! Checks that `stepper-profiles` builds for bare-metal targets: a table made
//! by `period_table!` at compile time, and the same table generated at run
//! time by `Spec::generate`, with no allocator and no `std`; and the periods
//! of `player::Timed` typed by their timer's rate (feature `fugit`).
#![no_std]
#![forbid(unsafe_code)]

use stepper_profiles::fugit::TimerDurationU32;
use stepper_profiles::player::{Ramp, Rated, Timed};
use stepper_profiles::{Arithmetic, Curve, Discretization, Rounding, Sigmoid, Spec, Timer};

/// Seed 000's orange curve, bit for bit as its C code computes it, in flash.
pub static T: [u16; 1000] = stepper_profiles::period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64000,
    flexible = 8,
    timer_hz = 10_000_000,
    discretization = index,
    rounding = truncate,
    arithmetic = f32,
);

/// The default mode (exact pulse times, diffused rounding) of the same curve.
pub static EXACT: [u16; 1000] = stepper_profiles::period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64000,
    flexible = 8,
    timer_hz = 10_000_000,
);

fn orange() -> Spec {
    Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        }),
        Timer::new(10_000_000),
    )
}

/// Regenerates `spec`'s table into `buf` and compares it with `expected`.
fn same<const N: usize>(spec: &Spec, buf: &mut [u16; N], expected: &[u16; N]) -> bool {
    spec.generate(buf).is_ok() && buf == expected
}

/// `true` when the run-time tables equal the compile-time ones, bit for bit.
pub fn tables_match() -> bool {
    let mut buf = [0u16; 1000];
    let c_compatible = orange()
        .with_discretization(Discretization::Index)
        .with_rounding(Rounding::Truncate)
        .with_arithmetic(Arithmetic::F32);
    same(&c_compatible, &mut buf, &T) && same(&orange(), &mut buf, &EXACT)
}

/// The ramp of `EXACT` with its timer's rate as a type.
const RAMP: Rated<'static, u16, 10_000_000> = Rated::new(Ramp::steps(&EXACT), 0);

/// The periods of a move of `EXACT`, as durations of its 10 MHz timer
/// (feature `fugit`), summed in ticks.
pub fn move_ticks(steps: u32) -> u64 {
    let mut timed = Timed::new(RAMP);
    timed.start(steps);
    let mut ticks = 0u64;
    while let Some(d) = timed.next_duration() {
        let d: TimerDurationU32<10_000_000> = d;
        ticks += u64::from(d.ticks());
    }
    ticks
}

#[cfg(test)]
mod tests {
    #[test]
    fn run_time_tables_equal_compile_time_tables() {
        assert!(super::tables_match());
        assert_eq!((super::T[0], super::T[999]), (19183, 156));
    }

    #[test]
    fn durations_of_a_move_sum_to_its_ticks() {
        let table: u64 = super::EXACT.iter().map(|&p| u64::from(p)).sum();
        let top = u64::from(super::EXACT[999]);
        assert_eq!(super::move_ticks(2500), 2 * table + 500 * top);
    }
}
