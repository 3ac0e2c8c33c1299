//! The C header on an 8051, built as the exponential-ramp article's users
//! build (SDCC, `sdcc -mmcs51 --model-large`, the tables in code memory with
//! `--storage __code`) and run in ucsim's `s51` on an 8052: 256 bytes of
//! internal RAM, 128 of them addressable directly, as on the article's
//! C8051F040, whose 4 KB of external RAM the link is held to
//! (`--xram-size 4096`). The header holds one per-step table and one
//! compressed ramp; each program is built from one header and from a header
//! and its source file (`--split`).
//!
//! - Without its players (`RAMPS_NO_PLAYER`, `RAMPS_NO_RUNS_PLAYER`), the
//!   program links with no player in it and sums the table and the run
//!   expander's periods (their count, sum and an order-sensitive checksum)
//!   exactly as Rust does.
//! - With them, it plays moves on each player (up, along the top and down; a
//!   triangle; stops and cruise changes midway; a start of `u32::MAX` steps),
//!   and the count, sum and checksum of the periods of every operation, and
//!   the steps remaining after it, are those of the Rust `Player` playing the
//!   same operations. It paints the internal RAM above the stack before each
//!   call and reports the highest byte the call wrote: the stack never
//!   reaches the top of the internal RAM.
//!
//! The program writes its lines through ucsim's simulator interface (a byte
//! of external RAM at 0xFFFF, `-I if=xram[0xffff],out=FILE`) and stops the
//! simulation there. SDCC and ucsim are Debian's `sdcc` and `sdcc-ucsim`; a
//! missing one fails the test, as a missing C compiler fails the other C
//! tests. `--nocapture` prints the stack each call used.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use profile_codegen::Generated;
use profile_codegen::profiles::{CStyle, Profiles};
use profile_core::TableWord;
use profile_core::player::{Layout, Player, Ramp};

/// One per-step table (an exponential ramp, as in the article) and one
/// compressed ramp, on a 2 MHz timer.
const PROFILES: &str = r#"
[defaults]
timer_hz = "2 MHz"

[profiles.exponential]
curve = "exponential"
fmin = 200
fmax = 2000
f_inf = 2500
len = 200

[profiles.runs]
curve = "linear"
fmin = 400
fmax = 8000
accel = 40000
compress = 1
"#;

/// How the article's users build, and the C8051F040's external RAM.
const SDCC: &[&str] = &["-mmcs51", "--model-large", "--xram-size", "4096"];

/// The program's output: a byte of external RAM that ucsim's simulator
/// interface answers at, the commands it takes (`w` a byte to the output
/// file, `s` stop), decimal numbers, and the stack painted and measured.
const PRELUDE: &str = r#"
#define SIF (*(volatile __xdata unsigned char *)0xFFFF)
__sfr __at(0x81) stack_pointer;

static void put(char c)
{
    SIF = 'w';
    SIF = c;
}

static void put_text(const char *s)
{
    while (*s) {
        put(*s++);
    }
}

