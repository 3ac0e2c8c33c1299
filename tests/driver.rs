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
