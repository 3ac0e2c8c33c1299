//! The C of the shipped `profiles.toml`, one header or a header and a source
//! file, compiles cleanly as C89 and C99 and holds the same tables and
//! figures as the Rust side.
//!
//! The test writes the C with `Profiles::write_c_header` or
//! `write_c_split`, generates a C program that prints every profile's first
//! and last entries, its sum and each `#define`, compiles the generated files
//! as C89 and the program as C99 with `-Wall -Wextra -Werror -pedantic` (set
//! `CC` to use another compiler), runs it and compares.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use profile_codegen::Generated;
use profile_codegen::profiles::{CStyle, Profiles};

const FLAGS: &[&str] = &["-Wall", "-Wextra", "-Werror", "-pedantic"];
/// A storage word as a user's toolchain would define it (`__code` on SDCC);
/// gcc has none, so it is a macro here.
/// `ALIGNED(n)` is an attribute macro as CMSIS's `__ALIGNED(n)` is.
const DEFINES: &[&str] = &["-DROM=", "-DALIGNED(n)=__attribute__((aligned(n)))"];

fn work_dir_existing(name: &str) -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("c_header")
        .join(name)
}

fn work_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("c_header")
        .join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

/// A printed figure: integers exactly, floating-point figures by their bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Figure {
    Int(u64),
    Float(u64),
    /// `RELOAD_OFFSET`, which may be negative.
    Signed(i64),
}

impl Figure {
    /// An integer figure's value.
    fn int(self) -> i128 {
        match self {
            Figure::Int(v) => i128::from(v),
            Figure::Signed(v) => i128::from(v),
            Figure::Float(_) => panic!("not an integer figure"),
        }
    }
}

fn float(v: f64) -> Figure {
    Figure::Float(v.to_bits())
}

/// What the C program must print for each profile, from the Rust tables.
fn expected(profiles: &Profiles) -> BTreeMap<String, BTreeMap<String, Figure>> {
    let mut all = BTreeMap::new();
    for p in profiles.profiles() {
        let mut m = BTreeMap::new();
        let int = |v: u64| Figure::Int(v);
        match &p.table {
            Generated::Steps(t) => {
                let f = &t.figures;
                let word = match t.spec.timer.word {
                    profile_core::Word::U16 => 2,
                    profile_core::Word::U32 => 4,
                };
                // The table holds each period plus `reload_offset`.
                let stored = t.stored_periods();
                m.insert("entries".into(), int(stored.len() as u64));
                m.insert("word_bytes".into(), int(word));
                m.insert("first".into(), int(u64::from(stored[0])));
                m.insert("last".into(), int(u64::from(*stored.last().unwrap())));
                m.insert(
                    "sum".into(),
                    int(stored.iter().map(|&p| u64::from(p)).sum()),
                );
                m.insert("TIMER_HZ".into(), int(u64::from(t.spec.timer.timer_hz)));
                m.insert(
                    "TICKS_PER_STEP".into(),
                    int(u64::from(t.spec.timer.ticks_per_step)),
                );
                m.insert("LEN".into(), int(u64::from(f.len)));
                m.insert("TOTAL_TICKS".into(), int(f.total_ticks));
                m.insert("FIRST_TICKS".into(), int(u64::from(f.first_ticks)));
                m.insert("LAST_TICKS".into(), int(u64::from(f.last_ticks)));
                m.insert("DURATION_S".into(), float(f.duration_s));
                m.insert("START_HZ".into(), float(f.start_hz));
                m.insert("FINAL_HZ".into(), float(f.final_hz));
            }
            Generated::Runs(_) => {}
            Generated::Segments(t) => {
                let f = &t.figures;
                let pairs = t.stored_pairs();
                let (p0, c0) = pairs[0];
                let (pn, cn) = *pairs.last().unwrap();
                m.insert("entries".into(), int(pairs.len() as u64));
                m.insert("first".into(), int(u64::from(p0)));
                m.insert("first_count".into(), int(u64::from(c0)));
                m.insert("last".into(), int(u64::from(pn)));
                m.insert("last_count".into(), int(u64::from(cn)));
                m.insert(
                    "steps".into(),
                    int(t.pairs.iter().map(|&(_, c)| u64::from(c)).sum()),
                );
                m.insert(
                    "sum".into(),
                    int(pairs
                        .iter()
                        .map(|&(p, c)| u64::from(p) * u64::from(c))
                        .sum()),
                );
                m.insert("TIMER_HZ".into(), int(u64::from(t.spec.timer.timer_hz)));
                m.insert(
                    "TICKS_PER_STEP".into(),
                    int(u64::from(t.spec.timer.ticks_per_step)),
                );
                m.insert("SEGMENT_COUNT".into(), int(u64::from(f.entries)));
                m.insert("LEN".into(), int(u64::from(f.steps)));
                m.insert("TOTAL_TICKS".into(), int(f.total_ticks));
                m.insert("DURATION_S".into(), float(f.duration_s));
            }
            _ => panic!("a layout this test does not know"),
        }
        if let Generated::Runs(t) = &p.table {
            let f = &t.figures;
            // What the C player plays: the stored runs, each period plus
            // `reload_offset`.
            let stored = t.stored_runs();
            let periods: Vec<u32> = profile_core::runs::Expand::new(&stored).collect();
            m.insert("entries".into(), int(t.runs.len() as u64));
            m.insert("steps".into(), int(periods.len() as u64));
            m.insert("first".into(), int(u64::from(periods[0])));
            m.insert("last".into(), int(u64::from(*periods.last().unwrap())));
            m.insert(
                "sum".into(),
                int(periods.iter().map(|&p| u64::from(p)).sum()),
            );
            m.insert("checksum".into(), int(checksum(&periods)));
            m.insert("TIMER_HZ".into(), int(u64::from(t.spec.timer.timer_hz)));
            m.insert(
                "TICKS_PER_STEP".into(),
                int(u64::from(t.spec.timer.ticks_per_step)),
            );
            m.insert("RUN_COUNT".into(), int(u64::from(f.entries)));
            m.insert("LEN".into(), int(u64::from(f.steps)));
            m.insert("TOTAL_TICKS".into(), int(f.total_ticks));
            m.insert("DURATION_S".into(), float(f.duration_s));
            m.insert("MAX_EDGE_ERROR_TICKS".into(), float(f.max_edge_error_ticks));
        }
        m.insert(
            "RELOAD_OFFSET".into(),
            Figure::Signed(i64::from(p.table.spec().reload_offset)),
        );
        // A profile that names a motor: where its torque margin is smallest.
        if let Some(t) = &p.torque {
            m.insert("TORQUE_MARGIN_NM".into(), float(t.min_margin_nm));
            m.insert("TORQUE_MARGIN_STEP".into(), int(u64::from(t.step)));
        }
        // A profile that names a driver: its times in ticks, rounded up,
        // in whole nanoseconds and integers here.
        if let Some(d) = &p.driver {
            let hz = u64::from(p.table.spec().timer.timer_hz);
            let ticks = |seconds: f64| {
                let ns = (seconds * 1e9).round() as u64;
                (ns * hz).div_ceil(1_000_000_000)
            };
            m.insert("STEP_PULSE_TICKS".into(), int(ticks(d.step_pulse)));
            m.insert("STEP_SPACE_TICKS".into(), int(ticks(d.step_space)));
            m.insert("DIR_SETUP_TICKS".into(), int(ticks(d.dir_setup)));
        }
        // A profile that names bands: the periods that play in each, from
        // whole steps/s in integers here (the shortest period at most the
        // band's top rate, the longest at least its bottom), plus the
        // table's offset.
        if let Some(bands) = &p.avoid {
            let spec = p.table.spec();
            let hz = u64::from(spec.timer.timer_hz);
            let per = u64::from(spec.timer.ticks_per_step);
            let offset = i64::from(spec.reload_offset);
            m.insert("AVOID_COUNT".into(), int(bands.full_steps().len() as u64));
            for (i, (lo, hi)) in bands.steps().into_iter().enumerate() {
                assert!(
                    lo.fract() == 0.0 && hi.fract() == 0.0 && lo > 0.0,
                    "{lo} {hi}"
                );
                let (lo, hi) = (lo as u64 * per, hi as u64 * per);
                let shortest = hz.div_ceil(hi) as i64 + offset;
                let longest = (hz / lo) as i64 + offset;
                m.insert(format!("avoid_{i}_shortest"), int(shortest as u64));
                m.insert(format!("avoid_{i}_longest"), int(longest as u64));
            }
        }
        all.insert(p.name.clone(), m);
    }
    all
}

