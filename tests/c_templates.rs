//! The C players' sources, as the files in `profile-codegen/src/emit/c/player/`
//! hold them, compile on their own: each player's files in the order the
//! header emits them, with their placeholders (`tpl`, `TPL_WORD`,
//! `TPL_STORAGE `, `TPL_READ`) defined as a header fills them, by the C
//! compiler (`CC`, or `cc`) as C89 with `-pedantic -Wall -Wextra -Werror`,
//! unoptimised and at `-O2` (where more is analysed).

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The folder of the players' C.
fn sources() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("profile-codegen/src/emit/c/player")
}

/// One player: its name, the period's type, and its files in the order the
/// header holds them (the API, then the definitions).
struct Player {
    name: &'static str,
    word: &'static str,
    files: &'static [&'static str],
}

/// The per-step players' files, for either word.
const STEP_FILES: &[&str] = &[
    "steps.h",
    "axis.h",
    "steps.c",
    "plan.c",
    "steps_init.c",
    "axis.c",
];

const PLAYERS: &[Player] = &[
    Player {
        name: "player",
        word: "uint16_t",
        files: STEP_FILES,
    },
    Player {
        name: "player32",
        word: "uint32_t",
        files: STEP_FILES,
    },
    Player {
        name: "runs_player",
        word: "uint16_t",
        files: &[
            "runs.h",
            "axis.h",
            "runs_refill.c",
            "cursor.c",
            "runs.c",
            "plan.c",
            "runs_init.c",
            "axis.c",
        ],
    },
];

/// A translation unit of `player`'s files, included from where they are.
fn unit(player: &Player, storage: &str) -> String {
    let mut c = format!(
        "#include <stdint.h>\n#define TPL_WORD {}\n#define TPL_STORAGE {storage}\n\
         #define TPL_READ(p) (*(p))\n#include \"portability.h\"\n",
        player.word
    );
    for file in player.files {
        c.push_str(&format!("#include \"{file}\"\n"));
    }
    c
}

#[test]
#[ignore = "slow: compiles C with the C compiler; CI runs it with --ignored"]
fn the_players_c_compiles_on_its_own_as_c89() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("c_templates");
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    let mut compiled = 0;
    for player in PLAYERS {
        // Tables in RAM, and behind a qualifier where a header puts its
        // storage word (`__code`, `__flash`).
        for (tag, storage) in [("ram", ""), ("rom", "volatile")] {
            let path = dir.join(format!("{}_{tag}.c", player.name));
            fs::write(&path, unit(player, storage)).unwrap();
            for opt in ["-O0", "-O2"] {
                let out = Command::new(&cc)
                    .args(["-std=c89", "-pedantic", "-Wall", "-Wextra", "-Werror", opt])
                    .arg("-I")
                    .arg(sources())
                    .arg("-c")
                    .arg(&path)
                    .arg("-o")
                    .arg(dir.join(format!("{}_{tag}{opt}.o", player.name)))
                    .output()
                    .unwrap_or_else(|e| panic!("`{cc}` could not run: {e}"));
                assert!(
                    out.status.success(),
                    "{} ({tag}, {opt}): {}",
                    player.name,
                    String::from_utf8_lossy(&out.stderr)
                );
                compiled += 1;
            }
        }
    }
    assert_eq!(compiled, 12);
}

/// Every C file in the folder is one some player is made of, and holds
/// none of the placeholders' old spellings.
#[test]
fn every_c_file_belongs_to_a_player() {
    let mut files: Vec<String> = fs::read_dir(sources())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| f.ends_with(".c") || f.ends_with(".h"))
        .collect();
    files.sort();
    let mut used: Vec<String> = PLAYERS
        .iter()
        .flat_map(|p| p.files.iter().map(|f| f.to_string()))
        .chain(["portability.h".to_string()])
        .collect();
    used.sort();
    used.dedup();
    assert_eq!(files, used);
    for file in &files {
        let text = fs::read_to_string(sources().join(file)).unwrap();
        assert!(
            !text.contains('@'),
            "{file}: a placeholder C does not compile"
        );
    }
}
