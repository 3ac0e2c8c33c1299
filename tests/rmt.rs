//! The ESP32-C3 RMT example's conversion
//! (`examples/hal/esp32c3/src/rmt_step.rs`) played back on the host: each
//! symbol's halves read as the RMT reads them (bits 0-14 and 16-30 the
//! lengths, 15 and 31 the levels, a length of 0 the end), the pin's level
//! followed tick by tick: every step must rise at its period from the one
//! before, high for the pulse, every half of 1 to 32 767 ticks, in as few
//! symbols as the halves allow.

#[path = "../examples/hal/esp32c3/src/rmt_step.rs"]
#[allow(dead_code)]
mod rmt_step;

use rmt_step::{END, MAX_LEN, PULSE, RAMP, StepError, step};
use stepper_profiles::player::{Player, Ramp};
use test_support::lcg::Lcg;

/// The waveform of `words`, to the end symbol: each rising edge's tick and
/// how long the pin stayed high; panics on a half out of range.
fn play(words: &[u32]) -> (Vec<u64>, Vec<u64>) {
    let (mut t, mut level, mut rose) = (0u64, false, 0u64);
    let (mut rises, mut highs) = (Vec::new(), Vec::new());
    for &w in words {
        for (length, high) in [
            (w & 0x7FFF, w >> 15 & 1 == 1),
            (w >> 16 & 0x7FFF, w >> 31 == 1),
        ] {
            if length == 0 {
                if level {
                    highs.push(t - rose);
                }
                return (rises, highs);
            }
            if high && !level {
                rises.push(t);
                rose = t;
            }
            if !high && level {
                highs.push(t - rose);
            }
            level = high;
            t += u64::from(length);
        }
    }
    panic!("no end symbol");
}

/// The symbols of `periods`, the end after them.
fn symbols(periods: &[u32], pulse: u32) -> Vec<u32> {
    let mut out = Vec::new();
    for &p in periods {
        let n = step(p, pulse, |w| out.push(w)).unwrap();
        // As few as an odd number of low halves allows.
        let halves = (p - pulse).div_ceil(MAX_LEN);
        assert_eq!(n as u32, 1 + halves / 2, "{p} ticks");
    }
    out.push(END);
    out
}

/// Uniform in `[0, n)`.
fn below(rng: &mut Lcg, n: u32) -> u32 {
    (rng.next_unit() * f64::from(n)) as u32
}

fn check(periods: &[u32], pulse: u32) {
    let words = symbols(periods, pulse);
    let (rises, highs) = play(&words);
    assert_eq!(rises.len(), periods.len());
    for (k, w) in rises.windows(2).enumerate() {
        assert_eq!(w[1] - w[0], u64::from(periods[k]), "step {k}");
    }
    assert!(highs.iter().all(|&h| h == u64::from(pulse)), "{highs:?}");
}

#[test]
fn the_example_s_move_rises_at_every_period() {
    let mut player = Player::new(Ramp::steps(&RAMP));
    player.start(2000);
    let mut periods = Vec::new();
    let mut buffer = [0u16; 64];
    loop {
        let n = player.fill(&mut buffer);
        periods.extend(buffer[..n].iter().map(|&p| u32::from(p)));
        if n < buffer.len() {
            break;
        }
    }
    assert_eq!(periods.len(), 2000);
    check(&periods, PULSE);
    // The slowest steps take two symbols.
    assert!(u32::from(RAMP[0]) > PULSE + MAX_LEN);
    assert!(symbols(&periods, PULSE).len() > 2001);
}

#[test]
fn random_periods_and_pulses_rise_at_every_period() {
    let mut rng = Lcg(0x2A7);
    for _ in 0..200 {
        let pulse = 1 + below(&mut rng, MAX_LEN);
        let periods: Vec<u32> = (0..50)
            .map(|_| match below(&mut rng, 4) {
                0 => pulse + 1 + below(&mut rng, 3),
                1 => pulse + MAX_LEN * (1 + below(&mut rng, 4)) + below(&mut rng, 3),
                _ => {
                    let bits = 1 + below(&mut rng, 23);
                    pulse + 1 + below(&mut rng, 1 << bits)
                }
            })
            .collect();
        check(&periods, pulse);
    }
}

#[test]
fn what_has_no_symbols_is_an_error() {
    let nothing = |_| panic!("no symbol");
    assert_eq!(
        step(25, 25, nothing),
        Err(StepError::TooShort {
            period: 25,
            pulse: 25
        })
    );
    assert_eq!(
        step(10, 25, nothing),
        Err(StepError::TooShort {
            period: 10,
            pulse: 25
        })
    );
    assert_eq!(
        step(100, 0, nothing),
        Err(StepError::PulseTooLong { pulse: 0 })
    );
    assert_eq!(
        step(100_000, MAX_LEN + 1, nothing),
        Err(StepError::PulseTooLong { pulse: MAX_LEN + 1 })
    );
}
