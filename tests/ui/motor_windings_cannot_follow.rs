use stepper_profiles::period_table;

// A TRINAMIC QSH4218-47-28-040's windings on a 6 V supply: above 3400 full
// steps/s the derived pull-out torque falls below what the ramp needs.
static T: [u16; 64] = period_table!(
    curve = linear, fmin = 300, fmax = 9000, accel = 100_000, timer_hz = 10_000_000,
    step_angle = 1.8, rotor_inertia = 6.8e-6, load_inertia = 1.36e-5, friction = 0.02,
    resistance = 0.5, inductance = 0.6e-3, rated_current = 2.8, holding_torque = 0.40,
    supply_voltage = 6,
);

fn main() {}