/// Each period times its 1-based step, summed modulo 2^32: the order of
/// the periods counts, not only their sum.
fn checksum(periods: &[u32]) -> u64 {
    periods.iter().enumerate().fold(0u64, |s, (k, &p)| {
        (s + (k as u64 + 1) * u64::from(p)) & 0xFFFF_FFFF
    })
}

/// The header's file name: the profiles file's stem (`ramps.h` for
/// `ramps.toml`), after which the header is named in C.
fn header_name(profiles: &Profiles) -> String {
    let stem = Path::new(profiles.file()).file_stem().unwrap();
    format!("{}.h", stem.to_string_lossy())
}

/// The run player's prefix: the header's (and the profiles file's) stem.
fn prefix(profiles: &Profiles) -> String {
    let stem = Path::new(profiles.file())
        .file_stem()
        .unwrap()
        .to_string_lossy()
        .to_lowercase();
    // Stems that are no C identifier, as the C output page names their prefixes.
    match stem.as_str() {
        "3d_printer" => "profiles_3d_printer".to_string(),
        "é" | "__" => "profiles".to_string(),
        "x--y_" => "x_y".to_string(),
        _ => stem,
    }
}

/// The include guard's stem: the file stem in upper case, every run of
/// characters other than a letter or digit one `_`, none at either end.
fn guard_stem(profiles: &Profiles) -> String {
    let stem = Path::new(profiles.file())
        .file_stem()
        .unwrap()
        .to_string_lossy()
        .to_uppercase();
    match stem.as_str() {
        "É" | "__" => "PROFILES".to_string(),
        "X--Y_" => "X_Y".to_string(),
        _ => stem,
    }
}

/// `#define NAME_FIGURE value` lines of the header, per profile, in order:
/// whether each is a floating-point figure.
fn defines(header: &str, profiles: &Profiles) -> BTreeMap<String, Vec<(String, bool)>> {
    let mut out: BTreeMap<String, Vec<(String, bool)>> = BTreeMap::new();
    for line in header.lines() {
        let Some(rest) = line.strip_prefix("#define ") else {
            continue;
        };
        let Some((macro_name, value)) = rest.split_once(' ') else {
            continue; // the include guard
        };
        if macro_name.ends_with("_RUNS_READ(p)")
            || macro_name.ends_with("_READ32(p)")
            || macro_name.starts_with("STEPPER_PROFILES_")
        {
            continue; // the players' memory access and inline step paths
        }
        let owner = profiles
            .profiles()
            .iter()
            .map(|p| p.name.to_uppercase())
            .filter(|upper| macro_name.starts_with(&format!("{upper}_")))
            .max_by_key(|upper| upper.len())
            .unwrap_or_else(|| panic!("`#define {macro_name}` belongs to no profile"));
        let figure = macro_name[owner.len() + 1..].to_string();
        // A figure above 32 bits is defined twice, for C99 and for C89:
        // the program is C99, so the first one counts.
        if out
            .get(&owner.to_lowercase())
            .is_some_and(|seen| seen.iter().any(|(f, _)| *f == figure))
        {
            continue;
        }
        let is_float = !value.ends_with(['u', 'l']) && value.contains(['.', 'e', 'E']);
        out.entry(owner.to_lowercase())
            .or_default()
            .push((figure, is_float));
    }
    out
}

