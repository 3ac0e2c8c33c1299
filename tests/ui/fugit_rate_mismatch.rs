// A table made for a 10 MHz timer, played where a 1 MHz timer takes its
// durations: a type error, not a move ten times too slow.
use stepper_profiles::fugit::TimerDurationU32;
use stepper_profiles::player::Timed;

mod profiles {
    // The shipped profiles file, from trybuild's crate under target/.
    stepper_profiles::include_profiles!("../../../../profiles.toml");
}

/// A HAL's timer of 1 MHz, as it types its durations.
fn arm(_after: TimerDurationU32<1_000_000>) {}

fn main() {
    let mut timed = Timed::new(profiles::sigmoid_exact::RAMP);
    timed.start(100);
    arm(timed.next_duration().unwrap());
}
