//! The C header's move players against the Rust `Player`, period for period.
//!
//! The test draws random tables of each kind the players play (`uint16_t`
//! and `uint32_t` periods: falling with ties, arbitrary, tiny; runs: random
//! words, empty runs included) and the generated tables of a profiles file,
//! each with or without its own deceleration table, and random sequences of
//! operations (starts of 0 to 400 steps, of the profiles' lengths and of
//! `u32::MAX`, steps played, stops, cruise changes), and on the same random
//! tables an axis at 0 (`_axis_`, `Axis`) given random targets queued
//! between steps (`_axis_queue`, `Axis::queue`: moves that join at speed,
//! reversals at rest, a full queue refused). It writes them into a C
//! program that plays every sequence with the header's player and prints
//! every period and the steps remaining after each operation (an axis: each
//! target taken or not, its position and direction), compiles it
//! with the machine's C compiler (`cc`, or `$CC`) and compares its output
//! with the same sequences played by `Player::new(..).with_decel(..)` (per-step tables)
//! and `Player::new(&RUNS).with_decel(..)` (runs).
//!
//! Two builds: one header (C89, `-O0`), and a header with its source file
//! whose tables are in program memory (`PROGMEM`, with a storage word; C99,
//! `-O2`). In the second, every word of the program's tables is stored
//! scrambled and the stand-in for avr-libc's `pgm_read_word` and
//! `pgm_read_dword` unscrambles it: a player that read a table without the
//! header's read macro would play wrong periods.
//!
//! `C_PLAYER_CASES` sets the number of random sequences per kind (default
//! 200).

use test_support as common;

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use common::cc::CProgram;
use common::lcg::Lcg;
use profile_codegen::Generated;
use profile_codegen::profiles::{CStyle, Profiles};
use profile_core::TableWord;
use profile_core::player::{Axis, Layout, Player, Ramp};
use profile_core::runs::LinearRun;

/// A table the players play.
#[derive(Clone, Debug)]
enum Table {
    U16(Vec<u16>),
    U32(Vec<u32>),
    Runs(Vec<[u16; 5]>),
}

#[derive(Clone, Copy, Debug)]
enum Op {
    Start(u32),
    Play(u32),
    Stop,
    Cruise(u32),
    /// An axis's queued target (`Axis::queue`, `_axis_queue`).
    Queue(i32),
}

/// A sequence: its tables (the deceleration table the acceleration table's
/// when `None`) and its operations.
#[derive(Clone, Debug)]
struct Case {
    accel: Table,
    decel: Option<Table>,
    ops: Vec<Op>,
    /// Bands of periods the cruise keeps out of (`Player::avoiding`,
    /// `_avoid`).
    avoid: Vec<(u32, u32)>,
    /// Played as an axis at 0 with a queue (`Axis`, `_axis_`): its
    /// operations are queued targets and steps.
    axis: bool,
}

/// The profiles whose header holds all three players, and whose tables are
/// played too.
const PROFILES: &str = r#"
[defaults]
curve = "linear"
timer_hz = "1 MHz"

[profiles.short]
fmin = 500
fmax = 5000
len = 60

[profiles.wide]
word = "u32"
timer_hz = "16 MHz"
fmin = 100
fmax = 20000
len = 150

[profiles.runs]
timer_hz = "2 MHz"
fmin = 400
fmax = 16000
accel = 200000
compress = 1
"#;

fn below(rng: &mut Lcg, n: u32) -> u32 {
    ((rng.next_unit() * f64::from(n)) as u32).min(n.saturating_sub(1))
}

/// Periods from 1 to `top`: falling with ties, falling in plateaus (up to
/// 40 equal entries), arbitrary, or a tiny table.
fn periods(rng: &mut Lcg, top: u32) -> Vec<u32> {
    let len = 1 + below(rng, 80) as usize;
    let mut p = 2 + below(rng, top - 1);
    match below(rng, 6) {
        0..=2 => {
            let drop = 1 + top / 1500;
            (0..len)
                .map(|_| {
                    let v = p;
                    p = p.saturating_sub(below(rng, 3) * drop).max(1);
                    v
                })
                .collect()
        }
        3 => {
            let mut out = Vec::new();
            while out.len() < len {
                let plateau = 1 + below(rng, 40) as usize;
                out.extend(std::iter::repeat_n(p, plateau));
                p = p.saturating_sub(1 + below(rng, 1 + top / 200)).max(1);
            }
            out
        }
        4 => (0..len).map(|_| 1 + below(rng, 400)).collect(),
        _ => (0..1 + below(rng, 3)).map(|_| 1 + below(rng, 3)).collect(),
    }
}

