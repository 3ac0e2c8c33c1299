//! Units in both front ends: a value with a unit gives the table of the
//! plain number it stands for, bit for bit.

use profile_codegen::Generated;
use profile_codegen::profiles::Profiles;
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
        _ => panic!("a per-step profile"),
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

// A motor as its datasheet writes it, in the macro: the units as suffixes
// (`3.4mH`, `68gcm2`) or as strings with the datasheet's symbols.
static DATASHEET_UNITS: [u16; 416] = period_table!(
    curve = linear, fmin = 300, fmax = 5000, accel = 30_000, timer_hz = 10_000_000,
    step_angle = "1.8°", rotor_inertia = 68gcm2, load_inertia = "136 g·cm²", friction = 2Ncm,
    resistance = "0.5 Ω", inductance = 0.6mH, rated_current = 2800mA, holding_torque = 40 Ncm,
    supply_voltage = 24V, driver_current = 2500mA, iron_loss = "3 N·cm", safety = 1.5,
    damping_ratio = 0.1,
);

/// The motor and the table of a profiles file's only profile.
fn motor_and_table(file: &str) -> (profile_codegen::motor::Motor, Vec<u32>) {
    let profiles = Profiles::parse("profiles.toml", file).unwrap_or_else(|e| panic!("{e}"));
    let profile = &profiles.profiles()[0];
    match &profile.table {
        Generated::Steps(t) => (profile.motor.expect("a motor"), t.periods.clone()),
        _ => panic!("a per-step profile"),
    }
}

#[test]
fn a_motor_is_read_in_its_datasheets_units() {
    let ramp = "[profiles.p]\ncurve = \"linear\"\nfmin = 300\nfmax = 5000\naccel = 30_000\n\
                timer_hz = 10_000_000\nmotor = \"m\"\nsafety = 1.5\ndamping_ratio = 0.1\n";
    let (units, _) = motor_and_table(&format!(
        "[motors.m]\nstep_angle = \"1.8°\"\nrotor_inertia = \"68 g·cm²\"\n\
         load_inertia = \"136gcm2\"\nfriction = \"2 N·cm\"\nresistance = \"500 mohm\"\n\
         inductance = \"600 µH\"\nrated_current = \"2.8 A\"\nholding_torque = \"400 mN·m\"\n\
         supply_voltage = \"24 V\"\ndriver_current = \"2500 mA\"\niron_loss = \"30 mN·m\"\n{ramp}"
    ));
    let (plain, table) = motor_and_table(&format!(
        "[motors.m]\nstep_angle = 1.8\nrotor_inertia = 6.8e-6\nload_inertia = 1.36e-5\n\
         friction = 0.02\nresistance = 0.5\ninductance = 0.6e-3\nrated_current = 2.8\n\
         holding_torque = 0.40\nsupply_voltage = 24\ndriver_current = 2.5\niron_loss = 0.03\n{ramp}"
    ));
    assert_eq!(units, plain);
    // The macro read its motor in units and checked the table against it:
    // the table is the file's.
    assert_eq!(DATASHEET_UNITS.map(u32::from).to_vec(), table);
}

#[test]
fn a_torque_curve_is_read_in_its_datasheets_units() {
    let ramp = "[profiles.p]\ncurve = \"linear\"\nfmin = 100\nfmax = 500\naccel = 1000\n\
                timer_hz = 1_000_000\nmotor = \"m\"\n";
    let motor = "[motors.m]\nstep_angle = 1.8\nrotor_inertia = 5.4e-6\ndamping_ratio = 0.1\n";
    let (units, _) = motor_and_table(&format!(
        "{motor}torque_curve = [[0, \"40 N·cm\"], [\"1 kHz\", \"330 mNm\"], [\"2_000 Hz\", \
         \"0.24Nm\"]]\n{ramp}"
    ));
    let (plain, _) = motor_and_table(&format!(
        "{motor}torque_curve = [[0, 0.40], [1000, 0.33], [2000, 0.24]]\n{ramp}"
    ));
    assert_eq!(units, plain);
}

// The same curve in the macro, with and without units: the motor read in
// units passes the same check (the table itself does not depend on it).
static CURVE_UNITS: [u16; 120] = period_table!(
    curve = linear, fmin = 100, fmax = 500, accel = 1000, timer_hz = 1_000_000,
    step_angle = 1.8, rotor_inertia = 54 gcm2, damping_ratio = 0.1,
    torque_curve = [(0, 40Ncm), (1kHz, 330 mNm), (2_000 Hz, 0.24 Nm)],
);
static CURVE_PLAIN: [u16; 120] = period_table!(
    curve = linear,
    fmin = 100,
    fmax = 500,
    accel = 1000,
    timer_hz = 1_000_000,
    step_angle = 1.8,
    rotor_inertia = 5.4e-6,
    damping_ratio = 0.1,
    torque_curve = [(0, 0.40), (1000, 0.33), (2000, 0.24)],
);

#[test]
fn the_macro_reads_a_torque_curve_in_units() {
    assert_eq!(CURVE_UNITS, CURVE_PLAIN);
}
