//! The move players of a C header: `Player`'s semantics in C89, one player
//! per kind of table the header holds (`uint16_t` periods, `uint32_t`
//! periods, runs), each emitted only where a profile has that kind.
//!
//! Each player's step path (`PREFIX_player_step`, `_next`) is an inline
//! function in the header, so that a step interrupt saves only the registers
//! it uses: the per-step tables' refill is inline too (16-bit counts, no
//! call); the runs' refill, which reads a run, is called at a run's end, so
//! that its registers are saved only then. The planner (`_init`, `_start`,
//! `_stop`, `_set_cruise`, `_remaining`) is defined once, where the run
//! expander is. A user leaves a player out with its macro (`PREFIX_NO_PLAYER`,
//! `PREFIX_NO_PLAYER32`, `PREFIX_NO_RUNS_PLAYER`), which guards its API and
//! its definitions alike.
//!
//! On SDCC's 8051 port the players fit a core whose internal RAM is 256
//! bytes, of which 128 are addressable directly: every function is
//! `__reentrant` (`STEPPER_PROFILES_REENTRANT`), so that SDCC spills its
//! registers to the stack while it runs rather than to that RAM for good;
//! the planner's locals are `static` (`STEPPER_PROFILES_LOCAL`, in external
//! RAM with `--model-large`), so that the stack holds little more than the
//! calls; nothing is inline (SDCC 4.2 miscompiles these functions inlined into
//! reentrant ones); the step path multiplies by shifts and additions (SDCC's
//! long multiplication is not reentrant), and the definitions turn off the
//! optimisations that keep values in temporaries across a function (`#pragma
//! nogcse`, `noinduction`, `noinvariant`). Every macro is the user's to
//! define first.
//!
//! The C is in C files beside this one, read with `include_str!` and
//! compiled on their own as C89 by the tests (`tests/c_templates.rs`):
//!
//! - `portability.h`: the macros above, each the user's to define first.
//! - `steps.h`, `steps.c`, `steps_init.c`: the player of per-step tables
//!   (`NAME_PERIODS`, `uint16_t` or `uint32_t`): its type, its inline step
//!   path and its declarations; the definitions the shared planner uses;
//!   `_init`, after the planner it starts.
//! - `runs.h`, `runs_refill.c`, `cursor.c`, `runs.c`, `runs_init.c`: the
//!   player of compressed tables (`NAME_RUNS`): its type, step path and
//!   declarations; the refill the step path calls at a run's end; positions
//!   along a table of runs (a cursor at a step, found by reading the runs
//!   from the first, then moved a step at a time either way, the remainder
//!   carried as the step path carries it); where a stretch starts and the
//!   definitions the planner uses; `_init` (the tables' lengths in steps,
//!   the deceleration table's fastest period, the first acceleration step
//!   faster than it). A run is played with the recurrence of
//!   `runs::Expand` (`x = frac + interval; period = x >> 16; frac = x &
//!   0xFFFF; interval += add`), the remainder `frac` in 16 bits, as the Rust
//!   player plays it: forwards from a run's first step, backwards from its
//!   last with the remainder's complement and `-add` (the reflected edges'
//!   ceiling differences). The remainder carries from run to run either
//!   way, so that entering the next run forwards reads its words, and
//!   entering the previous run backwards reads its words and computes its
//!   last step's interval (one multiplication per run).
//! - `plan.c`: the move's plan, shared by both: `Player::start`, `stop` and
//!   `set_cruise` with the planner of `player::plan`, written against a few
//!   functions each kind defines (`_period_`, `_place_`, `_settle_`,
//!   `_crossing_`, `_capped_walk_`, `_last_`, `_enter_`, `_first_`).
//! - `axis.h`, `axis.c`: an axis on either player, `Axis::queue`'s rules:
//!   a position, a direction and a queue of moves that join at speed (the
//!   move playing extended as `Player::retarget` extends it).
//!
//! In them, `tpl` stands for the player's prefix (`ramps_player`),
//! `TPL_WORD` for the period's type, `TPL_STORAGE ` for the storage word
//! and a space (or nothing) and `TPL_READ` for the macro that reads one
//! word of a table: names C compiles as they are, each replaced whole.

