//! Instructions per table entry of run-time table generation
//! (`Spec::generate`), on the core this is built for, in QEMU
//! (`generate.sh`).
//!
//! # How
//!
//! QEMU runs with `-icount shift=0,sleep=off`: every instruction advances
//! the virtual clock by 1 ns, deterministically. SysTick counts that clock
//! at whatever rate the board gives its processor clock; its count wraps
//! every 2^24 ticks and the SysTick exception counts the wraps, so a case
//! may take any time. At startup a loop of a known number of instructions
//! (`subs; bne`, two instructions per iteration, in `asm!`) is timed twice,
//! 1 and 2 million iterations: the difference gives the ticks per
//! instruction, and the board's clock rate need not be known.
//!
//! Each case is timed once, from before the call to after it, the cost of
//! reading the clock taken off; the spec goes through `black_box`, so that
//! the code measured is the general one a firmware runs on parameters it
//! learns at run time. One SysTick tick is 62.5 (M0), 80 (M3) or 40 (M4F)
//! instructions, so a figure per entry is within 0.1 instruction on a
//! 1000-entry table (0.3 on three_stage's 261 entries). The SysTick figures
//! agree with QEMU's instruction trace (`-singlestep -d exec,nochain`) to
//! within a tick.
//!
//! # What
//!
//! Each case prints `generate: <case> <label>: <instructions per entry>`:
//! the instructions to compute a whole table (the spec's check included),
//! divided by its entries. Case 7 is the S-curve article's C function
//! `CalculateSModelLine` (`c/article.c`, compiled by gcc for the same
//! core, newlib's `expf`); its table is compared entry by entry with case
//! 6's (the same curve in the article's mode, `index`, `truncate`, `f32`),
//! and the comparison printed as `compare: ...`, with the C's frequency
//! `fre[i]` at the first entry that differs. The run ends with `ok` and
//! a semihosting exit; a failure prints `FAIL ...` and exits with failure.
#![no_std]
#![no_main]

use core::arch::asm;
use core::hint::black_box;
use core::sync::atomic::{AtomicU32, Ordering};

use cortex_m::peripheral::syst::SystClkSource;
use cortex_m::peripheral::{SCB, SYST};
use cortex_m_rt::{entry, exception};
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;
use stepper_profiles::{
    Arithmetic, Curve, Discretization, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, Rounding, Sigmoid, Spec, ThreeStage, Timer,
};

unsafe extern "C" {
    /// The S-curve article's function, as gcc compiles it by default
    /// (`-O2`, which on the Cortex-M4F contracts `delt * deno + fre_min`
    /// into a fused multiply-add, `vfma.f32`).
    fn CalculateSModelLine(
        fre: *mut f32,
        period: *mut u16,
        len: f32,
        fre_max: f32,
        fre_min: f32,
        flexible: f32,
    );
    /// The same compiled with `-ffp-contract=off`.
    fn CalculateSModelLine_nocontract(
        fre: *mut f32,
        period: *mut u16,
        len: f32,
        fre_max: f32,
        fre_min: f32,
        flexible: f32,
    );
}

/// SysTick's reload value: the whole 24-bit count.
const RELOAD: u32 = 0x00FF_FFFF;

/// The largest table of the cases: the one buffer they share.
const MAX_ENTRIES: usize = 1000;

/// The article's tables: 1000 entries.
const ARTICLE_LEN: usize = 1000;

/// Wraps of SysTick's count since it was started; written by the SysTick
/// exception alone.
static WRAPS: AtomicU32 = AtomicU32::new(0);

#[exception]
fn SysTick() {
    // Only this handler writes: a load and a store (no read-modify-write
    // atomics on the Cortex-M0).
    WRAPS.store(WRAPS.load(Ordering::Relaxed) + 1, Ordering::Relaxed);
}

/// SysTick ticks since it was started.
fn now() -> u64 {
    loop {
        let wraps = WRAPS.load(Ordering::SeqCst);
        let current = SYST::get_current();
        let pending = SCB::is_pendst_pending();
        if WRAPS.load(Ordering::SeqCst) != wraps {
            continue;
        }
        // Wrapped, its exception not yet taken: the count read is after
        // the wrap when it is still high.
        let wraps = u64::from(wraps) + u64::from(pending && current > RELOAD / 2);
        return (wraps << 24) + u64::from(RELOAD - current);
    }
}

