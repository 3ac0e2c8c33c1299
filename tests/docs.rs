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
