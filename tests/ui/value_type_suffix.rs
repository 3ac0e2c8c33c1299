use stepper_profiles::period_table;

// A type suffix is not a unit; it would be silently ignored.
static T: [u16; 100] = period_table!(
    curve = linear, fmin = 200u8, fmax = 1000, len = 100, timer_hz = 1_000_000,
);

fn main() {}
