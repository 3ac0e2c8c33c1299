use stepper_profiles::period_table;

// A torque curve read off a datasheet in N·cm; one point's unit mistyped.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    step_angle = 1.8, rotor_inertia = 54gcm2,
    torque_curve = [(0, 40 Ncm), (1kHz, 33 Ncm), (4kHz, 12 Nmc)],
);

fn main() {}
