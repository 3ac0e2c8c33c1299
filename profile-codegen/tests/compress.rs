//! The compressed layout's flash against the per-step table, on the ramps
//! the goals name, and the runs' expansion against the per-step arithmetic.
//! (Every edge against an independent oracle: `tests/oracle.rs`.)

use profile_codegen::SpecTables;
use profile_core::runs::{Expand, LinearRun};
use profile_core::{Curve, Linear, LinearExtent, Sigmoid, Spec, Timer, Word};

fn timer(timer_hz: u32) -> Timer {
    Timer {
        timer_hz,
        word: Word::U16,
        ticks_per_step: 1,
    }
}

/// 200 -> 20 200 Hz at 20 000 Hz/s on a 2 MHz timer: 10 200 steps.
fn linear() -> Spec {
    Spec::new(
        Curve::Linear(Linear {
            fmin: 200.0,
            fmax: 20_200.0,
            extent: LinearExtent::Accel(20_000.0),
        }),
        timer(2_000_000),
    )
}

/// 400 -> 48 000 Hz, flexible 6, 8 000 steps on a 10 MHz timer.
fn sigmoid() -> Spec {
    Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 400.0,
            fmax: 48_000.0,
            flexible: 6.0,
            len: 8000,
        }),
        timer(10_000_000),
    )
}

/// `[u16; N]` bytes over the runs' bytes.
fn ratio(spec: &Spec, compress: f64) -> f64 {
    let t = spec.run_table(compress).unwrap();
    let f = t.figures;
    assert!(f.max_edge_error_ticks <= compress, "{f:?}");
    assert_eq!(Expand::new(&t.runs).count() as u32, f.steps);
    assert_eq!(f.flash_bytes, 10 * f.entries);
    f.per_step_flash_bytes as f64 / f.flash_bytes as f64
}

/// 500 -> 64 000 Hz, flexible 8, 1 000 steps on a 10 MHz timer (the
/// S-curve article's orange curve in time).
fn short_sigmoid() -> Spec {
    Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        }),
        timer(10_000_000),
    )
}

/// The table of the guide's compression page: `cargo test -p profile-codegen --test
/// compress -- --nocapture` prints it.
#[test]
fn the_goals_flash_ratios_hold() {
    let ramps = [
        ("linear, 10 200 steps", linear()),
        ("sigmoid, 8 000 steps", sigmoid()),
        ("sigmoid, 1 000 steps", short_sigmoid()),
    ];
    let mut table = [[0.0; 3]; 3];
    for (row, (name, spec)) in table.iter_mut().zip(&ramps) {
        for (cell, compress) in row.iter_mut().zip([0.5, 1.0, 2.0]) {
            *cell = ratio(spec, compress);
        }
        eprintln!(
            "{name}: {:.1}x at 0.5 tick, {:.1}x at 1, {:.1}x at 2",
            row[0], row[1], row[2]
        );
    }
    assert!(table[0][1] >= 20.0, "linear at 1 tick");
    assert!(table[1][1] >= 12.0, "sigmoid at 1 tick");
    assert!(table[0][0] >= 8.0, "linear at 0.5 tick");
}

/// What compressing adds to generating a table of `MAX_LEN` entries, in
/// this build (a debug build, as a proc macro runs in one, under `cargo
/// test`): printed, not asserted.
#[test]
fn generation_time_of_the_longest_table() {
    let spec = Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: profile_core::MAX_LEN,
        }),
        timer(10_000_000),
    );
    let start = std::time::Instant::now();
    spec.table().unwrap();
    let per_step = start.elapsed();
    let start = std::time::Instant::now();
    let runs = spec.run_table(1.0).unwrap();
    let compressed = start.elapsed();
    eprintln!(
        "{} steps: per-step table {per_step:.2?}, compressed (1 tick, {} runs) {compressed:.2?}",
        profile_core::MAX_LEN,
        runs.figures.entries
    );
}

