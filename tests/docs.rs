//! The documentation users read: every key of `period_table!` is documented
//! where an editor shows it (the macro's doc comment), and public docs name
//! the articles, never this repository's file numbers for them.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The doc comment of `period_table!`: the `///` lines above it.
fn period_table_docs() -> String {
    let source = fs::read_to_string(root().join("profile-macros/src/lib.rs")).unwrap();
    let end = source
        .find("pub fn period_table(")
        .expect("profile-macros defines period_table");
    let before: Vec<&str> = source[..end].lines().collect();
    let docs: Vec<&str> = before
        .iter()
        .rev()
        .skip_while(|l| !l.trim_start().starts_with("///"))
        .take_while(|l| l.trim_start().starts_with("///") || l.trim_start().starts_with("#["))
        .filter_map(|l| l.trim_start().strip_prefix("///"))
        .collect();
    docs.into_iter().rev().collect::<Vec<_>>().join("\n")
}

#[test]
fn every_key_is_documented_on_period_table() {
    let docs = period_table_docs();
    assert!(docs.contains("Computes a period table"), "{docs}");
    let missing: Vec<&str> = profile_codegen::__private::schema::all_keys()
        .into_iter()
        .map(|k| k.name())
        .filter(|name| !docs.contains(&format!("`{name}`")))
        .collect();
    assert!(
        missing.is_empty(),
        "keys missing from period_table!'s docs: {missing:?}"
    );
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap().flatten() {
        let path = entry.path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn public_docs_name_the_articles_not_seed_numbers() {
    let mut files = Vec::new();
    for dir in [
        "src",
        "profile-core/src",
        "profile-codegen/src",
        "profile-macros/src",
        "profile-cli/src",
    ] {
        rust_files(&root().join(dir), &mut files);
    }
    let mut found = Vec::new();
    for file in &files {
        let text = fs::read_to_string(file).unwrap();
        for (i, line) in text.lines().enumerate() {
            let doc = line.trim_start();
            let is_doc = doc.starts_with("///") || doc.starts_with("//!");
            if is_doc && doc.to_lowercase().contains("seed") {
                found.push(format!("{}:{}: {doc}", file.display(), i + 1));
            }
        }
    }
    for readme in [
        "README.md",
        "profile-core/README.md",
        "profile-codegen/README.md",
        "profile-macros/README.md",
        "profile-cli/README.md",
    ] {
        let text = fs::read_to_string(root().join(readme)).unwrap_or_default();
        for (i, line) in text.lines().enumerate() {
            if line.to_lowercase().contains("seed") {
                found.push(format!("{readme}:{}: {line}", i + 1));
            }
        }
    }
    assert!(
        found.is_empty(),
        "public docs say \"seed\":\n{}",
        found.join("\n")
    );
}

/// Every file and folder under the repository's root, as paths relative to
/// it (`/`-separated; folders end in `/`), `target/` and `.git/` aside.
fn repository_paths() -> Vec<String> {
    fn walk(dir: &Path, out: &mut Vec<String>) {
        for entry in fs::read_dir(dir).unwrap().flatten() {
            let path = entry.path();
            let name = entry.file_name().to_string_lossy().into_owned();
            if name == "target" || name == ".git" {
                continue;
            }
            let rel = path.strip_prefix(root()).unwrap().to_string_lossy();
            let rel = rel.replace(std::path::MAIN_SEPARATOR, "/");
            if path.is_dir() {
                out.push(format!("{rel}/"));
                walk(&path, out);
            } else {
                out.push(rel);
            }
        }
    }
    let mut out = Vec::new();
    walk(root(), &mut out);
    out
}

/// What in `text` names a file or folder of the repository: the text of a
/// backtick span or a link's target that holds a `/` and either ends in one
/// or has an extension (`profile-core/src/lib.rs`, `tests/ui/`,
/// `golden/lines.rs`); not a URL, an absolute path, a pattern or a command.
fn named_paths(text: &str) -> Vec<String> {
    let mut spans: Vec<&str> = text.split('`').skip(1).step_by(2).collect();
    spans.extend(text.split("](").skip(1).filter_map(|s| s.split(')').next()));
    spans
        .into_iter()
        .map(|s| s.split('#').next().unwrap_or(""))
        .filter(|s| {
            let last = s.trim_end_matches('/').rsplit('/').next().unwrap_or("");
            let extension = last.rsplit_once('.').is_some_and(|(stem, e)| {
                !stem.is_empty()
                    && (1..=7).contains(&e.len())
                    && e.chars().all(|c| c.is_ascii_alphanumeric())
            });
            s.contains('/')
                && (s.ends_with('/') || extension)
                && !s.starts_with('/')
                && !s.starts_with('.')
                && !s.contains("://")
                && !s.chars().any(|c| " *{}<>$=:()[],;\"'|\\".contains(c))
                && !s.split(['/', '.']).any(|part| PLACEHOLDERS.contains(&part))
        })
        .map(str::to_string)
        .collect()
}

/// Paths the documents name that are not this repository's.
const NOT_REPOSITORY_PATHS: &[&str] = &[
    // Two profiles files in folders of a test's own (tests/c_header.rs).
    "a/profiles.toml",
    "b/profiles.toml",
    // Files of other repositories, cited as the sources of a motor's chart.
    "projects/CONVEYONE-OMNI-ZPA/out/analisis/research_motores_drivers.md",
    "src/catalog/motion.ts",
];

/// Words that stand for a name in a path (`curves/NAME.rs`,
/// `OUT_DIR/profiles.rs`): such a path is a pattern, not a file.
const PLACEHOLDERS: &[&str] = &["NAME", "OUT_DIR", "DIR"];

#[test]
fn every_path_the_documents_name_exists() {
    let paths = repository_paths();
    // A path exists if it is one from the root or from the document's
    // folder, or ends one (on a `/`): the tables of ARCHITECTURE.md name a
    // module's files from its folder (`golden/lines.rs`, `c/player/`).
    let exists = |doc_dir: &str, named: &str| {
        let from_doc = format!("{doc_dir}{named}");
        paths.iter().any(|p| {
            p == named
                || *p == from_doc
                || p.trim_end_matches('/') == named.trim_end_matches('/')
                || (p.ends_with(&format!("/{named}")) && p.ends_with('/') == named.ends_with('/'))
        })
    };
    let mut documents = vec![
        "README.md".to_string(),
        "ARCHITECTURE.md".to_string(),
        "tests/README.md".to_string(),
    ];
    for entry in fs::read_dir(root().join("docs")).unwrap().flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.ends_with(".md") {
            documents.push(format!("docs/{name}"));
        }
    }
    let mut missing = Vec::new();
    let mut named_count = 0;
    for doc in &documents {
        let text = fs::read_to_string(root().join(doc)).unwrap();
        let doc_dir = doc
            .rsplit_once('/')
            .map_or(String::new(), |(d, _)| format!("{d}/"));
        for (i, line) in text.lines().enumerate() {
            for named in named_paths(line) {
                named_count += 1;
                if !NOT_REPOSITORY_PATHS.contains(&named.as_str()) && !exists(&doc_dir, &named) {
                    missing.push(format!("{doc}:{}: `{named}`", i + 1));
                }
            }
        }
    }
    assert!(
        named_count > 50,
        "only {named_count} paths found: the reader is broken"
    );
    assert!(
        missing.is_empty(),
        "{} path(s) named in the documents do not exist:\n{}",
        missing.len(),
        missing.join("\n")
    );
}

/// The reader itself: what counts as a path and what does not.
#[test]
fn the_path_reader_sees_paths_only() {
    let line = "see `profile-core/src/lib.rs`, [a](docs/x.svg), `tests/ui/`, \
                `period_table!`, `a::b`, `cargo test --test x`, `https://x.org/a.html`, \
                `1/2`, `tests/ui/*.rs`, `/usr/include/a.h`, `profiles.toml:3:1`, \
                `curves/NAME.rs`";
    assert_eq!(
        named_paths(line),
        ["profile-core/src/lib.rs", "tests/ui/", "docs/x.svg"]
    );
}

// ---------------------------------------------------------------------------
// Byte figures of types: what the documents say a type takes, against
// `size_of`.

/// The documents whose text states figures: the READMEs, the architecture,
/// the changelog, the guide's pages and `docs/`, and the doc comments of
/// every crate's sources (`///`, `//!` and `#[doc = "..."]`, emitted
/// docs included), each as `(path, text)` with its whitespace collapsed.
fn documents() -> Vec<(String, String)> {
    let mut names: Vec<String> = [
        "README.md",
        "ARCHITECTURE.md",
        "CHANGELOG.md",
        "tests/README.md",
        "profile-core/README.md",
        "profile-codegen/README.md",
        "profile-macros/README.md",
        "profile-cli/README.md",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    for dir in ["docs", "src/guide"] {
        for entry in fs::read_dir(root().join(dir)).unwrap().flatten() {
            let name = entry.file_name().to_string_lossy().into_owned();
            if name.ends_with(".md") {
                names.push(format!("{dir}/{name}"));
            }
        }
    }
    let mut out: Vec<(String, String)> = names
        .into_iter()
        .map(|name| {
            let text = fs::read_to_string(root().join(&name)).unwrap();
            let text = collapse(&text);
            (name, text)
        })
        .collect();
    let mut files = Vec::new();
    for dir in [
        "src",
        "profile-core/src",
        "profile-codegen/src",
        "profile-macros/src",
        "profile-cli/src",
    ] {
        rust_files(&root().join(dir), &mut files);
    }
    files.sort();
    for file in files {
        let rel = file.strip_prefix(root()).unwrap().to_string_lossy();
        let rel = rel.replace(std::path::MAIN_SEPARATOR, "/");
        let text = fs::read_to_string(&file).unwrap();
        out.push((rel, collapse(&doc_text(&text))));
    }
    out
}

/// The doc text of a Rust source: its `///` and `//!` lines and the
/// strings of its `#[doc = "..."]` attributes, one after the other.
fn doc_text(source: &str) -> String {
    let mut out = String::new();
    for line in source.lines() {
        let line = line.trim_start();
        let doc = line
            .strip_prefix("///")
            .or_else(|| line.strip_prefix("//!"))
            .or_else(|| {
                line.strip_prefix("#[doc = \"")
                    .and_then(|rest| rest.rsplit_once("\"]"))
                    .map(|(doc, _)| doc)
            });
        if let Some(doc) = doc {
            out.push_str(doc);
            out.push('\n');
        }
    }
    out
}

/// `text` with every run of whitespace one space.
fn collapse(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Numbers written as words in the documents.
const NUMBER_WORDS: &[&str] = &[
    "zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
    "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen",
];

/// The number at the start of `text` (digits or a word of
/// [`NUMBER_WORDS`]), with its length in bytes.
fn number_at(text: &str) -> Option<(usize, usize)> {
    let digits = text.bytes().take_while(u8::is_ascii_digit).count();
    if digits > 0 {
        return Some((text[..digits].parse().ok()?, digits));
    }
    let word: String = text.chars().take_while(char::is_ascii_alphabetic).collect();
    let value = NUMBER_WORDS
        .iter()
        .position(|w| *w == word.to_lowercase())?;
    Some((value, word.len()))
}

/// A figure a document states, with the text it stands in: `phrase` is
/// that text with `{}` for each figure (written in digits or as a word),
/// and `sizes` says what each figure is, `(the type, its size)`.
struct SizeClaim {
    file: &'static str,
    phrase: &'static str,
    sizes: Vec<(&'static str, usize)>,
}

/// Each place of `phrase` in `text`: its range and the figures read where
/// the `{}` stand.
fn phrase_matches(text: &str, phrase: &str) -> Vec<(std::ops::Range<usize>, Vec<usize>)> {
    let parts: Vec<&str> = phrase.split("{}").collect();
    assert!(
        !parts[0].is_empty(),
        "\"{phrase}\": a phrase starts with text, not a figure"
    );
    let mut out = Vec::new();
    for (start, _) in text.match_indices(parts[0]) {
        let (mut at, mut figures) = (start + parts[0].len(), Vec::new());
        let mut whole = true;
        for part in &parts[1..] {
            let Some((value, len)) = number_at(&text[at..]) else {
                whole = false;
                break;
            };
            figures.push(value);
            at += len;
            if !text[at..].starts_with(part) {
                whole = false;
                break;
            }
            at += part.len();
        }
        if whole {
            out.push((start..at, figures));
        }
    }
    out
}

/// Every figure of a type's size the documents state, with what it is.
fn size_claims() -> Vec<SizeClaim> {
    use profile_core::runs::{IndexedRun, RunIndex};
    use std::mem::size_of;
    let run = ("a run, `[u16; 5]`", size_of::<[u16; 5]>());
    let entry = ("a `u16` entry", size_of::<u16>());
    let indexed = ("`runs::IndexedRun`", size_of::<IndexedRun>());
    let index = ("`runs::RunIndex<0>`", size_of::<RunIndex<0>>());
    // What the slack, the shortest period and the `Fall` added to an
    // index: all but its buckets' `shift`, `first` and `period`.
    let buckets = size_of::<u32>() + 2 * 64 * size_of::<u16>();
    let figures = ("`runs::RunIndex<0>` less its buckets", index.1 - buckets);
    let claim = |file, phrase, sizes: &[(&'static str, usize)]| SizeClaim {
        file,
        phrase,
        sizes: sizes.to_vec(),
    };
    vec![
        claim("README.md", "runs of {} bytes", &[run]),
        claim("src/guide/compression.md", "runs of {} bytes", &[run]),
        claim(
            "src/guide/compression.md",
            "instead of {} bytes a step",
            &[entry],
        ),
        claim(
            "src/guide/compression.md",
            "table costs {} bytes a step",
            &[entry],
        ),
        claim(
            "src/guide/compression.md",
            "a step count, {} bytes,",
            &[run],
        ),
        claim(
            "src/guide/compression.md",
            "carried into it ({} bytes a run, computed by a `const fn`, and {} bytes for 64 buckets",
            &[indexed, index],
        ),
        claim(
            "docs/performance.md",
            "with its slack ({} bytes of flash",
            &[figures],
        ),
        claim(
            "docs/performance.md",
            "was 132; {} with the slack",
            &[index],
        ),
        claim(
            "profile-core/src/table/runs.rs",
            "from every run before. {} bytes, where a run alone is {}.",
            &[indexed, run],
        ),
        claim(
            "profile-core/src/table/runs.rs",
            "performance.md)). {} bytes of flash a run, and {} for the buckets",
            &[indexed, index],
        ),
        claim(
            "profile-core/src/table/segments.rs",
            "in bytes (two words a segment, {} per run)",
            &[run],
        ),
        claim(
            "profile-codegen/src/table/compress.rs",
            "64 runs ({} bytes,",
            &[("64 runs, `[[u16; 5]; 64]`", size_of::<[[u16; 5]; 64]>())],
        ),
    ]
}

/// Figures in bytes the documents state that are not a type's size, each
/// as the text it stands in.
const NOT_TYPE_SIZES: &[(&str, &str)] = &[
    // A table's flash, the report's figure.
    (
        "src/guide/compression.md",
        "97 runs: 970 bytes instead of 14 384",
    ),
    (
        "src/guide/compression.md",
        "97 runs take 970 bytes of flash",
    ),
    // Measured flash of compiled code.
    ("docs/performance.md", "the player module 146 to 216 bytes"),
    ("docs/performance.md", "takes 1128 bytes of flash on the M3"),
    ("docs/performance.md", "33678, 33790 bytes of flash"),
    // The history of an index's size: its buckets with their periods,
    // before the slack, the shortest period and `Fall` were added.
    (
        "docs/performance.md",
        "(260 bytes of flash an index for the buckets",
    ),
    // An 8051's internal RAM, and what the C players take of it and of
    // external RAM there, measured with SDCC (tests/c_8051.rs).
    (
        "profile-codegen/src/emit/c/player/mod.rs",
        "whose internal RAM is 256 bytes, of which 128",
    ),
    ("tests/README.md", "(256 bytes of internal RAM)"),
    (
        "src/guide/c_output.md",
        "an 8051 addresses 128 bytes directly",
    ),
    (
        "src/guide/c_output.md",
        "planners would take over 500 bytes",
    ),
    (
        "src/guide/c_output.md",
        "some 25 bytes less stack for about 460 bytes more code",
    ),
    (
        "src/guide/c_output.md",
        "(256 bytes of internal RAM, as the article's C8051F040",
    ),
    ("src/guide/c_output.md", "(they needed over 500 bytes)"),
    ("src/guide/c_output.md", "3.7 KB) and 1 212 bytes of"),
];

/// A type's size stated in the documents is its `size_of`, and every
/// figure in bytes they state is either one of [`size_claims`] or one of
/// [`NOT_TYPE_SIZES`].
#[test]
fn byte_figures_are_the_types_sizes() {
    let documents = documents();
    let claims = size_claims();
    let mut problems = Vec::new();
    let mut covered: Vec<(&str, std::ops::Range<usize>)> = Vec::new();
    let text_of = |file: &str| {
        documents
            .iter()
            .find(|(name, _)| name == file)
            .map(|(_, text)| text.as_str())
            .unwrap_or_else(|| panic!("{file} is not among the documents read"))
    };
    for claim in &claims {
        let text = text_of(claim.file);
        let found = phrase_matches(text, claim.phrase);
        if found.is_empty() {
            problems.push(format!(
                "{}: no \"{}\" (a figure where each `{{}}` stands): the text changed; \
                 say the size again and update size_claims() in tests/docs.rs",
                claim.file, claim.phrase
            ));
        }
        for (range, figures) in found {
            for (figure, (what, size)) in figures.iter().zip(&claim.sizes) {
                if figure != size {
                    problems.push(format!(
                        "{}: \"{}\" says {figure} bytes for {what}, which is {size} \
                         (`size_of`)",
                        claim.file,
                        &text[range.clone()]
                    ));
                }
            }
            covered.push((claim.file, range));
        }
    }
    for (file, phrase) in NOT_TYPE_SIZES {
        let text = text_of(file);
        let found: Vec<_> = text.match_indices(phrase).collect();
        if found.is_empty() {
            problems.push(format!(
                "{file}: no \"{phrase}\": update NOT_TYPE_SIZES in tests/docs.rs"
            ));
        }
        for (start, _) in found {
            covered.push((file, start..start + phrase.len()));
        }
    }
    let mut figures = 0;
    for (file, text) in &documents {
        for (at, _) in text.match_indices(" byte") {
            let before = &text[..at];
            let word_start = before
                .rfind(|c: char| !c.is_ascii_alphanumeric())
                .map_or(0, |i| i + 1);
            if number_at(&before[word_start..]).is_none_or(|(_, len)| len != at - word_start) {
                continue;
            }
            figures += 1;
            let inside = covered
                .iter()
                .any(|(f, range)| f == file && range.start <= word_start && at <= range.end);
            if !inside {
                let from = before[..word_start]
                    .char_indices()
                    .rev()
                    .nth(40)
                    .map_or(0, |(i, _)| i);
                let to = (at + 30..text.len())
                    .find(|&i| text.is_char_boundary(i))
                    .unwrap_or(text.len());
                problems.push(format!(
                    "{file}: \"...{}...\" states a figure in bytes the test does not \
                     know: add it to size_claims() (a type's size) or NOT_TYPE_SIZES in \
                     tests/docs.rs",
                    &text[from..to]
                ));
            }
        }
    }
    assert!(
        figures > 10,
        "only {figures} figures found: the reader is broken"
    );
    assert!(
        problems.is_empty(),
        "{} problem(s) with the documents' byte figures:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The reader of figures: numbers in digits and words, phrases with
/// several figures.
#[test]
fn the_figure_reader_reads_figures() {
    assert_eq!(number_at("304 for"), Some((304, 3)));
    assert_eq!(number_at("Ten bytes"), Some((10, 3)));
    assert_eq!(number_at("bytes"), None);
    let text = "a (16 bytes a run and 260 for the buckets), (x bytes a run and 2 for";
    assert_eq!(
        phrase_matches(text, "({} bytes a run and {} for the"),
        vec![(2..33, vec![16, 260])]
    );
    assert_eq!(
        collapse(&doc_text(
            "/// a\n  //! b\n#[doc = \" c \\\"d\\\"\"]\nlet x;"
        )),
        "a b c \\\"d\\\""
    );
}

/// The emitted `RUN_INDEX`'s docs state its sizes as `size_of` gives them.
#[test]
fn the_emitted_run_index_states_its_size() {
    use profile_core::runs::{IndexedRun, RunIndex};
    use std::mem::size_of;
    let profiles = profile_codegen::profiles::Profiles::parse(
        "runs.toml",
        "[profiles.ramp]\ncurve = \"linear\"\nfmin = 1600\nfmax = 48_000\n\
         accel = 160_000\ntimer_hz = 10_000_000\ncompress = 1\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let source = profiles.rust_source();
    let docs = collapse(&doc_text(
        &source[..source.find("pub static RUN_INDEX").expect("a RUN_INDEX")],
    ));
    let phrase = "bucket of steps ({} bytes of flash a run and {} for the buckets, in place \
                  of `RUNS`' {} a run";
    let found = phrase_matches(&docs, phrase);
    assert_eq!(
        found.iter().map(|(_, f)| f.clone()).collect::<Vec<_>>(),
        vec![vec![
            size_of::<IndexedRun>(),
            size_of::<RunIndex<0>>(),
            size_of::<[u16; 5]>()
        ]],
        "the emitted RUN_INDEX's docs should say \"{phrase}\" with `size_of` \
         `IndexedRun`, `RunIndex<0>` and `[u16; 5]`:\n{docs}"
    );
}

// ---------------------------------------------------------------------------
// Features: what the documents say each cargo feature brings, against the
// `[features]` tables and the `cfg` attributes of the sources.

/// The two crates with features: `stepper-profiles` (the root) and
/// `profile-core`, each its manifest and the prefix of its paths in
/// `tests/public-api.txt`.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Crate {
    Facade,
    Core,
}

impl Crate {
    fn manifest(self) -> &'static str {
        match self {
            Crate::Facade => "Cargo.toml",
            Crate::Core => "profile-core/Cargo.toml",
        }
    }

    fn api_prefix(self) -> &'static str {
        match self {
            Crate::Facade => "stepper_profiles",
            Crate::Core => "profile_core",
        }
    }
}

/// A feature of a manifest: its name, what it enables, and the comment
/// above it (its lines joined).
#[derive(Debug)]
struct Feature {
    name: String,
    enables: Vec<String>,
    comment: String,
}

/// The `[features]` table of `krate`'s manifest (`default` aside).
fn features(krate: Crate) -> Vec<Feature> {
    let text = fs::read_to_string(root().join(krate.manifest())).unwrap();
    let table = text
        .split("\n[features]\n")
        .nth(1)
        .unwrap_or_else(|| panic!("{} has no [features]", krate.manifest()));
    let mut out = Vec::new();
    let mut comment = Vec::new();
    for line in table.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            break;
        }
        if let Some(c) = line.strip_prefix('#') {
            comment.push(c.trim().to_string());
            continue;
        }
        if let Some((name, list)) = line.split_once('=') {
            let name = name.trim().to_string();
            let enables = list
                .split('"')
                .skip(1)
                .step_by(2)
                .map(str::to_string)
                .collect();
            if name != "default" {
                out.push(Feature {
                    name,
                    enables,
                    comment: comment.join(" "),
                });
            }
        }
        comment.clear();
    }
    assert!(!out.is_empty(), "{}: no features read", krate.manifest());
    out
}

/// The features `feature` of `krate` turns on, itself included: those of
/// its own manifest it implies, and `profile-core`'s it enables.
fn core_features(krate: Crate, feature: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut stack = vec![(krate, feature.to_string())];
    while let Some((krate, name)) = stack.pop() {
        if !out.insert(name.clone()) {
            continue;
        }
        let all = features(krate);
        let Some(f) = all.iter().find(|f| f.name == name) else {
            continue;
        };
        for e in &f.enables {
            if let Some(core) = e.strip_prefix("profile-core/") {
                stack.push((Crate::Core, core.to_string()));
            } else if !e.starts_with("dep:") && !e.contains('/') {
                stack.push((krate, e.clone()));
            }
        }
    }
    out
}

/// Where the API and the modules' `cfg`s say what needs a feature: each
/// path of `tests/public-api.txt` (`stepper_profiles::simulate::run`) and
/// each module `profile-core/src/lib.rs` declares (`profile_core::schema`),
/// with the features of `profile-core` it needs.
fn gates() -> BTreeMap<String, BTreeSet<String>> {
    let mut out = BTreeMap::new();
    let api = fs::read_to_string(root().join("tests/public-api.txt")).unwrap();
    for line in api.lines().filter(|l| !l.starts_with('#')) {
        let mut words = line.split_whitespace();
        let (Some(_kind), Some(path)) = (words.next(), words.next()) else {
            continue;
        };
        let krate = if path.starts_with("profile_core::") {
            Crate::Core
        } else {
            Crate::Facade
        };
        let needs: BTreeSet<String> = line
            .split_once("(feature ")
            .map(|(_, f)| f.trim_end_matches(')'))
            .into_iter()
            .flat_map(|f| f.split(", "))
            .flat_map(|f| core_features(krate, f))
            .collect();
        out.insert(path.to_string(), needs);
    }
    let lib = fs::read_to_string(root().join("profile-core/src/lib.rs")).unwrap();
    let mut cfg = None;
    for line in lib.lines() {
        let line = line.trim();
        if let Some(f) = line.strip_prefix("#[cfg(feature = \"") {
            cfg = f.split('"').next().map(str::to_string);
            continue;
        }
        let module = line
            .strip_prefix("pub mod ")
            .or_else(|| line.strip_prefix("mod "))
            .and_then(|m| m.strip_suffix(';'));
        if let Some(module) = module {
            let needs = cfg
                .iter()
                .flat_map(|f| core_features(Crate::Core, f))
                .collect();
            out.entry(format!("profile_core::{module}"))
                .or_insert(needs);
        }
        if !line.starts_with("#[") {
            cfg = None;
        }
    }
    assert!(
        out.len() > 100,
        "{} paths read: the reader is broken",
        out.len()
    );
    out
}

/// The features of `profile-core` that what `span` names needs, read from
/// [`gates`]: `span` is a path from `krate`'s root (`profiles::Profiles`,
/// `fugit::TimerDurationU32<HZ>`, `simulate::run(...)`, `Table`), resolved
/// to its longest known prefix. `None` when it names nothing known.
fn needs(
    gates: &BTreeMap<String, BTreeSet<String>>,
    krate: Crate,
    span: &str,
) -> Option<BTreeSet<String>> {
    let path: String = span
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == ':')
        .collect();
    let mut parts: Vec<&str> = path.split("::").filter(|p| !p.is_empty()).collect();
    if parts.first() == Some(&krate.api_prefix()) {
        parts.remove(0);
    }
    while !parts.is_empty() {
        let full = format!("{}::{}", krate.api_prefix(), parts.join("::"));
        if let Some(needs) = gates.get(&full) {
            return Some(needs.clone());
        }
        // The facade names what `profile-core` declares privately by the
        // same path (`schema`, `pipeline`, `emit`).
        if let Some(needs) = gates.get(&format!("profile_core::{}", parts.join("::"))) {
            return Some(needs.clone());
        }
        parts.pop();
    }
    None
}

/// What the phrases of feature lists that are not a path in backticks
/// name, as a path [`needs`] reads.
const PHRASES: &[(&str, &str)] = &[
    ("owned tables", "Table"),
    ("the runs' fitter", "RunTable"),
    ("the simulator", "simulate"),
    ("the schema", "schema"),
    ("the argument schema", "schema"),
    ("the pipeline", "pipeline"),
    ("the emitter", "emit"),
    ("profiles files", "profiles"),
    ("the profiles file", "profiles"),
    ("the golden-file checks", "golden::check"),
];

/// The lists of features in the documents, each where it begins (text
/// found once in the file) and the crate whose features it lists:
/// `` `name` (what it brings, ...; implies `other`; `no_std`), ... ``.
const FEATURE_LISTS: &[(&str, &str, Crate)] = &[
    (
        "README.md",
        "Features of `stepper-profiles`:",
        Crate::Facade,
    ),
    ("profile-core/README.md", "Features:", Crate::Core),
    ("ARCHITECTURE.md", "runs. Its one feature:", Crate::Core),
    (
        "ARCHITECTURE.md",
        "doc tests). Its features:",
        Crate::Facade,
    ),
];

/// The list of features at the start of `text`: each feature's name and
/// what its parentheses hold.
fn feature_list(text: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut rest = text;
    loop {
        rest = rest.trim_start_matches([' ', ',']);
        rest = rest.strip_prefix("and ").unwrap_or(rest);
        let Some(after) = rest.strip_prefix('`') else {
            break;
        };
        let Some((name, after)) = after.split_once('`') else {
            break;
        };
        let Some(after) = after.strip_prefix(" (") else {
            break;
        };
        let mut depth = 1;
        let Some(end) = after.char_indices().find_map(|(i, c)| {
            depth += match c {
                '(' => 1,
                ')' => -1,
                _ => 0,
            };
            (depth == 0).then_some(i)
        }) else {
            break;
        };
        out.push((name.to_string(), after[..end].to_string()));
        rest = &after[end + 1..];
    }
    out
}

/// The parts of a feature's parentheses: split at the `,` and `;` outside
/// backticks.
fn parts(content: &str) -> Vec<String> {
    let (mut out, mut part, mut quoted) = (Vec::new(), String::new(), false);
    for c in content.chars() {
        match c {
            '`' => {
                quoted = !quoted;
                part.push(c);
            }
            ',' | ';' if !quoted => out.push(std::mem::take(&mut part)),
            _ => part.push(c),
        }
    }
    out.push(part);
    out.into_iter()
        .map(|p| p.trim().trim_start_matches("and ").trim().to_string())
        .filter(|p| !p.is_empty())
        .collect()
}

/// The spans in backticks of `text`.
fn spans(text: &str) -> Vec<&str> {
    text.split('`').skip(1).step_by(2).collect()
}

/// What one feature of `krate` is said to bring (`parts` of its
/// parentheses), against what needs it: each problem, worded.
fn check_feature(
    gates: &BTreeMap<String, BTreeSet<String>>,
    krate: Crate,
    feature: &str,
    parts: &[String],
    wherein: &str,
) -> Vec<String> {
    let names: Vec<String> = features(krate).into_iter().map(|f| f.name).collect();
    let brings = core_features(krate, feature);
    let mut problems = Vec::new();
    for part in parts {
        if let Some(implied) = part.strip_prefix("implies ") {
            for other in spans(implied) {
                if !names.iter().any(|n| n == other) {
                    problems.push(format!(
                        "{wherein}: `{feature}` implies `{other}`, which is no feature of {}",
                        krate.manifest()
                    ));
                } else if !core_features(krate, other).is_subset(&brings) {
                    problems.push(format!(
                        "{wherein}: `{feature}` implies `{other}`, which {} does not say",
                        krate.manifest()
                    ));
                }
            }
            continue;
        }
        if part == "`no_std`" {
            if brings.contains("std") {
                problems.push(format!(
                    "{wherein}: `{feature}` is said `no_std`, and {} has it turn `std` on",
                    krate.manifest()
                ));
            }
            continue;
        }
        let named: Vec<String> = if part.contains('`') {
            spans(part).into_iter().map(str::to_string).collect()
        } else if let Some((_, path)) = PHRASES.iter().find(|(p, _)| *p == part) {
            vec![path.to_string()]
        } else {
            problems.push(format!(
                "{wherein}: `{feature}` (... {part} ...): the test cannot tell what \"{part}\" \
                 names; name it in backticks or add it to PHRASES in tests/docs.rs"
            ));
            continue;
        };
        for path in named {
            match needs(gates, krate, &path) {
                None => problems.push(format!(
                    "{wherein}: `{feature}` brings `{path}`, which is not in \
                     tests/public-api.txt nor a module of profile-core"
                )),
                Some(n) if n.is_empty() => problems.push(format!(
                    "{wherein}: `{feature}` is said to bring `{path}` ({part}), which needs no \
                     feature"
                )),
                Some(n) if !n.is_subset(&brings) => problems.push(format!(
                    "{wherein}: `{feature}` is said to bring `{path}` ({part}), which needs \
                     {n:?}"
                )),
                Some(_) => {}
            }
        }
    }
    problems
}

/// Each list of features in the documents names every feature of its
/// crate's manifest and no other, and what it says each brings needs that
/// feature (`tests/public-api.txt`, the `cfg`s of `profile-core`'s
/// modules); each feature of the manifests has a comment, whose paths in
/// backticks need it too (but for those it says need no feature).
#[test]
fn feature_lists_say_what_the_features_bring() {
    let gates = gates();
    let mut problems = Vec::new();
    for (file, anchor, krate) in FEATURE_LISTS {
        let text = collapse(&fs::read_to_string(root().join(file)).unwrap());
        let found: Vec<_> = text.match_indices(anchor).collect();
        if found.len() != 1 {
            problems.push(format!(
                "{file}: \"{anchor}\" found {} times, not once: update FEATURE_LISTS in \
                 tests/docs.rs",
                found.len()
            ));
            continue;
        }
        let list = feature_list(&text[found[0].0 + anchor.len()..]);
        let names: Vec<String> = features(*krate).into_iter().map(|f| f.name).collect();
        let listed: Vec<&str> = list.iter().map(|(n, _)| n.as_str()).collect();
        let wherein = format!("{file} (\"{anchor}\")");
        for name in &names {
            if !listed.contains(&name.as_str()) {
                problems.push(format!(
                    "{wherein}: no `{name}`, a feature of {}",
                    krate.manifest()
                ));
            }
        }
        for (name, content) in &list {
            if !names.contains(name) {
                problems.push(format!(
                    "{wherein}: `{name}` is no feature of {}",
                    krate.manifest()
                ));
                continue;
            }
            problems.extend(check_feature(
                &gates,
                *krate,
                name,
                &parts(content),
                &wherein,
            ));
        }
    }
    for krate in [Crate::Facade, Crate::Core] {
        let names: Vec<String> = features(krate).into_iter().map(|f| f.name).collect();
        for feature in features(krate) {
            let wherein = format!("{} (`{}`'s comment)", krate.manifest(), feature.name);
            if feature.comment.is_empty() {
                problems.push(format!("{wherein}: none; say what the feature brings"));
            }
            for sentence in feature.comment.split(". ") {
                let none = sentence.contains("needs no feature");
                for span in spans(sentence) {
                    if names.iter().any(|n| n == span) || span == "no_std" {
                        continue;
                    }
                    match needs(&gates, krate, span) {
                        None => problems.push(format!(
                            "{wherein}: `{span}` is not in tests/public-api.txt nor a \
                             module of profile-core"
                        )),
                        Some(n) if none && !n.is_empty() => problems.push(format!(
                            "{wherein}: `{span}` is said to need no feature, and needs {n:?}"
                        )),
                        Some(n) if !none && n.is_empty() => {
                            problems.push(format!("{wherein}: `{span}` needs no feature"))
                        }
                        Some(n) if !none && !n.is_subset(&core_features(krate, &feature.name)) => {
                            problems.push(format!("{wherein}: `{span}` needs {n:?}"))
                        }
                        Some(_) => {}
                    }
                }
            }
        }
    }
    assert!(
        problems.is_empty(),
        "{} problem(s) with what the documents say the features bring:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The features the text names: `` feature `x` ``, `` the `x` feature ``,
/// `features = ["x", ...]` (of `stepper-profiles` or `profile-core`) and
/// `--features x`, each with where it stands and the crate it is of when
/// the text says (else `None`: either).
fn feature_mentions(text: &str) -> Vec<(usize, String, Option<Crate>)> {
    let mut out = Vec::new();
    for (at, _) in text.match_indices("feature `") {
        // Not "the `fugit` feature `player::Timed`".
        if text[..at].ends_with("` ") {
            continue;
        }
        let name = text[at + 9..].split('`').next().unwrap_or("");
        out.push((at, name.to_string(), None));
    }
    for (at, _) in text.match_indices("` feature") {
        if let Some(open) = text[..at].rfind('`') {
            out.push((open, text[open + 1..at].to_string(), None));
        }
    }
    for (at, _) in text.match_indices("features = [") {
        let before = &text[..at];
        let krate = before.rsplit_once(" = {").and_then(|(name, _)| {
            match name
                .rsplit(' ')
                .next()
                .unwrap_or("")
                .trim_start_matches('`')
            {
                "stepper-profiles" => Some(Some(Crate::Facade)),
                "profile-core" => Some(Some(Crate::Core)),
                _ => None,
            }
        });
        let Some(krate) = krate else { continue };
        let list = text[at..].split(']').next().unwrap_or("");
        for name in list.split('"').skip(1).step_by(2) {
            out.push((at, name.to_string(), krate));
        }
    }
    for (at, _) in text.match_indices("--features ") {
        let name: String = text[at + 11..]
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '-')
            .collect();
        let krate = text[at.saturating_sub(40)..at]
            .contains("-p profile-core")
            .then_some(Crate::Core);
        out.push((at, name, krate.or(Some(Crate::Facade))));
    }
    out
}

/// The parenthesised text around `at` (within its sentence), and the span
/// in backticks just before it (a few words before, in the same clause):
/// what a `(feature `x`)` or a `(no feature needed)` speaks of.
fn group_around(text: &str, at: usize) -> Option<(&str, Option<&str>)> {
    let sentence_start = text[..at].rfind(". ").map_or(0, |i| i + 2);
    let mut depth = 0;
    let open = text[sentence_start..at]
        .char_indices()
        .rev()
        .find_map(|(i, c)| {
            match c {
                ')' => depth += 1,
                '(' if depth == 0 => return Some(sentence_start + i),
                '(' => depth -= 1,
                _ => {}
            }
            None
        })?;
    let mut depth = 0;
    let close = text[open..].char_indices().find_map(|(i, c)| {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(open + i);
                }
            }
            _ => {}
        }
        None
    })?;
    let before = &text[sentence_start..open];
    let mut pieces = before.rsplit('`');
    let (between, last) = (pieces.next().unwrap_or(""), pieces.next());
    let near = between.len() <= 40 && !between.contains([';', '(', ')']);
    Some((&text[open + 1..close], last.filter(|_| near)))
}

