//! The C the `header` command writes: what `--storage` and `--attribute`
//! accept, and the names a header takes from its file or `--prefix`.

mod common;

use common::{run, text};
use std::fs;
use std::path::PathBuf;

fn work_dir(name: &str) -> PathBuf {
    common::work_dir("c_output", name)
}

/// A per-step table and a compressed one, whose run player's pointers
/// carry the storage word too.
const RAMPS: &str = "[defaults]\ntimer_hz = 1_000_000\ncurve = \"linear\"\nfmin = 500\n\
     fmax = 5000\n\n[profiles.steps]\nlen = 50\n\n[profiles.runs]\nlen = 300\ncompress = 1\n";

/// What each option expects, as its messages say.
const STORAGE: &str = "give words that qualify the element type, such as `__code` or `__flash`";
const ATTRIBUTE: &str =
    "give words such as `PROGMEM`, or `__attribute__((...))` with balanced parentheses";

/// Text that would break the C is refused, naming the option and saying
/// what it takes; nothing is written.
#[test]
fn storage_and_attribute_refuse_what_breaks_the_c() {
    let dir = work_dir("refused");
    fs::write(dir.join("ramps.toml"), RAMPS).unwrap();
    let mut cases: Vec<(&str, &str, String)> = Vec::new();
    for (option, expected) in [("--storage", STORAGE), ("--attribute", ATTRIBUTE)] {
        for (value, token) in [
            ("/*", "/*"),
            ("*/", "*/"),
            ("//", "//"),
            ("\\", "\\"),
            ("{", "{"),
        ] {
            cases.push((
                option,
                value,
                format!("`{option}` cannot hold `{token}`: {expected}"),
            ));
        }
        cases.push((
            option,
            "#define X",
            format!("`{option}` cannot hold `#define`: {expected} (got `#define X`)"),
        ));
        cases.push((
            option,
            "= {0}",
            format!("`{option}` cannot hold `=`: {expected} (got `= {{0}}`)"),
        ));
        cases.push((
            option,
            "PROGMEM; int x",
            format!("`{option}` cannot hold `;`: {expected} (got `PROGMEM; int x`)"),
        ));
        cases.push((
            option,
            "X\n#define Y",
            format!("`{option}` cannot hold `\\n#define`: {expected} (got `X\\n#define Y`)"),
        ));
    }
    cases.extend([
        (
            "--storage",
            "const",
            "`--storage` cannot hold `const`: the tables are `const` already; give words that \
             qualify the element type, such as `__code` or `__flash`"
                .to_string(),
        ),
        (
            "--storage",
            "__code const",
            "`--storage` cannot hold `const`: the tables are `const` already; give words that \
             qualify the element type, such as `__code` or `__flash`"
                .to_string(),
        ),
        (
            "--storage",
            "static",
            "`--storage` cannot hold `static`: the header gives the tables their storage class \
             (`static const` in one header, `extern const` in a split one)"
                .to_string(),
        ),
        (
            "--storage",
            "int",
            "`--storage` cannot hold `int`: the element type is the table's word (`uint16_t` or \
             `uint32_t`)"
                .to_string(),
        ),
        (
            "--storage",
            "__attribute__((aligned(4)))",
            "`--storage` cannot hold `__attribute__`: an attribute goes after the array's name; \
             give words that qualify the element type, such as `__code` or `__flash`"
                .to_string(),
        ),
        (
            "--storage",
            "_Alignas(4)",
            format!(
                "`--storage` cannot hold `_Alignas`: a C keyword that does not qualify the \
                 element type; {STORAGE}"
            ),
        ),
        (
            "--storage",
            " ",
            "`--storage` is blank: give a word that qualifies the element type, such as `__code` \
             or `__flash`"
                .to_string(),
        ),
        (
            "--attribute",
            " ",
            "`--attribute` is blank: give a word such as `PROGMEM`, or `__attribute__((...))`"
                .to_string(),
        ),
        (
            "--attribute",
            "const",
            "`--attribute` cannot hold `const`: a C keyword cannot follow the array's name; give \
             words such as `PROGMEM`, or `__attribute__((...))` with balanced parentheses"
                .to_string(),
        ),
        (
            "--attribute",
            "__attribute__((section(\".ramps\"))",
            format!(
                "`--attribute` has unbalanced parentheses: {ATTRIBUTE} \
                 (got `__attribute__((section(\".ramps\"))`)"
            ),
        ),
        (
            "--attribute",
            "__attribute__((used)))",
            format!(
                "`--attribute` has unbalanced parentheses: {ATTRIBUTE} \
                 (got `__attribute__((used)))`)"
            ),
        ),
        (
            "--attribute",
            "(used)",
            format!("`--attribute` cannot hold `(used)`: {ATTRIBUTE}"),
        ),
        (
            "--attribute",
            "__attribute__((section(\".a\\\"b\")))",
            format!(
                "`--attribute` cannot hold `\\\"b\")))`: {ATTRIBUTE} \
                 (got `__attribute__((section(\".a\\\"b\")))`)"
            ),
        ),
    ]);
    for (option, value, message) in &cases {
        for args in [
            &["header", "ramps.toml", option, value][..],
            &[
                "header",
                "ramps.toml",
                "-o",
                "ramps.h",
                "--split",
                option,
                value,
            ],
        ] {
            let out = run(&dir, args);
            assert_eq!(out.status.code(), Some(1), "{args:?}");
            assert_eq!(text(&out.stderr), format!("{message}\n"), "{args:?}");
            assert_eq!(text(&out.stdout), "", "{args:?}");
        }
    }
    assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
}

