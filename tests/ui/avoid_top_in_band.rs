use stepper_profiles::period_table;

// Without a motor a full step is a table step: the ramp's top, about 1000
// steps/s, lies in the band.
static T: [u16; 200] = period_table!(
    curve = linear, len = 200, fmin = 500, fmax = 1kHz, timer_hz = 1MHz,
    avoid = [(900, 1100)],
);

fn main() {}