/// Random runs: counts from 0, periods from 1 to about 4000 ticks with any
/// remainder (half of them one a step's carry makes `0xFFFF` or 0), changing
/// by up to 6 ticks a step, ending in range.
fn runs(rng: &mut Lcg) -> Vec<[u16; 5]> {
    (0..1 + below(rng, 12))
        .map(|_| {
            let count = below(rng, 30) as u16;
            let frac = match below(rng, 8) {
                0 => 0x7FFF,
                1 => 0x8000,
                2 => 0xFFFF,
                3 => 0,
                _ => below(rng, 65_536),
            };
            let interval = ((1 + below(rng, 3000)) << 16) | frac;
            let add = match below(rng, 6) {
                0 => 0,
                1 => 1,
                2 => -1,
                _ => below(rng, 800_000) as i32 - 400_000,
            };
            let end = i64::from(interval) + (i64::from(count.max(1)) - 1) * i64::from(add);
            let add = if (1 << 16..4000 << 16).contains(&end) {
                add
            } else {
                0
            };
            LinearRun {
                count,
                interval,
                add,
            }
            .encode()
        })
        .collect()
}

/// Sequences that reach what random ones rarely do: a stop whose entry
/// a bisection would not find; a stop right after a
/// step whose remainder was `0xFFFF` before it; a stop on a plateau of more
/// than 16 equal entries; a cruise of more than 65 535 steps; a cruise
/// change one step before the acceleration table runs faster than the
/// deceleration table's fastest entry.
fn edge_cases() -> Vec<Case> {
    let remainder = Table::Runs(vec![[3, 1000, 0x7FFF, 0, 0], [6, 900, 0, 0xFFFF, 0xF000]]);
    let mut plateau = vec![900u16; 20];
    plateau.extend([800; 30]);
    plateau.push(700);
    let mut out = Vec::new();
    // A stop at 800 ticks on a table that is not ordered: its last entry
    // of 800 is its fifth, where a bisection finds the second.
    out.push(Case {
        accel: Table::U16(vec![900, 800, 700, 800, 800, 600]),
        decel: None,
        ops: vec![Op::Start(20), Op::Play(2), Op::Stop, Op::Play(10)],
        avoid: vec![],
        axis: false,
    });
    for k in 1..6 {
        out.push(Case {
            accel: remainder.clone(),
            decel: None,
            ops: vec![Op::Start(30), Op::Play(k), Op::Stop, Op::Play(40)],
            avoid: vec![],
            axis: false,
        });
        out.push(Case {
            accel: Table::U16(plateau.clone()),
            decel: None,
            ops: vec![
                Op::Start(200),
                Op::Play(20 + 10 * k),
                Op::Stop,
                Op::Play(80),
            ],
            avoid: vec![],
            axis: false,
        });
    }
    // A cruise longer than 65 535 steps, played across the step path's
    // pieces, then stopped.
    for accel in [
        Table::U16(vec![300, 200, 100]),
        Table::Runs(vec![[3, 300, 0, 0xFFCE, 0], [2, 100, 0x8000, 0, 0]]),
    ] {
        out.push(Case {
            accel,
            decel: None,
            ops: vec![Op::Start(140_000), Op::Play(66_000), Op::Stop, Op::Play(20)],
            avoid: vec![],
            axis: false,
        });
    }
    for played in 0..5 {
        out.push(Case {
            accel: Table::U16(vec![4000, 3000, 2000, 1000, 900]),
            decel: Some(Table::U16(vec![4000, 2500])),
            ops: vec![Op::Start(40), Op::Play(played), Op::Cruise(4), Op::Play(50)],
            avoid: vec![],
            axis: false,
        });
    }
    // Bands: a cruise inside one gives way to the fastest entry slower than
    // it, past a second band that search lands in, and not past a band
    // that reaches the longest period there is.
    let bands = [
        vec![(1500, 2500)],
        vec![(1500, 2500), (2900, 3100)],
        vec![(1500, 2500), (2900, u32::MAX)],
        vec![(0, 950)],
    ];
    for avoid in bands {
        for accel in [
            Table::U16(vec![4000, 3000, 2000, 1000, 900]),
            Table::Runs(vec![
                [3, 3000, 0, 0xFC18, 0xFFFF],
                [2, 1000, 0, 0xFF9C, 0xFFFF],
            ]),
        ] {
            out.push(Case {
                accel,
                decel: None,
                ops: vec![
                    Op::Cruise(2),
                    Op::Start(30),
                    Op::Play(10),
                    Op::Cruise(3),
                    Op::Play(40),
                ],
                avoid: avoid.clone(),
                axis: false,
            });
        }
    }
    out
}

