use stepper_profiles::period_table;

static T: &[[u16; 5]] = &period_table!(
    curve = linear,
    fmin = 500,
    fmax = 5000,
    len = 200,
    timer_hz = 1_000_000,
    compress = 1e20,
);

fn main() {}
