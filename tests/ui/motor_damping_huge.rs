use stepper_profiles::period_table;

// A damping no motor has: refused at its value, with the range taken, not
// read as a torque of 300 digits.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    step_angle = 1.8,
    rotor_inertia = 5.4e-6,
    load_inertia = 2.0e-5,
    torque_curve = [(0, 0.40), (500, 0.38), (1000, 0.33), (2000, 0.24), (4000, 0.12), (6000, 0.06)],
    damping = 1e300,
    safety = 1.5,
);

fn main() {}