/// A C program printing `name key value` lines for every profile.
fn program(profiles: &Profiles, defines: &BTreeMap<String, Vec<(String, bool)>>) -> String {
    let mut c = String::new();
    c.push_str("#include <stdio.h>\n#include <stddef.h>\n");
    // The one file that defines a single header's run player.
    let stem = guard_stem(profiles);
    let _ = writeln!(c, "#define STEPPER_PROFILES_{stem}_IMPLEMENTATION");
    let header = header_name(profiles);
    let _ = writeln!(
        c,
        "#include \"{header}\"\n#include \"{header}\" /* the guard */\n"
    );
    c.push_str("unsigned long other_first(void);\n\n");
    c.push_str(
        "int main(void)\n{\n    size_t i, n;\n    unsigned long long sum, steps;\n\n    \
         /* Not every kind of table uses every one. */\n    \
         (void)i;\n    (void)n;\n    sum = 0;\n    steps = 0;\n    (void)steps;\n\n",
    );
    for p in profiles.profiles() {
        let name = &p.name;
        let up = name.to_uppercase();
        let _ = writeln!(c, "    /* {name} */");
        match &p.table {
            Generated::Steps(_) => {
                let t = format!("{up}_PERIODS");
                let _ = writeln!(
                    c,
                    "    n = sizeof({t}) / sizeof({t}[0]);\n    sum = 0;\n    \
                     for (i = 0; i < n; i++) {{\n        sum += {t}[i];\n    }}"
                );
                let _ = writeln!(
                    c,
                    "    printf(\"{name} entries %lu\\n\", (unsigned long)n);\n    \
                     printf(\"{name} word_bytes %lu\\n\", (unsigned long)sizeof({t}[0]));\n    \
                     printf(\"{name} first %lu\\n\", (unsigned long){t}[0]);\n    \
                     printf(\"{name} last %lu\\n\", (unsigned long){t}[n - 1]);\n    \
                     printf(\"{name} sum %llu\\n\", sum);"
                );
            }
            Generated::Runs(_) => {}
            Generated::Segments(_) => {
                let t = format!("{up}_SEGMENTS");
                let _ = writeln!(
                    c,
                    "    n = sizeof({t}) / sizeof({t}[0]);\n    sum = 0;\n    steps = 0;\n    \
                     for (i = 0; i < n; i++) {{\n        \
                     sum += (unsigned long long){t}[i][0] * {t}[i][1];\n        \
                     steps += {t}[i][1];\n    }}"
                );
                let _ = writeln!(
                    c,
                    "    printf(\"{name} entries %lu\\n\", (unsigned long)n);\n    \
                     printf(\"{name} first %lu\\n\", (unsigned long){t}[0][0]);\n    \
                     printf(\"{name} first_count %lu\\n\", (unsigned long){t}[0][1]);\n    \
                     printf(\"{name} last %lu\\n\", (unsigned long){t}[n - 1][0]);\n    \
                     printf(\"{name} last_count %lu\\n\", (unsigned long){t}[n - 1][1]);\n    \
                     printf(\"{name} steps %llu\\n\", steps);\n    \
                     printf(\"{name} sum %llu\\n\", sum);"
                );
            }
            _ => panic!("a layout this test does not know"),
        }
        if let Generated::Runs(_) = &p.table {
            let t = format!("{up}_RUNS");
            let pre = prefix(profiles);
            let _ = writeln!(
                c,
                "    {{\n        {pre}_runs_t r;\n        uint16_t q;\n        \
                 unsigned long k = 0, first = 0, last = 0, check = 0;\n        sum = 0;\n        \
                 {pre}_runs_start(&r, {t}, (uint16_t)(sizeof({t}) / sizeof({t}[0])));\n        \
                 while ((q = {pre}_runs_next(&r)) != 0) {{\n            k++;\n            \
                 if (k == 1) {{\n                first = q;\n            }}\n            \
                 last = q;\n            sum += q;\n            \
                 check = (check + k * q) & 0xFFFFFFFFul;\n        }}\n        \
                 printf(\"{name} entries %lu\\n\", (unsigned long)(sizeof({t}) / sizeof({t}[0])));\n        \
                 printf(\"{name} steps %lu\\n\", k);\n        \
                 printf(\"{name} first %lu\\n\", first);\n        \
                 printf(\"{name} last %lu\\n\", last);\n        \
                 printf(\"{name} sum %llu\\n\", sum);\n        \
                 printf(\"{name} checksum %lu\\n\", check);\n    }}"
            );
        }
        if let Some(bands) = &p.avoid {
            for i in 0..bands.full_steps().len() {
                let _ = writeln!(
                    c,
                    "    printf(\"{name} avoid_{i}_shortest %lu\\n\", (unsigned long){up}_AVOID[{}]);\n    \
                     printf(\"{name} avoid_{i}_longest %lu\\n\", (unsigned long){up}_AVOID[{}]);",
                    2 * i,
                    2 * i + 1
                );
            }
        }
        for (figure, is_float) in defines.get(name).map(Vec::as_slice).unwrap_or(&[]) {
            let m = format!("{up}_{figure}");
            if *is_float {
                let _ = writeln!(c, "    printf(\"{name} {figure} %.17g\\n\", (double){m});");
            } else if figure == "RELOAD_OFFSET" {
                let _ = writeln!(c, "    printf(\"{name} {figure} %ld\\n\", (long){m});");
            } else {
                let _ = writeln!(
                    c,
                    "    printf(\"{name} {figure} %llu\\n\", (unsigned long long){m});"
                );
            }
        }
        c.push('\n');
    }
    c.push_str("    printf(\"other_first %lu\\n\", other_first());\n    return 0;\n}\n");
    c
}

fn run(command: &mut Command, what: &str) -> String {
    let output = command.output().unwrap_or_else(|e| {
        panic!(
            "cannot run {what} ({:?}): {e}. The C header test needs a C99 compiler: \
             install one (e.g. `apt-get install gcc`) or set CC",
            command.get_program()
        )
    });
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        output.status.success(),
        "{what} failed ({}):\n{stdout}{stderr}",
        output.status
    );
    assert!(
        stderr.trim().is_empty(),
        "{what} printed warnings or errors:\n{stderr}"
    );
    stdout
}

/// How the C is laid out: one header of `static` tables, or a header of
/// `extern` declarations and one source file, with a placement.
enum Layout {
    Single(CStyle),
    Split(CStyle),
}

