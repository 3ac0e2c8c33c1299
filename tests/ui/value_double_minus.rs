use stepper_profiles::period_table;

// `--300` is not a number: one minus at most.
static T: [u16; 100] = period_table!(
    curve = linear, fmin = --300, fmax = 1000, len = 100, timer_hz = 1_000_000,
);

fn main() {}
