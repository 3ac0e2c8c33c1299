//! The layers of `ARCHITECTURE.md`, checked on the source.
//!
//! `ARCHITECTURE.md` lists each crate's modules by layer in its tables; this
//! test reads those tables and every `crate::` and `super::` path in
//! `profile-core/src` and `profile-macros/src` (comments aside), and checks:
//!
//! - no module imports one of a higher layer (a parent declaring its own
//!   children is structure, not an import, and is not counted);
//! - no two modules import each other, directly or around a loop;
//! - no function outside tests is over 100 lines, no source file over 600.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

const MAX_FUNCTION_LINES: usize = 100;
const MAX_FILE_LINES: usize = 600;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The layer of each top-level module of `krate`, from ARCHITECTURE.md's
/// table under the heading that names the crate: rows `| N | `a`, `b` | ... |`.
fn layers(krate: &str) -> BTreeMap<String, u32> {
    let doc = fs::read_to_string(root().join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let section = doc
        .split("\n### ")
        .find(|s| s.starts_with(&format!("`{krate}`")))
        .unwrap_or_else(|| panic!("ARCHITECTURE.md has no `### `{krate}`` section"));
    let mut layers = BTreeMap::new();
    for line in section.lines() {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let Some(layer) = cells.get(1).and_then(|c| c.parse::<u32>().ok()) else {
            continue;
        };
        for module in cells[2].split(',') {
            layers.insert(module.trim().trim_matches('`').to_string(), layer);
        }
    }
    assert!(!layers.is_empty(), "no layer table for `{krate}`");
    layers
}

/// Every `.rs` file under `dir`, with its module path (`base::error`;
/// `base` for `base/mod.rs`; empty for `lib.rs`).
fn modules(dir: &Path) -> Vec<(String, PathBuf)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let rel = path.strip_prefix(dir).unwrap().with_extension("");
            let parts: Vec<String> = rel
                .iter()
                .map(|p| p.to_string_lossy().into_owned())
                .filter(|p| p != "mod" && p != "lib")
                .collect();
            out.push((parts.join("::"), path));
        }
    }
    out.sort();
    out
}

/// The code of a file without comments (line comments and doc comments).
fn code(text: &str) -> String {
    text.lines()
        .map(|l| match l.find("//") {
            Some(i) if !l[..i].contains('"') => &l[..i],
            _ => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The module paths `text` refers to with `crate::` or `super::`, resolved
/// from `module` to the longest known module.
fn references(
    module: &str,
    is_mod_rs: bool,
    text: &str,
    known: &BTreeSet<String>,
) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let here: Vec<&str> = module.split("::").filter(|s| !s.is_empty()).collect();
    // `super` from a file `a/b.rs` (module a::b) is `a`; from `a/mod.rs` it is the parent of `a`.
    let parent: Vec<&str> = if is_mod_rs || here.is_empty() {
        here[..here.len().saturating_sub(1)].to_vec()
    } else {
        here[..here.len() - 1].to_vec()
    };
    let bytes = text.as_bytes();
    for (prefix, base) in [("crate::", Vec::new()), ("super::", parent)] {
        let mut from = 0;
        while let Some(i) = text[from..].find(prefix) {
            let start = from + i;
            from = start + prefix.len();
            if start > 0 && (bytes[start - 1].is_ascii_alphanumeric() || bytes[start - 1] == b'_') {
                continue;
            }
            let rest = &text[from..];
            let path: String = rest
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == ':')
                .collect();
            let mut paths = vec![path.trim_end_matches(':').to_string()];
            if rest[path.len()..].starts_with('{') {
                let inner = &rest[path.len() + 1..rest.find('}').unwrap_or(rest.len())];
                for item in inner.split(',') {
                    let item = item.trim();
                    paths.push(format!("{path}{item}"));
                }
            }
            for p in paths {
                let mut parts: Vec<&str> = base.clone();
                parts.extend(p.split("::").filter(|s| !s.is_empty()));
                while !parts.is_empty() {
                    let candidate = parts.join("::");
                    if known.contains(&candidate) {
                        out.insert(candidate);
                        break;
                    }
                    parts.pop();
                }
            }
        }
    }
    out
}

fn top(module: &str) -> &str {
    module.split("::").next().unwrap_or("")
}

/// Checks one crate; returns the problems found.
fn check_crate(krate: &str, dir: &str) -> Vec<String> {
    let layers = layers(krate);
    let files = modules(&root().join(dir));
    let known: BTreeSet<String> = files.iter().map(|(m, _)| m.clone()).collect();
    let mut problems = Vec::new();
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (module, path) in &files {
        let text = fs::read_to_string(path).unwrap();
        let lines = text.lines().count();
        if lines > MAX_FILE_LINES {
            problems.push(format!(
                "{}: {lines} lines, more than {MAX_FILE_LINES}",
                path.display()
            ));
        }
        problems.extend(long_functions(path, &text));
        if module.is_empty()
            || path
                .file_name()
                .is_some_and(|n| n.to_string_lossy().ends_with("_tests.rs"))
        {
            continue;
        }
        let Some(&layer) = layers.get(top(module)) else {
            problems.push(format!(
                "{krate}: module `{module}` is in no layer of ARCHITECTURE.md"
            ));
            continue;
        };
        let is_mod_rs = path.ends_with("mod.rs");
        let code = code(&text);
        let code = code
            .split("#[cfg(test)]\nmod tests")
            .next()
            .unwrap_or(&code);
        for dep in references(module, is_mod_rs, code, &known) {
            // A parent declaring and re-exporting its children: structure.
            if dep == *module || dep.starts_with(&format!("{module}::")) || dep.is_empty() {
                continue;
            }
            let dep_layer = layers.get(top(&dep)).copied().unwrap_or(u32::MAX);
            if top(&dep) != top(module) && dep_layer > layer {
                problems.push(format!(
                    "{krate}: `{module}` (layer {layer}) imports `{dep}` (layer {dep_layer}), a higher layer"
                ));
            }
            graph.entry(module.clone()).or_default().insert(dep);
        }
    }
    problems.extend(cycles(krate, &graph));
    problems
}

/// Loops in the import graph, each reported once.
fn cycles(krate: &str, graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        stack: &mut Vec<String>,
        done: &mut BTreeSet<String>,
        found: &mut Vec<String>,
    ) {
        if let Some(i) = stack.iter().position(|s| s == node) {
            found.push(stack[i..].join(" -> ") + " -> " + node);
            return;
        }
        if done.contains(node) {
            return;
        }
        stack.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            visit(next, graph, stack, done, found);
        }
        stack.pop();
        done.insert(node.to_string());
    }
    let (mut done, mut found) = (BTreeSet::new(), Vec::new());
    for node in graph.keys() {
        visit(node, graph, &mut Vec::new(), &mut done, &mut found);
    }
    found
        .into_iter()
        .map(|c| format!("{krate}: modules import each other: {c}"))
        .collect()
}

