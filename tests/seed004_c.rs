//! Seed 004 compatibility: the article's integer `pulse()` against `profile-core`.
//!
//! Seed 004 builds its constant-acceleration table in integer arithmetic:
//! `A = ((fmax-f0)*(fmax+f0))/(2*trans)`, `f[i] = sqrt_16(2*A*i+f0*f0)`, and a
//! timer reload of `50000000/(2*f[i])` (its S3C4510 timer overflows twice per
//! pulse). The mode `curve = linear, discretization = index, rounding =
//! truncate, arithmetic = integer` promises that table, with `len = trans + 1`
//! entries, `timer_hz` for 50 MHz and `ticks_per_step` for the 2; and where the
//! article's 16-bit variables would overflow, an error instead of the wrapped
//! numbers C would compute.
//!
//! This test writes `pulse()` in C with the article's types (`REG16` and
//! `UINT16` as `uint16_t`, `int` 32-bit as on its ARM7), a bit-by-bit integer
//! square root for `sqrt_16`, and a `main` that first checks, in 64-bit
//! arithmetic, whether any intermediate would leave its C type (and if so
//! prints which, rather than run into undefined behaviour), then runs
//! `pulse()` and prints each `f[i]` and reload `timer_hz / (ticks_per_step *
//! f[i])` (the doubling done in a `REG16`, as the article's `f0 += f0`). It is
//! compiled with the system C compiler (`cc`, or `$CC`) and compared entry for
//! entry with `period_table!` for the seed's call and with [`Spec::table`] for
//! the seed, hand-picked corners and a deterministic spread of parameter sets.
//! Every set C would overflow must be an error in Rust.
//!
//! A missing C compiler is a failure, not a skip: a silently skipped
//! compatibility test promises nothing.

use test_support as common;

use std::fmt;
use std::sync::OnceLock;

use common::cc::CProgram;
use common::lcg::Lcg;
use common::seeds::{SEED004_INTEGER, integer_compat, seed004_ramp};
use profile_codegen::SpecTables;
use stepper_profiles::{Curve, Error, Key, Linear, LinearExtent, Spec, Timer, Word};

/// Seed 004's `pulse()`, its globals and a checking `main`.
const C_SOURCE: &str = r#"#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* The article's types: 16-bit registers and variables; `int` is 32-bit. */
typedef uint16_t REG16;
typedef uint16_t UINT16;

/* The globals `pulse()` writes (the timer registers are plain variables here). */
static REG16 trans, step, tempstep, status;
static UINT16 f[65536];
static uint32_t TDATA0, TMOD;

