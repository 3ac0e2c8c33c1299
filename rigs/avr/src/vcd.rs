//! The VCD file simavr writes for the firmware's `.mmcu` traces: the step
//! pin's edges and the writes of `TCCR1B`, in CPU cycles.
//!
//! simavr 1.6 stamps each change in units of 10 ns: `cycles * 1e6 /
//! (F_CPU / 1000) / 10`, rounded down at each division. At 16 MHz a cycle is
//! 6.25 units, so every cycle has its own stamp and the cycle is recovered
//! exactly. A signal that changes twice at one stamp is written one unit
//! later the second time (simavr's way to show short pulses): such a stamp
//! is no cycle's, and belongs to the cycle one unit before.

use std::collections::HashMap;

/// A change of a traced signal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Change {
    /// The CPU cycle it happened at.
    pub cycle: u64,
    /// Its new value.
    pub value: u32,
}

/// The changes of each signal, by name, in order; a value written again at
/// the same cycle (simavr logs a pin's change once from the timer and once
/// from the port) counts once.
pub fn parse(text: &str, f_cpu: u64) -> Result<HashMap<String, Vec<Change>>, String> {
    let mut names = HashMap::new();
    let mut out: HashMap<String, Vec<Change>> = HashMap::new();
    let mut stamp = None;
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        let at = |e: String| format!("line {}: {e}: `{line}`", i + 1);
        if let Some(rest) = line.strip_prefix("$var ") {
            // $var wire 8 ! TCCR1B $end
            let words: Vec<&str> = rest.split_whitespace().collect();
            if words.len() < 4 {
                return Err(at("a $var without its name".into()));
            }
            names.insert(words[2].to_string(), words[3].to_string());
        } else if let Some(units) = line.strip_prefix('#') {
            let units: u64 = units.parse().map_err(|e| at(format!("{e}")))?;
            let cycle = cycle_of(units, f_cpu)
                .or_else(|| cycle_of(units.checked_sub(1)?, f_cpu))
                .ok_or_else(|| at("no cycle has this stamp".into()))?;
            stamp = Some(cycle);
        } else if let Some(cycle) = stamp {
            let (value, id) = if let Some(rest) = line.strip_prefix('b') {
                let (bits, id) = rest
                    .split_once(' ')
                    .ok_or_else(|| at("a vector without its id".into()))?;
                match u32::from_str_radix(bits, 2) {
                    Ok(v) => (v, id),
                    Err(_) => continue, // `bxxxxxxxx`: not yet known
                }
            } else {
                let (bit, id) = line.split_at(1);
                match bit {
                    "0" => (0, id),
                    "1" => (1, id),
                    _ => continue, // `x`, `z`
                }
            };
            let name = names.get(id).ok_or_else(|| at(format!("no $var `{id}`")))?;
            let changes = out.entry(name.clone()).or_default();
            if changes
                .last()
                .is_some_and(|c| c.value == value && c.cycle == cycle)
            {
                continue;
            }
            changes.push(Change { cycle, value });
        }
    }
    Ok(out)
}

/// The cycle stamped `units` (of 10 ns), or `None` when no cycle is.
pub fn cycle_of(units: u64, f_cpu: u64) -> Option<u64> {
    let khz = f_cpu / 1000;
    let stamp = |c: u64| c * 1_000_000 / khz / 10;
    // The stamp grows by at least 6 units a cycle at 16 MHz: start below
    // and step up.
    let mut c = units * 10 * khz / 1_000_000;
    c = c.saturating_sub(2);
    while stamp(c) < units {
        c += 1;
    }
    (stamp(c) == units).then_some(c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_cycle_has_its_stamp() {
        for c in 0..100_000u64 {
            let units = c * 1_000_000 / 16_000 / 10;
            assert_eq!(cycle_of(units, 16_000_000), Some(c));
        }
        // 6.25 units a cycle: 1 is no cycle's stamp.
        assert_eq!(cycle_of(1, 16_000_000), None);
    }

    #[test]
    fn changes_are_read_with_their_names() {
        let text = "$timescale 10ns $end\n$scope module logic $end\n\
                    $var wire 8 ! TCCR1B $end\n$var wire 1 \" OC1A $end\n\
                    $upscope $end\n$enddefinitions $end\n$dumpvars\nbxxxxxxxx !\nx\"\n$end\n\
                    #625\nb00001001 !\n#1250\n1\"\n#1251\n1\"\n";
        let v = parse(text, 16_000_000).unwrap();
        assert_eq!(
            v["TCCR1B"],
            [Change {
                cycle: 100,
                value: 9
            }]
        );
        assert_eq!(
            v["OC1A"],
            [Change {
                cycle: 200,
                value: 1
            }]
        );
    }
}
