//! The one emitter: Rust source and C headers for tables.
//!
//! `period_table!`, `include_profiles!`, the build-script API and the report
//! all print tables through these functions, so the bits and the figures that
//! reach firmware are written in one place.

use core::fmt::Write;
use std::format;
use std::string::{String, ToString};

use crate::params::describe;
use crate::spec::Word;
use crate::table::{SegmentTable, Table};

/// A generated table in one of the two layouts.
#[derive(Clone, Debug, PartialEq)]
pub enum Generated {
    /// One period per step.
    Steps(Table),
    /// Seed 001's equal-time segments.
    Segments(SegmentTable),
}

impl Generated {
    /// One period per step: the table itself, or the segments expanded.
    pub fn step_periods(&self) -> std::vec::Vec<u32> {
        match self {
            Generated::Steps(t) => t.periods.clone(),
            Generated::Segments(t) => t
                .pairs
                .iter()
                .flat_map(|&(p, c)| core::iter::repeat_n(p, c as usize))
                .collect(),
        }
    }

    /// The spec the table was computed from.
    pub fn spec(&self) -> &crate::Spec {
        match self {
            Generated::Steps(t) => &t.spec,
            Generated::Segments(t) => &t.spec,
        }
    }
}

/// A named table, as declared in `profiles.toml`.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    /// The profile's name: a Rust identifier, the module's name.
    pub name: String,
    /// Its table.
    pub table: Generated,
    /// Where its motor has the least torque to spare, when it names one.
    pub torque: Option<crate::motor::TorqueFigures>,
    /// The motor it drives, when it names one: for plots and simulations
    /// ([`Motor::check_with`](crate::motor::Motor::check_with),
    /// [`simulate::run`](crate::simulate::run)).
    pub motor: Option<crate::motor::Motor>,
}

/// Rust source of an array expression holding `periods` as `word`s:
/// `[19183u16, 18866, ...]`. Only the first literal carries the suffix;
/// the array's type follows from it.
pub fn rust_array(word: Word, periods: &[u32]) -> String {
    let mut out = String::with_capacity(periods.len() * 7 + 2);
    out.push('[');
    for (i, p) in periods.iter().enumerate() {
        if i == 0 {
            let _ = write!(out, "{p}{}", word.name());
        } else {
            let _ = write!(out, ", {p}");
        }
    }
    out.push(']');
    out
}

/// Rust source of an array of `(period, count)` pairs, as `word`s:
/// `[(9533u16, 3u16), (4750, 9), ...]`.
pub fn rust_pairs(word: Word, pairs: &[(u32, u32)]) -> String {
    let mut out = String::with_capacity(pairs.len() * 14 + 2);
    out.push('[');
    for (i, (period, count)) in pairs.iter().enumerate() {
        if i == 0 {
            let w = word.name();
            let _ = write!(out, "({period}{w}, {count}{w})");
        } else {
            let _ = write!(out, ", ({period}, {count})");
        }
    }
    out.push(']');
    out
}