/* sqrt_16: the integer square root, rounded down, bit by bit. */
static UINT16 sqrt_16(uint32_t x)
{
    uint32_t root = 0;
    uint32_t bit = (uint32_t)1 << 30;
    while (bit > x) {
        bit >>= 2;
    }
    while (bit != 0) {
        if (x >= root + bit) {
            x -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return (UINT16)root;
}

/* Seed 004, as published, without the interrupt-controller calls
   (SysDisableInt, SysSetInterrupt, SysEnableInt). */
void pulse(REG16 f0, REG16 fmax, REG16 tran, REG16 steep)
{
    UINT16 i, A;
    trans = tran;
    A = ((fmax - f0) * (fmax + f0)) / (2 * trans);
    for (i = 0; i <= trans; i++) {
        f[i] = sqrt_16(2 * A * i + f0 * f0);
    }
    f0 += f0;               /* 2f0 */
    TMOD = 0x00;            /* disable timer0 and timer1 */
    TDATA0 = 0x2FAF080 / f0; /* f0 = 50,000,000 / TDATA0 */
    TMOD = 0x03;            /* enable timer0 and timer1 in interval mode */
    step = steep + steep;   /* 2step */
    trans = trans + trans;
    tempstep = 0;
    status = 0;
}

/* The reload for a step at f[i]: the timer overflows ticks_per_step times per
   pulse, the rate doubled in a REG16 as the article's `f0 += f0`. */
static uint32_t reload(uint32_t timer_hz, unsigned ticks_per_step, UINT16 fi)
{
    REG16 rate = fi;
    if (ticks_per_step == 2) {
        rate += rate;
    }
    return timer_hz / rate;
}

static long long arg(const char *s)
{
    char *end;
    long long v = strtoll(s, &end, 10);
    if (*s == '\0' || *end != '\0' || v < 0) {
        fprintf(stderr, "not a non-negative integer: %s\n", s);
        exit(2);
    }
    return v;
}

static long long isqrt64(long long x)
{
    long long r = 0;
    while ((r + 1) * (r + 1) <= x) {
        r++;
    }
    return r;
}

static int flagged = 0;

static void flag(int overflow, const char *what)
{
    if (overflow) {
        printf("overflow %s\n", what);
        flagged = 1;
    }
}

int main(int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: %s f0 fmax len timer_hz ticks_per_step\n", argv[0]);
        return 2;
    }
    long long f0 = arg(argv[1]), fmax = arg(argv[2]), len = arg(argv[3]);
    long long timer_hz = arg(argv[4]), tps = arg(argv[5]);
    long long tr = len - 1;
    if (f0 < 1 || fmax <= f0 || tr < 1 || timer_hz > UINT32_MAX || (tps != 1 && tps != 2)) {
        fprintf(stderr, "expected 0 < f0 < fmax, len >= 2, a 32-bit timer_hz, tps 1 or 2\n");
        return 2;
    }
    /* Every intermediate of pulse() against its C type, in the order pulse()
       computes them; stop before anything that would be undefined. */
    flag(f0 > 65535 || fmax > 65535, "REG16 f0, fmax");
    flag(tr > 65535, "REG16 tran");
    flag(tr == 65535, "UINT16 i <= trans never ends");
    if (flagged) {
        return 0;
    }
    long long product = (fmax - f0) * (fmax + f0);
    flag(product > INT32_MAX, "int (fmax-f0)*(fmax+f0)");
    if (flagged) {
        return 0;
    }
    long long a = product / (2 * tr);
    flag(a > 65535, "UINT16 A");
    flag(f0 * f0 > INT32_MAX, "int f0*f0");
    flag(2 * a * tr + f0 * f0 > INT32_MAX, "int 2*A*i+f0*f0");
    if (flagged) {
        return 0;
    }
    flag(tps * isqrt64(2 * a * tr + f0 * f0) > 65535, "REG16 f0 += f0");
    if (flagged) {
        return 0;
    }
    pulse((REG16)f0, (REG16)fmax, (REG16)tr, 0);
    printf("TDATA0 %u\n", (unsigned)TDATA0);
    for (long long i = 0; i <= tr; i++) {
        uint32_t r = reload((uint32_t)timer_hz, (unsigned)tps, f[i]);
        printf("%u %u\n", (unsigned)f[i], (unsigned)r);
    }
    return 0;
}
"#;

/// [`C_SOURCE`] and how to compile it.
static C_PROGRAM: CProgram = CProgram {
    dir: "seed004_c",
    name: "pulse",
    source: C_SOURCE,
    flags: &["-O2", "-std=c99", "-Wall", "-Wextra"],
    libs: &[],
    what: "seed 004's pulse()",
    what_in_full: "seed 004's integer pulse()",
    executable: OnceLock::new(),
};

/// One call `pulse(f0, fmax, trans, ...)` on a timer: `len = trans + 1` entries.
#[derive(Clone, Copy, Debug)]
struct Call {
    f0: u32,
    fmax: u32,
    len: u32,
    timer_hz: u32,
    ticks_per_step: u8,
}

impl fmt::Display for Call {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "(f0 {}, fmax {}, trans {}, timer_hz {}, ticks_per_step {})",
            self.f0,
            self.fmax,
            self.len - 1,
            self.timer_hz,
            self.ticks_per_step
        )
    }
}

const fn call(f0: u32, fmax: u32, len: u32, timer_hz: u32, ticks_per_step: u8) -> Call {
    Call {
        f0,
        fmax,
        len,
        timer_hz,
        ticks_per_step,
    }
}

/// The article's call: 500 Hz to 5000 Hz in 200 transition steps at 50 MHz.
const SEED: Call = call(500, 5000, 201, 50_000_000, 2);

/// What the C program says about a call.
#[derive(Debug)]
enum COutcome {
    /// `pulse()` ran: `TDATA0` after the call, and per entry `f[i]` and the reload.
    Table {
        tdata0: u32,
        entries: Vec<(u32, u32)>,
    },
    /// Some intermediate would overflow its C type; which ones.
    Overflow(Vec<String>),
}

