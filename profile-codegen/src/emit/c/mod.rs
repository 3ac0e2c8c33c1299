//! C: every profile's table and figures, as one header or as a header of
//! declarations and a source file of definitions.
//!
//! The output compiles under C89 (`-std=c89 -pedantic`) as well as C99 and
//! later: block comments only, no `long long` constant where C89 cannot take
//! one, `<stdint.h>` types for the tables. With the tables come a run
//! expander for compressed tables and a move player per kind of table
//! (`player`), `Player`'s semantics in C.

use core::fmt::Write;
use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

use super::{Constant, Number, Profile, avoid_periods, constants};
use crate::schema::describe;
use crate::table::computed::Generated;
use profile_core::Word;

mod player;
mod style;

use player::Kinds;
pub use style::{CStyle, CStyleError};

/// A header of `extern` declarations and `#define`d figures, and the one
/// source file that defines the tables.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Split {
    /// The header, to include wherever the tables are used.
    pub header: String,
    /// The definitions, to compile once; it includes the header by the name
    /// it was given.
    pub source: String,
}

/// The names a header takes from its own name: its include guard, its
/// players' prefix and the macros that go with them. Two headers in one
/// program need two names.
struct Names<'a> {
    /// In capitals, for the guard and the implementation macro.
    stem: String,
    /// The players' prefix, a C identifier.
    prefix: String,
    /// The profiles file, for the banner.
    source: &'a str,
}

impl<'a> Names<'a> {
    /// The names of a header called `name` (a file's stem: `x_axis` for
    /// `x_axis.h`), or `style.prefix` when it is set. From a file's stem,
    /// every run of characters other than ASCII letters and digits is one
    /// `_`, none leading or trailing (`y-axis` gives `Y_AXIS`); the prefix is
    /// that in lower case, made an identifier C leaves to programs:
    /// `profiles_` before a leading digit (`3d_printer` gives
    /// `profiles_3d_printer`), `profiles` for a name with no letter or digit
    /// (`é`).
    fn new(name: &str, style: &CStyle, source: &'a str) -> Self {
        if let Some(prefix) = &style.prefix {
            return Names {
                stem: prefix.to_uppercase(),
                prefix: prefix.clone(),
                source,
            };
        }
        let words: Vec<&str> = name
            .split(|c: char| !c.is_ascii_alphanumeric())
            .filter(|w| !w.is_empty())
            .collect();
        let joined = words.join("_").to_lowercase();
        let prefix = match words.first() {
            None => "profiles".to_string(),
            Some(w) if w.starts_with(|c: char| c.is_ascii_digit()) => {
                format!("profiles_{joined}")
            }
            Some(_) => joined,
        };
        let stem = if words.is_empty() {
            "PROFILES".to_string()
        } else {
            words.join("_").to_uppercase()
        };
        Names {
            stem,
            prefix,
            source,
        }
    }

    /// The include guard: `STEPPER_PROFILES_X_AXIS_H`.
    fn guard(&self) -> String {
        format!("STEPPER_PROFILES_{}_H", self.stem)
    }

    /// The macro that asks a single header for the players' definitions.
    fn implementation(&self) -> String {
        format!("STEPPER_PROFILES_{}_IMPLEMENTATION", self.stem)
    }

    /// The macro the players read a 16-bit word of the tables with.
    fn read(&self) -> String {
        format!("{}_RUNS_READ", self.prefix.to_uppercase())
    }

    /// The macro the players read a 32-bit period with.
    fn read32(&self) -> String {
        format!("{}_READ32", self.prefix.to_uppercase())
    }
}

/// Whether the tables go to avr-libc's program memory (`PROGMEM`), which
/// plain loads cannot read: the header then includes `<avr/pgmspace.h>`
/// and the players read with `pgm_read_word` (`pgm_read_dword`).
fn progmem(style: &CStyle) -> bool {
    style.attribute.as_deref().is_some_and(|a| {
        a.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .any(|word| word == "PROGMEM")
    })
}

/// The storage word with a space after it, or nothing.
fn storage_word(style: &CStyle) -> String {
    style
        .storage
        .as_deref()
        .map_or(String::new(), |s| format!("{} ", s.trim()))
}