/// The figures of a table as `(NAME, Rust type, value, doc)`: the constants
/// of a profile module and the `#define`s of a C header.
fn constants(
    profile: &Profile,
) -> std::vec::Vec<(&'static str, &'static str, String, &'static str)> {
    let table = &profile.table;
    let spec = table.spec();
    let mut c = std::vec![
        (
            "TIMER_HZ",
            "u32",
            spec.timer.timer_hz.to_string(),
            "Timer tick rate after the prescaler, in Hz."
        ),
        (
            "TICKS_PER_STEP",
            "u8",
            spec.timer.ticks_per_step.to_string(),
            "Timer reloads per step (2: each entry is a half period)."
        ),
    ];
    match table {
        Generated::Steps(t) => {
            let f = &t.figures;
            c.extend([
                (
                    "LEN",
                    "usize",
                    f.len.to_string(),
                    "Entries in `PERIODS`: steps of the ramp.",
                ),
                (
                    "TOTAL_TICKS",
                    "u64",
                    f.total_ticks.to_string(),
                    "Sum of `PERIODS`, in ticks.",
                ),
                (
                    "FIRST_TICKS",
                    "u32",
                    f.first_ticks.to_string(),
                    "First (slowest) period, in ticks.",
                ),
                (
                    "LAST_TICKS",
                    "u32",
                    f.last_ticks.to_string(),
                    "Last (fastest) period, in ticks.",
                ),
                (
                    "DURATION_S",
                    "f64",
                    format!("{:?}", f.duration_s),
                    "Ramp duration as played, in s.",
                ),
                (
                    "START_HZ",
                    "f64",
                    format!("{:?}", f.start_hz),
                    "Step frequency of the first entry, in Hz.",
                ),
                (
                    "FINAL_HZ",
                    "f64",
                    format!("{:?}", f.final_hz),
                    "Step frequency of the last entry, in Hz.",
                ),
            ]);
        }
        Generated::Segments(t) => {
            let f = &t.figures;
            c.extend([
                (
                    "SEGMENT_COUNT",
                    "usize",
                    f.segments.to_string(),
                    "Entries in `SEGMENTS`.",
                ),
                (
                    "LEN",
                    "usize",
                    f.steps.to_string(),
                    "Steps of the ramp: the sum of the segments' counts.",
                ),
                (
                    "TOTAL_TICKS",
                    "u64",
                    f.total_ticks.to_string(),
                    "Sum of period times count, in ticks.",
                ),
                (
                    "DURATION_S",
                    "f64",
                    format!("{:?}", f.duration_s),
                    "Ramp duration as played, in s.",
                ),
            ]);
        }
    }
    if let Some(t) = &profile.torque {
        c.extend([
            (
                "TORQUE_MARGIN_NM",
                "f64",
                format!("{:?}", t.min_margin_nm),
                "Smallest torque the motor has to spare over the ramp, in N·m.",
            ),
            (
                "TORQUE_MARGIN_STEP",
                "usize",
                t.step.to_string(),
                "The step where the torque margin is smallest.",
            ),
        ]);
    }
    c
}

/// Markdown lines describing a table: parameters and figures.
pub fn doc_lines(table: &Generated) -> std::vec::Vec<String> {
    let spec = table.spec();
    let mut lines = std::vec![
        "| parameter | value |".to_string(),
        "| --- | --- |".to_string(),
    ];
    for (key, value) in describe(spec) {
        lines.push(format!("| `{key}` | {value} |"));
    }
    lines.push(String::new());
    match table {
        Generated::Steps(t) => {
            let f = &t.figures;
            lines.push(format!(
                "{} entries, {} to {} ticks ({:.2} Hz to {:.2} Hz), {} ticks in all ({:.6} s); \
                 pulse edges within {:.3} tick of the unrounded curve, drift {:.3} tick; \
                 peak acceleration {:.0} Hz/s.",
                f.len,
                f.first_ticks,
                f.last_ticks,
                f.start_hz,
                f.final_hz,
                f.total_ticks,
                f.duration_s,
                f.max_edge_error_ticks,
                f.total_error_ticks,
                f.max_accel_hz_s
            ));
        }
        Generated::Segments(t) => {
            let f = &t.figures;
            lines.push(format!(
                "{} segments for {} steps, {} bytes instead of {} per step; {} ticks in all \
                 ({:.6} s); pulse edges within {:.1} ticks of the curve.",
                f.segments,
                f.steps,
                f.flash_bytes,
                f.per_step_flash_bytes,
                f.total_ticks,
                f.duration_s,
                f.max_edge_error_ticks
            ));
        }
    }
    lines
}

