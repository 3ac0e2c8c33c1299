//! Resonance bands through the front doors: bands the ramp only crosses
//! change no period; a top inside a band is refused at its bounds exactly,
//! and a motor's microsteps scale the bands. (The messages are pinned in
//! `tests/toml_errors/avoid_*.txt`.)

use stepper_profiles::period_table;

static PLAIN: [u16; 200] = period_table!(
    curve = linear,
    len = 200,
    fmin = 500,
    fmax = 5kHz,
    timer_hz = 1MHz,
);

static CROSSED: [u16; 200] = period_table!(
    curve = linear,
    len = 200,
    fmin = 500,
    fmax = 5kHz,
    timer_hz = 1MHz,
    avoid = [(800, 1.2kHz), (2000, 2500)],
);

#[test]
fn bands_the_ramp_crosses_change_no_period() {
    assert_eq!(CROSSED, PLAIN);
}

/// A 1 MHz timer and a ramp to about 1000 steps/s: its top, the rate of
/// its shortest period, is refused in a band that reaches it by either
/// bound, and accepted a billionth outside; with a motor in 1/8 steps the
/// same top is an eighth as many full steps/s.
#[test]
fn the_top_is_refused_inside_a_band_bounds_included() {
    use profile_codegen::profiles::Profiles;
    let file = |motor: &str, lo: f64, hi: f64| {
        format!(
            "[motors.m]\nstep_angle = 1.8\nmicrosteps = 8\nrotor_inertia = \"82 gcm2\"\n\
             torque_curve = [[0, 0.4], [10000, 0.3]]\n\n[profiles.p]\ncurve = \"linear\"\n\
             fmin = 500\nfmax = 1000\naccel = 10_000\ntimer_hz = \"1MHz\"\n{motor}\
             avoid = [[{lo:?}, {hi:?}]]\n"
        )
    };
    let parse = |text: String| Profiles::parse("profiles.toml", &text);
    let refused = |text: String| parse(text).is_err();
    // The top, from the table itself.
    let p = parse(file("", 600.0, 700.0)).unwrap();
    let profile = &p.profiles()[0];
    let periods = profile.table.step_periods();
    let shortest = *periods.iter().min().unwrap();
    let top = 1e6 / f64::from(shortest);
    assert!((top - 1000.0).abs() < 2.0, "{top}");
    let (below, above) = (top * (1.0 - 1e-9), top * (1.0 + 1e-9));
    assert!(refused(file("", 900.0, top)));
    assert!(!refused(file("", 900.0, below)));
    assert!(refused(file("", top, 1100.0)));
    assert!(!refused(file("", above, 1100.0)));
    // With the motor, in full steps/s.
    let motor = "motor = \"m\"\n";
    assert!(refused(file(motor, 120.0, top / 8.0)));
    assert!(!refused(file(motor, 120.0, below / 8.0)));
    assert!(!refused(file(motor, 900.0, top)));
    // The report's time in a band: the ramp's steps inside it, summed.
    let bands = profile.avoid.as_ref().unwrap();
    let timer = profile.table.spec().timer;
    let inside: u32 = periods
        .iter()
        .filter(|&&t| (600.0..=700.0).contains(&(1e6 / f64::from(t))))
        .sum();
    assert!(inside > 0);
    assert_eq!(
        bands.time_in(&timer, &periods),
        vec![f64::from(inside) * 1e-6]
    );
}
