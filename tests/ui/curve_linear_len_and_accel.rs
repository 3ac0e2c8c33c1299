use stepper_profiles::period_table;

static T: [u16; 200] = period_table!(
    curve = linear,
    fmin = 500,
    fmax = 5000,
    len = 200,
    accel = 61875,
    timer_hz = 1_000_000,
);

fn main() {}