/// SysTick ticks that `f` takes, the cost of reading the clock included.
fn ticks(f: impl FnOnce()) -> u64 {
    let start = now();
    f();
    now() - start
}

/// `2 n` instructions: `n` iterations of `subs; bne` (`n` > 0).
#[inline(never)]
fn spin(n: u32) {
    // SAFETY: counts a register down to 0; no memory, no stack.
    unsafe {
        asm!(
            "2:",
            "subs {0}, {0}, #1",
            "bne 2b",
            inout(reg) n => _,
            options(nomem, nostack),
        );
    }
}

/// Turns SysTick ticks into instructions.
struct Clock {
    /// Ticks per instruction.
    ticks_per_instruction: f64,
    /// Ticks of an empty measurement: the reads of the clock.
    overhead: u64,
}

impl Clock {
    /// Starts SysTick on the processor clock, with its interrupt, and
    /// calibrates it on [`spin`].
    fn start(mut syst: SYST) -> Clock {
        syst.set_clock_source(SystClkSource::Core);
        syst.set_reload(RELOAD);
        syst.clear_current();
        syst.enable_interrupt();
        syst.enable_counter();
        // The count reads 0 until the first tick loads the reload value.
        while SYST::get_current() == 0 {}
        // The difference of 2 and 1 million iterations: 2 million
        // instructions, the call and the reads of the clock cancelled.
        let one = ticks(|| spin(black_box(1_000_000)));
        let two = ticks(|| spin(black_box(2_000_000)));
        let ticks_per_instruction = (two - one) as f64 / 2_000_000.0;
        if ticks_per_instruction <= 0.0 {
            fail("calibration: SysTick did not count (is QEMU run with -icount?)");
        }
        let overhead = (0..4).map(|_| ticks(|| {})).min().unwrap_or(0);
        hprintln!(
            "calibration: {} ticks per 2 million instructions, SysTick at {:.3} MHz of virtual time (1 instruction = 1 ns), one tick = {:.1} instructions",
            two - one,
            ticks_per_instruction * 1000.0,
            1.0 / ticks_per_instruction
        );
        Clock {
            ticks_per_instruction,
            overhead,
        }
    }

    /// Instructions that `f` takes.
    fn instructions(&self, f: impl FnOnce()) -> f64 {
        let t = ticks(f).saturating_sub(self.overhead);
        t as f64 / self.ticks_per_instruction
    }

    /// Times `f`, which computes a table of `entries` entries, and prints
    /// its instructions per entry.
    fn case(&self, label: core::fmt::Arguments<'_>, entries: usize, f: impl FnOnce()) {
        let per_entry = self.instructions(f) / entries as f64;
        hprintln!("generate: {}: {:.2}", label, per_entry);
    }
}

/// Prints `FAIL <what>` and exits with failure.
fn fail(what: &str) -> ! {
    hprintln!("FAIL {}", what);
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::wfi();
    }
}

/// The timer of cases 1, 2, 4, 5: 10 MHz.
const TIMER: Timer = Timer::new(10_000_000);

/// Case 1: the S-curve article's orange curve in the default modes.
fn sigmoid() -> Spec {
    Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        }),
        TIMER,
    )
}

/// Case 2: 1000 entries, asymptote 25 kHz.
fn exponential() -> Spec {
    Spec::new(
        Curve::Exponential(Exponential {
            fmin: 500.0,
            fmax: 20_000.0,
            f_inf: 25_000.0,
            extent: ExponentialExtent::Len(1000),
        }),
        TIMER,
    )
}

/// Case 3: `[profiles.three_stage]` of profiles.toml.
fn three_stage() -> Spec {
    Spec::new(
        Curve::ThreeStage(ThreeStage {
            fmin: 100.0,
            fmax: 1200.0,
            accel: 4000.0,
            f1: 400.0,
            f2: 900.0,
            shape: 12.0,
        }),
        Timer::new(1_000_000),
    )
}