/// Functions over [`MAX_FUNCTION_LINES`] lines, outside `#[cfg(test)]` modules.
fn long_functions(path: &Path, text: &str) -> Vec<String> {
    let lines: Vec<&str> = text.lines().collect();
    let test_module = lines
        .windows(2)
        .position(|w| w[0].trim() == "#[cfg(test)]" && w[1].trim_start().starts_with("mod "))
        .unwrap_or(lines.len());
    let is_test_file = path
        .file_name()
        .is_some_and(|n| n.to_string_lossy().ends_with("_tests.rs"));
    let mut out = Vec::new();
    if is_test_file {
        return out;
    }
    let mut i = 0;
    while i < test_module {
        let line = lines[i].trim_start();
        let is_fn = (line.starts_with("fn ") || line.contains(" fn "))
            && !line.starts_with("//")
            && !line.ends_with(';');
        if !is_fn {
            i += 1;
            continue;
        }
        // The body ends where the braces opened after the signature close.
        let (mut depth, mut opened, mut j) = (0i64, false, i);
        while j < lines.len() {
            for c in lines[j].chars() {
                match c {
                    '{' => {
                        depth += 1;
                        opened = true;
                    }
                    '}' => depth -= 1,
                    _ => {}
                }
            }
            if opened && depth <= 0 {
                break;
            }
            j += 1;
        }
        let length = j + 1 - i;
        if length > MAX_FUNCTION_LINES {
            out.push(format!(
                "{}:{}: a function of {length} lines, more than {MAX_FUNCTION_LINES}",
                path.display(),
                i + 1
            ));
        }
        i = j + 1;
    }
    out
}

#[test]
fn layers_hold_and_nothing_is_too_long() {
    let mut problems = check_crate("profile-core", "profile-core/src");
    problems.extend(check_crate("profile-macros", "profile-macros/src"));
    assert!(
        problems.is_empty(),
        "{} problem(s) with the architecture (ARCHITECTURE.md):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The checker itself: paths resolve to modules, loops and upward imports
/// are found.
#[test]
fn the_checker_sees_imports_and_loops() {
    let known: BTreeSet<String> = [
        "",
        "base",
        "base::key",
        "curves",
        "curves::kind",
        "table::spec",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let text = "use crate::base::key::Key;\nuse super::kind::{CurveKind, Length};\nlet x = crate::table::spec::Spec::new();";
    let refs = references("curves::sigmoid", false, &code(text), &known);
    let expected: BTreeSet<String> = ["base::key", "curves::kind", "table::spec"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(refs, expected);
    // Comments are not imports.
    assert!(references("curves", true, &code("// crate::table::spec"), &known).is_empty());
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    graph.entry("a".into()).or_default().insert("b".into());
    graph.entry("b".into()).or_default().insert("a".into());
    assert_eq!(
        cycles("k", &graph),
        vec!["k: modules import each other: a -> b -> a"]
    );
    let long = format!("fn f() {{\n{}}}\n", "    x();\n".repeat(MAX_FUNCTION_LINES));
    assert_eq!(long_functions(Path::new("f.rs"), &long).len(), 1);
}
