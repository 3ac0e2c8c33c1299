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
