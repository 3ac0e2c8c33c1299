use stepper_profiles::period_table;

static T: [(u16, u16); 200] = period_table!(
    curve = exponential,
    fmin = 500,
    fmax = 10000,
    f_inf = 15000,
    len = 120,
    timer_hz = 1_000_000,
    segments = 200,
);

fn main() {}
