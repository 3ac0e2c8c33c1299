use stepper_profiles::period_table;

// One number where the curve's points go.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    step_angle = 1.8,
    rotor_inertia = 5.4e-6,
    load_inertia = 2.0e-5,
    torque_curve = 0.4,
    friction = 0.02,
    safety = 1.5,
    max_start_hz = 1200,
);

fn main() {}
