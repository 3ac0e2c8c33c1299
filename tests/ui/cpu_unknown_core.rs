use stepper_profiles::period_table;

static T: [u16; 200] = period_table!(
    curve = linear, len = 200, fmin = 1000, fmax = 10kHz, timer_hz = 1MHz,
    core = "cortex-m7", cpu_hz = 480MHz,
);

fn main() {}