/// Runs the compiled C code for `call`.
fn run_c(call: &Call) -> COutcome {
    let stdout = C_PROGRAM.run(
        [
            call.f0.to_string(),
            call.fmax.to_string(),
            call.len.to_string(),
            call.timer_hz.to_string(),
            call.ticks_per_step.to_string(),
        ],
        call,
    );
    let overflows: Vec<String> = stdout
        .lines()
        .filter_map(|l| l.strip_prefix("overflow "))
        .map(str::to_owned)
        .collect();
    if !overflows.is_empty() {
        return COutcome::Overflow(overflows);
    }
    let mut lines = stdout.lines();
    let tdata0 = lines
        .next()
        .and_then(|l| l.strip_prefix("TDATA0 "))
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("expected `TDATA0 n` first from the C program for {call}"));
    let entries: Vec<(u32, u32)> = lines
        .map(|line| {
            let (f, reload) = line
                .split_once(' ')
                .unwrap_or_else(|| panic!("expected `f reload` from the C program, got {line:?}"));
            (
                f.parse().expect("a decimal f[i]"),
                reload.parse().expect("a decimal reload"),
            )
        })
        .collect();
    assert_eq!(
        entries.len(),
        call.len as usize,
        "expected the C program to print trans + 1 entries for {call}"
    );
    COutcome::Table { tdata0, entries }
}

/// The spec that claims to reproduce `call`.
fn compat_spec(call: &Call, word: Word) -> Spec {
    integer_compat(Spec::new(
        Curve::Linear(Linear {
            fmin: call.f0 as f64,
            fmax: call.fmax as f64,
            extent: LinearExtent::Len(call.len),
        }),
        Timer {
            timer_hz: call.timer_hz,
            word,
            ticks_per_step: call.ticks_per_step,
        },
    ))
}

/// What one call amounted to.
#[derive(Debug, PartialEq, Eq)]
enum Verdict {
    /// C and Rust agree entry for entry.
    Matched { entries: usize },
    /// C overflows, Rust says so.
    Rejected,
    /// C's reloads do not fit the word, Rust says so.
    PeriodOverflow,
}

/// Compares the C program and `Spec::table()` for `call` with table word
/// `word`, and returns what happened or a description of the disagreement.
fn compare(call: &Call, word: Word) -> Result<Verdict, String> {
    let spec = compat_spec(call, word);
    let rust = spec.table();
    match run_c(call) {
        COutcome::Overflow(what) => match rust {
            Err(Error::IntegerOverflow { .. }) => Ok(Verdict::Rejected),
            other => Err(format!(
                "{call}: C overflows ({}), expected Spec::table() to return \
                 Err(IntegerOverflow), got {}",
                what.join(", "),
                match other {
                    Ok(t) => format!("a table of {} entries", t.periods.len()),
                    Err(e) => format!("Err({e:?})"),
                }
            )),
        },
        COutcome::Table { tdata0, entries } => {
            // The C program's own consistency: the reload is timer / (tps f[i]),
            // and pulse()'s own TDATA0 (50 MHz, 2 f0) is the reload of f[0] on
            // the article's timer.
            for (i, &(f, reload)) in entries.iter().enumerate() {
                assert_eq!(
                    reload,
                    call.timer_hz / (u32::from(call.ticks_per_step) * f),
                    "{call}: C reload {i}"
                );
            }
            if (call.timer_hz, call.ticks_per_step) == (50_000_000, 2) {
                assert_eq!(tdata0, entries[0].1, "{call}: C TDATA0");
            }
            let overflow_at = entries.iter().position(|&(_, r)| r > word.max());
            match (rust, overflow_at) {
                (Err(Error::PeriodOverflow { index, .. }), Some(at)) if index as usize == at => {
                    Ok(Verdict::PeriodOverflow)
                }
                (Ok(table), None) => {
                    let mismatches: Vec<String> = entries
                        .iter()
                        .zip(&table.periods)
                        .enumerate()
                        .filter(|(_, ((_, c), r))| c != *r)
                        .take(10)
                        .map(|(i, ((f, c), r))| format!("index {i}: C {c} (f[i] = {f}), Rust {r}"))
                        .collect();
                    if table.periods.len() != entries.len() || !mismatches.is_empty() {
                        return Err(format!(
                            "{call}, word {}: expected Spec::table() to equal C's {} reloads, got \
                             {} entries; {}",
                            word.name(),
                            entries.len(),
                            table.periods.len(),
                            mismatches.join("; ")
                        ));
                    }
                    Ok(Verdict::Matched {
                        entries: entries.len(),
                    })
                }
                (rust, at) => Err(format!(
                    "{call}, word {}: C computes a table whose first reload above {} is at {at:?}, \
                     expected Spec::table() to agree, got {}",
                    word.name(),
                    word.max(),
                    match rust {
                        Ok(t) => format!("a table of {} entries", t.periods.len()),
                        Err(e) => format!("Err({e:?})"),
                    }
                )),
            }
        }
    }
}

