//! The layers of `ARCHITECTURE.md`, checked on the source.
//!
//! `ARCHITECTURE.md` lists each crate's modules by layer in its tables; this
//! test reads those tables and every `crate::` and `super::` path in
//! `profile-core/src`, `profile-codegen/src` and `profile-macros/src`
//! (comments aside), and checks:
//!
//! - no module imports one of a higher layer (a parent declaring its own
//!   children is structure, not an import, and is not counted);
//! - no two modules import each other, directly or around a loop;
//! - no source file is over 600 lines.
//!
//! And, reading every source file of the five crates (`profile-core`,
//! `profile-codegen`, `profile-macros`, `profile-cli` and the facade's
//! `src/`) with `syn`: no
//! function outside tests is over 100 lines, from its `fn` to its closing
//! brace.

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

/// Where no function may be over [`MAX_FUNCTION_LINES`] lines: every
/// crate's sources.
const FUNCTION_SOURCES: &[&str] = &[
    "profile-core/src",
    "profile-codegen/src",
    "profile-macros/src",
    "profile-cli/src",
    "src",
];

/// Functions over [`MAX_FUNCTION_LINES`] lines, each named as the check
/// names it (`file: function`), with why it is let be. Empty: none is.
const LONG_FUNCTIONS_ALLOWED: &[&str] = &[];

/// A function of a source file: its name (`Type::method` in an `impl`,
/// `Trait::method` for a trait's default body), the line of its `fn`
/// (attributes and doc comments aside) and its length in lines, to its
/// closing brace.
#[derive(Debug, PartialEq)]
struct Function {
    name: String,
    line: usize,
    lines: usize,
}

fn is_cfg_test(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|a| {
        a.path().is_ident("cfg")
            && a.meta
                .require_list()
                .is_ok_and(|l| l.tokens.to_string() == "test")
    })
}

/// The functions of `source`, outside `#[cfg(test)]` items, nested ones
/// (in a function's body, a module, an `impl`, a trait) included.
fn functions(source: &str) -> syn::Result<Vec<Function>> {
    fn function(name: String, sig: &syn::Signature, body: &syn::Block, out: &mut Vec<Function>) {
        let first = sig.fn_token.span.start().line;
        let last = body.brace_token.span.close().end().line;
        out.push(Function {
            name,
            line: first,
            lines: last + 1 - first,
        });
        for stmt in &body.stmts {
            if let syn::Stmt::Item(item) = stmt {
                items(std::slice::from_ref(item), "", out);
            }
        }
    }
    fn type_name(ty: &syn::Type) -> String {
        match ty {
            syn::Type::Path(p) => p
                .path
                .segments
                .last()
                .map_or_else(String::new, |s| s.ident.to_string()),
            _ => "impl".to_string(),
        }
    }
    fn items(list: &[syn::Item], prefix: &str, out: &mut Vec<Function>) {
        for item in list {
            match item {
                syn::Item::Fn(f) if !is_cfg_test(&f.attrs) => {
                    function(format!("{prefix}{}", f.sig.ident), &f.sig, &f.block, out);
                }
                syn::Item::Mod(m) if !is_cfg_test(&m.attrs) => {
                    if let Some((_, content)) = &m.content {
                        items(content, &format!("{prefix}{}::", m.ident), out);
                    }
                }
                syn::Item::Impl(i) if !is_cfg_test(&i.attrs) => {
                    let ty = type_name(&i.self_ty);
                    for item in &i.items {
                        if let syn::ImplItem::Fn(f) = item {
                            if !is_cfg_test(&f.attrs) {
                                let name = format!("{prefix}{ty}::{}", f.sig.ident);
                                function(name, &f.sig, &f.block, out);
                            }
                        }
                    }
                }
                syn::Item::Trait(t) if !is_cfg_test(&t.attrs) => {
                    for item in &t.items {
                        if let syn::TraitItem::Fn(f) = item {
                            if let Some(body) = &f.default {
                                let name = format!("{prefix}{}::{}", t.ident, f.sig.ident);
                                function(name, &f.sig, body, out);
                            }
                        }
                    }
                }
                _ => {}
            }
        }
    }
    let file = syn::parse_file(source)?;
    let mut out = Vec::new();
    items(&file.items, "", &mut out);
    Ok(out)
}

/// Functions over [`MAX_FUNCTION_LINES`] lines in the workspace's sources
/// (test modules and `*_tests.rs` files aside), but for those
/// [`LONG_FUNCTIONS_ALLOWED`] lets be; and entries of that list that name
/// no function over the limit, which are stale.
fn long_functions() -> Vec<String> {
    let mut found = Vec::new();
    let mut problems = Vec::new();
    for dir in FUNCTION_SOURCES {
        for (_, path) in modules(&root().join(dir)) {
            let rel = path.strip_prefix(root()).unwrap().to_string_lossy();
            let rel = rel.replace(std::path::MAIN_SEPARATOR, "/");
            if rel.ends_with("_tests.rs") {
                continue;
            }
            let text = fs::read_to_string(&path).unwrap();
            let functions = functions(&text).unwrap_or_else(|e| panic!("{rel}: not parsed: {e}"));
            for f in functions {
                if f.lines <= MAX_FUNCTION_LINES {
                    continue;
                }
                let named = format!("{rel}: {}", f.name);
                if !LONG_FUNCTIONS_ALLOWED.contains(&named.as_str()) {
                    problems.push(format!(
                        "{rel}:{}: `{}` is {} lines, more than {MAX_FUNCTION_LINES}",
                        f.line, f.name, f.lines
                    ));
                }
                found.push(named);
            }
        }
    }
    for allowed in LONG_FUNCTIONS_ALLOWED {
        if !found.iter().any(|f| f == allowed) {
            problems.push(format!(
                "LONG_FUNCTIONS_ALLOWED names `{allowed}`, which is no function over \
                 {MAX_FUNCTION_LINES} lines: take it off the list"
            ));
        }
    }
    problems
}