/// Rust source of a module `name` holding the table and its figures.
pub fn rust_module(profile: &Profile) -> String {
    let mut out = String::new();
    let spec = profile.table.spec();
    let word = spec.timer.word;
    let _ = writeln!(
        out,
        "/// Profile `{}` ({}).",
        profile.name,
        spec.curve.name()
    );
    let _ = writeln!(out, "///");
    for line in doc_lines(&profile.table) {
        let _ = writeln!(out, "/// {line}");
    }
    // Unused figures are no reason for warnings in the user's crate.
    if let Some(t) = &profile.torque {
        let _ = writeln!(
            out,
            "///\n/// Motor: the smallest torque margin is {:.4} N·m at step {} ({:.1} Hz): {:.4} N·m needed of {:.4} N·m available.",
            t.min_margin_nm, t.step, t.hz, t.needed_nm, t.available_nm
        );
    }
    let _ = writeln!(out, "#[allow(dead_code)]");
    let _ = writeln!(out, "pub mod {} {{", profile.name);
    match &profile.table {
        Generated::Steps(t) => {
            let _ = writeln!(
                out,
                "    /// Timer periods, one per step, in ticks of `TIMER_HZ`."
            );
            let _ = writeln!(
                out,
                "    pub static PERIODS: [{}; {}] = {};",
                word.name(),
                t.periods.len(),
                rust_array(word, &t.periods)
            );
        }
        Generated::Segments(t) => {
            let _ = writeln!(
                out,
                "    /// `(period in ticks, steps)` per equal-time segment."
            );
            let _ = writeln!(
                out,
                "    pub static SEGMENTS: [({w}, {w}); {}] = {};",
                t.pairs.len(),
                rust_pairs(word, &t.pairs),
                w = word.name()
            );
        }
    }
    for (name, ty, value, doc) in constants(profile) {
        let _ = writeln!(out, "    /// {doc}");
        let _ = writeln!(out, "    pub const {name}: {ty} = {value};");
    }
    out.push_str("}\n");
    out
}

/// Rust source of one module per profile.
pub fn rust_modules(profiles: &[Profile]) -> String {
    profiles
        .iter()
        .map(rust_module)
        .collect::<std::vec::Vec<_>>()
        .join("\n")
}

/// A C99 header with each profile's table as `static const uintN_t NAME_PERIODS[N]`
/// (or `NAME_SEGMENTS[N][2]`) and its figures as `#define NAME_FIGURE`s.
pub fn c_header(guard: &str, source: &str, profiles: &[Profile]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "/* Stepper-motor period tables generated by stepper-profiles from {source}. */"
    );
    let _ = writeln!(
        out,
        "/* Do not edit: change {source} and generate again. */"
    );
    let _ = writeln!(
        out,
        "#ifndef {guard}\n#define {guard}\n\n#include <stdint.h>\n"
    );
    for p in profiles {
        let spec = p.table.spec();
        let upper = p.name.to_uppercase();
        let ctype = match spec.timer.word {
            Word::U16 => "uint16_t",
            Word::U32 => "uint32_t",
        };
        let _ = writeln!(out, "/* Profile {}:", p.name);
        for (key, value) in describe(spec) {
            let _ = writeln!(out, " *   {key} = {value}");
        }
        let _ = writeln!(out, " */");
        for (name, ty, value, _) in constants(p) {
            let suffix = match ty {
                "u64" => "ull",
                "u32" | "usize" => "ul",
                "u8" => "u",
                _ => "",
            };
            let _ = writeln!(out, "#define {upper}_{name} {value}{suffix}");
        }
        match &p.table {
            Generated::Steps(t) => {
                let _ = writeln!(
                    out,
                    "static const {ctype} {upper}_PERIODS[{}] = {{",
                    t.periods.len()
                );
                for chunk in t.periods.chunks(12) {
                    let line: std::vec::Vec<String> = chunk.iter().map(|v| v.to_string()).collect();
                    let _ = writeln!(out, "    {},", line.join(", "));
                }
            }
            Generated::Segments(t) => {
                let _ = writeln!(
                    out,
                    "static const {ctype} {upper}_SEGMENTS[{}][2] = {{",
                    t.pairs.len()
                );
                for chunk in t.pairs.chunks(6) {
                    let line: std::vec::Vec<String> =
                        chunk.iter().map(|(p, c)| format!("{{{p}, {c}}}")).collect();
                    let _ = writeln!(out, "    {},", line.join(", "));
                }
            }
        }
        let _ = writeln!(out, "}};\n");
    }
    let _ = writeln!(out, "#endif /* {guard} */");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_literal_is_suffixed() {
        assert_eq!(rust_array(Word::U16, &[3, 2, 1]), "[3u16, 2, 1]");
        assert_eq!(rust_array(Word::U32, &[70000]), "[70000u32]");
        assert_eq!(
            rust_pairs(Word::U16, &[(9, 3), (4, 9)]),
            "[(9u16, 3u16), (4, 9)]"
        );
    }
}