use std::format;
use std::string::String;
use std::vec::Vec;

use super::{CStyle, Names, progmem, storage_word};
use crate::emit::Profile;
use crate::table::computed::Generated;
use profile_core::Word;

/// The C the players are made of, as the files beside this one hold it.
mod c {
    pub(super) const PORTABILITY: &str = include_str!("portability.h");
    pub(super) const STEPS_API: &str = include_str!("steps.h");
    pub(super) const STEPS: &str = include_str!("steps.c");
    pub(super) const STEPS_INIT: &str = include_str!("steps_init.c");
    pub(super) const PLAN: &str = include_str!("plan.c");
    pub(super) const RUNS_API: &str = include_str!("runs.h");
    pub(super) const RUNS_REFILL: &str = include_str!("runs_refill.c");
    pub(super) const CURSOR: &str = include_str!("cursor.c");
    pub(super) const RUNS: &str = include_str!("runs.c");
    pub(super) const RUNS_INIT: &str = include_str!("runs_init.c");
    pub(super) const AXIS_API: &str = include_str!("axis.h");
    pub(super) const AXIS: &str = include_str!("axis.c");
}

/// Which players a header holds: one per kind of table among its profiles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Kinds {
    /// Per-step tables of `uint16_t`.
    pub(super) u16: bool,
    /// Per-step tables of `uint32_t`.
    pub(super) u32: bool,
    /// Compressed tables.
    pub(super) runs: bool,
}

impl Kinds {
    /// The kinds of `profiles`' tables (segment tables have no player).
    pub(super) fn of(profiles: &[Profile]) -> Self {
        let mut kinds = Kinds::default();
        for p in profiles {
            match &p.table {
                Generated::Steps(t) => match t.spec.timer.word {
                    Word::U16 => kinds.u16 = true,
                    Word::U32 => kinds.u32 = true,
                },
                Generated::Runs(_) => kinds.runs = true,
                Generated::Segments(_) => {}
            }
        }
        kinds
    }

    fn any(self) -> bool {
        self.u16 || self.u32 || self.runs
    }
}

/// A read macro: `name(p)` reads through `p` with `load`, unless the user
/// defines it, or `fallback(p)` for every header, first.
fn read_macro(name: &str, fallback: &str, load: &str) -> String {
    format!(
        "#ifndef {name}\n#ifdef {fallback}\n#define {name}(p) {fallback}(p)\n#else\n\
         #define {name}(p) {load}\n#endif\n#endif\n"
    )
}

/// The macros the players and the run expander read the tables with: one
/// for 16-bit words (runs and `uint16_t` periods), one for 32-bit periods;
/// `pgm_read_word` and `pgm_read_dword` for `PROGMEM` tables.
pub(super) fn read_macros(names: &Names, style: &CStyle, kinds: Kinds) -> String {
    let mut out = String::new();
    let pgm = progmem(style);
    if kinds.runs || kinds.u16 {
        let read = names.read();
        out.push_str(&format!(
            "/* Reads one 16-bit word of this file's tables. Define {read}(p) before\n \
             * including it for tables another way must read (or STEPPER_RUNS_READ(p)\n \
             * for every such file that does not define its own). */\n"
        ));
        let load = if pgm { "pgm_read_word(p)" } else { "(*(p))" };
        out.push_str(&read_macro(&read, "STEPPER_RUNS_READ", load));
        out.push('\n');
    }
    if kinds.u32 {
        let read = names.read32();
        out.push_str(&format!(
            "/* Reads one 32-bit period of this file's tables. Define {read}(p) before\n \
             * including it for tables another way must read (or STEPPER_READ32(p)\n \
             * for every such file that does not define its own). */\n"
        ));
        let load = if pgm { "pgm_read_dword(p)" } else { "(*(p))" };
        out.push_str(&read_macro(&read, "STEPPER_READ32", load));
        out.push('\n');
    }
    out
}

/// What a player's text is filled with.
struct Fill {
    /// The player's prefix: `ramps_player`.
    name: String,
    /// The period's type.
    word: &'static str,
    /// The storage word and a space, or nothing.
    storage: String,
    /// The read macro.
    read: String,
    /// The macro that leaves the player out: `RAMPS_NO_PLAYER`.
    omit: String,
}

