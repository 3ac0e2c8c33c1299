use stepper_profiles::period_table;

// No preset of that name: the nearest is suggested.
static T: [u16; 200] = period_table!(
    curve = linear, len = 200, fmin = 500, fmax = 20kHz, timer_hz = 1MHz, driver = tmc2208,
);

fn main() {}