/// Writes the C of `profiles` in `layout`, compiles it as C89 (the
/// generated files and a C89 user) and, with a program printing every
/// figure, as C99; runs the program and checks every figure against the
/// Rust tables; returns what C printed.
fn check_header(
    profiles: &Profiles,
    dir_name: &str,
    layout: &Layout,
) -> BTreeMap<String, BTreeMap<String, Figure>> {
    let dir = work_dir(dir_name);
    let name = header_name(profiles);
    let header_path = dir.join(&name);
    let source_name = Path::new(&name).with_extension("c");
    let source_name = source_name.to_str().unwrap();
    let mut sources = vec!["main.c", "other.c"];
    let header = match layout {
        Layout::Single(style) if *style == CStyle::default() => {
            profiles.write_c_header(&header_path).unwrap();
            let header = fs::read_to_string(&header_path).unwrap();
            assert_eq!(header, profiles.c_header());
            header
        }
        Layout::Single(style) => {
            let header = profiles.c_header_with(style);
            fs::write(&header_path, &header).unwrap();
            header
        }
        Layout::Split(style) => {
            let (h, c) = profiles.write_c_split(&header_path, style).unwrap();
            assert_eq!(
                (h.as_path(), c.as_path()),
                (header_path.as_path(), dir.join(source_name).as_path())
            );
            let header = fs::read_to_string(&h).unwrap();
            let source = fs::read_to_string(&c).unwrap();
            assert_eq!(header, profiles.c_split(&name, style).header);
            assert!(source.contains(&format!("#include \"{name}\"\n")));
            // Declarations only: no table is defined in the header, and
            // nothing is static but the players' inline step paths (and,
            // on SDCC's 8051 port, the planner's locals).
            assert!(!header.contains("] = {"), "{header}");
            let allowed = |l: &str| {
                l.starts_with("STEPPER_PROFILES_INLINE ")
                    || l.starts_with("STEPPER_PROFILES_NOINLINE static ")
                    || l.contains("#define STEPPER_PROFILES_INLINE static")
                    || l == "#define STEPPER_PROFILES_LOCAL static"
            };
            assert!(
                header.lines().filter(|l| l.contains("static")).all(allowed),
                "{header}"
            );
            sources.push(source_name);
            header
        }
    };

    let defines = defines(&header, profiles);
    let first = profiles.profiles()[0].name.to_uppercase();
    let first_table = match profiles.profiles()[0].table {
        Generated::Steps(_) => format!("{first}_PERIODS[0]"),
        Generated::Segments(_) => format!("{first}_SEGMENTS[0][0]"),
        // The player, from another file: the single header's definitions
        // are in main.c.
        Generated::Runs(_) => {
            let pre = prefix(profiles);
            format!("{pre}_runs_first()")
        }
        _ => panic!("a layout this test does not know"),
    };
    fs::write(dir.join("main.c"), program(profiles, &defines)).unwrap();
    // A second translation unit: including the header twice in one program
    // must link (`static` tables, or `extern` ones defined once).
    fs::write(
        dir.join("other.c"),
        format!(
            "#include \"{name}\"\n\nunsigned long other_first(void);\n\n{}\
             unsigned long other_first(void)\n{{\n    return {first_table};\n}}\n",
            match profiles.profiles()[0].table {
                Generated::Runs(_) => {
                    let pre = prefix(profiles);
                    format!(
                        "static unsigned long {pre}_runs_first(void)\n{{\n    \
                         {pre}_runs_t r;\n    {pre}_runs_start(&r, {first}_RUNS, 1);\n    \
                         return {pre}_runs_next(&r);\n}}\n\n"
                    )
                }
                _ => String::new(),
            }
        ),
    )
    .unwrap();

    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    let flags = |std: &'static str| {
        let mut f = vec![std];
        f.extend(FLAGS);
        f.extend(DEFINES);
        f
    };
    // C89: the generated files and a user of them compile without a warning.
    for c89 in sources.iter().filter(|s| **s != "main.c") {
        run(
            Command::new(&cc)
                .args(flags("-std=c89"))
                .args(["-c", c89, "-o", "/dev/null"])
                .current_dir(&dir),
            &format!("`{cc} -std=c89 {} -c {c89}`", FLAGS.join(" ")),
        );
    }
    let exe = dir.join("profiles");
    run(
        Command::new(&cc)
            .args(flags("-std=c99"))
            .arg("-o")
            .arg(&exe)
            .args(&sources)
            .current_dir(&dir),
        &format!("`{cc} -std=c99 {}`", FLAGS.join(" ")),
    );
    let stdout = run(&mut Command::new(&exe), "the compiled C program");

    let expected = expected(profiles);
    let mut printed: BTreeMap<String, BTreeMap<String, Figure>> = BTreeMap::new();
    for line in stdout.lines() {
        let fields: Vec<&str> = line.split(' ').collect();
        if let ["other_first", v] = fields[..] {
            let v = Figure::Int(v.parse::<u64>().unwrap());
            let name = &profiles.profiles()[0].name;
            assert_eq!(Some(&v), expected[name].get("first"), "other.c");
            continue;
        }
        let [name, figure, value] = fields[..] else {
            panic!("unexpected line `{line}`");
        };
        let is_float = defines
            .get(name)
            .is_some_and(|d| d.iter().any(|(f, fl)| f == figure && *fl));
        let value = if is_float {
            float(
                value
                    .parse::<f64>()
                    .unwrap_or_else(|e| panic!("`{line}`: {e}")),
            )
        } else if figure == "RELOAD_OFFSET" {
            Figure::Signed(value.parse().unwrap_or_else(|e| panic!("`{line}`: {e}")))
        } else {
            Figure::Int(value.parse().unwrap_or_else(|e| panic!("`{line}`: {e}")))
        };
        printed
            .entry(name.to_string())
            .or_default()
            .insert(figure.to_string(), value);
    }
    assert!(stdout.contains("other_first "), "other.c was not called");

    // Every profile, every figure; the C side has no more and no fewer.
    assert_eq!(
        printed.keys().collect::<Vec<_>>(),
        expected.keys().collect::<Vec<_>>(),
        "profiles in the header"
    );
    for (name, want) in &expected {
        let got = &printed[name];
        for (figure, value) in want {
            assert_eq!(
                got.get(figure),
                Some(value),
                "`{name}` {figure}: C printed {:?}, Rust has {value:?}",
                got.get(figure)
            );
        }
        let extra: Vec<_> = got.keys().filter(|k| !want.contains_key(*k)).collect();
        assert!(extra.is_empty(), "`{name}`: figures not checked: {extra:?}");
        // The figures describe the table: its periods, each stored plus
        // `reload_offset`.
        let offset = got["RELOAD_OFFSET"].int();
        let steps = got.get("steps").unwrap_or(&got["entries"]).int();
        assert_eq!(
            got["sum"].int(),
            got["TOTAL_TICKS"].int() + offset * steps,
            "`{name}`: sum"
        );
        if got.contains_key("FIRST_TICKS") {
            assert_eq!(
                got["first"].int(),
                got["FIRST_TICKS"].int() + offset,
                "`{name}`"
            );
            assert_eq!(
                got["last"].int(),
                got["LAST_TICKS"].int() + offset,
                "`{name}`"
            );
            assert_eq!(got["entries"], got["LEN"], "`{name}`");
        } else if got.contains_key("RUN_COUNT") {
            assert_eq!(got["entries"], got["RUN_COUNT"], "`{name}`");
            assert_eq!(got["steps"], got["LEN"], "`{name}`");
        } else {
            assert_eq!(got["entries"], got["SEGMENT_COUNT"], "`{name}`");
            assert_eq!(got["steps"], got["LEN"], "`{name}`");
        }
    }
    printed
}

