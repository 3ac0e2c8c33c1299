use stepper_profiles::period_table;

// `KHz` is `kHz` in the wrong case: the suggestion is `kHz`, not `Hz`.
static T: [u16; 1000] = period_table!(
    curve = sigmoid, len = 1000, fmin = 500, fmax = 64KHz, flexible = 8, timer_hz = 10MHz,
);

fn main() {}