/// What a declaration holds there is written as given.
#[test]
fn storage_and_attribute_take_what_a_declaration_holds() {
    let dir = work_dir("accepted");
    fs::write(dir.join("ramps.toml"), RAMPS).unwrap();
    for (storage, attribute, declaration) in [
        (
            "__code",
            "PROGMEM",
            "static const __code uint16_t STEPS_PERIODS[50] PROGMEM = {",
        ),
        (
            "__far  __xdata",
            "__attribute__((section(\".ramps\"), aligned(4)))",
            "static const __far  __xdata uint16_t STEPS_PERIODS[50] \
             __attribute__((section(\".ramps\"), aligned(4))) = {",
        ),
        (
            "__flash",
            "__attribute__ ((aligned (8))) __ALIGNED(2)",
            "static const __flash uint16_t STEPS_PERIODS[50] \
             __attribute__ ((aligned (8))) __ALIGNED(2) = {",
        ),
        (
            "volatile",
            "__attribute__((used))",
            "static const volatile uint16_t STEPS_PERIODS[50] __attribute__((used)) = {",
        ),
    ] {
        let out = run(
            &dir,
            &[
                "header",
                "ramps.toml",
                "--storage",
                storage,
                "--attribute",
                attribute,
            ],
        );
        assert!(out.status.success(), "{}", text(&out.stderr));
        let header = text(&out.stdout);
        assert!(header.contains(declaration), "{header}");
    }
}

/// Two files of the same name give headers named after where they are
/// written, or after `--prefix`: a guard, a run player and a read macro of
/// their own, so that one C file can include both.
#[test]
fn a_header_is_named_after_its_file_or_its_prefix() {
    let dir = work_dir("names");
    for axis in ["a", "b"] {
        fs::create_dir(dir.join(axis)).unwrap();
        fs::write(dir.join(axis).join("profiles.toml"), RAMPS).unwrap();
    }
    let names = |stem: &str, prefix: &str| {
        let upper = stem.to_uppercase();
        [
            format!("#ifndef STEPPER_PROFILES_{upper}_H\n#define STEPPER_PROFILES_{upper}_H\n"),
            format!("#ifndef {}_RUNS_READ\n", prefix.to_uppercase()),
            format!("}} {prefix}_runs_t;\n"),
            format!("void {prefix}_runs_start({prefix}_runs_t *p, "),
            format!("uint16_t {prefix}_runs_next({prefix}_runs_t *p);\n"),
        ]
    };
    for (args, file, stem, prefix) in [
        (
            &["header", "a/profiles.toml", "-o", "x_axis.h"][..],
            "x_axis.h",
            "X_AXIS",
            "x_axis",
        ),
        (
            &["header", "b/profiles.toml", "-o", "out/y-axis.h", "--split"],
            "out/y-axis.h",
            "Y_AXIS",
            "y_axis",
        ),
        (
            &["header", "a/profiles.toml", "-o", "z.h", "--prefix", "Left"],
            "z.h",
            "LEFT",
            "Left",
        ),
        (
            &["header", "b/profiles.toml", "-o", "3d.h"],
            "3d.h",
            "3D",
            "profiles_3d",
        ),
    ] {
        let out = run(&dir, args);
        assert!(out.status.success(), "{}", text(&out.stderr));
        let header = fs::read_to_string(dir.join(file)).unwrap();
        for name in names(stem, prefix) {
            assert!(header.contains(&name), "{args:?}: {name}\n{header}");
        }
        assert!(!header.contains("PROFILES_PROFILES"), "{header}");
    }
    let implementation = "#ifdef STEPPER_PROFILES_X_AXIS_IMPLEMENTATION\n";
    assert!(
        fs::read_to_string(dir.join("x_axis.h"))
            .unwrap()
            .contains(implementation)
    );
    let source = fs::read_to_string(dir.join("out/y-axis.c")).unwrap();
    assert!(source.contains("#include \"y-axis.h\"\n"), "{source}");
    // Without a file, the profiles file names it, unless `--prefix` does.
    for (args, stem, prefix) in [
        (&["header", "a/profiles.toml"][..], "PROFILES", "profiles"),
        (
            &["header", "a/profiles.toml", "--prefix", "motor_x"],
            "MOTOR_X",
            "motor_x",
        ),
    ] {
        let out = run(&dir, args);
        assert!(out.status.success(), "{}", text(&out.stderr));
        let header = text(&out.stdout);
        for name in names(stem, prefix) {
            assert!(header.contains(&name), "{args:?}: {name}\n{header}");
        }
    }
}

