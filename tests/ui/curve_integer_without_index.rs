use stepper_profiles::period_table;

static T: [u16; 201] = period_table!(
    curve = linear,
    fmin = 500,
    fmax = 5000,
    len = 201,
    timer_hz = 50_000_000,
    ticks_per_step = 2,
    rounding = truncate,
    arithmetic = integer,
);

fn main() {}