/// Up to three random bands of periods below `top`: none half of the time;
/// some reach to 0 or to `u32::MAX`.
fn bands(rng: &mut Lcg, top: u32) -> Vec<(u32, u32)> {
    let n = match below(rng, 6) {
        0..=2 => 0,
        k => k - 2,
    };
    (0..n)
        .map(|_| {
            let (a, b) = (below(rng, top), below(rng, top / 4 + 1));
            match below(rng, 8) {
                0 => (0, a),
                1 => (a, u32::MAX),
                _ => (a, a.saturating_add(b)),
            }
        })
        .collect()
}

/// Random operations: `long` makes starts and plays as long as `long`.
fn ops(rng: &mut Lcg, long: u32) -> Vec<Op> {
    (0..1 + below(rng, 12))
        .map(|_| match below(rng, 13) {
            0..=2 => Op::Start(match below(rng, 10) {
                0 => 0,
                1 => u32::MAX,
                2 if long > 0 => below(rng, 3 * long),
                _ => below(rng, 400),
            }),
            3..=8 => Op::Play(below(rng, 200.max(long))),
            9 | 10 => Op::Stop,
            _ => Op::Cruise(below(rng, 120.max(long))),
        })
        .collect()
}

/// `cases` random sequences of each kind, then sequences on the profiles'
/// tables.
fn cases(cases: u32, profiles: &Profiles) -> Vec<Case> {
    let mut rng = Lcg(0x5EED_C0DE);
    let mut out = edge_cases();
    for _ in 0..cases {
        let u16s =
            |rng: &mut Lcg| Table::U16(periods(rng, 65_535).iter().map(|&p| p as u16).collect());
        let u32s = |rng: &mut Lcg| Table::U32(periods(rng, 3_000_000));
        let make: [&dyn Fn(&mut Lcg) -> Table; 3] = [&u16s, &u32s, &|rng| Table::Runs(runs(rng))];
        for table in make {
            let accel = table(&mut rng);
            let decel = (below(&mut rng, 2) == 0).then(|| table(&mut rng));
            let ops = ops(&mut rng, 0);
            let top = match accel {
                Table::U32(_) => 3_000_000,
                _ => 65_535,
            };
            let avoid = bands(&mut rng, top);
            out.push(Case {
                accel: accel.clone(),
                decel: decel.clone(),
                ops,
                avoid,
                axis: false,
            });
            // The same tables as an axis with a queue (no bands: an
            // axis's moves keep the player's).
            out.push(Case {
                accel,
                decel,
                ops: axis_ops(&mut rng, 0),
                avoid: vec![],
                axis: true,
            });
        }
    }
    let real: Vec<Table> = profiles
        .profiles()
        .iter()
        .map(|p| match &p.table {
            Generated::Steps(t) => match t.spec.timer.word {
                profile_core::Word::U16 => {
                    Table::U16(t.periods.iter().map(|&p| p as u16).collect())
                }
                profile_core::Word::U32 => Table::U32(t.periods.clone()),
            },
            Generated::Runs(t) => Table::Runs(t.runs.clone()),
            Generated::Segments(_) => unreachable!("no segment table here"),
            _ => panic!("a layout this test does not know"),
        })
        .collect();
    for table in &real {
        let len = match table {
            Table::U16(t) => t.len() as u32,
            Table::U32(t) => t.len() as u32,
            Table::Runs(r) => r.iter().map(|w| u32::from(w[0])).sum(),
        };
        for _ in 0..cases / 10 + 2 {
            let decel = (below(&mut rng, 3) == 0).then(|| match table {
                Table::Runs(_) => Table::Runs(runs(&mut rng)),
                Table::U16(t) => Table::U16(t[..t.len() / 2].to_vec()),
                Table::U32(t) => Table::U32(t[t.len() / 3..].to_vec()),
            });
            let ops = ops(&mut rng, len);
            let top = match table {
                Table::U32(t) => t[0],
                Table::U16(t) => u32::from(t[0]),
                Table::Runs(_) => 65_535,
            };
            let avoid = bands(&mut rng, top);
            out.push(Case {
                accel: table.clone(),
                decel,
                ops,
                avoid,
                axis: false,
            });
        }
    }
    out
}

