use stepper_profiles::period_table;

// A unit the key does not accept is an error naming the units it does.
static T: [u16; 1000] = period_table!(
    curve = sigmoid, len = 1000, fmin = 500, fmax = 64kHz2, flexible = 8, timer_hz = 10MHz,
);

fn main() {}
