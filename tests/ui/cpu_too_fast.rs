use stepper_profiles::period_table;

// A Cortex-M0 at 16 MHz: the guide's step interrupt takes about 101 cycles
// a step on average and 284 at most, so it serves 56 338 steps/s at most
// (the largest step must end within the period); the ramp's top is faster.
static T: [u16; 2000] = period_table!(
    curve = linear, len = 2000, fmin = 1000, fmax = 100kHz, timer_hz = 16MHz,
    core = "cortex-m0", cpu_hz = 16MHz,
);

fn main() {}
