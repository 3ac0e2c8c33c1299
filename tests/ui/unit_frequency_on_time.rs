use stepper_profiles::period_table;

// A frequency unit on a time key.
static T: [u16; 120] = period_table!(
    curve = exponential, fmin = 200, fmax = 1200, f_inf = 1300, tau = 5kHz, timer_hz = 1MHz,
);

fn main() {}