#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn the_c_header_compiles_and_matches_the_rust_tables() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("profiles.toml");
    let profiles = Profiles::load(&path).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        profiles
            .c_header()
            .contains("#ifndef STEPPER_PROFILES_PROFILES_H\n")
    );
    let printed = check_header(&profiles, "shipped", &Layout::Single(CStyle::default()));

    // The seeds, through C.
    let orange = &printed["sigmoid_orange"];
    assert_eq!(
        (orange["first"], orange["last"]),
        (Figure::Int(19183), Figure::Int(156))
    );
    assert_eq!(printed["exponential"]["LEN"], Figure::Int(120));
    let linear = &printed["linear_integer"];
    assert_eq!(
        (linear["first"], linear["last"]),
        (Figure::Int(50_000), Figure::Int(5_000))
    );
}

/// 32-bit words: `uint32_t` tables with periods above 65 535.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn u32_tables_in_c() {
    let source = r#"
[defaults]
timer_hz = 10_000_000
word = "u32"

[profiles.slow_linear]
curve = "linear"
fmin = 10
fmax = 1000
len = 100

# 72 s on a 100 MHz timer: 7.3e9 ticks in all, a figure above 32 bits.
[profiles.very_slow]
curve = "linear"
fmin = 1
fmax = 10
len = 400
timer_hz = 100_000_000

[profiles.slow_segments]
curve = "exponential"
fmin = 20
fmax = 1000
f_inf = 1500
len = 300
segments = 6
"#;
    let profiles = Profiles::parse("slow.toml", source).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        profiles
            .c_header()
            .contains("#ifndef STEPPER_PROFILES_SLOW_H\n")
    );
    let printed = check_header(&profiles, "u32", &Layout::Single(CStyle::default()));
    assert_eq!(printed["slow_linear"]["word_bytes"], Figure::Int(4));
    assert!(printed["slow_linear"]["first"] > Figure::Int(65_535));
    assert!(printed["slow_segments"]["first"] > Figure::Int(65_535));
    // Read through `ull` in C99; C89 gets the same value as a double.
    assert!(printed["very_slow"]["TOTAL_TICKS"] > Figure::Int(u64::from(u32::MAX)));
    let header = profiles.c_header();
    assert!(
        header.contains("#else\n#define VERY_SLOW_TOTAL_TICKS "),
        "{header}"
    );
}

/// The split layout: the header declares, one source file defines, in a
/// storage and a linker section of the user's choice.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn split_c_files_define_the_tables_once_where_the_user_places_them() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("profiles.toml");
    let profiles = Profiles::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let style = CStyle {
        storage: Some("ROM".into()),
        attribute: Some("__attribute__((section(\".rodata.ramps\")))".into()),
        ..CStyle::default()
    };
    let files = profiles.c_split("profiles.h", &style);
    assert!(
        files.header.contains(
            "extern const ROM uint16_t SIGMOID_ORANGE_PERIODS[1000] \
             __attribute__((section(\".rodata.ramps\")));\n"
        ),
        "{}",
        files.header
    );
    assert!(
        files.source.contains(
            "const ROM uint16_t SIGMOID_ORANGE_PERIODS[1000] \
             __attribute__((section(\".rodata.ramps\"))) = {\n    19183, "
        ),
        "{}",
        files.source
    );
    let printed = check_header(&profiles, "split", &Layout::Split(style));
    let orange = &printed["sigmoid_orange"];
    assert_eq!(
        (orange["first"], orange["last"]),
        (Figure::Int(19183), Figure::Int(156))
    );
    // Every table sits in the section, once.
    let dir = work_dir_existing("split");
    let object = dir.join("profiles.o");
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    run(
        Command::new(&cc)
            .args(["-std=c99", "-DROM=", "-c", "profiles.c", "-o"])
            .arg(&object)
            .current_dir(&dir),
        "compiling profiles.c",
    );
    let symbols = run(
        Command::new("objdump").arg("-t").arg(&object),
        "`objdump -t` (binutils)",
    );
    for p in profiles.profiles() {
        let upper = p.name.to_uppercase();
        let lines: Vec<&str> = symbols
            .lines()
            .filter(|l| {
                l.ends_with(&format!(" {upper}_PERIODS"))
                    || l.ends_with(&format!(" {upper}_SEGMENTS"))
                    || l.ends_with(&format!(" {upper}_RUNS"))
            })
            .collect();
        assert_eq!(lines.len(), 1, "{upper}: {symbols}");
        assert!(lines[0].contains(".rodata.ramps"), "{}", lines[0]);
    }
}

