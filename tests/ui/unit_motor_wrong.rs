use stepper_profiles::period_table;

// A motor's keys take its datasheet's units; `mh` is `mH` in the wrong case.
static T: [u16; 405] = period_table!(
    curve = linear, fmin = 300, fmax = 9000, accel = 100_000, timer_hz = 10_000_000,
    step_angle = 1.8, rotor_inertia = 68gcm2, load_inertia = 136gcm2, friction = 2Ncm,
    resistance = 0.5ohm, inductance = 0.6mh, rated_current = 2.8A, holding_torque = 40Ncm,
    supply_voltage = 24V,
);

fn main() {}
