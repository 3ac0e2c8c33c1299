use stepper_profiles::period_table;

// A motor described without its inertia and torque curve.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    step_angle = 1.8,
    load_inertia = 2.0e-5,
    friction = 0.02,
    safety = 1.5,
    max_start_hz = 1200,
);

fn main() {}
