//! The step interrupt's budget through the front doors: a table the
//! interrupt serves compiles, with the same bits as without the keys; the
//! fastest entry allowed is exact to the tick of the measured figures.
//! (A table too fast is a compile error: `tests/toml_errors/cpu_*.txt` pin
//! the messages.)

use stepper_profiles::period_table;

/// 20 kHz at most on a 1 MHz timer: 50 ticks a step.
static PLAIN: [u16; 200] = period_table!(
    curve = linear,
    len = 200,
    fmin = 500,
    fmax = 20kHz,
    timer_hz = 1MHz,
);

static BUDGETED: [u16; 200] = period_table!(
    curve = linear,
    len = 200,
    fmin = 500,
    fmax = 20kHz,
    timer_hz = 1MHz,
    core = "cortex-m3",
    cpu_hz = 72MHz,
    axes = 3,
    cpu_load = 0.25,
);

#[test]
fn a_budget_changes_no_period() {
    assert_eq!(BUDGETED, PLAIN);
}

/// An ATmega328P at 16 MHz with its timer at clk/8 (2 MHz): the C player's
/// 88.24 cycles a step take half the CPU at 22.06 ticks, so a table whose
/// shortest entry is 23 ticks compiles and one of 22 does not. Computed
/// here from the figure, not from the crate's model.
#[test]
fn the_fastest_entry_is_exact_to_the_tick() {
    use profile_codegen::profiles::Profiles;
    let shortest_allowed = (88.24f64 / 0.5 / 8.0).ceil();
    assert_eq!(shortest_allowed, 23.0);
    let file = |fmax: &str| {
        format!(
            "[profiles.fast]\ncurve = \"linear\"\nfmin = 1000\nfmax = {fmax}\n\
             accel = 10_000_000\ntimer_hz = \"2MHz\"\ncore = \"avr\"\ncpu_hz = \"16MHz\"\n"
        )
    };
    // 2 MHz / 23 ticks and / 22 ticks.
    assert!(Profiles::parse("profiles.toml", &file("86956")).is_ok());
    let e = Profiles::parse("profiles.toml", &file("90909")).unwrap_err();
    assert!(
        e.to_string().contains(
            "is 22 ticks, 90909.1 steps/s: the step interrupt (`core = \"avr\"` at 16 MHz, 1 axis)"
        ),
        "{e}"
    );
    // The whole CPU allowed: the largest step, 175 cycles, bounds it (22
    // ticks are 176 cycles).
    let whole = format!("{}cpu_load = 1\n", file("90909"));
    assert!(Profiles::parse("profiles.toml", &whole).is_ok());
    // A clock without its core: the message names every core.
    let clock_only = "[profiles.p]\ncurve = \"linear\"\nfmin = 1000\nfmax = 2000\naccel = 10_000\n\
                      timer_hz = \"2MHz\"\ncpu_hz = \"16MHz\"\n";
    let e = Profiles::parse("profiles.toml", clock_only).unwrap_err();
    assert!(
        e.to_string().contains(
            "`cpu_hz` checks the step interrupt's budget, which needs `core` (one of \
             \"cortex-m0\", \"cortex-m3\", \"cortex-m4f\", \"avr\") and `cpu_hz`"
        ),
        "{e}"
    );
}
