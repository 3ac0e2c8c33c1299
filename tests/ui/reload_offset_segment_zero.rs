use stepper_profiles::period_table;

static T: [(u16, u16); 5] = period_table!(
    curve = linear, len = 50, fmin = 200kHz, fmax = 1MHz,
    timer_hz = 1MHz, segments = 5,
    reload_offset = -1,
);

fn main() {}
