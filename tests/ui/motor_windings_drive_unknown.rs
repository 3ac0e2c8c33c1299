use stepper_profiles::period_table;

// A drive the model does not know: the three it does, and the nearest.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    step_angle = 1.8, rotor_inertia = 6.8e-6,
    resistance = 0.5, inductance = 0.6e-3, rated_current = 2.8, holding_torque = 0.40,
    supply_voltage = 24, drive = halfstep,
);

fn main() {}
