use stepper_profiles::period_table;

static T: [u16; 65537] = period_table!(
    curve = sigmoid,
    len = 65537,
    fmin = 500,
    fmax = 64000,
    flexible = 8,
    timer_hz = 10_000_000,
);

fn main() {}