/// Case 4: `[profiles.jerk_limited]` of profiles.toml.
fn jerk_limited() -> Spec {
    Spec::new(
        Curve::JerkLimited(JerkLimited {
            fmin: 200.0,
            fmax: 5000.0,
            accel: 20_000.0,
            jerk: 400_000.0,
        }),
        TIMER,
    )
}

/// Case 5: constant acceleration over 1000 entries.
fn linear() -> Spec {
    Spec::new(
        Curve::Linear(Linear {
            fmin: 500.0,
            fmax: 20_000.0,
            extent: LinearExtent::Len(1000),
        }),
        TIMER,
    )
}

/// Case 6: case 1 as the article's C function computes it.
fn sigmoid_article() -> Spec {
    sigmoid()
        .with_discretization(Discretization::Index)
        .with_rounding(Rounding::Truncate)
        .with_arithmetic(Arithmetic::F32)
}

/// The table's length, checked to fit the shared buffer.
fn entries(spec: &Spec, name: &str) -> usize {
    match spec.check() {
        Ok(checked) if checked.len() as usize <= MAX_ENTRIES => checked.len() as usize,
        Ok(checked) => {
            hprintln!(
                "FAIL {}: {} entries, more than {}",
                name,
                checked.len(),
                MAX_ENTRIES
            );
            fail("buffer too small")
        }
        Err(e) => {
            hprintln!("FAIL {}: {}", name, e);
            fail("spec")
        }
    }
}

/// Times `Spec::generate` of `spec` into the first entries of `table`, then
/// `Spec::generate_periods` (the periods alone, without the figures) into
/// the same entries, prints the instructions per entry of each, and fails
/// unless the two tables are the same bits (compared by a hash: a second
/// buffer does not fit the micro:bit's stack beside the solver's).
#[inline(never)]
fn generate_case(clock: &Clock, case: u32, label: &str, spec: Spec, table: &mut [u16]) -> usize {
    let len = entries(&spec, label);
    let table = &mut table[..len];
    let mut result = Ok(());
    clock.case(
        format_args!("{case} {label}, {len} entries, generate"),
        len,
        || {
            result = black_box(spec).generate(table).map(|_| ());
        },
    );
    if let Err(e) = result {
        hprintln!("FAIL {}: {}", label, e);
        fail("generate");
    }
    let full = hash(table);
    table.fill(0);
    clock.case(
        format_args!("{case}p {label}, {len} entries, generate_periods"),
        len,
        || {
            result = black_box(spec).generate_periods(table);
        },
    );
    if let Err(e) = result {
        hprintln!("FAIL {}: {}", label, e);
        fail("generate_periods");
    }
    if hash(table) != full {
        hprintln!("FAIL {}: generate_periods differs from generate", label);
        fail("generate_periods");
    }
    len
}

/// FNV-1a over a table's entries.
fn hash(table: &[u16]) -> u64 {
    table.iter().fold(0xcbf2_9ce4_8422_2325, |h, &p| {
        (h ^ u64::from(p)).wrapping_mul(0x100_0000_01b3)
    })
}

/// Compares the C table `period` with the Rust one, and prints how many
/// entries differ; at the first that does, both periods and the C's
/// frequency `fre[i]` with its bits. (Rust's own frequency is not computed
/// here: a second caller of `Sigmoid::freq_at_index_f32` changes how LTO
/// inlines it, and with it case 6's figure by up to 4 %.)
fn compare(label: &str, period: &[u16], fre: &[f32], rust: &[u16]) {
    let differ = period.iter().zip(rust).filter(|(a, b)| a != b).count();
    let Some(i) = period.iter().zip(rust).position(|(a, b)| a != b) else {
        hprintln!(
            "compare: {} vs Rust article mode: identical, {} entries (first {}, last {})",
            label,
            period.len(),
            period[0],
            period[period.len() - 1]
        );
        return;
    };
    hprintln!(
        "compare: {} vs Rust article mode: {} of {} entries differ, the first at index {}: C {} (fre {} = {:#x}), Rust {}",
        label,
        differ,
        period.len(),
        i,
        period[i],
        fre[i],
        fre[i].to_bits(),
        rust[i]
    );
}