static void put_number(unsigned long v)
{
    char digits[10];
    unsigned char n = 0;
    do {
        digits[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v != 0);
    while (n > 0) {
        put(digits[--n]);
    }
    put(' ');
}

/* The caller's stack pointer when it painted. */
static unsigned char base;

/* Fills the internal RAM above the caller's stack with a pattern (above
 * this call's return address, which the caller's next call overwrites). */
static void paint(void)
{
    unsigned char i;
    base = (unsigned char)(stack_pointer - 2);
    for (i = (unsigned char)(stack_pointer + 1); i != 0; i++) {
        *(__idata unsigned char *)i = 0xA5;
    }
}

/* The highest byte of internal RAM written since `paint`. */
static unsigned char high(void)
{
    unsigned char i = 0xFF;
    while (i > base && *(__idata unsigned char *)i == 0xA5) {
        i--;
    }
    return i;
}

/* The bytes of stack used since `paint`, and the highest one written. */
static void put_stack(void)
{
    unsigned char top = high();
    put_number((unsigned char)(top - base));
    put_number(top);
}
"#;

#[derive(Clone, Copy, Debug)]
enum Op {
    Start(u32),
    Play(u32),
    Stop,
    Cruise(u32),
}

/// The operations played on a table of `len` steps: a move up, along the
/// top and down; a triangle; a short one; stops and cruise changes midway;
/// a start of `u32::MAX` steps, stopped.
fn ops(len: u32) -> Vec<Op> {
    use Op::{Cruise, Play, Start, Stop};
    let all = u32::MAX;
    vec![
        Start(2 * len + 300),
        Play(all),
        Start(len),
        Play(all),
        Start(len / 3),
        Play(all),
        Start(4 * len),
        Play(len + 50),
        Cruise(len / 2),
        Play(len / 2),
        Stop,
        Play(all),
        Start(3 * len),
        Play(len / 4),
        Cruise(len),
        Play(len),
        Stop,
        Play(all),
        Start(u32::MAX),
        Play(len / 2),
        Stop,
        Play(all),
    ]
}

/// Per operation: the periods played (count, sum, checksum) and the steps
/// remaining after it, as the C program prints them.
fn expected<W: TableWord, L: Layout>(player: &mut Player<'_, W, L>, ops: &[Op]) -> Vec<String> {
    ops.iter()
        .map(|op| {
            let (mut count, mut sum, mut check) = (0u64, 0u64, 0u64);
            match *op {
                Op::Start(n) => player.start(n),
                Op::Play(n) => {
                    while count < u64::from(n) {
                        let Some(p) = player.next_period() else { break };
                        let p = u64::from(p.into_ticks());
                        count += 1;
                        sum += p;
                        check = (check + count * p) & 0xFFFF_FFFF;
                    }
                }
                Op::Stop => player.stop(),
                Op::Cruise(pos) => player.set_cruise(pos),
            }
            assert!(sum <= u64::from(u32::MAX), "the C sums in 32 bits");
            format!("{count} {sum} {check} {}", player.remaining())
        })
        .collect()
}

/// A C array of the operations, in code memory.
fn c_ops(c: &mut String, name: &str, ops: &[Op]) {
    let _ = write!(c, "static const __code unsigned long {name}[] = {{");
    for op in ops {
        let (code, arg) = match *op {
            Op::Start(n) => (0, n),
            Op::Play(n) => (1, n),
            Op::Stop => (2, 0),
            Op::Cruise(pos) => (3, pos),
        };
        let _ = write!(c, " {code}, {arg}ul,");
    }
    let _ = writeln!(c, " 9, 0 }};");
}

/// The program playing `ops` on both players: per operation a line
/// `PLAYER INDEX COUNT SUM CHECK REMAINING USED TOP`, after `init` a line
/// `PLAYER init USED TOP`: the bytes of stack the call used, and the
/// highest byte of internal RAM it wrote.
fn players_program(prelude: &str, steps: &[Op], runs: &[Op]) -> String {
    let mut c = String::from(prelude);
    c.push_str(PRELUDE);
    c_ops(&mut c, "STEPS_OPS", steps);
    c_ops(&mut c, "RUNS_OPS", runs);
    c.push_str(
        r#"
static ramps_player_t steps_player;
static ramps_runs_player_t runs_player;

static void play(unsigned char runs, const __code unsigned long *o)
{
    unsigned long index = 0, count, sum, check, remaining;
    uint16_t period;
    unsigned char more, used, top;
    for (; o[0] != 9; o += 2, index++) {
        count = 0;
        sum = 0;
        check = 0;
        paint();
        if (o[0] == 0) {
            if (runs) {
                ramps_runs_player_start(&runs_player, o[1]);
            } else {
                ramps_player_start(&steps_player, o[1]);
            }
        } else if (o[0] == 1) {
            while (count < o[1]) {
                if (runs) {
                    more = ramps_runs_player_step(&runs_player, &period);
                } else {
                    more = ramps_player_step(&steps_player, &period);
                }
                if (!more) {
                    break;
                }
                count++;
                sum += period;
                check += count * period;
            }
        } else if (o[0] == 2) {
            if (runs) {
                ramps_runs_player_stop(&runs_player);
            } else {
                ramps_player_stop(&steps_player);
            }
        } else if (runs) {
            ramps_runs_player_set_cruise(&runs_player, o[1]);
        } else {
            ramps_player_set_cruise(&steps_player, o[1]);
        }
        top = high();
        used = (unsigned char)(top - base);
        remaining = runs ? ramps_runs_player_remaining(&runs_player)
                         : ramps_player_remaining(&steps_player);
        put_text(runs ? "runs " : "steps ");
        put_number(index);
        put_number(count);
        put_number(sum);
        put_number(check);
        put_number(remaining);
        put_number(used);
        put_number(top);
        put('\n');
    }
}

void main(void)
{
    paint();
    ramps_player_init(&steps_player, EXPONENTIAL_PERIODS, EXPONENTIAL_LEN,
        EXPONENTIAL_PERIODS, EXPONENTIAL_LEN);
    put_text("steps init ");
    put_stack();
    put('\n');
    paint();
    ramps_runs_player_init(&runs_player, RUNS_RUNS, RUNS_RUN_COUNT, RUNS_RUNS, RUNS_RUN_COUNT);
    put_text("runs init ");
    put_stack();
    put('\n');
    play(0, STEPS_OPS);
    play(1, RUNS_OPS);
    SIF = 's';
}
"#,
    );
    c
}

/// The program summing the table and the run expander's periods: lines
/// `NAME COUNT SUM CHECK`.
fn tables_program(prelude: &str) -> String {
    let mut c = String::from(prelude);
    c.push_str(PRELUDE);
    c.push_str(
        r#"
void main(void)
{
    ramps_runs_t r;
    unsigned long k, sum = 0, check = 0;
    uint16_t period;
    for (k = 0; k < sizeof(EXPONENTIAL_PERIODS) / sizeof(EXPONENTIAL_PERIODS[0]); k++) {
        sum += EXPONENTIAL_PERIODS[k];
        check += (k + 1) * EXPONENTIAL_PERIODS[k];
    }
    put_text("exponential ");
    put_number(k);
    put_number(sum);
    put_number(check);
    put('\n');
    ramps_runs_start(&r, RUNS_RUNS, RUNS_RUN_COUNT);
    k = 0;
    sum = 0;
    check = 0;
    while ((period = ramps_runs_next(&r)) != 0) {
        k++;
        sum += period;
        check += k * period;
    }
    put_text("runs ");
    put_number(k);
    put_number(sum);
    put_number(check);
    put('\n');
    SIF = 's';
}
"#,
    );
    c
}

fn work_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("c_8051")
        .join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

fn missing(tool: &str, e: &std::io::Error) -> String {
    format!(
        "cannot run `{tool}` ({e}): this test builds the C header for an 8051 with SDCC and runs \
         it in ucsim's s51 (`apt-get install sdcc sdcc-ucsim`); it fails rather than skips"
    )
}

/// Runs `sdcc` in `dir`; a failure shows what it printed.
fn sdcc(dir: &Path, args: &[&str], what: &str) {
    let output = Command::new("sdcc")
        .args(SDCC)
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| panic!("{}", missing("sdcc", &e)));
    assert!(
        output.status.success(),
        "`sdcc {} {}` ({what}) failed ({}):\n{}{}",
        SDCC.join(" "),
        args.join(" "),
        output.status,
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
}

/// Runs `program.ihx` in `s51` until the program stops the simulation, and
/// returns what it wrote.
fn s51(dir: &Path, program: &str) -> String {
    let out = dir.join("out.txt");
    let _ = fs::remove_file(&out);
    // With -G, s51 quits when the program stops it; its console's input is
    // held open meanwhile.
    let mut child = Command::new("s51")
        .args(["-t", "C52", "-G", "-I"])
        .arg(format!("if=xram[0xffff],out={}", out.display()))
        .arg(program)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap_or_else(|e| panic!("{}", missing("s51", &e)));
    let deadline = Instant::now() + Duration::from_secs(300);
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            panic!(
                "{program} did not stop the simulation within 300 s; it wrote:\n{}",
                fs::read_to_string(&out).unwrap_or_default()
            );
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    assert!(status.success(), "s51 exited with {status}");
    fs::read_to_string(&out).unwrap_or_else(|e| panic!("{program} wrote nothing ({e})"))
}

fn profiles() -> Profiles {
    Profiles::parse("ramps.toml", PROFILES).unwrap_or_else(|e| panic!("{e}"))
}

fn code_storage() -> CStyle {
    CStyle {
        storage: Some("__code".into()),
        ..CStyle::default()
    }
}

/// The stored table and runs of the two profiles.
fn tables(profiles: &Profiles) -> (Vec<u16>, Vec<[u16; 5]>) {
    let [steps, runs] = profiles.profiles() else {
        panic!("two profiles");
    };
    let (Generated::Steps(t), Generated::Runs(r)) = (&steps.table, &runs.table) else {
        panic!("a per-step table, then runs");
    };
    let table = t.stored_periods().iter().map(|&p| p as u16).collect();
    (table, r.stored_runs())
}

/// Builds `main.c` in `dir` against one header (`single`) or a header and
/// its source file, each compiled with `defines`.
fn build(dir: &Path, single: bool, main: &str, defines: &[&str]) {
    let profiles = profiles();
    let style = code_storage();
    let header = if single {
        profiles
            .write_c_header_with(dir.join("ramps.h"), &style)
            .unwrap();
        fs::read_to_string(dir.join("ramps.h")).unwrap()
    } else {
        profiles.write_c_split(dir.join("ramps.h"), &style).unwrap();
        fs::read_to_string(dir.join("ramps.c")).unwrap()
    };
    assert!(header.contains("const __code uint16_t EXPONENTIAL_PERIODS[200]"));
    fs::write(dir.join("main.c"), main).unwrap();
    let mut args: Vec<&str> = defines.to_vec();
    if single {
        args.push("main.c");
        sdcc(dir, &args, "one header");
    } else {
        args.extend(["-c", "ramps.c"]);
        sdcc(dir, &args, "the source file");
        let mut args: Vec<&str> = defines.to_vec();
        args.extend(["main.c", "ramps.rel"]);
        sdcc(dir, &args, "a header and its source file");
    }
}

fn prelude(single: bool, defines: &str) -> String {
    let implementation = if single {
        "#define STEPPER_PROFILES_RAMPS_IMPLEMENTATION\n"
    } else {
        ""
    };
    format!("{defines}{implementation}#include \"ramps.h\"\n")
}

#[test]
#[ignore = "slow: builds C with SDCC and runs it in s51; CI runs it with --ignored"]
fn an_8051_links_and_sums_a_header_without_its_players() {
    let (table, runs) = tables(&profiles());
    let line = |name: &str, periods: &[u32]| {
        let sum: u64 = periods.iter().map(|&p| u64::from(p)).sum();
        let check = periods.iter().enumerate().fold(0u64, |s, (k, &p)| {
            (s + (k as u64 + 1) * u64::from(p)) & 0xFFFF_FFFF
        });
        format!("{name} {} {sum} {check} \n", periods.len())
    };
    let table: Vec<u32> = table.iter().map(|&p| u32::from(p)).collect();
    let expanded: Vec<u32> = profile_core::runs::Expand::new(&runs).collect();
    let want = line("exponential", &table) + &line("runs", &expanded);
    for single in [true, false] {
        let layout = if single { "single" } else { "split" };
        let dir = work_dir(&format!("tables_{layout}"));
        // In the file, for one header; on the command line, for a header and
        // its source file, which both must see them.
        let (main, defines): (String, &[&str]) = if single {
            let defines = "#define RAMPS_NO_PLAYER\n#define RAMPS_NO_RUNS_PLAYER\n";
            (tables_program(&prelude(true, defines)), &[])
        } else {
            (
                tables_program(&prelude(false, "")),
                &["-DRAMPS_NO_PLAYER", "-DRAMPS_NO_RUNS_PLAYER"],
            )
        };
        build(&dir, single, &main, defines);
        let map = fs::read_to_string(dir.join("main.map")).unwrap();
        assert!(
            !map.contains("_player_"),
            "{layout}: a player was linked in:\n{map}"
        );
        assert_eq!(s51(&dir, "main.ihx"), want, "{layout}");
    }
}

#[test]
#[ignore = "slow: builds C with SDCC and runs it in s51; CI runs it with --ignored"]
fn an_8051_plays_moves_as_the_rust_player() {
    let (table, runs) = tables(&profiles());
    let run_steps: u32 = runs.iter().map(|r| u32::from(r[0])).sum();
    let (steps_ops, runs_ops) = (ops(table.len() as u32), ops(run_steps));
    let mut want = Vec::new();
    let mut player = Player::new(Ramp::steps(&table)).with_decel(Ramp::steps(&table));
    for (i, line) in expected(&mut player, &steps_ops).iter().enumerate() {
        want.push(format!("steps {i} {line}"));
    }
    let mut player = Player::<u16, _>::new(&runs[..]).with_decel(&runs[..]);
    for (i, line) in expected(&mut player, &runs_ops).iter().enumerate() {
        want.push(format!("runs {i} {line}"));
    }
    for single in [true, false] {
        let layout = if single { "single" } else { "split" };
        let dir = work_dir(&format!("players_{layout}"));
        let main = players_program(&prelude(single, ""), &steps_ops, &runs_ops);
        build(&dir, single, &main, &[]);
        let printed = s51(&dir, "main.ihx");
        let mut got = Vec::new();
        // Per call: the player and the operation, the stack used, the top.
        let mut stack = Vec::new();
        for line in printed.lines() {
            let mut fields: Vec<&str> = line.split_whitespace().collect();
            let top: u32 = fields.pop().unwrap().parse().unwrap();
            let used: u32 = fields.pop().unwrap().parse().unwrap();
            let ops = if fields[0] == "runs" {
                &runs_ops
            } else {
                &steps_ops
            };
            let op = match fields[1] {
                "init" => "init",
                i => match ops[i.parse::<usize>().unwrap()] {
                    Op::Start(_) => "start",
                    Op::Play(_) => "step",
                    Op::Stop => "stop",
                    Op::Cruise(_) => "set_cruise",
                },
            };
            stack.push((fields[0], op, used, top));
            if fields[1] != "init" {
                got.push(fields.join(" "));
            }
        }
        assert_eq!(got, want, "{layout}: C (left) and Rust (right)");
        for &(player, op, _, top) in &stack {
            assert!(
                top < 0xFF,
                "{layout}: {player} {op} reached the top of the internal RAM"
            );
        }
        for player in ["steps", "runs"] {
            for op in ["init", "start", "step", "stop", "set_cruise"] {
                let used = stack
                    .iter()
                    .filter(|s| (s.0, s.1) == (player, op))
                    .map(|s| s.2)
                    .max()
                    .unwrap();
                println!("{layout}: {player} {op}: at most {used} bytes of stack");
            }
        }
    }
}

/// On the host too, a player's macro leaves it out, and the header compiles
/// as C89 without it: one header (`RAMPS_*`) and split (`SPLIT_*`), each
/// player's functions in the objects exactly when not left out.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn a_player_left_out_is_not_compiled() {
    let profiles = profiles();
    let dir = work_dir("c89");
    profiles.write_c_header(dir.join("ramps.h")).unwrap();
    profiles
        .write_c_split(dir.join("split.h"), &CStyle::default())
        .unwrap();
    fs::write(
        dir.join("main.c"),
        "#define STEPPER_PROFILES_RAMPS_IMPLEMENTATION\n#include \"ramps.h\"\n\
         #include \"split.h\"\nint main(void)\n{\n    return 0;\n}\n",
    )
    .unwrap();
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    let players = [
        "RAMPS_NO_PLAYER",
        "RAMPS_NO_RUNS_PLAYER",
        "SPLIT_NO_PLAYER",
        "SPLIT_NO_RUNS_PLAYER",
    ];
    for left_out in 0..16u32 {
        let defines: Vec<String> = (0..4)
            .filter(|i| left_out >> i & 1 == 1)
            .map(|i| format!("-D{}", players[i]))
            .collect();
        let mut symbols = String::new();
        for source in ["main.c", "split.c"] {
            let output = Command::new(&cc)
                .args(["-std=c89", "-pedantic", "-Wall", "-Wextra", "-Werror", "-c"])
                .args(&defines)
                .args([source, "-o", "out.o"])
                .current_dir(&dir)
                .output()
                .unwrap_or_else(|e| panic!("cannot run `{cc}`: {e}"));
            assert!(
                output.status.success(),
                "{defines:?} {source}: {}",
                String::from_utf8_lossy(&output.stderr)
            );
            let nm = Command::new("nm")
                .arg("out.o")
                .current_dir(&dir)
                .output()
                .unwrap_or_else(|e| panic!("cannot run `nm` (binutils): {e}"));
            symbols.push_str(&String::from_utf8_lossy(&nm.stdout));
        }
        for (i, name) in players.iter().enumerate() {
            let function = name.to_lowercase().replace("_no_", "_") + "_init";
            let defined = symbols
                .lines()
                .any(|l| l.ends_with(&format!(" T {function}")));
            assert_eq!(
                defined,
                left_out >> i & 1 == 0,
                "{defines:?}: `{function}` defined: {defined}\n{symbols}"
            );
        }
    }
}
