use stepper_profiles::period_table;

// A key without a unit refuses one.
static T: [u16; 1000] = period_table!(
    curve = sigmoid, len = 1000, fmin = 500, fmax = 64kHz, flexible = 8kHz, timer_hz = 10MHz,
);

fn main() {}
