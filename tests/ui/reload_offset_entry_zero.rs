use stepper_profiles::period_table;

static T: [u16; 10] = period_table!(
    curve = linear, len = 10, fmin = 100kHz, fmax = 1MHz,
    timer_hz = 1MHz,
    reload_offset = -1,
);

fn main() {}
