use stepper_profiles::period_table;

// The fastest ramp a motor allows needs the motor.
static T: [u16; 100] = period_table!(
    curve = torque_limited,
    fmax = 5000,
    margin = 0.5,
    timer_hz = 1_000_000,
);

fn main() {}
