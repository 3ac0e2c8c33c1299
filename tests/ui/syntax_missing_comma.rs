use stepper_profiles::period_table;

// The comma after `len's value is missing: `fmin` is the next key, not a unit.
static T: [u16; 1000] = period_table!(
    curve = sigmoid, len = 1000 fmin = 500, fmax = 64kHz, flexible = 8, timer_hz = 10MHz,
);

fn main() {}