/// Plays `ops` on `player`, as the C program prints them: the periods of
/// each `Play` (0 once the move is done), then the steps remaining.
fn play<W: TableWord, L: Layout>(out: &mut String, player: &mut Player<'_, W, L>, ops: &[Op]) {
    for op in ops {
        match *op {
            Op::Start(n) => player.start(n),
            Op::Play(n) => print_periods(out, n, || player.next_period()),
            Op::Stop => player.stop(),
            Op::Cruise(pos) => player.set_cruise(pos),
            Op::Queue(_) => unreachable!("an axis's operation"),
        }
        let _ = writeln!(out, " | {}", player.remaining());
    }
}

/// Up to `n` periods from `next`, as the C program prints them: each in
/// ticks, and a 0 once the move is done.
fn print_periods<W: TableWord>(out: &mut String, n: u32, mut next: impl FnMut() -> Option<W>) {
    for _ in 0..n {
        let p = next().map_or(0, TableWord::into_ticks);
        let _ = write!(out, " {p}");
        if p == 0 {
            break;
        }
    }
}

/// Plays `ops` on an axis at 0 on `player`, as the C program prints them:
/// whether each target is taken, the periods of each `Play` (0 once every
/// move is done), then the position and the direction.
fn play_axis<W: TableWord, L: Layout>(out: &mut String, player: Player<'_, W, L>, ops: &[Op]) {
    let mut axis = Axis::new(player, 0);
    for op in ops {
        match *op {
            Op::Queue(target) => {
                let _ = write!(out, " q{}", u8::from(axis.queue(target.into()).is_ok()));
            }
            Op::Play(n) => print_periods(out, n, || axis.next_period()),
            _ => unreachable!("a player's operation"),
        }
        let _ = writeln!(out, " | {} {}", axis.position(), axis.direction().sign());
    }
}

/// Random operations on an axis: targets within 300 steps of 0, queued
/// between steps played.
fn axis_ops(rng: &mut Lcg, long: u32) -> Vec<Op> {
    (0..1 + below(rng, 16))
        .map(|_| match below(rng, 5) {
            0..=2 => Op::Queue(below(rng, 601) as i32 - 300),
            _ => Op::Play(below(rng, 200.max(long))),
        })
        .collect()
}

