use stepper_profiles::period_table;

// A timer rate in MHz must still be a whole number of Hz.
static T: [u16; 100] = period_table!(
    curve = linear, fmin = 200, fmax = 1000, len = 100, timer_hz = 1.0000005MHz,
);

fn main() {}
