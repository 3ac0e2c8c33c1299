//! Every variant of `Error` with its exact message.

extern crate std;
use std::string::ToString;
use std::vec::Vec;

use super::*;
use crate::base::key::Key;
use crate::base::modes::Discretization;
use crate::base::numbers::{Fixed, Significant};
use crate::base::timer::Word;

/// One example of every variant with its exact message. The match in
/// `covered` has no wildcard: a new variant does not compile until it
/// is added here.
fn examples() -> Vec<(Error, &'static str)> {
    std::vec![
        (
            Error::NotFinite {
                key: Key::FMAX,
                value: f64::INFINITY
            },
            "`fmax` must be a finite number (got inf)"
        ),
        (
            Error::NotPositive {
                key: Key::FMIN,
                value: -500.0
            },
            "`fmin` must be greater than 0 (got -500)"
        ),
        (
            Error::NotPositive {
                key: Key::FLEXIBLE,
                value: 1e-308
            },
            "`flexible` must be at least 2.2250738585072014e-308, the smallest normal float \
             (got 1e-308)"
        ),
        (
            Error::TooLarge {
                key: Key::FLEXIBLE,
                value: 501.0,
                max: 500.0
            },
            "`flexible` must be at most 500 (got 501)"
        ),
        (
            Error::NotGreater {
                key: Key::FMAX,
                value: 400.0,
                other: Key::FMIN,
                other_value: 500.0
            },
            "`fmax` must be greater than `fmin` (got 400 <= 500)",
        ),
        (Error::Zero { key: Key::SHAPE }, "`shape` must not be 0"),
        (
            Error::TooSmall {
                key: Key::SHAPE,
                value: -20.0,
                min: -40.0 / 3.0,
                why: ", that is -accel / (f1 - fmin), for a concave start"
            },
            "`shape` must be greater than -13.3333, that is -accel / (f1 - fmin), for a concave start (got -20)",
        ),
        (
            Error::NotAtLeast {
                key: Key::F2,
                value: 300.0,
                other: Key::F1,
                other_value: 400.0
            },
            "`f2` must be at least `f1` (got 300 < 400)",
        ),
        (
            Error::NotWhole {
                key: Key::FMIN,
                value: 500.5
            },
            "`fmin` must be a whole number with `arithmetic = integer` (got 500.5)",
        ),
        (
            Error::IntegerOverflow {
                key: Key::FMIN,
                expression: "f0*f0",
                value: 4_294_836_225,
                max: 2_147_483_647
            },
            "`fmin` overflows the integer `pulse()` code: `f0*f0` is 4294836225, more than 2147483647",
        ),
        (
            Error::RampTooLong {
                key: Key::TAU,
                steps: 123_456.4,
                max: 65_536
            },
            "`tau` makes the ramp 123456 steps long; at most 65536 are allowed",
        ),
        (
            Error::RampTooLong {
                key: Key::ACCEL,
                steps: 1.25e200,
                max: 65_536
            },
            "`accel` makes the ramp 1.25e200 steps long; at most 65536 are allowed",
        ),
        (
            Error::RampTooLong {
                key: Key::ACCEL,
                steps: f64::INFINITY,
                max: 65_536
            },
            "`accel` makes the ramp longer than a float counts (1.8e308 steps); at most 65536 are allowed",
        ),
        (
            Error::RampTooLong {
                key: Key::ACCEL,
                steps: f64::NAN,
                max: 65_536
            },
            "`accel` gives the ramp no length in steps (got NaN); from 1 to 65536 are allowed",
        ),
        (
            Error::EmptySegment {
                index: 0,
                steps: 120
            },
            "segment 0 holds no step of the 120-step ramp; use fewer `segments`",
        ),
        (
            Error::SegmentTooLong {
                index: 0,
                count: 65_536,
                word: Word::U16
            },
            "segment 0 holds 65536 steps, more than a `word = u16` count holds (65535); use more `segments`",
        ),
        (
            Error::SegmentsNeedTime {
                discretization: Discretization::Index
            },
            "`segments` cuts the curve into equal-time pieces and needs `discretization = exact` (got `index`)",
        ),
        (Error::LenZero, "`len` must be at least 1 (got 0)"),
        (
            Error::LenTooLarge {
                len: 65_537,
                max: 65_536
            },
            "`len` must be at most 65536 (got 65537)"
        ),
        (
            Error::TimerZero,
            "`timer_hz` must be greater than 0 (got 0)"
        ),
        (
            Error::TicksPerStep { value: 3 },
            "`ticks_per_step` must be 1 or 2 (got 3)"
        ),
        (
            Error::ReloadOffsetRange {
                offset: 70_000,
                word: Word::U16
            },
            "`reload_offset` must be from -65534 to 65534 with `word = u16`: a period of 1 to 65535 ticks plus the offset must fit the word (got 70000)",
        ),
        (
            Error::ReloadOffset {
                what: "entry",
                index: 999,
                ticks: 1,
                offset: -1,
                word: Word::U16
            },
            "`reload_offset = -1` makes entry 999 (1 tick) 0: a stored value, the period plus the offset, must be from 1 to 65535 (`word = u16`)",
        ),
        (
            Error::ReloadOffset {
                what: "step",
                index: 0,
                ticks: 65_535,
                offset: 2,
                word: Word::U16
            },
            "`reload_offset = 2` makes step 0 (65535 ticks) 65537: a stored value, the period plus the offset, must be from 1 to 65535 (`word = u16`)",
        ),
        (
            Error::Unsupported {
                key: Key::ARITHMETIC,
                value: "f32",
                applies: "with `discretization = index`"
            },
            "`arithmetic = f32` applies only with `discretization = index`",
        ),
        (
            Error::PeriodOverflow {
                index: 0,
                ticks: 99_980.0,
                word: Word::U16,
                timer_hz: 10_000_000,
                lowest_hz: 152.590218
            },
            "entry 0 is 99980 ticks, more than `word = u16` holds (65535); at `timer_hz = 10000000` the lowest step frequency that fits is 152.59 Hz",
        ),
        (
            Error::PeriodOverflow {
                index: 3,
                ticks: 1e300,
                word: Word::U32,
                timer_hz: 10_000_000,
                lowest_hz: 10_000_000.0 / 4_294_967_295.0
            },
            "entry 3 is 1e300 ticks, more than `word = u32` holds (4294967295); at `timer_hz = 10000000` the lowest step frequency that fits is 0.00232831 Hz",
        ),
        (
            Error::PeriodZero {
                index: 999,
                highest_hz: 10_000_000.0
            },
            "entry 999 rounds to 0 ticks; the timer resolves step frequencies up to 10000000 Hz",
        ),
        (
            Error::BufferLength {
                expected: 1000,
                got: 10
            },
            "the buffer holds 10 entries but the table has `len = 1000`",
        ),
        (
            Error::WordMismatch {
                expected: Word::U16,
                got: Word::U32
            },
            "the buffer holds `u32` entries but the spec has `word = u16`",
        ),
        (
            Error::NoConvergence {
                index: 7,
                iterations: 100
            },
            "the pulse time of step 7 did not converge within 100 iterations: the curve's step count is not a finite number there",
        ),
        (
            Error::CompressTooSmall {
                value: 0.25,
                ticks_per_step: 1,
            },
            "`compress` is the largest pulse-edge error allowed, in ticks, and must be at least 0.5: a whole tick cannot land nearer to every edge (got 0.25)",
        ),
        (
            Error::CompressTooSmall {
                value: 0.5,
                ticks_per_step: 2,
            },
            "`compress` is the largest step-edge error allowed, in timer ticks, and must be at least 1 with `ticks_per_step = 2`: each entry is played twice, so step edges fall on every other tick (got 0.5)",
        ),
        (
            Error::CompressTooLarge { value: 1e20 },
            "`compress` is the largest pulse-edge error allowed, in ticks, and must be at most 65535, the longest period a run's 16-bit word holds (got 1e20)",
        ),
        (
            Error::CompressUnreachable {
                step: 12,
                tolerance: 0.5
            },
            "no run of 16-bit periods keeps pulse edge 12 within 0.5 ticks of the curve; raise `compress`",
        ),
        (
            Error::AccelCurve {
                hz: 2500.0,
                accel: -40.0,
            },
            "the acceleration at 2500 Hz must be above 0 (got -40 Hz/s): the motor has no torque to spare there",
        ),
        (
            Error::AccelCurve {
                hz: 300.0,
                accel: f64::NAN,
            },
            "the acceleration curve must have rising frequencies from `fmin` or below to `fmax` or above (its first point is at 300 Hz)",
        ),
    ]
}

