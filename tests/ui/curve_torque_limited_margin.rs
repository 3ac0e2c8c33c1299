use stepper_profiles::period_table;

static T: [u16; 100] = period_table!(
    curve = torque_limited, fmax = 5000, margin = 1, timer_hz = 1_000_000,
    step_angle = 1.8, rotor_inertia = 6.8e-6, damping_ratio = 0.1,
    torque_curve = [(0, 0.40), (5000, 0.20)],
);

fn main() {}
