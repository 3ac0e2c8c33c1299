use stepper_profiles::period_table;

// A misspelt motor key: the error names the key it was meant to be, and
// that key is not reported missing as well.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    step_angle = 1.8, rotor_inerta = 6.8e-6, torque_curve = [(0, 0.40), (4000, 0.25)],
);

fn main() {}
