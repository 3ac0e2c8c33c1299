use stepper_profiles::period_table;

static T: [u16; 100] = period_table!(
    curve = linear,
    fmin = 500,
    fmax = 5000,
    len = 100,
    timer_hz = 50_000_000,
    ticks_per_step = 2,
    discretization = index,
    rounding = truncate,
    arithmetic = integer,
);

fn main() {}