/// The run expander's type and functions, declared: its pointers carry the
/// tables' storage word, so that they point where the tables are.
fn runs_api(names: &Names, style: &CStyle) -> String {
    let prefix = &names.prefix;
    let storage = storage_word(style);
    format!(
        "/* Plays a compressed ramp (a NAME_RUNS table) forwards, one period per call,\n \
         * with integer additions and shifts only: no division, no floating point.\n \
         * The move players below play moves (up, cruise, down, stops). */\n\
         typedef struct {{\n    \
         const {storage}uint16_t *next; /* the next run's five words */\n    \
         uint16_t runs_left;   /* runs not started yet */\n    \
         uint16_t left;        /* steps left in this run */\n    \
         uint32_t interval;    /* the next period, 16.16 fixed point */\n    \
         uint32_t add;         /* added after each step, two's complement */\n    \
         uint32_t frac;        /* the edges' sub-tick remainder */\n\
         }} {prefix}_runs_t;\n\n\
         /* Starts playing `count` runs from `runs` (NAME_RUNS, NAME_RUN_COUNT). */\n\
         void {prefix}_runs_start({prefix}_runs_t *p, const {storage}uint16_t (*runs)[5], uint16_t count);\n\
         /* The next period, in ticks; 0 once every step has been played. */\n\
         uint16_t {prefix}_runs_next({prefix}_runs_t *p);\n\n"
    )
}

/// The run expander's definitions: `runs::Expand`, in C89.
fn runs_player(names: &Names, style: &CStyle) -> String {
    let (prefix, read) = (&names.prefix, names.read());
    let storage = storage_word(style);
    format!(
        "void {prefix}_runs_start({prefix}_runs_t *p, const {storage}uint16_t (*runs)[5], uint16_t count)\n\
         {{\n    \
         p->next = runs[0];\n    \
         p->runs_left = count;\n    \
         p->left = 0;\n    \
         p->interval = 0;\n    \
         p->add = 0;\n    \
         p->frac = 0x8000ul;\n\
         }}\n\n\
         uint16_t {prefix}_runs_next({prefix}_runs_t *p)\n\
         {{\n    \
         uint32_t x;\n    \
         while (p->left == 0) {{\n        \
         if (p->runs_left == 0) {{\n            \
         return 0;\n        \
         }}\n        \
         p->runs_left--;\n        \
         p->left = {read}(p->next);\n        \
         p->interval = ((uint32_t){read}(p->next + 1) << 16)\n            \
         | {read}(p->next + 2);\n        \
         p->add = ((uint32_t){read}(p->next + 3) << 16)\n            \
         | {read}(p->next + 4);\n        \
         p->next += 5;\n    \
         }}\n    \
         p->left--;\n    \
         x = p->frac + p->interval;\n    \
         p->frac = x & 0xFFFFul;\n    \
         p->interval += p->add;\n    \
         return (uint16_t)(x >> 16);\n\
         }}\n\n"
    )
}

/// One header holding everything: each table as
/// `static const uintN_t NAME_PERIODS[N]` (or `NAME_SEGMENTS[N][2]`) and its
/// figures as `#define NAME_FIGURE`s. `name` names the header in C (its
/// guard `STEPPER_PROFILES_NAME_H`, its players `name_runs_*`, `name_player_*`) unless
/// `style.prefix` does: the stem of the file it is written to (`x_axis`
/// for `x_axis.h`). `source` is the profiles file, for the banner.
pub fn header(name: &str, source: &str, profiles: &[Profile], style: &CStyle) -> String {
    let names = Names::new(name, style, source);
    header_of(&names, profiles, style, "static const", true)
}

/// A header declaring each table `extern` (with the figures) and a source
/// file defining them, so that the tables are in flash once however many
/// files include the header. `header_name` is how the source includes it;
/// `name` names the header in C, as for [`header`].
pub fn split(
    name: &str,
    source: &str,
    header_name: &str,
    profiles: &[Profile],
    style: &CStyle,
) -> Split {
    let names = Names::new(name, style, source);
    let header = header_of(&names, profiles, style, "extern const", false);
    let mut c = String::new();
    banner(&mut c, &names);
    let _ = writeln!(c, "#include \"{header_name}\"\n");
    let kinds = Kinds::of(profiles);
    if kinds.runs {
        c.push_str(&runs_player(&names, style));
    }
    c.push_str(&player::definitions(&names, style, kinds));
    for p in profiles {
        let _ = writeln!(c, "/* Profile {}: see {header_name}. */", p.name);
        table(&mut c, p, "const", style, true);
        stop_steps(&mut c, p, "const", style, true);
        avoid(&mut c, p, "const", true, false);
        c.push('\n');
    }
    Split { header, source: c }
}