/// What the C program must print: every case played by the Rust player.
fn expected(cases: &[Case]) -> String {
    let mut out = String::new();
    for (i, case) in cases.iter().enumerate() {
        let _ = writeln!(out, "case {i}");
        let decel = case.decel.as_ref().unwrap_or(&case.accel);
        if case.axis {
            match (&case.accel, decel) {
                (Table::U16(a), Table::U16(d)) => play_axis(
                    &mut out,
                    Player::new(Ramp::steps(a)).with_decel(Ramp::steps(d)),
                    &case.ops,
                ),
                (Table::U32(a), Table::U32(d)) => play_axis(
                    &mut out,
                    Player::new(Ramp::steps(a)).with_decel(Ramp::steps(d)),
                    &case.ops,
                ),
                (Table::Runs(a), Table::Runs(d)) => play_axis(
                    &mut out,
                    Player::<u16, _>::new(&a[..]).with_decel(&d[..]),
                    &case.ops,
                ),
                _ => unreachable!("one kind per case"),
            }
            continue;
        }
        match (&case.accel, decel) {
            (Table::U16(a), Table::U16(d)) => play(
                &mut out,
                &mut Player::new(Ramp::steps(a))
                    .with_decel(Ramp::steps(d))
                    .avoiding(&case.avoid),
                &case.ops,
            ),
            (Table::U32(a), Table::U32(d)) => play(
                &mut out,
                &mut Player::new(Ramp::steps(a))
                    .with_decel(Ramp::steps(d))
                    .avoiding(&case.avoid),
                &case.ops,
            ),
            (Table::Runs(a), Table::Runs(d)) => play(
                &mut out,
                &mut Player::<u16, _>::new(&a[..])
                    .with_decel(&d[..])
                    .avoiding(&case.avoid),
                &case.ops,
            ),
            _ => unreachable!("one kind per case"),
        }
    }
    out
}

/// A C array of `table`'s words, each XOR a key when `scramble`.
fn array(c: &mut String, name: &str, table: &Table, qualifiers: &str, scramble: bool) {
    let (key16, key32) = if scramble {
        (0xA5C3u64, 0xA5C3_5A3Cu64)
    } else {
        (0, 0)
    };
    let (ty, dims, rows): (&str, &str, Vec<String>) = match table {
        Table::U16(t) => (
            "uint16_t",
            "",
            t.iter()
                .map(|&v| format!("{}u", u64::from(v) ^ key16))
                .collect(),
        ),
        Table::U32(t) => (
            "uint32_t",
            "",
            t.iter()
                .map(|&v| format!("{}ul", u64::from(v) ^ key32))
                .collect(),
        ),
        Table::Runs(r) => (
            "uint16_t",
            "[5]",
            r.iter()
                .map(|w| {
                    let words: Vec<String> = w
                        .iter()
                        .map(|&v| format!("{}u", u64::from(v) ^ key16))
                        .collect();
                    format!("{{{}}}", words.join(", "))
                })
                .collect(),
        ),
    };
    let (storage, attribute) = qualifiers.split_once('|').unwrap_or(("", ""));
    let _ = write!(
        c,
        "static const {storage}{ty} {name}[]{dims}{attribute} = {{"
    );
    for (i, row) in rows.iter().enumerate() {
        let sep = if i % 8 == 0 { "\n    " } else { " " };
        let _ = write!(c, "{sep}{row},");
    }
    let _ = writeln!(c, "\n}};");
}

