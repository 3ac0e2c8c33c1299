use stepper_profiles::period_table;

// `ns` is a nanosecond, which `tau` does not take: no unit of another scale
// (`ms`) is suggested.
static T: [u16; 120] = period_table!(
    curve = exponential, fmin = 200, fmax = 1200, f_inf = 1300, tau = 50ns, timer_hz = 1MHz,
);

fn main() {}