fn covered(e: &Error) -> usize {
    match e {
        Error::NotFinite { .. } => 0,
        Error::NotPositive { .. } => 1,
        Error::TooLarge { .. } => 2,
        Error::NotGreater { .. } => 3,
        Error::Zero { .. } => 4,
        Error::TooSmall { .. } => 5,
        Error::NotWhole { .. } => 6,
        Error::IntegerOverflow { .. } => 7,
        Error::RampTooLong { .. } => 8,
        Error::EmptySegment { .. } => 9,
        Error::SegmentsNeedTime { .. } => 10,
        Error::LenZero => 11,
        Error::LenTooLarge { .. } => 12,
        Error::TimerZero => 13,
        Error::TicksPerStep { .. } => 14,
        Error::Unsupported { .. } => 15,
        Error::PeriodOverflow { .. } => 16,
        Error::PeriodZero { .. } => 17,
        Error::BufferLength { .. } => 18,
        Error::WordMismatch { .. } => 19,
        Error::NoConvergence { .. } => 20,
        Error::NotAtLeast { .. } => 21,
        Error::SegmentTooLong { .. } => 22,
        Error::CompressTooSmall { .. } => 23,
        Error::CompressUnreachable { .. } => 24,
        Error::CompressTooLarge { .. } => 25,
        Error::ReloadOffsetRange { .. } => 26,
        Error::ReloadOffset { .. } => 27,
        Error::AccelCurve { .. } => 28,
    }
}