#[test]
fn a_prefix_must_be_a_c_identifier() {
    let dir = work_dir("prefix_refused");
    fs::write(dir.join("ramps.toml"), RAMPS).unwrap();
    let expected = "a letter, then letters, digits or `_`, such as `x_axis`";
    for (prefix, message) in [
        (
            "3d",
            format!("`--prefix` must be a C identifier, {expected} (got `3d`)"),
        ),
        (
            "_x",
            format!("`--prefix` must be a C identifier, {expected} (got `_x`)"),
        ),
        (
            "x-y",
            format!("`--prefix` must be a C identifier, {expected} (got `x-y`)"),
        ),
        (
            "x y",
            format!("`--prefix` must be a C identifier, {expected} (got `x y`)"),
        ),
        (
            "é",
            format!("`--prefix` must be a C identifier, {expected} (got `é`)"),
        ),
        (
            "/*",
            format!("`--prefix` must be a C identifier, {expected} (got `/*`)"),
        ),
        (
            "x\n",
            format!("`--prefix` must be a C identifier, {expected} (got `x\\n`)"),
        ),
        (
            "",
            "`--prefix` is blank: give a C identifier such as `x_axis`".to_string(),
        ),
    ] {
        for args in [
            &["header", "ramps.toml", "--prefix", prefix][..],
            &[
                "header",
                "ramps.toml",
                "-o",
                "r.h",
                "--split",
                "--prefix",
                prefix,
            ],
        ] {
            let out = run(&dir, args);
            assert_eq!(out.status.code(), Some(1), "{args:?}");
            assert_eq!(text(&out.stderr), format!("{message}\n"), "{args:?}");
        }
    }
    assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
}

/// `reload_offset`: the header's tables hold each period plus the offset,
/// its figures are the periods', and it says the offset; against the same
/// file without the offset.
#[test]
fn a_header_of_register_values() {
    let dir = work_dir("reload_offset");
    let arr = RAMPS.replace("[defaults]\n", "[defaults]\nreload_offset = -1\n");
    fs::write(dir.join("plain.toml"), RAMPS).unwrap();
    fs::write(dir.join("arr.toml"), arr).unwrap();
    for name in ["plain", "arr"] {
        let out = run(
            &dir,
            &[
                "header",
                &format!("{name}.toml"),
                "-o",
                &format!("{name}.h"),
            ],
        );
        assert!(out.status.success(), "{}", text(&out.stderr));
    }
    let (plain, arr) = (
        fs::read_to_string(dir.join("plain.h")).unwrap(),
        fs::read_to_string(dir.join("arr.h")).unwrap(),
    );
    let table = |h: &str| -> Vec<i64> {
        let start = h.find("STEPS_PERIODS[50] = {").unwrap();
        let body = &h[start..h[start..].find("};").unwrap() + start];
        body.split(['{', ','])
            .skip(1)
            .filter_map(|v| v.trim().parse().ok())
            .collect()
    };
    let (p, a) = (table(&plain), table(&arr));
    assert_eq!(p.len(), 50);
    assert_eq!(a, p.iter().map(|v| v - 1).collect::<Vec<_>>());
    let define = |h: &str, name: &str| -> String {
        let line = h
            .lines()
            .find(|l| l.starts_with(&format!("#define {name} ")))
            .unwrap_or_else(|| panic!("no {name}"));
        line[name.len() + 9..].to_string()
    };
    assert_eq!(define(&arr, "STEPS_RELOAD_OFFSET"), "(-1)");
    assert_eq!(define(&plain, "STEPS_RELOAD_OFFSET"), "0");
    for figure in ["STEPS_TOTAL_TICKS", "STEPS_FIRST_TICKS", "RUNS_TOTAL_TICKS"] {
        assert_eq!(define(&arr, figure), define(&plain, figure), "{figure}");
    }
    let total: i64 = p.iter().sum();
    assert_eq!(define(&arr, "STEPS_TOTAL_TICKS"), format!("{total}ul"));
    assert!(arr.contains(" *   reload_offset = -1\n"), "{arr}");
}
