use stepper_profiles::period_table;

// A 10 kHz timer cannot time 20 kHz steps, compressed or not.
static T: &[[u16; 5]] = &period_table!(
    curve = linear,
    fmin = 1000,
    fmax = 20000,
    accel = 20000,
    timer_hz = 10000,
    compress = 100,
);

fn main() {}