#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn seed_call_matches_c_through_the_macro() {
    let COutcome::Table { tdata0, entries } = run_c(&SEED) else {
        panic!("expected the seed's call to run in C without overflow");
    };
    // The article's numbers: A = 61875, f[0] = 500, f[200] = 5000, TDATA0 for 2 f0.
    assert_eq!(tdata0, 50_000, "TDATA0 = 0x2FAF080 / (2 * 500)");
    assert_eq!((entries[0].0, entries[200].0), (500, 5000));
    assert_eq!(entries[1].0, 611, "f[1] = isqrt(2 * 61875 + 250000)");
    let c: Vec<u32> = entries.iter().map(|&(_, r)| r).collect();
    let from_macro: Vec<u32> = SEED004_INTEGER.iter().map(|&p| u32::from(p)).collect();
    assert_eq!(
        from_macro, c,
        "expected period_table!(... arithmetic = integer) to equal seed 004's C reloads"
    );
    assert_eq!(
        compare(&SEED, Word::U16),
        Ok(Verdict::Matched { entries: 201 })
    );
    assert_eq!(
        compare(&SEED, Word::U32),
        Ok(Verdict::Matched { entries: 201 })
    );
}

/// Corners that fit: the shortest ramp, the largest `A`, the largest `f0`,
/// the largest doubled rate, truncated `A`s, and clock rates from 1 to 168 MHz.
const FITTING: [(Call, Word); 12] = [
    (call(500, 600, 2, 1_000_000, 1), Word::U16),
    // A = 262143 / 4 = 65535, the largest UINT16.
    (call(43_689, 43_692, 3, 50_000_000, 1), Word::U16),
    // f0 * f0 = 2147395600, just under INT_MAX; A truncates to 1.
    (call(46_340, 46_341, 30_001, 72_000_000, 1), Word::U16),
    // 2 * f[trans] = 65532, just under the REG16 limit of f0 += f0.
    (call(30_000, 32_767, 20_000, 72_000_000, 2), Word::U16),
    (call(1000, 1001, 2, 16_000_000, 2), Word::U16),
    (call(200, 4000, 1000, 8_000_000, 1), Word::U16),
    (call(200, 4000, 1000, 168_000_000, 1), Word::U32),
    // A = 4500 * 5500 / (2 * 189) = 65476: the seed's ramp in the fewest steps.
    (call(500, 5000, 190, 50_000_000, 2), Word::U16),
    (call(100, 2000, 4096, 1_000_000, 1), Word::U16),
    (call(3, 200, 1200, 48_000, 1), Word::U16),
    // A = (400² - 100²) / (2 * 65534) = 1.
    (call(100, 400, 65_535, 1_000_000, 1), Word::U16),
    (call(700, 9000, 3000, 72_000_000, 2), Word::U32),
];

#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn corner_calls_match_c() {
    for (call, word) in FITTING {
        let verdict = compare(&call, word).unwrap_or_else(|problem| panic!("{problem}"));
        assert!(
            matches!(verdict, Verdict::Matched { .. }),
            "expected {call} to fit, got {verdict:?}"
        );
    }
}

#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn spread_of_calls_matches_c_or_is_rejected_like_c() {
    let mut rng = Lcg(0x5EED_0004_0000_C0DE);
    let mut tally = (0, 0, 0, 0);
    let mut problems = Vec::new();
    for _ in 0..240 {
        let f0 = rng.log_uniform(20.0, 50_000.0).round() as u32;
        let fmax = (f0 as f64 * rng.log_uniform(1.001, 40.0))
            .round()
            .max(f0 as f64 + 1.0) as u32;
        let len = rng.log_uniform(2.0, 20_000.0).round() as u32;
        let timer_hz = rng.pick(&[
            1_000_000, 2_000_000, 8_000_000, 16_000_000, 48_000_000, 50_000_000, 72_000_000,
        ]);
        let ticks_per_step = rng.pick(&[1u8, 2]);
        let word = rng.pick(&[Word::U16, Word::U16, Word::U32]);
        let c = call(f0, fmax.min(70_000), len, timer_hz, ticks_per_step);
        if c.fmax <= c.f0 {
            continue;
        }
        match compare(&c, word) {
            Ok(Verdict::Matched { entries }) => {
                tally.0 += 1;
                tally.1 += entries;
            }
            Ok(Verdict::Rejected) => tally.2 += 1,
            Ok(Verdict::PeriodOverflow) => tally.3 += 1,
            Err(problem) => problems.push(problem),
        }
    }
    eprintln!(
        "spread: {} calls matched C ({} entries), {} overflowing calls rejected, {} with reloads \
         too long for the word",
        tally.0, tally.1, tally.2, tally.3
    );
    assert!(
        problems.is_empty(),
        "expected Spec::table() to agree with seed 004's C code:\n{}",
        problems.join("\n")
    );
    assert!(tally.0 >= 20, "only {} fitting calls compared", tally.0);
    assert!(tally.2 >= 20, "only {} overflowing calls compared", tally.2);
}