/// What a parenthesis speaks of: the paths in backticks it holds that
/// [`needs`] knows, or, when it holds none, the path just before it.
fn spoken_of<'a>(
    gates: &BTreeMap<String, BTreeSet<String>>,
    group: &'a str,
    before: Option<&'a str>,
    feature: &str,
) -> Vec<(&'a str, BTreeSet<String>)> {
    let known = |span: &'a str| needs(gates, Crate::Facade, span).map(|n| (span, n));
    let inside: Vec<_> = spans(group)
        .into_iter()
        .filter(|s| *s != feature)
        .filter_map(known)
        .collect();
    if inside.is_empty() {
        before.and_then(known).into_iter().collect()
    } else {
        inside
    }
}

/// Every feature the documents and doc comments name is one of the
/// manifests'; what a parenthesis naming a feature speaks of (the paths
/// in it, and the path in backticks just before it) needs that feature,
/// and what one saying "no feature" speaks of needs none.
#[test]
fn features_the_documents_name_exist_and_gate_what_they_say() {
    let gates = gates();
    let facade: Vec<String> = features(Crate::Facade)
        .into_iter()
        .map(|f| f.name)
        .collect();
    let core: Vec<String> = features(Crate::Core).into_iter().map(|f| f.name).collect();
    let mut problems = Vec::new();
    let mut count = 0;
    for (file, text) in documents() {
        for (at, name, krate) in feature_mentions(&text) {
            count += 1;
            let exists = match krate {
                Some(Crate::Facade) => facade.contains(&name),
                Some(Crate::Core) => core.contains(&name),
                None => facade.contains(&name) || core.contains(&name),
            };
            let context = &text[text[..at].rfind(". ").map_or(0, |i| i + 2)..];
            let context: String = context.chars().take(80).collect();
            if !exists {
                problems.push(format!(
                    "{file}: \"{context}...\" names a feature `{name}`, which no manifest has"
                ));
                continue;
            }
            let Some((group, before)) = group_around(&text, at) else {
                continue;
            };
            let brings = core_features(krate.unwrap_or(Crate::Facade), &name);
            for (span, n) in spoken_of(&gates, group, before, &name) {
                if n.is_empty() || !n.is_subset(&brings) {
                    problems.push(format!(
                        "{file}: \"{context}...\": `{span}` is said to need `{name}`, and \
                         needs {n:?}"
                    ));
                }
            }
        }
        for (at, _) in text.match_indices("no feature") {
            let Some((group, before)) = group_around(&text, at) else {
                continue;
            };
            for (span, n) in spoken_of(&gates, group, before, "") {
                if !n.is_empty() {
                    problems.push(format!(
                        "{file}: `{span}` is said to need no feature (\"{group}\"), and \
                         needs {n:?}"
                    ));
                }
            }
        }
    }
    assert!(
        count > 10,
        "only {count} features named: the reader is broken"
    );
    assert!(
        problems.is_empty(),
        "{} problem(s) with the features the documents name:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The readers of features: a list and its parts, the features a text
/// names, what a parenthesis speaks of.
#[test]
fn the_feature_readers_read_features() {
    let list = feature_list(
        " `std` (owned tables, the runs' fitter), `golden` (`golden::check` for tests; \
         implies `codegen`), and `fugit` (`a::B<C, D>`; `no_std`). Without features",
    );
    let names: Vec<&str> = list.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["std", "golden", "fugit"]);
    assert_eq!(parts(&list[0].1), ["owned tables", "the runs' fitter"]);
    assert_eq!(
        parts(&list[1].1),
        ["`golden::check` for tests", "implies `codegen`"]
    );
    assert_eq!(parts(&list[2].1), ["`a::B<C, D>`", "`no_std`"]);
    let text = "with the `fugit` feature `player::Timed`, (feature `golden`) and \
                `profile-core = { version = \"0.1\", features = [\"codegen\"] }`; \
                `cargo test -p profile-core --features std`";
    let named: Vec<(String, Option<Crate>)> = feature_mentions(text)
        .into_iter()
        .map(|(_, n, k)| (n, k))
        .collect();
    assert_eq!(
        named,
        [
            ("golden".to_string(), None),
            ("fugit".to_string(), None),
            ("codegen".to_string(), Some(Crate::Core)),
            ("std".to_string(), Some(Crate::Core)),
        ]
    );
    let text = "`golden::check`: golden files (feature `golden`); x (`a`; y) (b)";
    let at = text.find("feature").unwrap();
    assert_eq!(
        group_around(text, at),
        Some(("feature `golden`", Some("golden::check")))
    );
    let gates = gates();
    assert_eq!(
        needs(&gates, Crate::Facade, "simulate::run(&m)"),
        Some(BTreeSet::from(["std".to_string()]))
    );
    assert_eq!(
        needs(&gates, Crate::Facade, "player::Player"),
        Some(BTreeSet::new())
    );
    assert_eq!(
        needs(&gates, Crate::Facade, "fugit::TimerDurationU32<HZ>"),
        Some(BTreeSet::from(["fugit".to_string()]))
    );
    assert_eq!(
        needs(&gates, Crate::Facade, "profiles::Profiles"),
        Some(BTreeSet::from(["codegen".to_string(), "std".to_string()]))
    );
    assert_eq!(needs(&gates, Crate::Core, "schema"), None);
    assert_eq!(needs(&gates, Crate::Facade, "build::Profiles"), None);
}
