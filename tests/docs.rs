//! The documentation users read: every key of `period_table!` is documented
//! where an editor shows it (the macro's doc comment), and public docs name
//! the articles, never this repository's file numbers for them.

use std::fs;
use std::path::{Path, PathBuf};

use profile_core::Key;

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
    let missing: Vec<&str> = Key::all()
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
            "CHANGELOG.md",
            "`const fn` ({} bytes a run and {} for the buckets",
            &[indexed, index],
        ),
        claim("CHANGELOG.md", "too: {} bytes more an index", &[figures]),
        claim("CHANGELOG.md", "`[[u16; 5]; N]`, {} bytes a run", &[run]),
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
            "profile-core/src/table/compress.rs",
            "in bytes ({} per run)",
            &[run],
        ),
        claim(
            "profile-core/src/table/compress.rs",
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
    ("docs/performance.md", "26916, 27004 bytes of flash"),
    // The history of an index's size: its buckets with their periods,
    // before the slack, the shortest period and `Fall` were added.
    (
        "docs/performance.md",
        "(260 bytes of flash an index for the buckets",
    ),
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
    let profiles = profile_core::profiles::Profiles::parse(
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