/// Calls whose C arithmetic overflows, each for a different reason.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn overflowing_calls_are_errors() {
    let cases: [(Call, &str, Key); 6] = [
        // 4500 * 5500 / (2 * 99) = 125000: A is a UINT16.
        (call(500, 5000, 100, 50_000_000, 2), "UINT16 A", Key::LEN),
        // 4500 * 5500 / (2 * 188) = 65824, one transition step short of fitting.
        (call(500, 5000, 189, 50_000_000, 2), "UINT16 A", Key::LEN),
        // f0 * f0 = 2.5e9 in a 32-bit int.
        (
            call(50_000, 50_001, 2, 72_000_000, 1),
            "int f0*f0",
            Key::FMIN,
        ),
        // (fmax - f0)(fmax + f0) = 2.5e9 in a 32-bit int.
        (
            call(1000, 50_000, 60_000, 72_000_000, 1),
            "int (fmax-f0)*(fmax+f0)",
            Key::FMAX,
        ),
        // 2 A trans + f0 * f0 = 2152960000 in a 32-bit int.
        (
            call(46_000, 46_400, 1001, 72_000_000, 1),
            "int 2*A*i+f0*f0",
            Key::FMAX,
        ),
        // 2 * f[trans] = 80000 in a REG16.
        (
            call(30_000, 40_000, 20_001, 72_000_000, 2),
            "REG16 f0 += f0",
            Key::FMAX,
        ),
    ];
    for (call, c_says, key) in cases {
        match run_c(&call) {
            COutcome::Overflow(what) => assert_eq!(
                what.first().map(String::as_str),
                Some(c_says),
                "{call}: expected C to overflow first at {c_says}"
            ),
            COutcome::Table { .. } => panic!("{call}: expected C to overflow at {c_says}"),
        }
        let err = compat_spec(&call, Word::U32)
            .table()
            .expect_err("an overflowing call");
        let Error::IntegerOverflow {
            key: blamed,
            value,
            max,
            ..
        } = err
        else {
            panic!("{call}: expected Err(IntegerOverflow), got Err({err:?})")
        };
        assert!(value > u128::from(max), "{call}: {err}");
        assert_eq!(blamed, key, "{call}: blamed key ({err})");
        // The same error before any table is computed.
        assert_eq!(compat_spec(&call, Word::U32).validate(), Err(err));
    }

    // Frequencies must be whole numbers and fit a REG16.
    let spec = |fmin: f64, fmax: f64| integer_compat(seed004_ramp(fmin, fmax, 201));
    assert_eq!(
        spec(500.0, 5000.5).table().map(|t| t.periods.len()),
        Err(Error::NotWhole {
            key: Key::FMAX,
            value: 5000.5
        })
    );
    assert_eq!(
        spec(500.25, 5000.0).table().map(|t| t.periods.len()),
        Err(Error::NotWhole {
            key: Key::FMIN,
            value: 500.25
        })
    );
    assert!(
        matches!(
            spec(500.0, 70_000.0).table(),
            Err(Error::IntegerOverflow { key: Key::FMAX, .. })
        ),
        "fmax = 70000 does not fit a REG16"
    );
    assert!(
        matches!(
            run_c(&call(500, 70_000, 201, 50_000_000, 2)),
            COutcome::Overflow(_)
        ),
        "C: fmax = 70000 does not fit a REG16"
    );
}

/// `len = 65536` is `trans = 65535`: the article's `for (i = 0; i <= trans; i++)`
/// with `UINT16 i` never ends, so there is no C table to be compatible with.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn trans_65535_is_rejected_like_c() {
    let call = call(100, 400, 65_536, 1_000_000, 1);
    let flagged = match run_c(&call) {
        COutcome::Overflow(what) => what.iter().any(|w| w.contains("never ends")),
        COutcome::Table { .. } => false,
    };
    assert!(flagged, "expected C's UINT16 loop to be flagged for {call}");
    let result = compat_spec(&call, Word::U16).table();
    assert!(
        matches!(result, Err(Error::IntegerOverflow { key: Key::LEN, .. })),
        "expected Err(IntegerOverflow) blaming `len` for {call}, got {:?}",
        result.map(|t| t.periods.len())
    );
}
