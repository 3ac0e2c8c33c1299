use stepper_profiles::period_table;

// `nan` is a name, not a number.
static T: [u16; 100] = period_table!(
    curve = linear, fmin = 300, fmax = 1000, len = 100, timer_hz = 1_000_000,
    step_angle = 1.8, rotor_inertia = 5.4e-6, torque_curve = [(0, 0.4), (5000, 0.1)],
    safety = nan,
);

fn main() {}
