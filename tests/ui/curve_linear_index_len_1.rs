use stepper_profiles::period_table;

static T: [u16; 1] = period_table!(
    curve = linear,
    fmin = 500,
    fmax = 5000,
    len = 1,
    timer_hz = 1_000_000,
    discretization = index,
);

fn main() {}
