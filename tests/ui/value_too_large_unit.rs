use stepper_profiles::period_table;

// 1e306 MHz is beyond a 64-bit float once scaled to Hz.
static T: [u16; 100] = period_table!(
    curve = linear, fmin = 300, fmax = 1e306MHz, len = 100, timer_hz = 1MHz,
);

fn main() {}