/// A header: per profile its parameters, figures and table, declared with
/// `qualifiers` and defined when `body` is true.
fn header_of(
    names: &Names,
    profiles: &[Profile],
    style: &CStyle,
    qualifiers: &str,
    body: bool,
) -> String {
    let mut out = String::new();
    banner(&mut out, names);
    let guard = names.guard();
    let _ = writeln!(
        out,
        "#ifndef {guard}\n#define {guard}\n\n#include <stdint.h>\n"
    );
    if progmem(style) {
        let _ = writeln!(out, "#include <avr/pgmspace.h>\n");
    }
    let kinds = Kinds::of(profiles);
    out.push_str(&player::read_macros(names, style, kinds));
    if kinds.runs {
        out.push_str(&runs_api(names, style));
    }
    out.push_str(&player::api(names, style, kinds));
    let definitions = player::definitions(names, style, kinds);
    if body && (kinds.runs || !definitions.is_empty()) {
        // One file defines the players: `#define ..._IMPLEMENTATION`
        // before including the header there.
        let implementation = names.implementation();
        let _ = writeln!(out, "#ifdef {implementation}");
        if kinds.runs {
            out.push_str(&runs_player(names, style));
        }
        out.push_str(&definitions);
        let _ = writeln!(out, "#endif /* {implementation} */\n");
    }
    for p in profiles {
        profile_comment(&mut out, p);
        figures(&mut out, p);
        table(&mut out, p, qualifiers, style, body);
        stop_steps(&mut out, p, qualifiers, style, body);
        avoid(&mut out, p, qualifiers, body, true);
        out.push('\n');
    }
    let _ = writeln!(out, "#endif /* {guard} */");
    out
}

fn banner(out: &mut String, names: &Names) {
    let source = names.source;
    let _ = writeln!(
        out,
        "/* Stepper-motor period tables generated by stepper-profiles from {source}. */"
    );
    let _ = writeln!(
        out,
        "/* Do not edit: change {source} and generate again. */"
    );
}

fn profile_comment(out: &mut String, p: &Profile) {
    let _ = writeln!(out, "/* Profile {}:", p.name);
    for (key, value) in describe(p.table.spec()) {
        let _ = writeln!(out, " *   {key} = {value}");
    }
    let _ = writeln!(out, " */");
}

/// `#define NAME_FIGURE value` for every figure. An integer above
/// `0xFFFFFFFF` needs `long long`, which C89 lacks: there it is a double
/// (exact below 2^53).
fn figures(out: &mut String, p: &Profile) {
    let upper = p.name.to_uppercase();
    for Constant { name, value, .. } in constants(p) {
        let define = format!("#define {upper}_{name}");
        let _ = match value {
            Number::U8(v) => writeln!(out, "{define} {v}u"),
            Number::I32(v) if v < 0 => writeln!(out, "{define} ({v})"),
            Number::I32(v) => writeln!(out, "{define} {v}"),
            Number::U32(v) => writeln!(out, "{define} {v}ul"),
            Number::U64(v) | Number::Usize(v) if v <= u64::from(u32::MAX) => {
                writeln!(out, "{define} {v}ul")
            }
            Number::U64(v) | Number::Usize(v) => writeln!(
                out,
                "#if defined(__STDC_VERSION__) && __STDC_VERSION__ >= 199901L\n\
                 {define} {v}ull\n#else\n{define} {v}.0\n#endif"
            ),
            Number::F64(v) => writeln!(out, "{define} {v:?}"),
        };
    }
}

/// A profile's bands (`avoid`) as the periods that play in them,
/// `NAME_AVOID`: the pairs `{shortest, longest}` in a flat array in
/// ordinary memory (never `PROGMEM`: the players' `_avoid` reads it
/// directly), declared with `qualifiers`, defined when `body` is true;
/// in a header (`header`), `NAME_AVOID_COUNT` first.
fn avoid(out: &mut String, p: &Profile, qualifiers: &str, body: bool, header: bool) {
    let Some(pairs) = avoid_periods(p) else {
        return;
    };
    let upper = p.name.to_uppercase();
    if header {
        let _ = writeln!(
            out,
            "/* The bands of `avoid` as the periods that play in them, {{shortest, longest}}\n \
             * in ticks (as the table stores them), inclusive: for\n \
             * _avoid(&player, {upper}_AVOID, {upper}_AVOID_COUNT). */\n\
             #define {upper}_AVOID_COUNT {}u",
            pairs.len()
        );
    }
    let declarator = format!("{qualifiers} uint32_t {upper}_AVOID[{}]", 2 * pairs.len());
    if !body {
        let _ = writeln!(out, "{declarator};");
        return;
    }
    let values: Vec<String> = pairs
        .iter()
        .map(|(shortest, longest)| format!("{shortest}ul, {longest}ul"))
        .collect();
    let _ = writeln!(out, "{declarator} = {{ {} }};", values.join(", "));
}

