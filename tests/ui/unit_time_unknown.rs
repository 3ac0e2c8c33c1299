use stepper_profiles::period_table;

// `min` is not a time unit a key takes.
static T: [u16; 120] = period_table!(
    curve = exponential, fmin = 200, fmax = 1200, f_inf = 1300, tau = 5 min, timer_hz = 1MHz,
);

fn main() {}