/// A run table is one integer recurrence: played by hand, run by run, it
/// gives what `Expand` gives.
#[test]
fn expansion_is_the_documented_recurrence() {
    let t = sigmoid().run_table(1.0).unwrap();
    let mut frac: u64 = 1 << 15;
    let mut by_hand = Vec::new();
    for words in &t.runs {
        let run = LinearRun::decode(words);
        let mut interval = i64::from(run.interval);
        for _ in 0..run.count {
            let x = frac + interval as u64;
            by_hand.push((x >> 16) as u32);
            frac = x & 0xFFFF;
            interval += i64::from(run.add);
        }
    }
    assert_eq!(Expand::new(&t.runs).collect::<Vec<_>>(), by_hand);
}

#[test]
fn a_tolerance_below_half_a_tick_is_refused() {
    let e = linear().run_table(0.4).unwrap_err();
    assert_eq!(
        e.to_string(),
        "`compress` is the largest pulse-edge error allowed, in ticks, and must be at least \
         0.5: a whole tick cannot land nearer to every edge (got 0.4)"
    );
    let e = linear()
        .with_rounding(profile_core::Rounding::Truncate)
        .run_table(1.0)
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "`rounding = truncate` applies only without `compress` (runs place every edge within \
         `compress` ticks)"
    );
}

#[test]
fn the_largest_tolerance_fits_and_a_larger_one_is_refused() {
    // At the bound the band arithmetic stays in range on the longest table
    // the linear ramp gives: every edge within the bound, no panic.
    let t = linear()
        .run_table(profile_codegen::MAX_COMPRESS_TICKS)
        .unwrap();
    assert!(
        t.figures.max_edge_error_ticks <= 65_535.0,
        "{:?}",
        t.figures
    );
    assert_eq!(Expand::new(&t.runs).count(), 10_200);
    for huge in [65_535.5, 1e20, 1e300, f64::INFINITY] {
        let e = linear().run_table(huge).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!(
                "`compress` is the largest pulse-edge error allowed, in ticks, and must be at \
                 most 65535, the longest period a run's 16-bit word holds (got {})",
                match huge {
                    1e20 => "1e20",
                    1e300 => "1e300",
                    x if x.is_infinite() => "inf",
                    _ => "65535.5",
                }
            )
        );
    }
}

#[test]
fn a_period_the_per_step_table_refuses_is_refused_before_fitting() {
    // 1 000 -> 20 000 Hz on a 10 kHz timer: the per-step table's error, at
    // once, whatever the tolerance.
    let spec = Spec::new(
        Curve::Linear(Linear {
            fmin: 1000.0,
            fmax: 20_000.0,
            extent: LinearExtent::Accel(20_000.0),
        }),
        timer(10_000),
    );
    let per_step = spec.figures().unwrap_err();
    for compress in [0.5, 100.0, 65_535.0] {
        assert_eq!(spec.run_table(compress).unwrap_err(), per_step);
    }
    assert_eq!(
        per_step.to_string(),
        "entry 2546 rounds to 0 ticks; the timer resolves step frequencies up to 10000 Hz"
    );
}

/// However loose the tolerance, no run steps faster than the curve: every
/// period is at least the curve's shortest, rounded down (156 ticks for
/// 64 kHz on a 10 MHz timer), as in the per-step table. A tolerance of 1000
/// ticks once played 123-tick periods (81 kHz), and 10 000 ticks 1-tick
/// ones; a two-step ramp at the largest tolerance, periods of 1 tick.
#[test]
fn no_run_steps_faster_than_the_curve() {
    let per_step = short_sigmoid().table().unwrap().periods;
    let fastest = *per_step.iter().min().unwrap();
    assert_eq!(fastest, 156);
    for compress in [
        1.0,
        100.0,
        1000.0,
        10_000.0,
        profile_codegen::MAX_COMPRESS_TICKS,
    ] {
        let t = short_sigmoid().run_table(compress).unwrap();
        let shortest = Expand::new(&t.runs).min().unwrap();
        assert!(
            shortest >= 156,
            "compress {compress}: a {shortest}-tick period"
        );
        assert!(
            t.figures.max_edge_error_ticks <= compress,
            "{:?}",
            t.figures
        );
        assert_eq!(Expand::new(&t.runs).count(), 1000);
    }
    let two = Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 2,
        }),
        timer(10_000_000),
    );
    let fastest = *two.table().unwrap().periods.iter().min().unwrap();
    let t = two.run_table(profile_codegen::MAX_COMPRESS_TICKS).unwrap();
    let shortest = Expand::new(&t.runs).min().unwrap();
    assert!(shortest + 1 >= fastest, "{shortest} against {fastest}");
}

