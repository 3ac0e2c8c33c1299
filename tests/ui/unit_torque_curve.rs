use stepper_profiles::period_table;

// A torque curve's frequency with a unit it does not take.
static T: [u16; 1000] = period_table!(
    curve = sigmoid, len = 1000, fmin = 500, fmax = 64kHz, flexible = 8, timer_hz = 10MHz, step_angle = 1.8, rotor_inertia = 5.4e-6, torque_curve = [(0, 0.4), (1khz, 0.3)],
);

fn main() {}