#[test]
fn every_variant_has_a_pinned_message() {
    let examples = examples();
    let mut seen = [false; 29];
    for (error, message) in &examples {
        assert_eq!(error.to_string(), *message);
        seen[covered(error)] = true;
        // Messages are lowercase with no trailing period.
        assert!(!message.ends_with('.'), "{message}");
        assert!(
            !message.starts_with(|c: char| c.is_ascii_uppercase()),
            "{message}"
        );
    }
    assert!(
        seen.iter().all(|s| *s),
        "a variant has no example: {seen:?}"
    );
}

#[test]
fn errors_blame_the_key_to_point_at() {
    assert_eq!(Error::LenZero.key(), Some(Key::LEN));
    assert_eq!(Error::TimerZero.key(), Some(Key::TIMER_HZ));
    assert_eq!(
        Error::EmptySegment { index: 0, steps: 1 }.key(),
        Some(Key::SEGMENTS)
    );
    assert_eq!(
        Error::BufferLength {
            expected: 1,
            got: 2
        }
        .key(),
        None
    );
}

/// Figures far out of any motor's range read in exponent form, not in
/// hundreds of digits; in range, as before.
#[test]
fn numbers_in_messages_stay_short() {
    let show = |v: f64| Significant(v).to_string();
    assert_eq!(show(-40.0 / 3.0), "-13.3333");
    assert_eq!(show(0.00232831), "0.00232831");
    assert_eq!(show(-4e300 / 3.0), "-1.33333e300");
    assert_eq!(show(1e300), "1e300");
    assert_eq!(show(2.5e-9), "2.5e-9");
    assert_eq!(show(1.0 / 3e20), "3.33333e-21");
    let fixed = |v: f64, decimals: usize| Fixed(v, decimals).to_string();
    assert_eq!(fixed(0.17994, 4), "0.1799");
    assert_eq!(fixed(1757.46, 1), "1757.5");
    assert_eq!(fixed(0.0, 4), "0.0000");
    assert_eq!(fixed(2.00152437155313e300, 4), "2.00152e300");
    assert_eq!(fixed(-1e20, 1), "-1e20");
    assert_eq!(fixed(3e-6, 4), "0.000003");
    assert_eq!(fixed(1e-300, 4), "1e-300");
    assert_eq!(fixed(f64::INFINITY, 4), "inf");
    let message = Error::TooSmall {
        key: Key::SHAPE,
        value: -2e300,
        min: -4e300 / 3.0,
        why: ", that is -accel / (f1 - fmin), for a concave start",
    }
    .to_string();
    assert_eq!(
        message,
        "`shape` must be greater than -1.33333e300, that is -accel / (f1 - fmin), for a \
         concave start (got -2e300)"
    );
}
