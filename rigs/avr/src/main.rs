//! The header's C player on an ATmega328P, in simavr, checked at the pin.
//!
//! Writes `ramps.h` from `ramps.toml` with `PROGMEM` tables, checks that it
//! and the guide's AVR example compile as C89 with avr-gcc, builds
//! `client.c` twice (the per-step
//! table with `ramps_player_*`, the compressed ramp with
//! `ramps_runs_player_*`) and the harness `sim.c` against libsimavr, and runs
//! each client in simavr with a time limit. Then:
//!
//! - every edge of the step pin in the VCD trace, as a CPU cycle, must be
//!   the move's start (the write of `TCCR1B` that starts Timer1's clock)
//!   plus the prescaler times the cumulative periods of the move, plus the
//!   one cycle simavr takes to wake a sleeping core (the same for every
//!   edge). The periods are the Rust `Player`'s for the same moves, and for
//!   the move up and down they are also built from the table alone (up, at
//!   the top, down);
//! - the direction pin (PD7) holds each move's direction from before its
//!   start to its last edge, and every change of it comes at least the
//!   driver's `dir_setup` (`driver` in `ramps.toml`) before the next step
//!   edge: the moves alternate direction, each a reversal;
//! - the cycles of every step interrupt, from the compare match to the end
//!   of `reti`, are printed per phase of the move up and down and over all
//!   moves, with the planning calls' costs, and must be within the goal:
//!   100 cycles a step on average for the per-step table, 150 for the
//!   compressed ramp, in every phase.
//!
//! `cargo run --release` exits 0 when everything holds, 1 otherwise, 2
//! when a tool is missing or fails.

mod capture;
mod cycles;
mod tools;
mod vcd;

use std::fs;
use std::path::Path;
use std::process::{Command, ExitCode};
use std::time::Duration;

use profile_codegen::Generated;
use profile_codegen::profiles::{CStyle, Profiles};
use profile_core::player::{Layout, Player, Ramp};
use profile_core::runs::Expand;

use cycles::{Isr, Stats};

/// The ATmega328P's clock, as the client is built for.
const F_CPU: u64 = 16_000_000;
/// The cycle simavr 1.6 takes to wake a sleeping core at a timer's event
/// (`avr->cycle += 1 + sleep` in its run loop): the pin's change is stamped
/// then, one cycle after the compare match, at every edge alike.
const WAKE: u64 = 1;
/// Steps at the top in the move up and down.
const CRUISE: u32 = 200;
/// Cycles and wall-clock time a simulation may take.
const MAX_CYCLES: u64 = 400_000_000;
const TIME_LIMIT: Duration = Duration::from_secs(300);

/// A table the client plays.
enum Table {
    Steps(Vec<u16>),
    Runs(Vec<[u16; 5]>),
}

impl Table {
    /// One period per step of the ramp, from the table alone.
    fn expansion(&self) -> Vec<u32> {
        match self {
            Table::Steps(t) => t.iter().map(|&p| u32::from(p)).collect(),
            Table::Runs(r) => Expand::new(r).collect(),
        }
    }

    /// The periods the Rust player plays for `m`.
    fn play(&self, m: &Move) -> Vec<u32> {
        match self {
            Table::Steps(t) => play(Player::new(Ramp::steps(t)), m),
            Table::Runs(r) => play(Player::<u16, _>::new(&r[..]), m),
        }
    }
}

/// Plays `m` on `player`: its periods, stopped after `stop_at` of them.
fn play<L: Layout>(mut player: Player<'_, u16, L>, m: &Move) -> Vec<u32> {
    player.start(m.steps);
    let mut out = Vec::new();
    loop {
        if m.stop_at != 0 && out.len() == m.stop_at as usize {
            player.stop();
        }
        match player.next_period() {
            Some(p) => out.push(u32::from(p)),
            None => return out,
        }
    }
}

/// A move the client plays: `steps`, stopped after `stop_at` (never at 0),
/// the direction pin high or low.
struct Move {
    what: String,
    steps: u32,
    stop_at: u32,
    dir: bool,
}

/// One build of the client: its table, player and moves.
struct Image {
    /// The VCD's stem and `RUNS`'s value.
    name: &'static str,
    runs: bool,
    what: String,
    player: &'static str,
    goal: u64,
    table: Table,
    prescaler: u64,
    moves: Vec<Move>,
    /// The driver's `dir_setup`, in the table's ticks.
    dir_setup: u32,
    /// The first move's exact edges, as `stepper-profiles trace` writes
    /// them.
    reference: profile_codegen::capture::Reference,
}