/// The table's declaration (`body` false) or definition.
fn table(out: &mut String, p: &Profile, qualifiers: &str, style: &CStyle, body: bool) {
    let upper = p.name.to_uppercase();
    let ctype = match p.table.spec().timer.word {
        Word::U16 => "uint16_t",
        Word::U32 => "uint32_t",
    };
    let (array, rows): (String, Vec<String>) = match &p.table {
        Generated::Steps(t) => (
            format!("{upper}_PERIODS[{}]", t.periods.len()),
            t.stored_periods()
                .chunks(12)
                .map(|chunk| {
                    let line: Vec<String> = chunk.iter().map(|v| v.to_string()).collect();
                    line.join(", ")
                })
                .collect(),
        ),
        Generated::Runs(t) => (
            format!("{upper}_RUNS[{}][5]", t.runs.len()),
            t.stored_runs()
                .chunks(3)
                .map(|chunk| {
                    let line: Vec<String> = chunk
                        .iter()
                        .map(|r| format!("{{{}, {}, {}, {}, {}}}", r[0], r[1], r[2], r[3], r[4]))
                        .collect();
                    line.join(", ")
                })
                .collect(),
        ),
        Generated::Segments(t) => (
            format!("{upper}_SEGMENTS[{}][2]", t.pairs.len()),
            t.stored_pairs()
                .chunks(6)
                .map(|chunk| {
                    let line: Vec<String> =
                        chunk.iter().map(|(p, c)| format!("{{{p}, {c}}}")).collect();
                    line.join(", ")
                })
                .collect(),
        ),
    };
    placed(out, (qualifiers, style, body), ctype, &array, rows);
}

/// A profile's `NAME_STOP_STEPS`, when it names an emergency ramp: the
/// steps an abort plays after each step of the table, placed as the
/// table is, declared with `qualifiers`, defined when `body` is true.
fn stop_steps(out: &mut String, p: &Profile, qualifiers: &str, style: &CStyle, body: bool) {
    let Some(emergency) = &p.emergency else {
        return;
    };
    let upper = p.name.to_uppercase();
    let steps = &emergency.stop_steps;
    let _ = writeln!(
        out,
        "/* Steps an abort along {} plays after each step of the table (the\n \
         * emergency ramp from its last entry not shorter, down to rest). */",
        emergency.profile
    );
    let ctype = match steps.iter().max().copied().unwrap_or(0) <= u32::from(u16::MAX) {
        true => "uint16_t",
        false => "uint32_t",
    };
    let rows = steps
        .chunks(16)
        .map(|chunk| {
            let line: Vec<String> = chunk.iter().map(u32::to_string).collect();
            line.join(", ")
        })
        .collect();
    let array = format!("{upper}_STOP_STEPS[{}]", steps.len());
    placed(out, (qualifiers, style, body), ctype, &array, rows);
}

/// An array `array` of `ctype` placed by `style` (its storage word and
/// attribute), declared with `qualifiers`, defined with `rows` when
/// `body` is true.
fn placed(
    out: &mut String,
    (qualifiers, style, body): (&str, &CStyle, bool),
    ctype: &str,
    array: &str,
    rows: Vec<String>,
) {
    let storage = storage_word(style);
    let attribute = style
        .attribute
        .as_deref()
        .map_or(String::new(), |a| format!(" {}", a.trim()));
    let declarator = format!("{qualifiers} {storage}{ctype} {array}{attribute}");
    if !body {
        let _ = writeln!(out, "{declarator};");
        return;
    }
    let _ = writeln!(out, "{declarator} = {{");
    for row in rows {
        let _ = writeln!(out, "    {row},");
    }
    let _ = writeln!(out, "}};");
}
