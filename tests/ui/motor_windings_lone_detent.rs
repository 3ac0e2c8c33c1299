use stepper_profiles::period_table;

// A detent torque beside a measured curve, without the windings it belongs to.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    step_angle = 1.8, rotor_inertia = 6.8e-6,
    torque_curve = [(0, 0.40), (4000, 0.25)], detent_torque = 0.01,
);

fn main() {}