/// The C program playing every case: `qualifiers` is `storage|attribute`
/// for its arrays.
fn program(cases: &[Case], prelude: &str, qualifiers: &str, scramble: bool) -> String {
    let mut c = String::from(prelude);
    let storage = qualifiers.split('|').next().unwrap_or("");
    for (i, case) in cases.iter().enumerate() {
        array(&mut c, &format!("A{i}"), &case.accel, qualifiers, scramble);
        if let Some(d) = &case.decel {
            array(&mut c, &format!("D{i}"), d, qualifiers, scramble);
        }
        let _ = write!(c, "static const unsigned long O{i}[] = {{");
        for op in &case.ops {
            let (code, arg) = match *op {
                Op::Start(n) => (0, n),
                Op::Play(n) => (1, n),
                Op::Stop => (2, 0),
                Op::Cruise(pos) => (3, pos),
                // A target, offset to be positive.
                Op::Queue(t) => (4, (t + 1_000_000) as u32),
            };
            let _ = write!(c, " {code}, {arg}ul,");
        }
        let _ = writeln!(c, " 9, 0 }};\n");
        // Bands in ordinary memory, as `_avoid` reads them.
        if !case.avoid.is_empty() {
            let _ = write!(c, "static const uint32_t B{i}[] = {{");
            for (shortest, longest) in &case.avoid {
                let _ = write!(c, " {shortest}ul, {longest}ul,");
            }
            let _ = writeln!(c, " }};\n");
        }
    }
    for (kind, player, word, table, len) in [
        ("u16", "players_player", "uint16_t", "uint16_t", "uint32_t"),
        (
            "u32",
            "players_player32",
            "uint32_t",
            "uint32_t",
            "uint32_t",
        ),
        (
            "runs",
            "players_runs_player",
            "uint16_t",
            "uint16_t (*",
            "uint16_t",
        ),
    ] {
        let (table, close) = match table.strip_suffix(" (*") {
            Some(t) => (format!("{t} (*"), ")[5]"),
            None => (format!("{table} *"), ""),
        };
        let _ = writeln!(
            c,
            "static void play_{kind}(const {storage}{table}a{close}, {len} na,\n    \
             const {storage}{table}d{close}, {len} nd, const unsigned long *o,\n    \
             const uint32_t *b, unsigned char nb)\n{{\n    \
             {player}_t p;\n    unsigned long k;\n    {word} v;\n    \
             {player}_init(&p, a, na, d, nd);\n    \
             {player}_avoid(&p, b, nb);\n    \
             for (; o[0] != 9; o += 2) {{\n        \
             if (o[0] == 0) {{\n            {player}_start(&p, o[1]);\n        \
             }} else if (o[0] == 1) {{\n            \
             for (k = 0; k < o[1]; k++) {{\n                \
             v = {player}_next(&p);\n                \
             printf(\" %lu\", (unsigned long)v);\n                \
             if (v == 0) {{\n                    break;\n                }}\n            }}\n        \
             }} else if (o[0] == 2) {{\n            {player}_stop(&p);\n        \
             }} else {{\n            {player}_set_cruise(&p, o[1]);\n        }}\n        \
             printf(\" | %lu\\n\", (unsigned long){player}_remaining(&p));\n    }}\n}}\n"
        );
        // The same tables as an axis at 0: targets queued, steps played.
        let _ = writeln!(
            c,
            "static void axis_{kind}(const {storage}{table}a{close}, {len} na,\n    \
             const {storage}{table}d{close}, {len} nd, const unsigned long *o)\n{{\n    \
             {player}_axis_t x;\n    unsigned long k;\n    {word} v;\n    \
             {player}_init(&x.player, a, na, d, nd);\n    \
             {player}_axis_init(&x, 0);\n    \
             for (; o[0] != 9; o += 2) {{\n        \
             if (o[0] == 4) {{\n            \
             printf(\" q%d\", (int){player}_axis_queue(&x, (int32_t)((long)o[1] - 1000000L)));\n        \
             }} else {{\n            \
             for (k = 0; k < o[1]; k++) {{\n                \
             if (!{player}_axis_step(&x, &v)) {{\n                    v = 0;\n                }}\n                \
             printf(\" %lu\", (unsigned long)v);\n                \
             if (v == 0) {{\n                    break;\n                }}\n            }}\n        }}\n        \
             printf(\" | %ld %d\\n\", (long){player}_axis_position(&x), \
             (int){player}_axis_direction(&x));\n    }}\n}}\n"
        );
    }
    c.push_str("int main(void)\n{\n");
    for (i, case) in cases.iter().enumerate() {
        let kind = match case.accel {
            Table::U16(_) => "u16",
            Table::U32(_) => "u32",
            Table::Runs(_) => "runs",
        };
        let d = if case.decel.is_some() { "D" } else { "A" };
        let n = |name: &str| format!("(sizeof({name}) / sizeof({name}[0]))");
        let bands = match case.avoid.len() {
            0 => "0, 0".to_string(),
            k => format!("B{i}, {k}"),
        };
        if case.axis {
            let _ = writeln!(
                c,
                "    printf(\"case {i}\\n\");\n    axis_{kind}(A{i}, {}, {d}{i}, {}, O{i});",
                n(&format!("A{i}")),
                n(&format!("{d}{i}"))
            );
            continue;
        }
        let _ = writeln!(
            c,
            "    printf(\"case {i}\\n\");\n    play_{kind}(A{i}, {}, {d}{i}, {}, O{i}, {bands});",
            n(&format!("A{i}")),
            n(&format!("{d}{i}"))
        );
    }
    c.push_str("    return 0;\n}\n");
    c
}

