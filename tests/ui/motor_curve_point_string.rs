use stepper_profiles::period_table;

// A word in a point of the torque curve: the error is at the word, not on the
// whole list.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    step_angle = 1.8,
    rotor_inertia = 5.4e-6,
    torque_curve = [(0, 0.40), ("fast", 0.24), (4000, 0.12)],
);

fn main() {}
