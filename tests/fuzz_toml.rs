//! Fuzzing of the TOML front door without nightly: random bytes, and valid
//! files mutated at random (deletions, duplications, insertions of TOML
//! syntax and hostile values), fed to `Profiles::parse`. It must return
//! profiles or an error, never panic; an error must render with a location.
//!
//! `FUZZ_CASES` sets the number of cases (default 1000; CI runs 20 000 from
//! an optimised build); the count run is printed (`cargo test --test
//! fuzz_toml -- --nocapture`).

use std::panic::{AssertUnwindSafe, catch_unwind};

use profile_codegen::profiles::Profiles;

/// xorshift64*: deterministic, so a failure names a reproducible case.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// TOML syntax, values and names; the keys come from the schema's list.
const PIECES: &[&str] = &[
    "=",
    "\"",
    "'",
    "[",
    "]",
    "[[",
    "]]",
    ".",
    ",",
    "\n",
    "#",
    "-",
    "+",
    "_",
    "{",
    "}",
    " ",
    "nan",
    "inf",
    "-inf",
    "1e999",
    "0",
    "-1",
    "0.5",
    "65537",
    "4294967296",
    "true",
    "1979-05-27",
    "\"sigmoid\"",
    "\"linear\"",
    "\"exponential\"",
    "\"three_stage\"",
    "\"jerk_limited\"",
    "\"index\"",
    "\"integer\"",
    "\"f32\"",
    "\"u32\"",
    "[profiles.x]",
    "[defaults]",
    "[profiles]",
    "é",
    "\u{0}",
    "\r\n",
    "\t",
    "[motors.m]",
    "motor = \"m\"",
    "[[0, 0.4], [1000, 0.3]]",
    "[[1000, 0.3], [0, 0.4]]",
    "[[0]]",
];

fn seeds() -> Vec<String> {
    let root = env!("CARGO_MANIFEST_DIR");
    let mut files = vec![std::fs::read_to_string(format!("{root}/profiles.toml")).unwrap()];
    if let Ok(dir) = std::fs::read_dir(format!("{root}/tests/toml_errors")) {
        let mut paths: Vec<_> = dir
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        paths.sort();
        files.extend(paths.iter().filter_map(|p| std::fs::read_to_string(p).ok()));
    }
    files
}

/// Every key, then the other pieces.
fn pieces() -> Vec<&'static str> {
    profile_codegen::__private::schema::all_keys()
        .into_iter()
        .map(|k| k.name())
        .chain(PIECES.iter().copied())
        .collect()
}

fn mutate(rng: &mut Rng, text: &str, pieces: &[&str]) -> String {
    let mut s: Vec<char> = text.chars().collect();
    for _ in 0..1 + rng.below(4) {
        let at = rng.below(s.len() + 1);
        match rng.below(5) {
            0 if !s.is_empty() => {
                let end = (at + 1 + rng.below(20)).min(s.len());
                s.drain(at.min(end)..end);
            }
            1 if !s.is_empty() => {
                let start = rng.below(s.len());
                let end = (start + 1 + rng.below(40)).min(s.len());
                let copy: Vec<char> = s[start..end].to_vec();
                s.splice(at..at, copy);
            }
            2 if !s.is_empty() => {
                let i = rng.below(s.len());
                s[i] = char::from_u32(rng.below(0x80) as u32).unwrap_or('x');
            }
            _ => {
                let piece = pieces[rng.below(pieces.len())];
                s.splice(at..at, piece.chars());
            }
        }
    }
    s.into_iter().collect()
}

fn cases() -> usize {
    std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1000)
}

fn check(input: &str, case: usize) {
    let result = catch_unwind(AssertUnwindSafe(|| Profiles::parse("profiles.toml", input)));
    match result {
        Err(_) => panic!("case {case}: the loader panicked on:\n{input}"),
        Ok(Err(e)) => assert!(
            e.message().starts_with("profiles.toml:"),
            "case {case}: error without a location: {e}\ninput:\n{input}"
        ),
        Ok(Ok(_)) => {}
    }
}

#[test]
fn mutated_files_never_panic() {
    let seeds = seeds();
    let mut rng = Rng(0x5eed_0001);
    let pieces = pieces();
    let n = cases();
    let mut errors = 0;
    for case in 0..n {
        let seed = &seeds[rng.below(seeds.len())];
        let input = mutate(&mut rng, seed, &pieces);
        check(&input, case);
        errors += usize::from(Profiles::parse("profiles.toml", &input).is_err());
    }
    println!("fuzz_toml: {n} mutated files, {errors} rejected with a located error");
}

#[test]
fn random_bytes_never_panic() {
    let mut rng = Rng(0x5eed_0002);
    let n = cases();
    for case in 0..n {
        let len = rng.below(200);
        let bytes: Vec<u8> = (0..len).map(|_| rng.next() as u8).collect();
        let input = String::from_utf8_lossy(&bytes);
        check(&input, case);
    }
    println!("fuzz_toml: {n} random byte strings");
}
