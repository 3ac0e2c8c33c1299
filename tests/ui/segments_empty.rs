use stepper_profiles::period_table;

// 100 equal-time segments of a 120-step ramp: the first 0.2 ms holds no step
// at 500 Hz.
static T: [(u16, u16); 100] = period_table!(
    curve = exponential,
    fmin = 500,
    fmax = 10_000,
    f_inf = 15_000,
    len = 120,
    timer_hz = 1_000_000,
    segments = 100,
);

fn main() {}