/// Text pasted into C must stay one declaration.
#[test]
fn a_placement_that_would_break_the_c_is_refused() {
    let profiles = Profiles::parse(
        "p.toml",
        "[profiles.a]\ncurve = \"linear\"\nfmin = 100\nfmax = 1000\nlen = 10\ntimer_hz = 1_000_000\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let dir = work_dir("refused");
    let bad = CStyle {
        storage: None,
        attribute: Some("PROGMEM; int x".into()),
        ..CStyle::default()
    };
    let err = profiles.write_c_split(dir.join("p.h"), &bad).unwrap_err();
    assert_eq!(
        err.to_string(),
        "the C `attribute` cannot hold `;`: give words such as `PROGMEM`, or \
         `__attribute__((...))` with balanced parentheses (got `PROGMEM; int x`)"
    );
    let blank = CStyle {
        storage: Some(" ".into()),
        attribute: None,
        ..CStyle::default()
    };
    assert_eq!(
        profiles
            .write_c_split(dir.join("p.h"), &blank)
            .unwrap_err()
            .to_string(),
        "the C `storage` is blank: give a word that qualifies the element type, such as \
         `__code` or `__flash`"
    );
    assert!(!dir.join("p.h").exists());
}

/// What `CStyle::check` accepts compiles: storage words (`volatile`, and
/// `ROM`, a macro standing in for `__code`) before the element type and on
/// the run player's pointers; attributes with nested parentheses, strings
/// and commas, or a macro taking an argument, after the name. In one
/// header and split, C89 and C99, with the run player.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn accepted_placements_compile() {
    let source = r#"
[defaults]
timer_hz = 1_000_000
curve = "linear"
fmin = 500
fmax = 5000

[profiles.runs]
len = 300
compress = 1

[profiles.steps]
len = 50

[profiles.segments]
len = 300
segments = 4
"#;
    let profiles = Profiles::parse("ramps.toml", source).unwrap_or_else(|e| panic!("{e}"));
    for (i, (storage, attribute)) in [
        (
            Some("ROM volatile"),
            Some("__attribute__((section(\".ramps\"), aligned(4)))"),
        ),
        (
            Some("volatile"),
            Some("__attribute__ ((aligned (8))) __attribute__((unused))"),
        ),
        (None, Some("ALIGNED(2)")),
        (Some("ROM"), None),
    ]
    .into_iter()
    .enumerate()
    {
        let style = CStyle {
            storage: storage.map(String::from),
            attribute: attribute.map(String::from),
            ..CStyle::default()
        };
        style.check().unwrap_or_else(|e| panic!("{e}"));
        for (name, layout) in [
            ("single", Layout::Single(style.clone())),
            ("split", Layout::Split(style.clone())),
        ] {
            let printed = check_header(&profiles, &format!("placement_{i}_{name}"), &layout);
            assert_eq!(printed["runs"]["steps"], Figure::Int(300));
        }
    }
}

/// One axis's profiles: a compressed ramp and a per-step table, named
/// after the axis (`x_runs`, `x_steps`).
fn axis(name: &str) -> String {
    format!(
        "[defaults]\ntimer_hz = 1_000_000\ncurve = \"linear\"\nfmin = 500\nfmax = 5000\n\n\
         [profiles.{name}_runs]\nlen = 300\ncompress = 1\n\n[profiles.{name}_steps]\nlen = 50\n"
    )
}

