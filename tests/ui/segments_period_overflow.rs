use stepper_profiles::period_table;

// Four segments would average the slow start away, but step 0 of the curve
// needs 70 634 ticks, more than `u16` holds: refused as a per-step table is.
static T: [(u16, u16); 4] = period_table!(
    curve = jerk_limited,
    fmin = 100,
    fmax = 5000,
    accel = 50000,
    jerk = 5e6,
    timer_hz = 10MHz,
    segments = 4,
);

fn main() {}
