use stepper_profiles::period_table;

// A 44-digit number in a string with a unit is a number: too many digits.
static T: [u16; 100] = period_table!(
    curve = linear, fmin = 300, fmax = "12345678901234567890123456789012345678901234 Hz", len = 100, timer_hz = 1MHz,
);

fn main() {}
