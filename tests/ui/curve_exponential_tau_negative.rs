use stepper_profiles::period_table;

static T: [u16; 120] = period_table!(
    curve = exponential,
    fmin = 500,
    fmax = 10000,
    f_inf = 15000,
    tau = -0.0185,
    timer_hz = 1_000_000,
);

fn main() {}
