use stepper_profiles::period_table;

// At 5000 Hz the curve gives 0.02 N·m, which the friction takes whole.
static T: [u16; 100] = period_table!(
    curve = torque_limited, fmax = 5000, margin = 0.5, timer_hz = 1_000_000,
    step_angle = 1.8, rotor_inertia = 6.8e-6, friction = 0.02, damping_ratio = 0.1,
    torque_curve = [(0, 0.40), (5000, 0.02)],
);

fn main() {}
