use stepper_profiles::period_table;

static T: [u16; 261] = period_table!(
    curve = three_stage,
    fmin = 100,
    fmax = 1200,
    accel = 4000,
    f1 = 400,
    f2 = 900,
    shape = 0,
    timer_hz = 1_000_000,
);

fn main() {}
