//! `emergency = "NAME"`: a profile's emergency ramp, another profile of the
//! same file that `Player::abort` plays, checked against the profile it
//! stops, and the steps an abort takes from each of its steps
//! (`STOP_STEPS`).

use std::format;
use std::ops::Range;
use std::string::{String, ToString};
use std::vec::Vec;

use crate::emit::{Emergency, Profile};
use crate::schema::{self, Arg, Diagnostic, Hint, Value, did_you_mean};
use crate::table::computed::Generated;

/// The most profile names an "unknown profile" message lists.
const LISTED: usize = 8;

/// The steps an abort plays when the last step played is each step of
/// `accel` in turn: the emergency ramp `emergency` (one period a step,
/// slow to fast but for ties of a tick) from its last step not shorter
/// than that step's period down to its first, or none when every step of
/// it is shorter. Each answer is a bisection over the ramp's suffix
/// maxima: the last step not shorter than `p` is the last whose suffix
/// reaches `p`.
pub(crate) fn stop_steps(accel: &[u32], emergency: &[u32]) -> Vec<u32> {
    let mut suffix = emergency.to_vec();
    for i in (0..suffix.len().saturating_sub(1)).rev() {
        suffix[i] = suffix[i].max(suffix[i + 1]);
    }
    accel
        .iter()
        .map(|&p| suffix.partition_point(|&longest| longest >= p) as u32)
        .collect()
}

/// Resolves each profile's `emergency` (`args[i]` for `profiles[i]`, the
/// profiles that computed): the named profile, checked to stop the one
/// that names it, and its `STOP_STEPS`; every problem at the name.
pub(crate) fn resolve(
    profiles: &mut [Profile],
    args: &[Option<Arg<Range<usize>>>],
    failed: &[String],
) -> Vec<Diagnostic<Range<usize>>> {
    let mut diagnostics = Vec::new();
    for (i, arg) in args.iter().enumerate() {
        let Some(arg) = arg else { continue };
        let at = |message: String| Diagnostic {
            loc: arg.value_loc.clone(),
            message,
        };
        let name = match &arg.value {
            Value::Name(n) => n,
            other => {
                diagnostics.push(at(format!(
                    "`emergency` takes the name of another profile of this file, as a string \
                     (`emergency = \"estop\"`), not {}",
                    other.quoted()
                )));
                continue;
            }
        };
        if failed.contains(name) {
            // Its own problems are reported.
            continue;
        }
        let Some(j) = profiles.iter().position(|p| &p.name == name) else {
            diagnostics.push(at(unknown(name, profiles, failed)));
            continue;
        };
        match check(&profiles[i], &profiles[j]) {
            Ok(steps) => {
                profiles[i].emergency = Some(Emergency {
                    profile: name.clone(),
                    stop_steps: steps,
                });
            }
            Err(message) => diagnostics.push(at(message)),
        }
    }
    diagnostics
}

/// "unknown profile": the file's profiles (a few, in order), and the
/// nearest.
fn unknown(name: &str, profiles: &[Profile], failed: &[String]) -> String {
    let names: Vec<&str> = profiles
        .iter()
        .map(|p| p.name.as_str())
        .chain(failed.iter().map(String::as_str))
        .collect();
    let hint = did_you_mean(name, names.iter().copied(), Hint::Before);
    let more = match names.len() > LISTED {
        true => ", ...",
        false => "",
    };
    format!(
        "unknown profile `{name}`; {hint}`emergency` names another profile of this file: {}{more}",
        schema::quoted(names.iter().take(LISTED))
    )
}

