use stepper_profiles::period_table;

static T: [u16; 754] = period_table!(
    curve = jerk_limited,
    fmin = 200,
    fmax = 5000,
    accel = 20000,
    jerk = 0,
    timer_hz = 10_000_000,
);

fn main() {}