fn main() -> ExitCode {
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

fn run() -> Result<bool, String> {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = manifest.join("target").join("avr");
    fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let profiles = Profiles::load(manifest.join("ramps.toml")).map_err(|e| e.to_string())?;
    let style = CStyle {
        attribute: Some("PROGMEM".into()),
        ..CStyle::default()
    };
    profiles
        .write_c_header_with(dir.join("ramps.h"), &style)
        .map_err(|e| e.to_string())?;
    fs::write(
        dir.join("c89.c"),
        "#define STEPPER_PROFILES_RAMPS_IMPLEMENTATION\n#include \"ramps.h\"\n",
    )
    .map_err(|e| e.to_string())?;
    tools::run(
        Command::new("avr-gcc").args([
            "-mmcu=atmega328p",
            "-std=c89",
            "-pedantic",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-Os",
            "-c",
            "c89.c",
            "-o",
            "c89.o",
        ]),
        &dir,
        "avr-gcc -std=c89 -pedantic on ramps.h",
    )?;
    readme_example(manifest, &dir)?;
    let version = tools::run(Command::new("avr-gcc").arg("--version"), &dir, "avr-gcc")?;
    tools::run(
        Command::new("gcc")
            .args([
                "-std=c99", "-O2", "-Wall", "-Wextra", "-Werror", "-o", "sim",
            ])
            .arg(manifest.join("sim.c"))
            .arg("-lsimavr"),
        &dir,
        "the harness (gcc, libsimavr)",
    )?;
    println!(
        "ATmega328P at 16 MHz in simavr, {} -Os; ramps.h from ramps.toml with PROGMEM tables \
         (compiles with -std=c89 -pedantic)",
        version.lines().next().unwrap_or("avr-gcc").trim()
    );
    let mut pass = true;
    let images = images(&profiles)?;
    for image in &images {
        pass &= check(image, manifest, &dir)?;
    }
    pass &= check_edited(&images[0], manifest, &dir)?;
    println!("{}", if pass { "pass" } else { "FAIL" });
    Ok(pass)
}

/// The per-step client built against a table whose entry `EDITED` is a
/// tick longer (the header edited as text): its trace, compared with the
/// move's exact edges as a capture, must be out first at that step.
fn check_edited(image: &Image, manifest: &Path, dir: &Path) -> Result<bool, String> {
    const EDITED: usize = 100;
    let edited = dir.join("edited");
    fs::create_dir_all(&edited).map_err(|e| e.to_string())?;
    let header = fs::read_to_string(dir.join("ramps.h")).map_err(|e| e.to_string())?;
    fs::write(
        edited.join("ramps.h"),
        capture::edit_entry(&header, "STEPS_PERIODS", EDITED)?,
    )
    .map_err(|e| e.to_string())?;
    let (_, vcd) = simulate(image, manifest, &edited, &dir.join("sim"))?;
    println!();
    capture::edited(&image.reference, &vcd, EDITED)
}

/// The guide's AVR example (`src/guide/c_output.md`, the C block with
/// `ramps_player_step`) compiles against the same header, as C89.
fn readme_example(manifest: &Path, dir: &Path) -> Result<(), String> {
    let readme = fs::read_to_string(manifest.join("../../src/guide/c_output.md"))
        .map_err(|e| e.to_string())?;
    let example = readme
        .split("```c\n")
        .skip(1)
        .filter_map(|block| block.split("```").next())
        .find(|block| block.contains("ISR(TIMER1_COMPA_vect)"))
        .ok_or("src/guide/c_output.md has no C block with the step interrupt")?;
    fs::write(dir.join("readme.c"), example).map_err(|e| e.to_string())?;
    tools::run(
        Command::new("avr-gcc").args([
            "-mmcu=atmega328p",
            "-std=c89",
            "-pedantic",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-Os",
            "-o",
            "readme.elf",
            "readme.c",
        ]),
        dir,
        "avr-gcc on the guide's example",
    )?;
    Ok(())
}

/// The two builds of the client: the per-step table (Timer1 at the CPU
/// clock) and the compressed ramp (Timer1 at clk/8).
fn images(profiles: &Profiles) -> Result<Vec<Image>, String> {
    let find = |name: &str| {
        profiles
            .profiles()
            .iter()
            .find(|p| p.name == name)
            .ok_or_else(|| format!("ramps.toml has no profile `{name}`"))
    };
    let (steps, runs) = (find("steps")?, find("runs")?);
    let (Generated::Steps(t), Generated::Runs(r)) = (&steps.table, &runs.table) else {
        return Err("`steps` must be a per-step table and `runs` compressed".into());
    };
    let prescaler = |hz: u32| {
        let p = F_CPU / u64::from(hz);
        match (p * u64::from(hz) == F_CPU, p) {
            (true, 1 | 8) => Ok(p),
            _ => Err(format!("{hz} Hz is not 16 MHz / 1 or / 8")),
        }
    };
    let reference = |p: &profile_codegen::profiles::Profile, steps: u32| {
        profile_codegen::capture::Reference::of(
            p,
            steps,
            None,
            profile_codegen::capture::Timing::Ends,
        )
        .map_err(|e| e.to_string())
    };
    let dir_setup = |p: &profile_codegen::profiles::Profile| {
        let d = p
            .driver
            .as_ref()
            .ok_or_else(|| format!("`{}` names no driver", p.name))?;
        Ok::<u32, String>(d.ticks(d.dir_setup, &p.table.spec().timer))
    };
    let table = Table::Steps(t.periods.iter().map(|&p| p as u16).collect());
    let len = t.periods.len() as u32;
    let steps_image = Image {
        name: "steps",
        runs: false,
        what: format!("per-step table STEPS_PERIODS ({len} entries), ramps_player_step"),
        player: "ramps_player",
        goal: 100,
        prescaler: prescaler(t.spec.timer.timer_hz)?,
        moves: vec![
            full(len),
            short(len),
            Move {
                what: format!("stopped after 60 of {} steps", 2 * len + CRUISE),
                steps: 2 * len + CRUISE,
                stop_at: 60,
                dir: false,
            },
        ],
        table,
        dir_setup: dir_setup(steps)?,
        reference: reference(steps, 2 * len + CRUISE)?,
    };
    let table = Table::Runs(r.runs.clone());
    let len = table.expansion().len() as u32;
    let runs_image = Image {
        name: "runs",
        runs: true,
        what: format!(
            "compressed RUNS_RUNS ({} runs, {len} steps), ramps_runs_player_step",
            r.runs.len()
        ),
        player: "ramps_runs_player",
        goal: 150,
        prescaler: prescaler(r.spec.timer.timer_hz)?,
        moves: vec![full(len), short(len)],
        table,
        dir_setup: dir_setup(runs)?,
        reference: reference(runs, 2 * len + CRUISE)?,
    };
    Ok(vec![steps_image, runs_image])
}

/// Up the whole ramp, `CRUISE` steps at the top, down.
fn full(len: u32) -> Move {
    Move {
        what: format!("up {len}, {CRUISE} at the top, down {len}"),
        steps: 2 * len + CRUISE,
        stop_at: 0,
        dir: false,
    }
}

/// Too short to reach the top: up and down where the ramps cross; the
/// other way.
fn short(len: u32) -> Move {
    Move {
        what: format!("{} steps back, too short for the top", len / 2 + 41),
        steps: len / 2 + 41,
        stop_at: 0,
        dir: true,
    }
}

/// Builds one client in `dir` (against the `ramps.h` there) and runs it in
/// simavr (the harness `sim`): what the harness printed, and the VCD.
fn simulate(
    image: &Image,
    manifest: &Path,
    dir: &Path,
    sim: &Path,
) -> Result<(String, String), String> {
    let elf = format!("client_{}.elf", image.name);
    let moves: Vec<String> = image
        .moves
        .iter()
        .map(|m| format!("{{{}ul, {}ul, {}}}", m.steps, m.stop_at, u8::from(m.dir)))
        .collect();
    tools::run(
        Command::new("avr-gcc")
            .args([
                "-mmcu=atmega328p",
                "-DF_CPU=16000000UL",
                &format!("-DRUNS={}", u8::from(image.runs)),
                &format!("-DMOVES={}", moves.join(", ")),
                "-Os",
                "-std=gnu99",
                "-Wall",
                "-Wextra",
                "-Werror",
                "-ffunction-sections",
                "-fdata-sections",
                "-Wl,--gc-sections",
                "-Wl,--undefined=_mmcu,--section-start=.mmcu=0x910000",
                "-I.",
                "-I/usr/include/simavr",
                "-o",
                &elf,
            ])
            .arg(manifest.join("client.c")),
        dir,
        &format!("avr-gcc on client.c ({})", image.name),
    )?;
    let functions = ["init", "start", "stop"].map(|f| format!("{}_{f}", image.player));
    let printed = tools::run_for(
        Command::new(sim)
            .arg(&elf)
            .arg(MAX_CYCLES.to_string())
            .args(&functions),
        dir,
        &format!("{}.cycles", image.name),
        TIME_LIMIT,
        &format!("simavr on {elf}"),
    )?;
    let vcd = fs::read_to_string(dir.join(format!("{}.vcd", image.name)))
        .map_err(|e| format!("the VCD of {elf}: {e}"))?;
    Ok((printed, vcd))
}

/// Builds and runs one client; checks its edges and prints its cycles.
fn check(image: &Image, manifest: &Path, dir: &Path) -> Result<bool, String> {
    let (printed, vcd) = simulate(image, manifest, dir, &dir.join("sim"))?;
    let trace = vcd::parse(&vcd, F_CPU)?;
    let (isrs, calls) = cycles::parse(&printed)?;
    println!(
        "\n{}: {}, Timer1 at 16 MHz / {}",
        image.name, image.what, image.prescaler
    );
    let played: Vec<Vec<u32>> = image.moves.iter().map(|m| image.table.play(m)).collect();
    let mut pass = check_full_move(image, &played[0]);
    pass &= check_edges(image, &trace, &played)?;
    pass &= check_directions(image, &trace)?;
    pass &= capture::whole(&image.reference, &vcd)?;
    pass &= report_cycles(image, &isrs, &played)?;
    report_planning(image, &calls);
    Ok(pass)
}

/// Prints the planning calls' cycles: `init`, each move's `start` and
/// `stop`, then the stop 60 steps into the first move that the client plans
/// with the timer off.
fn report_planning(image: &Image, calls: &[cycles::Call]) {
    let name = |c: &cycles::Call| {
        c.name
            .trim_start_matches(image.player)
            .trim_start_matches('_')
            .to_string()
    };
    let mut starts = image.moves.iter().map(|m| m.what.as_str());
    let mut out = Vec::new();
    for c in calls {
        let what = match name(c).as_str() {
            "start" => format!(
                "start ({})",
                starts.next().unwrap_or("60 steps, then a stop")
            ),
            other => other.to_string(),
        };
        out.push(format!("{what} {}", c.cycles));
    }
    println!("  planning, cycles per call: {}", out.join("; "));
}

/// The move up and down, from the table alone: each entry up, the top entry
/// `CRUISE` times, each entry down no faster than the top (as the player's
/// property tests state it); the Rust player must play exactly that.
fn check_full_move(image: &Image, played: &[u32]) -> bool {
    let up = image.table.expansion();
    let top = *up.last().unwrap_or(&0);
    let mut want = up.clone();
    want.extend(std::iter::repeat_n(top, CRUISE as usize));
    want.extend(up.iter().rev().map(|&p| p.max(top)));
    if want != played {
        println!("  FAIL: the Rust player's move up and down is not the table's");
        return false;
    }
    true
}

/// The cycles each move starts at (the writes of `TCCR1B` that select a
/// clock) and of every edge of the step pin.
fn starts_and_edges(
    trace: &std::collections::HashMap<String, Vec<vcd::Change>>,
) -> Result<(Vec<u64>, Vec<u64>), String> {
    let changes = |name: &str| {
        trace
            .get(name)
            .ok_or_else(|| format!("the VCD has no {name}"))
    };
    let starts = changes("TCCR1B")?
        .iter()
        .filter(|c| c.value & 0x07 != 0)
        .map(|c| c.cycle)
        .collect();
    let edges = changes("OC1A")?.iter().map(|c| c.cycle).collect();
    Ok((starts, edges))
}

/// Every edge of every move at its start plus the cumulative periods.
fn check_edges(
    image: &Image,
    trace: &std::collections::HashMap<String, Vec<vcd::Change>>,
    played: &[Vec<u32>],
) -> Result<bool, String> {
    let (starts, edges) = starts_and_edges(trace)?;
    let edges: Vec<u64> = edges
        .into_iter()
        .filter(|&c| starts.first().is_some_and(|&s| c > s))
        .collect();
    if starts.len() != played.len() {
        println!(
            "  FAIL: {} moves started, {} played",
            starts.len(),
            played.len()
        );
        return Ok(false);
    }
    let mut pass = true;
    for (i, (m, periods)) in image.moves.iter().zip(played).enumerate() {
        let next = starts.get(i + 1).copied().unwrap_or(u64::MAX);
        let got: Vec<u64> = edges
            .iter()
            .copied()
            .filter(|&c| c > starts[i] && c < next)
            .collect();
        let mut at = starts[i];
        let want: Vec<u64> = periods
            .iter()
            .map(|&p| {
                at += image.prescaler * u64::from(p);
                at + WAKE
            })
            .collect();
        let total: u64 = periods.iter().map(|&p| u64::from(p)).sum();
        if got == want {
            println!(
                "  {}: {} edges, each at the start + the cumulative periods to the cycle \
                 ({} ticks, {} cycles)",
                m.what,
                got.len(),
                total,
                total * image.prescaler
            );
            continue;
        }
        pass = false;
        let k = got.iter().zip(&want).position(|(g, w)| g != w);
        match k {
            Some(k) => println!(
                "  FAIL {}: edge {k} at cycle {}, expected {} (start {} + {} x the periods to it)",
                m.what, got[k], want[k], starts[i], image.prescaler
            ),
            None => println!(
                "  FAIL {}: {} edges, expected {}",
                m.what,
                got.len(),
                want.len()
            ),
        }
    }
    Ok(pass)
}

/// The direction pin at every move: its level from the move's start to its
/// last edge is the move's, and each change comes at least `dir_setup`
/// before the next step edge (the shortest such lead printed).
fn check_directions(
    image: &Image,
    trace: &std::collections::HashMap<String, Vec<vcd::Change>>,
) -> Result<bool, String> {
    let (starts, edges) = starts_and_edges(trace)?;
    let dir = trace.get("DIR").ok_or("the VCD has no DIR")?;
    // The pin's level at `cycle`: its last change at or before it.
    let level_at = |cycle: u64| {
        dir.iter()
            .take_while(|c| c.cycle <= cycle)
            .last()
            .is_some_and(|c| c.value != 0)
    };
    let setup = u64::from(image.dir_setup) * image.prescaler;
    let mut pass = true;
    let mut lead = u64::MAX;
    for (i, m) in image.moves.iter().enumerate() {
        let start = starts[i];
        let last = edges
            .iter()
            .copied()
            .rfind(|&c| c > start && c < starts.get(i + 1).copied().unwrap_or(u64::MAX))
            .unwrap_or(start);
        let flips = dir
            .iter()
            .filter(|c| c.cycle > start && c.cycle <= last)
            .count();
        if level_at(start) != m.dir || flips > 0 {
            println!(
                "  FAIL {}: the direction pin is not {} from the start to the last edge",
                m.what,
                u8::from(m.dir)
            );
            pass = false;
        }
    }
    for change in dir {
        let Some(&next) = edges.iter().find(|&&e| e > change.cycle) else {
            continue;
        };
        lead = lead.min(next - change.cycle);
        if next - change.cycle < setup {
            println!(
                "  FAIL: the direction changed at cycle {}, the next step edge {} cycles later, \
                 under dir_setup's {setup}",
                change.cycle,
                next - change.cycle
            );
            pass = false;
        }
    }
    // The reversals: changes of level (the trace's first value is none).
    let reversals = dir.windows(2).filter(|w| w[0].value != w[1].value).count();
    println!(
        "  direction: {reversals} reversals, each move's level held from its start to its last \
         edge; the shortest lead of a change to the next step edge {lead} cycles, dir_setup {} \
         ticks = {setup} cycles",
        image.dir_setup
    );
    Ok(pass)
}

/// Prints the step interrupt's cycles: per phase of the move up and down,
/// and over every step of every move; false above the goal.
fn report_cycles(image: &Image, isrs: &[Isr], played: &[Vec<u32>]) -> Result<bool, String> {
    let steps: usize = played.iter().map(Vec::len).sum();
    if isrs.len() != steps {
        return Err(format!(
            "{} step interrupts for {steps} steps: one per edge expected",
            isrs.len()
        ));
    }
    // Interrupt k of a move (from 1) hands out period k, the last ends it.
    let len = image.table.expansion().len();
    let full = &isrs[..played[0].len()];
    let phases = [
        ("accelerating", &full[..len - 1]),
        ("at the top", &full[len - 1..len - 1 + CRUISE as usize]),
        ("decelerating", &full[len - 1 + CRUISE as usize..]),
        ("every step of every move", isrs),
    ];
    println!(
        "  the step interrupt, compare match to the end of reti (to the end of its body), cycles:"
    );
    let mut pass = true;
    for (name, xs) in phases {
        let reti = Stats::of(xs.iter().copied().map(Isr::until_reti));
        let body = Stats::of(xs.iter().copied().map(Isr::until_body_end));
        let ok = reti.mean <= image.goal as f64;
        pass &= ok;
        println!(
            "    {name:<26} mean {:>7.2} ({:>7.2})   max {:>4} ({:>4})   {} steps{}",
            reti.mean,
            body.mean,
            reti.max,
            body.max,
            reti.count,
            if ok {
                String::new()
            } else {
                format!("   over the goal of {}", image.goal)
            }
        );
    }
    println!(
        "    goal: a mean of at most {} in every phase: {}",
        image.goal,
        if pass { "met" } else { "FAIL" }
    );
    Ok(pass)
}
