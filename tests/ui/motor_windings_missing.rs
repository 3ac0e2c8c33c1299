use stepper_profiles::period_table;

// A motor whose pull-out torque is to come from its windings, two of whose
// figures are missing.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    step_angle = 1.8, rotor_inertia = 6.8e-6,
    resistance = 0.5, rated_current = 2.8, holding_torque = 0.40,
);

fn main() {}
