use stepper_profiles::period_table;

// Values are literals: `100 + 100` is not evaluated.
static T: [u16; 200] = period_table!(
    curve = linear, fmin = 300, fmax = 1000, len = 100 + 100, timer_hz = 1_000_000,
);

fn main() {}
