//! Units in both front ends: a value with a unit gives the table of the
//! plain number it stands for, bit for bit.

use profile_core::Generated;
use profile_core::build::Profiles;
use stepper_profiles::period_table;

static SIGMOID_UNITS: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500Hz,
    fmax = 64kHz,
    flexible = 8,
    timer_hz = 10MHz,
);
static SIGMOID_PLAIN: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64_000,
    flexible = 8,
    timer_hz = 10_000_000,
);

static EXPONENTIAL_UNITS: [u16; 106] = period_table!(
    curve = exponential, fmin = 0.2 kHz, fmax = 1.2 kHz, f_inf = 1.3 kHz, tau = 50 ms,
    timer_hz = 2.5MHz,
);
static EXPONENTIAL_PLAIN: [u16; 106] = period_table!(
    curve = exponential,
    fmin = 200,
    fmax = 1200,
    f_inf = 1300,
    tau = 0.05,
    timer_hz = 2_500_000,
);

// Integer keys written as whole floats, as `1e7` is in Rust and TOML.
static SIGMOID_FLOATS: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1e3,
    fmin = 500,
    fmax = 64e3,
    flexible = 8,
    timer_hz = 1e7,
);

#[test]
fn the_macro_reads_units_as_the_numbers_they_stand_for() {
    assert_eq!(SIGMOID_FLOATS, SIGMOID_PLAIN);
    assert_eq!(SIGMOID_UNITS, SIGMOID_PLAIN);
    assert_eq!(EXPONENTIAL_UNITS, EXPONENTIAL_PLAIN);
}

fn periods(file: &str) -> Vec<u32> {
    let profiles = Profiles::parse("profiles.toml", file).unwrap_or_else(|e| panic!("{e}"));
    match &profiles.profiles()[0].table {
        Generated::Steps(t) => t.periods.clone(),
        Generated::Segments(_) | Generated::Runs(_) => panic!("a per-step profile"),
    }
}

#[test]
fn a_profiles_file_reads_units_as_the_numbers_they_stand_for() {
    let units = periods(
        r#"
        [profiles.ramp]
        curve = "exponential"
        fmin = "0.2 kHz"
        fmax = "1.2kHz"
        f_inf = "1300 Hz"
        tau = "50 ms"
        timer_hz = "2.5 MHz"
        "#,
    );
    let plain = periods(
        r#"
        [profiles.ramp]
        curve = "exponential"
        fmin = 200
        fmax = 1200
        f_inf = 1300
        tau = 0.05
        timer_hz = 2500000
        "#,
    );
    assert_eq!(units, plain);
    assert_eq!(units, EXPONENTIAL_PLAIN.map(u32::from).to_vec());
    let floats = periods(
        r#"
        [profiles.ramp]
        curve = "exponential"
        fmin = 2e2
        fmax = 1.2e3
        f_inf = 1300.0
        tau = 5e-2
        timer_hz = 2.5e6
        "#,
    );
    assert_eq!(floats, plain);
    // Digit separators inside a string, as in the literal `1_200Hz`.
    let separated = periods(
        r#"
        [profiles.ramp]
        curve = "exponential"
        fmin = "200 Hz"
        fmax = "1_200 Hz"
        f_inf = "1_300Hz"
        tau = "50 ms"
        timer_hz = "2_500 kHz"
        "#,
    );
    assert_eq!(separated, plain);
}
