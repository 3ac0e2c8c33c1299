use stepper_profiles::period_table;

// One segment of 65 536 steps: its count does not fit a u16.
static T: [(u16, u16); 1] = period_table!(
    curve = linear, fmin = 100, fmax = 200, len = 65536, timer_hz = 1_000_000, segments = 1,
);

fn main() {}