/// Two headers from two files of the same name (`a/profiles.toml`,
/// `b/profiles.toml`) in one translation unit: each is named after its
/// own file (`x_axis.h`: the guard `STEPPER_PROFILES_X_AXIS_H`, the player
/// `x_axis_runs_*`, `X_AXIS_RUNS_READ`), so neither is dropped as the
/// other's guard and the program uses both tables and both run players;
/// the one whose tables are in program memory reads them with
/// `pgm_read_word` (counted by a host's stand-in), the other with a load.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn two_headers_in_one_translation_unit() {
    let x = Profiles::parse("a/profiles.toml", &axis("x")).unwrap_or_else(|e| panic!("{e}"));
    let y = Profiles::parse("b/profiles.toml", &axis("y")).unwrap_or_else(|e| panic!("{e}"));
    let progmem = CStyle {
        attribute: Some("PROGMEM".into()),
        ..CStyle::default()
    };
    let main = "#include <stdio.h>\n\
        #define STEPPER_PROFILES_X_AXIS_IMPLEMENTATION\n\
        #define STEPPER_PROFILES_Y_AXIS_IMPLEMENTATION\n\
        #include \"x_axis.h\"\n#include \"y_axis.h\"\n#include \"x_axis.h\"\n\n\
        unsigned long pgm_reads = 0;\n\n\
        int main(void)\n{\n    \
            x_axis_runs_t x;\n    y_axis_runs_t y;\n    uint16_t q;\n    \
            unsigned long n = 0, sum = 0, reads;\n\n    \
            x_axis_runs_start(&x, X_RUNS_RUNS, (uint16_t)X_RUNS_RUN_COUNT);\n    \
            while ((q = x_axis_runs_next(&x)) != 0) {\n        n++;\n        sum += q;\n    }\n    \
            printf(\"x_runs %lu %lu %lu\\n\", n, sum, pgm_reads);\n    \
            reads = pgm_reads;\n    n = 0;\n    sum = 0;\n    \
            y_axis_runs_start(&y, Y_RUNS_RUNS, (uint16_t)Y_RUNS_RUN_COUNT);\n    \
            while ((q = y_axis_runs_next(&y)) != 0) {\n        n++;\n        sum += q;\n    }\n    \
            printf(\"y_runs %lu %lu %lu\\n\", n, sum, pgm_reads - reads);\n    \
            printf(\"x_steps %lu %lu\\n\", (unsigned long)X_STEPS_PERIODS[0], \
                   (unsigned long)X_STEPS_LEN);\n    \
            printf(\"y_steps %lu %lu\\n\", (unsigned long)Y_STEPS_PERIODS[0], \
                   (unsigned long)Y_STEPS_LEN);\n    \
            return 0;\n}\n";
    // avr-libc's program memory as a host stands in for it: reads counted.
    let pgmspace = "#include <stdint.h>\n#define PROGMEM\nextern unsigned long pgm_reads;\n\
                    #define pgm_read_word(p) (pgm_reads++, *(p))\n";
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    for (layout, y_style) in [("single", None), ("split", Some(&progmem))] {
        let dir = work_dir(&format!("two_headers_{layout}"));
        fs::create_dir(dir.join("avr")).unwrap();
        fs::write(dir.join("avr/pgmspace.h"), pgmspace).unwrap();
        fs::write(dir.join("main.c"), main).unwrap();
        let mut sources = vec!["main.c"];
        match y_style {
            None => {
                x.write_c_header(dir.join("x_axis.h")).unwrap();
                y.write_c_header(dir.join("y_axis.h")).unwrap();
            }
            Some(style) => {
                x.write_c_split(dir.join("x_axis.h"), &CStyle::default())
                    .unwrap();
                y.write_c_split(dir.join("y_axis.h"), style).unwrap();
                sources.extend(["x_axis.c", "y_axis.c"]);
            }
        }
        let header = fs::read_to_string(dir.join("x_axis.h")).unwrap();
        assert!(
            header.contains("#ifndef STEPPER_PROFILES_X_AXIS_H\n")
                && header.contains("x_axis_runs_t"),
            "{header}"
        );
        for std in ["-std=c89", "-std=c99"] {
            let exe = dir.join(format!("axes{std}"));
            run(
                Command::new(&cc)
                    .arg(std)
                    .args(FLAGS)
                    .args(["-I", "."])
                    .arg("-o")
                    .arg(&exe)
                    .args(&sources)
                    .current_dir(&dir),
                &format!("`{cc} {std} {}` of two headers", FLAGS.join(" ")),
            );
            let printed = run(&mut Command::new(&exe), "the program of two headers");
            let mut want = String::new();
            for (profiles, reads) in [(&x, 0), (&y, y_style.map_or(0, |_| 5))] {
                let [runs, steps] = profiles.profiles() else {
                    panic!("two profiles");
                };
                let (Generated::Runs(r), Generated::Steps(t)) = (&runs.table, &steps.table) else {
                    panic!("runs, then one entry per step");
                };
                let periods = runs.table.step_periods();
                let _ = writeln!(
                    want,
                    "{} {} {} {}",
                    runs.name,
                    periods.len(),
                    periods.iter().map(|&p| u64::from(p)).sum::<u64>(),
                    reads * r.runs.len()
                );
                let _ = write!(
                    want,
                    "{}",
                    format_args!("{} {} {}\n", steps.name, t.periods[0], t.periods.len())
                );
            }
            // In the program's order: both players, then both tables.
            let mut lines: Vec<&str> = want.lines().collect();
            lines.swap(1, 2);
            assert_eq!(printed, lines.join("\n") + "\n", "{layout} {std}");
        }
    }
}

/// The split files are written both or neither: a source that cannot be
/// written leaves no header behind.
#[test]
fn split_files_are_written_both_or_neither() {
    let profiles = Profiles::parse(
        "p.toml",
        "[profiles.a]\ncurve = \"linear\"\nfmin = 100\nfmax = 1000\nlen = 10\ntimer_hz = 1_000_000\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let dir = work_dir("both_or_neither");
    fs::create_dir(dir.join("p.c")).unwrap();
    let err = profiles
        .write_c_split(dir.join("p.h"), &CStyle::default())
        .unwrap_err();
    assert_eq!(
        err.to_string(),
        format!(
            "cannot write `{}`: it is a folder",
            dir.join("p.c").display()
        )
    );
    let left: Vec<_> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["p.c"]);
    fs::remove_dir(dir.join("p.c")).unwrap();
    let (h, c) = profiles
        .write_c_split(dir.join("p.h"), &CStyle::default())
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(h.is_file() && c.is_file());
    assert_eq!(fs::read_dir(&dir).unwrap().count(), 2);
}

/// Compressed ramps in C: the runs and the header's player, which plays
/// them period for period as `runs::Expand` (compared through every
/// period's sum and an order-sensitive checksum), as one header and split.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn compressed_runs_play_in_c_as_in_rust() {
    let source = r#"
[defaults]
timer_hz = "10 MHz"

# 1/16 microsteps, 100 to 3000 full steps/s at 10 000 full steps/s².
[profiles.microstep]
curve = "linear"
fmin = "1.6 kHz"
fmax = "48 kHz"
accel = 160_000
compress = 1

[profiles.s_curve]
curve = "sigmoid"
fmin = 500
fmax = "64 kHz"
flexible = 8
len = 1000
compress = 0.5

[profiles.per_step]
curve = "linear"
fmin = 500
fmax = 5000
len = 100
"#;
    let profiles = Profiles::parse("ramps.toml", source).unwrap_or_else(|e| panic!("{e}"));
    let Generated::Runs(micro) = &profiles.profiles()[0].table else {
        panic!("a compressed table");
    };
    assert!(micro.figures.steps > 7000 && micro.figures.max_edge_error_ticks <= 1.0);
    // A storage word the player's pointers must carry as well: `volatile`
    // stands in for a named address space (`__flash`, `__code`), which gcc
    // on the host lacks; a pointer without it is an error under `-Werror`.
    let storage = CStyle {
        storage: Some("volatile".into()),
        attribute: None,
        ..CStyle::default()
    };
    for (dir, layout) in [
        ("runs_single", Layout::Single(CStyle::default())),
        ("runs_split", Layout::Split(CStyle::default())),
        ("runs_storage", Layout::Split(storage)),
    ] {
        let printed = check_header(&profiles, dir, &layout);
        assert_eq!(
            printed["microstep"]["steps"],
            Figure::Int(u64::from(micro.figures.steps))
        );
    }
}

/// A header named after a file whose name is no C identifier (the
/// profiles file's, or its own) still gives a player whose names are
/// identifiers C leaves to programs: no leading digit, no leading or double
/// `_`; the C compiles and plays as with any other name.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn run_players_of_files_named_like_no_identifier() {
    let source = r#"