#[test]
fn no_function_is_over_the_limit() {
    let problems = long_functions();
    assert!(
        problems.is_empty(),
        "{} function(s) too long (ARCHITECTURE.md, what may import what):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn layers_hold_and_nothing_is_too_long() {
    let mut problems = check_crate("profile-core", "profile-core/src");
    problems.extend(check_crate("profile-codegen", "profile-codegen/src"));
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
}

/// The function reader: names, lines from `fn` to the closing brace,
/// nested functions and methods, test modules left out.
#[test]
fn the_function_reader_measures_functions() {
    let body = "    x();\n".repeat(MAX_FUNCTION_LINES);
    let source = format!(
        "/// Docs.\n#[inline]\nfn f() {{\n{body}}}\n\
         impl<T> S<T> {{\n    pub fn g(&self) {{\n        fn h() {{}}\n    }}\n}}\n\
         trait T {{\n    fn d() {{\n    }}\n    fn r();\n}}\n\
         mod m {{\n    fn i() {{ let s = \"}}\"; }}\n}}\n\
         #[cfg(test)]\nmod tests {{\n    fn t() {{}}\n}}\n"
    );
    let found = functions(&source).unwrap();
    let line = |name: &str| {
        found
            .iter()
            .find(|f| f.name == name)
            .map(|f| (f.line, f.lines))
    };
    // The line of `impl`.
    let at = 3 + MAX_FUNCTION_LINES + 2;
    assert_eq!(line("f"), Some((3, MAX_FUNCTION_LINES + 2)));
    assert_eq!(line("S::g"), Some((at + 1, 3)));
    assert_eq!(line("h"), Some((at + 2, 1)));
    assert_eq!(line("T::d"), Some((at + 6, 2)));
    assert_eq!(line("m::i"), Some((at + 11, 1)));
    assert_eq!(found.len(), 5, "{found:?}");
}

/// The names of the dependencies in the `[dependencies]` table of a
/// manifest.
fn dependencies(manifest: &str) -> Vec<String> {
    let text = fs::read_to_string(root().join(manifest)).unwrap();
    let table = text
        .split("\n[dependencies]\n")
        .nth(1)
        .unwrap_or_else(|| panic!("{manifest} has no [dependencies]"));
    table
        .lines()
        .take_while(|l| !l.starts_with('['))
        .filter_map(|l| l.split_once('=').map(|(name, _)| name.trim().to_string()))
        .filter(|name| !name.is_empty() && !name.starts_with('#'))
        .collect()
}

/// The firmware crate depends on nothing of the generator, and has no
/// feature that would bring it: a firmware build compiles `profile-core`
/// and its two numeric crates, and the generator only inside the macros,
/// on the host.
#[test]
fn the_firmware_crate_holds_none_of_the_generator() {
    assert_eq!(dependencies("profile-core/Cargo.toml"), ["libm", "fugit"]);
    let manifest = fs::read_to_string(root().join("profile-core/Cargo.toml")).unwrap();
    for feature in ["std", "codegen", "golden"] {
        assert!(
            !manifest.contains(&format!("\n{feature} = ")),
            "profile-core has a feature `{feature}`"
        );
    }
    // The facade builds the host crate only with a host feature.
    let facade = fs::read_to_string(root().join("Cargo.toml")).unwrap();
    assert!(facade.contains("profile-codegen = { workspace = true, optional = true }"));
    assert!(facade.contains("std = [\"dep:profile-codegen\"]"));
    // No module of the generator in the firmware crate's sources.
    for module in ["motor", "schema", "pipeline", "emit", "profiles", "golden"] {
        assert!(
            !root().join("profile-core/src").join(module).exists()
                && !root()
                    .join(format!("profile-core/src/{module}.rs"))
                    .exists(),
            "profile-core/src holds `{module}`"
        );
    }
}

/// One unit-test convention: a file's unit tests are its `mod tests`, at
/// its end; only where the file and its tests together would pass
/// [`MAX_FILE_LINES`] do they go in a sibling `NAME_tests.rs`
/// (`#[path = "NAME_tests.rs"] mod tests;`), and nowhere else.
#[test]
fn unit_tests_live_in_their_file_unless_it_would_be_too_long() {
    let mut problems = Vec::new();
    let mut seen = 0;
    for dir in FUNCTION_SOURCES {
        for (_, path) in modules(&root().join(dir)) {
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            if name.ends_with("_tests.rs") {
                continue;
            }
            let text = fs::read_to_string(&path).unwrap();
            let Some(at) = text.find("#[path = \"") else {
                continue;
            };
            let target = text[at + 10..].split('"').next().unwrap();
            seen += 1;
            let expected = format!("{}_tests.rs", name.trim_end_matches(".rs"));
            if target != expected {
                problems.push(format!(
                    "{}: tests in `{target}`, not `{expected}`",
                    path.display()
                ));
                continue;
            }
            let tests = fs::read_to_string(path.with_file_name(target)).unwrap();
            let together = text.lines().count() + tests.lines().count();
            if together <= MAX_FILE_LINES {
                problems.push(format!(
                    "{}: {together} lines with its tests: keep them in the file's `mod tests`",
                    path.display()
                ));
            }
        }
    }
    assert!(seen > 0, "no `#[path]` tests seen: the reader is broken");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