/// A looser bound never costs runs, and the ramp ends where the curve ends
/// as near as the bound lets the last run's end be chosen: on the linear
/// ramp from 200 Hz, `compress` from 0.5 to 65 535 ticks.
#[test]
fn a_looser_bound_never_compresses_worse() {
    let spec = linear();
    let exact_end = 2_000_000.0;
    let mut before = u32::MAX;
    for compress in [0.5, 1.0, 4.0, 100.0, 1000.0, 10_000.0, 30_000.0, 65_535.0] {
        let f = spec.run_table(compress).unwrap().figures;
        println!(
            "compress = {compress}: {} runs, ends {} ticks from the curve",
            f.entries, f.total_error_ticks
        );
        assert!(
            f.entries <= before,
            "compress = {compress}: {} runs, more than the {before} of a tighter bound",
            f.entries
        );
        assert!(f.max_edge_error_ticks <= compress, "{f:?}");
        assert!(
            (f.total_ticks as f64 - exact_end).abs() <= 1.0,
            "compress = {compress}: the ramp ends at {} ticks, the curve at {exact_end}",
            f.total_ticks
        );
        before = f.entries;
    }
}

/// With `ticks_per_step = 2` the timer plays each entry twice: `compress`
/// bounds the step edges the pin makes, in timer ticks, not the entries'
/// running sum, and a tolerance below one tick is refused.
#[test]
fn with_two_reloads_per_step_compress_bounds_the_step_edges() {
    let spec = Spec::new(
        Curve::Linear(Linear {
            fmin: 1600.0,
            fmax: 48_000.0,
            extent: LinearExtent::Accel(160_000.0),
        }),
        Timer {
            timer_hz: 10_000_000,
            word: Word::U16,
            ticks_per_step: 2,
        },
    );
    // The curve's step edges in timer ticks, summed on their own: the
    // constant-acceleration ramp reaches speed f after (f^2 - fmin^2) / 2a
    // steps, so step k is at t_k = (sqrt(fmin^2 + 2 a k) - fmin) / a.
    let (fmin, a) = (1600.0f64, 160_000.0f64);
    for compress in [1.0, 2.0, 10.0] {
        let t = spec.run_table(compress).unwrap();
        let mut edge = 0u64;
        let mut worst = 0.0f64;
        for (k, half) in Expand::new(&t.runs).enumerate() {
            edge += 2 * u64::from(half);
            let exact = ((fmin * fmin + 2.0 * a * (k + 1) as f64).sqrt() - fmin) / a * 1e7;
            worst = worst.max((edge as f64 - exact).abs());
        }
        assert!(
            worst <= compress + 1e-6,
            "compress = {compress}: a step edge is {worst} timer ticks off the curve"
        );
        assert!(
            (worst - t.figures.max_edge_error_ticks).abs() < 1e-6,
            "compress = {compress}: the figures say {}, the pin {worst}",
            t.figures.max_edge_error_ticks
        );
    }
    let e = spec.run_table(0.5).unwrap_err();
    assert_eq!(
        e.to_string(),
        "`compress` is the largest step-edge error allowed, in timer ticks, and must be at \
         least 1 with `ticks_per_step = 2`: each entry is played twice, so step edges fall on \
         every other tick (got 0.5)"
    );
}
