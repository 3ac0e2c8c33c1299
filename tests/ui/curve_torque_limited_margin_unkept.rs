use stepper_profiles::period_table;

// A heavy load on 1/8 steps and a 1 MHz timer: near 26 kHz a period is 38
// ticks, and a tick of rounding reads as more acceleration than the little
// torque there is to spare at the top.
static T: [u16; 100] = period_table!(
    curve = torque_limited, fmax = 26_000, margin = 0.72, timer_hz = 1_000_000,
    step_angle = 1.8, microsteps = 8, rotor_inertia = 375gcm2, load_inertia = 1440gcm2,
    friction = 0.065, damping_ratio = 0.07,
    torque_curve = [(0, 1.40), (4300, 1.03), (8700, 0.875), (13000, 0.807), (17400, 0.786),
        (21700, 0.644), (26000, 0.402), (30400, 0.384)],
);

fn main() {}
