use stepper_profiles::period_table;

static T: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1e20,
    fmin = 500,
    fmax = 64000,
    flexible = 8,
    timer_hz = 10_000_000,
);

fn main() {}
