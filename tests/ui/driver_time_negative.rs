use stepper_profiles::period_table;

// A driver's time is above 0.
static T: [u16; 200] = period_table!(
    curve = linear, len = 200, fmin = 500, fmax = 20kHz, timer_hz = 1MHz, dir_setup = -200ns,
);

fn main() {}
