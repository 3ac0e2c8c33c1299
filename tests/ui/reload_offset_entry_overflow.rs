use stepper_profiles::period_table;

static T: [u16; 100] = period_table!(
    curve = sigmoid, len = 100, fmin = 20, fmax = 1000, flexible = 4,
    timer_hz = 1_000_000,
    reload_offset = 60_000,
);

fn main() {}
