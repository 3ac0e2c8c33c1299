//! The step driver's timing through the front doors: a table within it
//! compiles, with the same bits as without it, and the times take units
//! down to nanoseconds. (A table too fast for its driver is a compile
//! error: `tests/toml_errors/driver_*.txt` pin the messages.)

use stepper_profiles::period_table;

/// 20 kHz at most on a 1 MHz timer: 50 ticks a step, far above every
/// preset's shortest step.
static PLAIN: [u16; 200] = period_table!(
    curve = linear,
    len = 200,
    fmin = 500,
    fmax = 20kHz,
    timer_hz = 1MHz,
);

static PRESET: [u16; 200] = period_table!(
    curve = linear,
    len = 200,
    fmin = 500,
    fmax = 20kHz,
    timer_hz = 1MHz,
    driver = drv8825,
);

static TIMES: [u16; 200] = period_table!(
    curve = linear,
    len = 200,
    fmin = 500,
    fmax = 20kHz,
    timer_hz = 1MHz,
    step_pulse = 2.5us,
    step_space = 2500ns,
    dir_setup = 5us,
);

#[test]
fn a_driver_changes_no_period() {
    assert_eq!(PRESET, PLAIN);
    assert_eq!(TIMES, PLAIN);
}

/// A DM542 takes 5 µs a step: at 10 MHz, 50 ticks. 200 kHz is exactly
/// that; a tick shorter is refused, at `fmax`, in a profiles file.
#[test]
fn the_shortest_step_a_driver_takes_is_exact_to_the_tick() {
    use profile_codegen::profiles::Profiles;
    let file = |fmax: &str| {
        format!(
            "[profiles.fast]\ncurve = \"linear\"\nfmin = 1000\nfmax = \"{fmax}\"\n\
             accel = 10_000_000\ntimer_hz = \"10MHz\"\ndriver = \"dm542\"\n"
        )
    };
    assert!(Profiles::parse("profiles.toml", &file("200kHz")).is_ok());
    let e = Profiles::parse("profiles.toml", &file("201kHz")).unwrap_err();
    assert!(
        e.to_string().contains(
            "the driver's timing (`driver = \"dm542\"`) takes at least 50 ticks a step, at \
             most 200000 steps/s"
        ),
        "{e}"
    );
}

/// A profile's driver times, in ticks of its timer rounded up, are
/// constants of its module and `#define`s of the C header: a DRV8825 at
/// 10 MHz takes 19 ticks high, 19 low and DIR 7 ticks (650 ns) ahead.
#[test]
fn the_driver_times_are_emitted_in_ticks() {
    use profile_codegen::profiles::Profiles;
    let profiles = Profiles::parse(
        "profiles.toml",
        "[profiles.ramp]\ncurve = \"linear\"\nfmin = 500\nfmax = \"20kHz\"\naccel = 100_000\n\
         timer_hz = \"10MHz\"\ndriver = \"drv8825\"\n",
    )
    .unwrap();
    let rust = profiles.rust_source();
    for constant in [
        "STEP_PULSE_TICKS: u32 = 19",
        "STEP_SPACE_TICKS: u32 = 19",
        "DIR_SETUP_TICKS: u32 = 7",
    ] {
        assert!(rust.contains(constant), "{constant} in\n{rust}");
    }
    let header = profiles.c_header();
    for define in [
        "#define RAMP_STEP_PULSE_TICKS 19",
        "#define RAMP_DIR_SETUP_TICKS 7",
    ] {
        assert!(header.contains(define), "{define} in\n{header}");
    }
}
