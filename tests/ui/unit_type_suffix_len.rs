use stepper_profiles::period_table;

// An integer type suffix is refused, not read as a unit.
static T: [u16; 1000] = period_table!(
    curve = sigmoid, len = 1000usize, fmin = 500, fmax = 64kHz, flexible = 8, timer_hz = 10MHz,
);

fn main() {}
