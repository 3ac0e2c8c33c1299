use stepper_profiles::period_table;

// Inertias whose sum is not a finite number: the first out of its range.
static T: [u16; 100] = period_table!(
    curve = linear, fmin = 300, fmax = 1000, len = 100, timer_hz = 1_000_000,
    step_angle = 1.8,
    rotor_inertia = 1e308,
    load_inertia = 1e308,
    torque_curve = [(0, 0.40), (500, 0.38), (1000, 0.33)],
);

fn main() {}