fn dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("c_player")
        .join(name);
    fs::create_dir_all(&dir).unwrap();
    dir
}

fn leak(s: String) -> &'static str {
    Box::leak(s.into_boxed_str())
}

/// Compares the C program's output with the Rust player's, case by case.
fn compare(what: &str, printed: &str, want: &str, cases: &[Case]) {
    let split = |s: &str| -> Vec<String> {
        s.split("case ")
            .skip(1)
            .map(|c| format!("case {c}"))
            .collect()
    };
    let (got, want) = (split(printed), split(want));
    assert_eq!(got.len(), want.len(), "{what}: cases printed");
    for (i, (g, w)) in got.iter().zip(&want).enumerate() {
        assert_eq!(
            g, w,
            "{what}: case {i} plays differently in C (left) and in Rust (right): {:?}",
            cases[i]
        );
    }
}

fn case_count() -> u32 {
    std::env::var("C_PLAYER_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(200)
}

#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn the_c_players_play_as_the_rust_player() {
    let profiles = Profiles::parse("players.toml", PROFILES).unwrap_or_else(|e| panic!("{e}"));
    let cases = cases(case_count(), &profiles);
    let want = expected(&cases);

    // One header, C89.
    let single = dir("single");
    profiles.write_c_header(single.join("players.h")).unwrap();
    let prelude = "#include <stdio.h>\n#define STEPPER_PROFILES_PLAYERS_IMPLEMENTATION\n\
                   #include \"players.h\"\n\n";
    let c89 = CProgram {
        dir: "c_player/single",
        name: "players_c89",
        source: leak(program(&cases, prelude, "", false)),
        flags: &[
            "-std=c89",
            "-O0",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
        ],
        libs: &[],
        what: "the C players (one header, C89)",
        what_in_full: "the header's move players",
        executable: OnceLock::new(),
    };
    let printed = c89.run(std::iter::empty::<&str>(), &"the cases");
    compare("one header, C89", &printed, &want, &cases);

    // A header and its source, tables in program memory, scrambled.
    let split = dir("progmem");
    fs::create_dir_all(split.join("avr")).unwrap();
    fs::write(
        split.join("avr/pgmspace.h"),
        "#define PROGMEM\n#define pgm_read_word(p) ((uint16_t)(*(p) ^ 0xA5C3u))\n\
         #define pgm_read_dword(p) ((uint32_t)(*(p) ^ 0xA5C35A3Cul))\n",
    )
    .unwrap();
    let style = CStyle {
        storage: Some("volatile".into()),
        attribute: Some("PROGMEM".into()),
        ..CStyle::default()
    };
    profiles
        .write_c_split(split.join("players.h"), &style)
        .unwrap();
    let header = fs::read_to_string(split.join("players.h")).unwrap();
    assert!(header.contains("pgm_read_dword(p)") && header.contains("pgm_read_word(p)"));
    let prelude = "#include <stdio.h>\n#include \"players.c\"\n\n";
    let c99 = CProgram {
        dir: "c_player/progmem",
        name: "players_progmem",
        source: leak(program(&cases, prelude, "volatile |  PROGMEM", true)),
        flags: Box::leak(Box::new([
            "-std=c99",
            "-O2",
            "-I",
            leak(split.display().to_string()),
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
        ])),
        libs: &[],
        what: "the C players (program memory)",
        what_in_full: "the header's move players",
        executable: OnceLock::new(),
    };
    let printed = c99.run(std::iter::empty::<&str>(), &"the cases");
    compare("program memory, C99 -O2", &printed, &want, &cases);
    let periods = want.split(' ').filter(|w| w.parse::<u32>().is_ok()).count();
    println!(
        "C players == Rust Player (and C axes == Rust Axis, {} of the sequences): {} sequences, {} operations, {periods} periods and counts compared, twice",
        cases.iter().filter(|c| c.axis).count(),
        cases.len(),
        cases.iter().map(|c| c.ops.len()).sum::<usize>()
    );
}