/// Case 7: the article's C function, in both builds, its table compared
/// with `rust`, case 6's. Not inlined: its buffers are on the stack only
/// while it runs.
#[inline(never)]
fn article(clock: &Clock, rust: &[u16]) {
    /// The C function's type.
    type Article = unsafe extern "C" fn(*mut f32, *mut u16, f32, f32, f32, f32);
    let mut fre = [0f32; ARTICLE_LEN];
    let mut period = [0u16; ARTICLE_LEN];
    let variants: [(&str, &str, Article); 2] = [
        (
            "7 article C CalculateSModelLine (gcc -O2), 1000 entries",
            "article C (gcc -O2)",
            CalculateSModelLine,
        ),
        (
            "7b article C, gcc -O2 -ffp-contract=off, 1000 entries",
            "article C (-ffp-contract=off)",
            CalculateSModelLine_nocontract,
        ),
    ];
    for (label, name, function) in variants {
        period.fill(0);
        clock.case(format_args!("{label}"), ARTICLE_LEN, || {
            // SAFETY: `fre` and `period` hold the `len` = 1000 entries the
            // call writes.
            unsafe {
                function(
                    black_box(fre.as_mut_ptr()),
                    black_box(period.as_mut_ptr()),
                    black_box(ARTICLE_LEN as f32),
                    black_box(64_000.0),
                    black_box(500.0),
                    black_box(8.0),
                )
            }
        });
        compare(name, &period, &fre, rust);
    }
}

/// Case 8, the edge solver alone: the exact times of case 1's edges,
/// without quantization, summed.
#[inline(never)]
fn exact_edges(clock: &Clock) {
    let spec = sigmoid();
    let len = entries(&spec, "sigmoid");
    let mut result = Ok(());
    let mut sum = 0.0;
    clock.case(
        format_args!(
            "8 sigmoid as case 1, exact edges only (Spec::for_each_exact_edge), {len} entries"
        ),
        len,
        || result = black_box(spec).for_each_exact_edge(|_, t| sum += t),
    );
    black_box(sum);
    if let Err(e) = result {
        hprintln!("FAIL for_each_exact_edge: {}", e);
        fail("for_each_exact_edge");
    }
}

#[entry]
fn main() -> ! {
    let peripherals = cortex_m::Peripherals::take().unwrap_or_else(|| fail("peripherals"));
    let clock = Clock::start(peripherals.SYST);

    // The one buffer of the Rust cases; case 6's table stays in it for the
    // comparison with the C's.
    let mut table = [0u16; MAX_ENTRIES];
    let cases = [
        (
            "sigmoid 500 Hz -> 64 kHz, flexible 8, 10 MHz, exact, diffuse",
            sigmoid(),
        ),
        (
            "exponential 500 Hz -> 20 kHz (f_inf 25 kHz), 10 MHz",
            exponential(),
        ),
        (
            "three_stage 100 -> 1200 Hz (profiles.toml), 1 MHz",
            three_stage(),
        ),
        (
            "jerk_limited 200 -> 5000 Hz (profiles.toml), 10 MHz",
            jerk_limited(),
        ),
        ("linear 500 Hz -> 20 kHz, 10 MHz", linear()),
    ];
    for (case, (label, spec)) in (1..).zip(cases) {
        generate_case(&clock, case, label, spec, &mut table);
    }

    let len = generate_case(
        &clock,
        6,
        "sigmoid as case 1, article mode (index, truncate, f32)",
        sigmoid_article(),
        &mut table,
    );
    let rust = &table[..len];
    if (rust[0], rust[len - 1]) != (19183, 156) {
        hprintln!(
            "FAIL article mode: first {}, last {} (19183, 156 expected)",
            rust[0],
            rust[len - 1]
        );
        fail("article mode");
    }
    article(&clock, rust);
    exact_edges(&clock);

    hprintln!("ok");
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
