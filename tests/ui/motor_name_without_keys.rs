use stepper_profiles::period_table;

// `motor = NAME` names a `[motors.NAME]` table of a profiles file; the macro has none.
static T: [u16; 978] = period_table!(
    curve = linear, fmin = 300, fmax = 2000, accel = 2000, timer_hz = 1_000_000,
    motor = nema17,
);

fn main() {}