[profiles.ramp]
curve = "linear"
fmin = 500
fmax = 5000
len = 300
timer_hz = 1_000_000
compress = 1
"#;
    for (file, dir, expected) in [
        (
            "3d_printer.toml",
            "runs_digit",
            "profiles_3d_printer_runs_start",
        ),
        ("é.toml", "runs_accent", "profiles_runs_start"),
        ("__.toml", "runs_underscores", "profiles_runs_start"),
        ("x--y_.toml", "runs_dashes", "x_y_runs_start"),
    ] {
        let profiles = Profiles::parse(file, source).unwrap_or_else(|e| panic!("{e}"));
        let split = profiles.c_split(&header_name(&profiles), &CStyle::default());
        assert!(split.header.contains(expected), "{}", split.header);
        assert!(profiles.c_header().contains(expected));
        // Named after the file it is written to, whatever the profiles file.
        let named = Profiles::parse("profiles.toml", source).unwrap_or_else(|e| panic!("{e}"));
        let name = header_name(&profiles);
        assert!(
            named
                .c_header_named(&name, &CStyle::default())
                .contains(expected)
        );
        assert!(
            named
                .c_split(&name, &CStyle::default())
                .header
                .contains(expected)
        );
        for layout in [
            Layout::Single(CStyle::default()),
            Layout::Split(CStyle::default()),
        ] {
            let printed = check_header(&profiles, dir, &layout);
            assert_eq!(printed["ramp"]["steps"], Figure::Int(300));
        }
    }
}

/// Tables in avr-libc's program memory (`PROGMEM`) cannot be read by a
/// plain load: the header brings `PROGMEM` in and the run player reads with
/// `pgm_read_word`, unless the user defines `RAMPS_RUNS_READ` (this
/// header's) or `STEPPER_RUNS_READ` (every header's) first.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn progmem_tables_are_read_from_program_memory() {
    let source = "[profiles.ramp]\ncurve = \"linear\"\nfmin = 500\nfmax = 5000\n\
                  len = 100\ntimer_hz = 1_000_000\ncompress = 1\n";
    let profiles = Profiles::parse("ramps.toml", source).unwrap_or_else(|e| panic!("{e}"));
    let style = CStyle {
        storage: None,
        attribute: Some("PROGMEM".into()),
        ..CStyle::default()
    };
    let files = profiles.c_split("ramps.h", &style);
    assert!(
        files
            .header
            .contains("#include <stdint.h>\n\n#include <avr/pgmspace.h>\n"),
        "{}",
        files.header
    );
    assert!(
        files.header.contains(
            "#ifndef RAMPS_RUNS_READ\n#ifdef STEPPER_RUNS_READ\n\
             #define RAMPS_RUNS_READ(p) STEPPER_RUNS_READ(p)\n#else\n\
             #define RAMPS_RUNS_READ(p) pgm_read_word(p)\n#endif\n#endif\n"
        ),
        "{}",
        files.header
    );
    assert!(
        files
            .source
            .contains("const uint16_t RAMP_RUNS[15][5] PROGMEM = {"),
        "{}",
        files.source
    );
    // Elsewhere, a plain load; `PROGMEM` only as a word of its own.
    for attribute in ["__attribute__((section(\".ramps\")))", "NOT_PROGMEM_AT_ALL"] {
        let style = CStyle {
            storage: None,
            attribute: Some(attribute.into()),
            ..CStyle::default()
        };
        let header = profiles.c_split("ramps.h", &style).header;
        assert!(!header.contains("pgmspace"), "{header}");
        assert!(
            header.contains("#else\n#define RAMPS_RUNS_READ(p) (*(p))\n#endif\n"),
            "{header}"
        );
    }
}

/// `reload_offset`: every table holds its periods plus the offset (the C
/// run player plays each period plus it), every figure is the periods',
/// and the header says the offset; one header and split.
#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn reload_offset_tables_hold_the_register_values() {
    let source = r#"
[defaults]
timer_hz = "1 MHz"
reload_offset = -1

[profiles.arr]
curve = "linear"
fmin = 500
fmax = 5000
len = 100

[profiles.wide]
curve = "linear"
fmin = 10
fmax = 1000
len = 50
word = "u32"
reload_offset = 2

[profiles.pieces]
curve = "exponential"
fmin = 200
fmax = 2000
f_inf = 2500
len = 300
segments = 6

[profiles.runs]
curve = "linear"
fmin = 500
fmax = 20000
accel = 200000
compress = 1
"#;
    let profiles = Profiles::parse("arr.toml", source).unwrap_or_else(|e| panic!("{e}"));
    let plain = Profiles::parse(
        "arr.toml",
        &source.replace("reload_offset", "# reload_offset"),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    for (dir, layout) in [
        ("offset_single", Layout::Single(CStyle::default())),
        ("offset_split", Layout::Split(CStyle::default())),
    ] {
        let printed = check_header(&profiles, dir, &layout);
        // Against the tables without the offset, computed on their own.
        for (p, q) in profiles.profiles().iter().zip(plain.profiles()) {
            let got = &printed[&p.name];
            let offset = i128::from(p.table.spec().reload_offset);
            let periods = q.table.step_periods();
            assert_eq!(
                got["TOTAL_TICKS"].int(),
                periods.iter().map(|&t| i128::from(t)).sum::<i128>(),
                "{}",
                p.name
            );
            let first = match &q.table {
                Generated::Segments(t) => t.pairs[0].0,
                _ => periods[0],
            };
            assert_eq!(got["first"].int(), i128::from(first) + offset, "{}", p.name);
        }
    }
    assert_eq!(
        printed_offsets(&profiles.c_header()),
        [
            "ARR_RELOAD_OFFSET (-1)",
            "WIDE_RELOAD_OFFSET 2",
            "PIECES_RELOAD_OFFSET (-1)",
            "RUNS_RELOAD_OFFSET (-1)"
        ]
    );
}

/// The header's `#define NAME_RELOAD_OFFSET` lines, without `#define `.
fn printed_offsets(header: &str) -> Vec<&str> {
    header
        .lines()
        .filter_map(|l| l.strip_prefix("#define "))
        .filter(|l| l.contains("_RELOAD_OFFSET "))
        .collect()
}