impl Fill {
    fn apply(&self, template: &str) -> String {
        template
            .replace("TPL_WORD", self.word)
            .replace("TPL_STORAGE ", &self.storage)
            .replace("TPL_READ", &self.read)
            .replace("tpl", &self.name)
    }

    /// `templates` filled, unless the user defines the player's omit macro.
    fn guarded(&self, templates: &[&str]) -> String {
        let mut body = String::new();
        for template in templates {
            body.push_str(&self.apply(template));
        }
        let omit = &self.omit;
        format!(
            "#ifndef {omit}\n{}\n#endif /* {omit} */\n\n",
            body.trim_end_matches('\n')
        )
    }
}

/// The macro that leaves out the player whose name follows `prefix_`:
/// `RAMPS_NO_RUNS_PLAYER` for `ramps_runs_player`.
fn omit(prefix: &str, player: &str) -> String {
    format!("{}_NO_{}", prefix.to_uppercase(), player.to_uppercase())
}

/// A player's templates: its API, for the header, and its definitions, in
/// the order C defines them.
struct Templates {
    api: &'static [&'static str],
    definitions: &'static [&'static str],
}

/// The per-step player's templates.
const STEPS: Templates = Templates {
    api: &[c::STEPS_API, c::AXIS_API],
    definitions: &[c::STEPS, c::PLAN, c::STEPS_INIT, c::AXIS],
};

/// The runs player's templates.
const RUNS: Templates = Templates {
    api: &[c::RUNS_API, c::AXIS_API],
    definitions: &[
        c::RUNS_REFILL,
        c::CURSOR,
        c::RUNS,
        c::PLAN,
        c::RUNS_INIT,
        c::AXIS,
    ],
};

/// The players of `kinds`, each with its templates.
fn players(names: &Names, style: &CStyle, kinds: Kinds) -> Vec<(Fill, Templates)> {
    let prefix = &names.prefix;
    let storage = storage_word(style);
    // (wanted, name after the prefix, word, read macro, templates)
    let all = [
        (kinds.u16, "player", "uint16_t", names.read(), STEPS),
        (kinds.u32, "player32", "uint32_t", names.read32(), STEPS),
        (kinds.runs, "runs_player", "uint16_t", names.read(), RUNS),
    ];
    all.into_iter()
        .filter(|(wanted, ..)| *wanted)
        .map(|(_, suffix, word, read, templates)| {
            let fill = Fill {
                name: format!("{prefix}_{suffix}"),
                omit: omit(prefix, suffix),
                word,
                storage: storage.clone(),
                read,
            };
            (fill, templates)
        })
        .collect()
}

/// The players' types, declarations and inline step paths, for the header,
/// after the read macros.
pub(super) fn api(names: &Names, style: &CStyle, kinds: Kinds) -> String {
    if !kinds.any() {
        return String::new();
    }
    let mut out = String::from(c::PORTABILITY);
    out.push('\n');
    for (fill, templates) in players(names, style, kinds) {
        out.push_str(&format!(
            "/* To leave this player out, define {} where the header is included\n \
             * and where its definitions are compiled. */\n",
            fill.omit
        ));
        out.push_str(&fill.guarded(templates.api));
    }
    out
}

/// The players' planners, defined once: in the single header's
/// implementation section, or in the split source file.
pub(super) fn definitions(names: &Names, style: &CStyle, kinds: Kinds) -> String {
    let players = players(names, style, kinds);
    if players.is_empty() {
        return String::new();
    }
    // SDCC's optimisations that keep values in temporaries across a
    // function spill them to the 8051's internal RAM: off for the players.
    let mut out = String::from(
        "#if defined(__SDCC_mcs51)\n#pragma save\n#pragma nogcse\n#pragma noinduction\n\
         #pragma noinvariant\n#endif\n\n",
    );
    for (fill, templates) in players {
        out.push_str(&fill.guarded(templates.definitions));
    }
    out.push_str("#if defined(__SDCC_mcs51)\n#pragma restore\n#endif\n\n");
    out
}