/// `emergency` checked to stop `profile`: on the same timer, word and
/// offset, in a layout its player plays, as fast at its top, and within
/// `profile`'s motor; its `STOP_STEPS`.
fn check(profile: &Profile, emergency: &Profile) -> Result<Vec<u32>, String> {
    let (name, other) = (&profile.name, &emergency.name);
    if name == other {
        return Err(format!(
            "`emergency` names another profile, one that stops sooner; `{name}` names itself"
        ));
    }
    let (a, e) = (profile.table.spec(), emergency.table.spec());
    if a.timer != e.timer || a.reload_offset != e.reload_offset {
        return Err(format!(
            "`{other}` stores {}, `{name}` {}: an emergency ramp plays on the same timer as the \
             ramp it stops; give both the same `timer_hz`, `ticks_per_step`, `word` and \
             `reload_offset`",
            stored(emergency),
            stored(profile)
        ));
    }
    let compressed = |p: &Profile| matches!(p.table, Generated::Runs(_));
    if compressed(profile) && !compressed(emergency) {
        return Err(format!(
            "`{name}` is compressed and its player (`Player::new(&RUN_INDEX)`) plays compressed \
             ramps only; compress `{other}` too (`compress = ...`)"
        ));
    }
    let (accel, stop) = (profile.table.step_periods(), emergency.table.step_periods());
    reaches(name, other, a.timer.frequency_scale(), &accel, &stop)?;
    if let (Some(motor), None) = (&profile.motor, &emergency.motor) {
        motor.check(e, &stop).map_err(|err| {
            format!("`{other}`, the emergency ramp of `{name}`, is too steep for `{name}`'s motor: {err}")
        })?;
    }
    Ok(stop_steps(&accel, &stop))
}

/// An abort at the top of `accel` enters `stop` at its fastest step: as
/// fast, or slower by no steeper a step than `stop`'s own steepest (each
/// step's acceleration the change of frequency over the step's time,
/// `scale` the timer's ticks a second a step). Periods in ticks.
fn reaches(name: &str, other: &str, scale: f64, accel: &[u32], stop: &[u32]) -> Result<(), String> {
    let (Some(&fastest), Some(&reach)) = (accel.iter().min(), stop.iter().min()) else {
        return Ok(());
    };
    if reach <= fastest {
        return Ok(());
    }
    let hz = |p: u32| scale / f64::from(p);
    // From a step of `p` to one of `q` ticks, in Hz/s.
    let change = |p: u32, q: u32| (hz(p) - hz(q)).abs() * hz(q);
    let steepest = stop
        .windows(2)
        .map(|w| change(w[0], w[1]))
        .fold(0.0, f64::max);
    let jump = change(fastest, reach);
    if jump <= steepest {
        return Ok(());
    }
    let fixed = |v: f64| crate::numbers::Fixed(v, 0);
    Err(format!(
        "`{other}` reaches {} Hz at its fastest and `{name}` {} Hz: an abort at full speed \
         would slow at once by {} Hz/s, more than any step of `{other}` ({} Hz/s at most); \
         give `{other}` an `fmax` of at least `{name}`'s",
        crate::numbers::Fixed(hz(reach), 1),
        crate::numbers::Fixed(hz(fastest), 1),
        fixed(jump),
        fixed(steepest)
    ))
}

/// How a profile's table stores its periods, for messages.
fn stored(p: &Profile) -> String {
    let spec = p.table.spec();
    format!(
        "{} of a {} Hz timer{}{}",
        spec.timer.word.name(),
        spec.timer.timer_hz,
        match spec.timer.ticks_per_step {
            1 => String::new(),
            n => format!(", {n} ticks a step"),
        },
        match spec.reload_offset {
            0 => String::new(),
            n => format!(", reload_offset {n}"),
        }
    )
    .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The walk down from the top, as the player's rule says it.
    fn walked(accel: &[u32], emergency: &[u32]) -> Vec<u32> {
        accel
            .iter()
            .map(|&p| {
                let mut at = emergency.len();
                while at > 0 && emergency[at - 1] < p {
                    at -= 1;
                }
                at as u32
            })
            .collect()
    }

    #[test]
    fn stop_steps_are_the_walk_down_from_the_top() {
        let emergency = [900, 700, 701, 500, 500, 300];
        let accel = [1000, 900, 800, 701, 700, 600, 500, 400, 300, 200];
        assert_eq!(
            stop_steps(&accel, &emergency),
            [0, 1, 1, 3, 3, 3, 5, 5, 6, 6]
        );
        let mut seed = 0x5eed_u64;
        let mut next = move |m: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % m
        };
        for _ in 0..500 {
            let mut p = 2000 + next(2000) as u32;
            let emergency: Vec<u32> = (0..next(40))
                .map(|_| {
                    p = (p + next(3) as u32).saturating_sub(next(120) as u32).max(1);
                    p
                })
                .collect();
            let accel: Vec<u32> = (0..next(60)).map(|_| 1 + next(4500) as u32).collect();
            assert_eq!(stop_steps(&accel, &emergency), walked(&accel, &emergency));
        }
    }
}
