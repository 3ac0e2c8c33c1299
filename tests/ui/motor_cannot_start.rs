use stepper_profiles::period_table;

// A one-entry table is checked too: the start needs 10 N·m against friction.
static T: [u16; 1] = period_table!(
    curve = linear, fmin = 400, fmax = 500, len = 1, timer_hz = 1_000_000,
    step_angle = 1.8,
    rotor_inertia = 5.4e-6,
    torque_curve = [(0, 0.40), (500, 0.38), (1000, 0.33)],
    friction = 10,
);

fn main() {}
