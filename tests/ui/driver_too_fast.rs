use stepper_profiles::period_table;

// A DRV8825 takes 1.9 µs high and 1.9 µs low: 38 ticks a step at 10 MHz,
// 263 157 steps/s at most; the ramp's top is faster.
static T: [u16; 2000] = period_table!(
    curve = linear, len = 2000, fmin = 1000, fmax = 300kHz, timer_hz = 10MHz, driver = drv8825,
);

fn main() {}
