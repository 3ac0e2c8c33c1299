//! VCD files (IEEE 1364 value change dumps): a reference written, a
//! capture read.

use std::collections::HashMap;
use std::format;
use std::string::String;
use std::vec::Vec;

use super::{Capture, CaptureError, Channel, Reference, error};

/// The unit a VCD file of `timer_hz` counts in, as its `$timescale` names
/// it, and a tick in that unit: the largest power of ten of femtoseconds
/// that divides a tick, or picoseconds (a tick then a fraction of them)
/// where a tick is no whole number of femtoseconds.
fn unit(timer_hz: u32) -> (&'static str, f64) {
    const NAMES: [&str; 16] = [
        "1 fs", "10 fs", "100 fs", "1 ps", "10 ps", "100 ps", "1 ns", "10 ns", "100 ns", "1 us",
        "10 us", "100 us", "1 ms", "10 ms", "100 ms", "1 s",
    ];
    const FS_PER_S: u64 = 1_000_000_000_000_000;
    let hz = u64::from(timer_hz.max(1));
    if FS_PER_S % hz != 0 {
        return ("1 ps", 1e12 / hz as f64);
    }
    let tick_fs = FS_PER_S / hz;
    let mut power = 0;
    let mut scale = 1u64;
    while power < 15 && tick_fs % (scale * 10) == 0 {
        scale *= 10;
        power += 1;
    }
    (NAMES[power], (tick_fs / scale) as f64)
}

/// The reference as a VCD file.
pub(super) fn write(r: &Reference) -> String {
    let (timescale, per_tick) = unit(r.timer_hz);
    let at = |ticks: u64| libm::round(ticks as f64 * per_tick) as u64;
    let shortest = r.periods.iter().copied().min().unwrap_or(1).max(1);
    let pulse = match r.pulse_ticks {
        Some(p) => u64::from(p).max(1),
        None => (shortest / 2).max(1),
    };
    let edges = r.edges();
    let stop = match r.stop_at {
        Some(k) => format!(", stopped after {k}: {} played", edges.len()),
        None => String::new(),
    };
    let timing = match r.timing {
        super::Timing::Starts => "each edge starting its period",
        super::Timing::Ends => "each edge ending its period",
    };
    let mut out = format!(
        "$version stepper-profiles {} $end\n\
         $comment profile `{}`: a move of {} steps{stop}, from rest, {timing}; timer {} Hz, a \
         tick is {} of {timescale}; time 0 a pulse before the first step $end\n\
         $timescale {timescale} $end\n\
         $scope module {} $end\n$var wire 1 ! STEP $end\n\
         $upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n0!\n$end\n",
        env!("CARGO_PKG_VERSION"),
        r.name,
        r.steps,
        r.timer_hz,
        per_tick,
        r.name,
    );
    for edge in edges {
        let rise = pulse + edge;
        out.push_str(&format!("#{}\n1!\n#{}\n0!\n", at(rise), at(rise + pulse)));
    }
    out
}

/// The seconds of a `$timescale`: `1ns`, `10 us`, `100 ps`.
fn timescale(text: &str) -> Result<f64, CaptureError> {
    let text: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let digits: String = text.chars().take_while(char::is_ascii_digit).collect();
    let factor = match digits.as_str() {
        "1" => 1.0,
        "10" => 10.0,
        "100" => 100.0,
        _ => {
            return error(format!(
                "`$timescale {text}`: expected 1, 10 or 100 and a unit"
            ));
        }
    };
    let per_second = match &text[digits.len()..] {
        "s" => 1.0,
        "ms" => 1e3,
        "us" => 1e6,
        "ns" => 1e9,
        "ps" => 1e12,
        "fs" => 1e15,
        other => return error(format!("`$timescale {text}`: unknown unit `{other}`")),
    };
    Ok(factor / per_second)
}

/// A VCD file's 1-bit channels.
pub(super) fn read(text: &str) -> Result<Capture, CaptureError> {
    let mut tokens = text.split_whitespace();
    let mut channels: Vec<Channel> = Vec::new();
    let mut known: Vec<bool> = Vec::new();
    let mut ids: HashMap<String, Vec<usize>> = HashMap::new();
    let mut seconds = 1e-9;
    let mut now = 0.0;
    while let Some(token) = tokens.next() {
        match token {
            "$timescale" => {
                let words: Vec<&str> = tokens.by_ref().take_while(|t| *t != "$end").collect();
                seconds = timescale(&words.concat())?;
            }
            "$var" => {
                let words: Vec<&str> = tokens.by_ref().take_while(|t| *t != "$end").collect();
                let [_, size, id, name, ..] = words[..] else {
                    return error(format!("`$var {}`: too few words", words.join(" ")));
                };
                if size == "1" {
                    ids.entry(id.into()).or_default().push(channels.len());
                    channels.push(Channel {
                        name: name.into(),
                        initial: false,
                        changes: Vec::new(),
                    });
                    known.push(false);
                }
            }
            "$scope" | "$upscope" | "$comment" | "$date" | "$version" | "$enddefinitions" => {
                tokens.by_ref().find(|t| *t == "$end");
            }
            "$dumpvars" | "$dumpall" | "$dumpon" | "$dumpoff" | "$end" => {}
            _ if token.starts_with('#') => {
                let units: u64 = token[1..]
                    .parse()
                    .map_err(|_| CaptureError(format!("`{token}`: not a time")))?;
                now = units as f64 * seconds;
            }
            _ if token.starts_with(['b', 'B', 'r', 'R']) => {
                tokens.next(); // a vector's or a real's identifier
            }
            _ => {
                let (value, id) = token.split_at(1);
                let level = match value {
                    "0" => false,
                    "1" => true,
                    "x" | "X" | "z" | "Z" => continue,
                    _ => return error(format!("`{token}`: not a value change")),
                };
                for &i in ids.get(id).map(Vec::as_slice).unwrap_or(&[]) {
                    let c = &mut channels[i];
                    if !known[i] {
                        known[i] = true;
                        c.initial = level;
                    } else if c.changes.last().map_or(c.initial, |&(_, l)| l) != level {
                        c.changes.push((now, level));
                    }
                }
            }
        }
    }
    Ok(Capture { channels })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_hold_a_tick_exactly() {
        assert_eq!(unit(1_000_000), ("1 us", 1.0));
        assert_eq!(unit(10_000_000), ("100 ns", 1.0));
        assert_eq!(unit(16_000_000), ("100 ps", 625.0));
        // 13 888 888.9 fs: no whole number of them.
        assert_eq!(unit(72_000_000).0, "1 ps");
    }

    #[test]
    fn timescales_read() {
        assert_eq!(timescale("1ns").unwrap(), 1e-9);
        assert_eq!(timescale("10 us").unwrap(), 1e-5);
        assert_eq!(timescale("100ps").unwrap(), 1e-10);
        assert_eq!(
            timescale("3 ns").unwrap_err().0,
            "`$timescale 3ns`: expected 1, 10 or 100 and a unit"
        );
    }
}
