use stepper_profiles::period_table;

static T: &[[u16; 5]] = &period_table!(
    curve = linear,
    fmin = 1600,
    fmax = 48000,
    accel = 160_000,
    timer_hz = 10_000_000,
    ticks_per_step = 2,
    compress = 0.5,
);

fn main() {}
