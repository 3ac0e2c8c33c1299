use stepper_profiles::period_table;

// `mhz` reads as millihertz: `MHz`, a billion times more, is not suggested.
static T: [u16; 1000] = period_table!(
    curve = sigmoid, len = 1000, fmin = 500, fmax = 1mhz, flexible = 8, timer_hz = 10MHz,
);

fn main() {}
