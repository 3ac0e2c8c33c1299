//! The public API, as a list: every path a user of `profile-core`,
//! `profile-codegen` or `stepper-profiles` can name, read from the sources
//! with `syn`, against `tests/public-api.txt`. The firmware crate's face
//! stays small: at most [`FIRMWARE_PATHS`] paths. A change to what is public shows in `git diff`;
//! bless it with `UPDATE_GOLDEN=1 cargo test --test public_api`.
//!
//! The reader follows `mod` declarations from each crate's `lib.rs` and
//! resolves `pub use` (items, modules, globs) to where they are defined: a
//! line is `kind path`, with the features it needs. Items marked
//! `#[doc(hidden)]` (`__private`, which is not API) and `#[cfg(test)]`
//! modules are left out; so are what items hold (fields, variants,
//! methods). The curves' public items come from the `curves!` list, which
//! the reader expands the way the macro does (`curves::public`).

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

use syn::{Attribute, Item, UseTree, Visibility};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A module as its source declares it.
#[derive(Default)]
struct Module {
    /// Items defined here: name -> (kind, public, hidden, features).
    items: BTreeMap<String, (String, bool, bool, Vec<String>)>,
    /// Child modules: name -> (public, hidden, features).
    mods: BTreeMap<String, (bool, bool, Vec<String>)>,
    /// `use` declarations, flattened.
    uses: Vec<Use>,
}

/// A `use` declaration, flattened: (the name it gives or `*`, its source
/// path, public, hidden, features).
type Use = (String, Vec<String>, bool, bool, Vec<String>);

/// Every module of a crate by its path from the crate root (`[]` for it).
type Tree = BTreeMap<Vec<String>, Module>;

fn hidden(attrs: &[Attribute]) -> bool {
    attrs.iter().any(|a| {
        let mut hidden = false;
        if a.path().is_ident("doc") {
            let _ = a.parse_nested_meta(|m| {
                hidden |= m.path.is_ident("hidden");
                Ok(())
            });
        }
        hidden
    })
}

/// `cfg(test)`, and the features of `cfg(feature = "x")`.
fn cfg(attrs: &[Attribute]) -> (bool, Vec<String>) {
    let (mut test, mut features) = (false, Vec::new());
    for a in attrs.iter().filter(|a| a.path().is_ident("cfg")) {
        let text = a.meta.require_list().map(|l| l.tokens.to_string());
        let text = text.unwrap_or_default();
        test |= text
            .split(|c: char| !c.is_alphanumeric() && c != '_')
            .any(|w| w == "test");
        for part in text.split("feature").skip(1) {
            if let Some(name) = part.split('"').nth(1) {
                features.push(name.to_string());
            }
        }
    }
    (test, features)
}

fn is_pub(vis: &Visibility) -> bool {
    matches!(vis, Visibility::Public(_))
}

fn flatten(tree: &UseTree, prefix: &mut Vec<String>, out: &mut Vec<(String, Vec<String>)>) {
    match tree {
        UseTree::Path(p) => {
            prefix.push(p.ident.to_string());
            flatten(&p.tree, prefix, out);
            prefix.pop();
        }
        UseTree::Name(n) => {
            let mut path = prefix.clone();
            path.push(n.ident.to_string());
            let name = if n.ident == "self" {
                prefix.last().cloned().unwrap_or_default()
            } else {
                n.ident.to_string()
            };
            if n.ident == "self" {
                path.pop();
            }
            out.push((name, path));
        }
        UseTree::Rename(r) => {
            let mut path = prefix.clone();
            path.push(r.ident.to_string());
            out.push((r.rename.to_string(), path));
        }
        UseTree::Glob(_) => out.push(("*".to_string(), prefix.clone())),
        UseTree::Group(g) => g.items.iter().for_each(|t| flatten(t, prefix, out)),
    }
}

/// Reads the module at `path` (its items `items`, in folder `dir`) and its
/// children into `tree`.
fn read(tree: &mut Tree, path: Vec<String>, items: &[Item], dir: &Path) {
    let mut module = Module::default();
    for item in items {
        let (kind, ident, vis, attrs) = match item {
            Item::Struct(i) => ("struct", &i.ident, &i.vis, &i.attrs),
            Item::Enum(i) => ("enum", &i.ident, &i.vis, &i.attrs),
            Item::Fn(i) => ("fn", &i.sig.ident, &i.vis, &i.attrs),
            Item::Const(i) => ("const", &i.ident, &i.vis, &i.attrs),
            Item::Static(i) => ("static", &i.ident, &i.vis, &i.attrs),
            Item::Trait(i) => ("trait", &i.ident, &i.vis, &i.attrs),
            Item::Type(i) => ("type", &i.ident, &i.vis, &i.attrs),
            Item::Union(i) => ("union", &i.ident, &i.vis, &i.attrs),
            Item::Mod(m) => {
                let (test, features) = cfg(&m.attrs);
                if test {
                    continue;
                }
                let name = m.ident.to_string();
                let mut child = path.clone();
                child.push(name.clone());
                module
                    .mods
                    .insert(name.clone(), (is_pub(&m.vis), hidden(&m.attrs), features));
                match &m.content {
                    Some((_, inner)) => read(tree, child, inner, &dir.join(&name)),
                    None => {
                        let (file, sub) = [
                            (dir.join(format!("{name}.rs")), dir.join(&name)),
                            (dir.join(&name).join("mod.rs"), dir.join(&name)),
                        ]
                        .into_iter()
                        .find(|(f, _)| f.exists())
                        .unwrap_or_else(|| {
                            panic!("no file for module {name} in {}", dir.display())
                        });
                        let text = fs::read_to_string(&file).unwrap();
                        let parsed = syn::parse_file(&text)
                            .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
                        read(tree, child, &parsed.items, &sub);
                    }
                }
                continue;
            }
            Item::Use(u) => {
                let (test, features) = cfg(&u.attrs);
                if test {
                    continue;
                }
                let mut flat = Vec::new();
                flatten(&u.tree, &mut Vec::new(), &mut flat);
                for (name, source) in flat {
                    module.uses.push((
                        name,
                        source,
                        is_pub(&u.vis),
                        hidden(&u.attrs),
                        features.clone(),
                    ));
                }
                continue;
            }
            Item::Macro(m) if m.mac.path.is_ident("curves") => {
                curves(tree, &mut module, &m.mac.tokens.to_string(), &path);
                continue;
            }
            _ => continue,
        };
        let (test, features) = cfg(attrs);
        if !test {
            let entry = (kind.to_string(), is_pub(vis), hidden(attrs), features);
            module.items.insert(ident.to_string(), entry);
        }
    }
    tree.insert(path, module);
}

/// What `curves!` makes public: the `Curve` enum, and `public`, a module
/// re-exporting the enum and every item of each curve module it lists.
fn curves(tree: &mut Tree, module: &mut Module, tokens: &str, path: &[String]) {
    let entry = ("enum".to_string(), true, false, Vec::new());
    module.items.insert("Curve".into(), entry);
    module
        .mods
        .insert("public".into(), (true, false, Vec::new()));
    let curve_modules: Vec<String> = tokens
        .split(',')
        .filter_map(|entry| entry.split("::").next())
        .filter_map(|m| m.split_whitespace().last())
        .filter(|m| m.chars().all(|c| c.is_ascii_lowercase() || c == '_'))
        .map(str::to_string)
        .collect();
    assert!(curve_modules.len() >= 5, "curves! lists {curve_modules:?}");
    let use_of = |name: &str, source: &str| {
        let source = vec!["super".to_string(), source.to_string()];
        (name.to_string(), source, true, false, Vec::new())
    };
    let mut public = Module::default();
    public.uses.push(use_of("Curve", "Curve"));
    for m in &curve_modules {
        public.uses.push(use_of("*", m));
    }
    let mut at = path.to_vec();
    at.push("public".into());
    tree.insert(at, public);
}

/// What a name resolves to.
#[derive(Clone)]
enum Target {
    Item(String, Vec<String>),
    Module(Vec<String>, Vec<String>),
}

struct Crate {
    tree: Tree,
}

impl Crate {
    fn load(src: &str) -> Self {
        let dir = root().join(src);
        let text = fs::read_to_string(dir.join("lib.rs")).unwrap();
        let file = syn::parse_file(&text).unwrap();
        let mut tree = Tree::new();
        read(&mut tree, Vec::new(), &file.items, &dir);
        Crate { tree }
    }

    /// `path` (a `use` path written in module `at`) resolved.
    fn resolve(&self, at: &[String], path: &[String], depth: u32) -> Option<Target> {
        assert!(depth < 20, "re-exports loop at {path:?}");
        let mut here: Vec<String> = at.to_vec();
        let mut rest = path;
        match path.first().map(String::as_str) {
            Some("crate") => (here, rest) = (Vec::new(), &path[1..]),
            Some("self") => rest = &path[1..],
            _ => {}
        }
        while rest.first().is_some_and(|s| s == "super") {
            here.pop();
            rest = &rest[1..];
        }
        let (last, between) = rest.split_last()?;
        for segment in between {
            match self.lookup(&here, segment, depth)? {
                Target::Module(m, _) => here = m,
                Target::Item(..) => return None,
            }
        }
        self.lookup(&here, last, depth)
    }

    /// `name` as module `at` sees it: a child, an item, or what a `use`
    /// there names.
    fn lookup(&self, at: &[String], name: &str, depth: u32) -> Option<Target> {
        let module = self.tree.get(at)?;
        if let Some((_, _, features)) = module.mods.get(name) {
            let mut path = at.to_vec();
            path.push(name.to_string());
            return Some(Target::Module(path, features.clone()));
        }
        if let Some((kind, _, _, features)) = module.items.get(name) {
            return Some(Target::Item(kind.clone(), features.clone()));
        }
        let Some((_, source, _, _, features)) = module.uses.iter().find(|u| u.0 == name) else {
            // A name a glob brings in.
            return module.uses.iter().filter(|u| u.0 == "*").find_map(|u| {
                match self.resolve(at, &u.1, depth + 1)? {
                    Target::Module(m, _) => self.lookup(&m, name, depth + 1),
                    Target::Item(..) => None,
                }
            });
        };
        if source.len() == 1 && source[0] == name {
            // `pub use fugit;`: another crate.
            return Some(Target::Item("crate".into(), features.clone()));
        }
        self.resolve(at, source, depth + 1)
    }

    /// Every public path under module `at`, named `prefix`, into `out`.
    fn public(&self, at: &[String], prefix: &str, features: &[String], out: &mut BTreeSet<String>) {
        let Some(module) = self.tree.get(at) else {
            return;
        };
        let line = |kind: &str, path: &str, own: &[String]| {
            let mut all: Vec<String> = features.iter().chain(own).cloned().collect();
            all.sort();
            all.dedup();
            if all.is_empty() {
                format!("{kind} {path}")
            } else {
                format!("{kind} {path} (feature {})", all.join(", "))
            }
        };
        for (name, (kind, public, hidden, own)) in &module.items {
            if *public && !hidden {
                out.insert(line(kind, &format!("{prefix}::{name}"), own));
            }
        }
        for (name, (public, hidden, own)) in &module.mods {
            if *public && !hidden {
                let path = format!("{prefix}::{name}");
                out.insert(line("mod", &path, own));
                let mut child = at.to_vec();
                child.push(name.clone());
                let all: Vec<String> = features.iter().chain(own).cloned().collect();
                self.public(&child, &path, &all, out);
            }
        }
        for (name, source, public, hidden, own) in &module.uses {
            if !public || *hidden {
                continue;
            }
            let all: Vec<String> = features.iter().chain(own).cloned().collect();
            if name == "*" {
                if let Some(Target::Module(m, _)) = self.resolve(at, source, 0) {
                    let mut inner = BTreeSet::new();
                    self.public(&m, prefix, &all, &mut inner);
                    // A glob re-exports the module's own names, not theirs.
                    out.extend(inner.into_iter().filter(|l| {
                        let path = l.split(' ').nth(1).unwrap_or("");
                        !path[prefix.len() + 2..].contains("::")
                    }));
                }
                continue;
            }
            let path = format!("{prefix}::{name}");
            match self.resolve(at, source, 0) {
                Some(Target::Item(kind, item_features)) => {
                    let both: Vec<String> = own.iter().chain(&item_features).cloned().collect();
                    out.insert(line(&kind, &path, &both));
                }
                Some(Target::Module(m, _)) => {
                    out.insert(line("mod", &path, own));
                    self.public(&m, &path, &all, out);
                }
                None => {
                    out.insert(line("extern", &path, own));
                }
            }
        }
    }
}

/// The public paths of the three crates, one a line: the firmware crate's,
/// the host crate's, and the facade's re-exports of both.
fn surface() -> String {
    let core = Crate::load("profile-core/src");
    let mut lines = BTreeSet::new();
    core.public(&[], "profile_core", &[], &mut lines);
    let codegen = Crate::load("profile-codegen/src");
    let mut codegen_lines = BTreeSet::new();
    codegen.public(&[], "profile_codegen", &[], &mut codegen_lines);
    let mut facade_lines = BTreeSet::new();
    let facade = Crate::load("src");
    let module = &facade.tree[&Vec::new()];
    for (name, source, public, hidden, own) in &module.uses {
        if !public || *hidden {
            continue;
        }
        let path = format!("stepper_profiles::{name}");
        match source.first().map(String::as_str) {
            Some("profile_macros") => {
                facade_lines.insert(format!("macro {path}"));
            }
            Some(name @ ("profile_core" | "profile_codegen")) => {
                let krate = if name == "profile_core" {
                    &core
                } else {
                    &codegen
                };
                let target = krate.resolve(&[], &source[1..], 0);
                let target = target.unwrap_or_else(|| panic!("{source:?} is not in {name}"));
                let with = |kind: &str, more: &[String]| {
                    let mut f: Vec<String> = own.iter().chain(more).cloned().collect();
                    f.sort();
                    f.dedup();
                    if f.is_empty() {
                        format!("{kind} {path}")
                    } else {
                        format!("{kind} {path} (feature {})", f.join(", "))
                    }
                };
                match target {
                    Target::Item(kind, f) => {
                        facade_lines.insert(with(&kind, &f));
                    }
                    Target::Module(m, f) => {
                        facade_lines.insert(with("mod", &f));
                        let all: Vec<String> = own.iter().chain(&f).cloned().collect();
                        krate.public(&m, &path, &all, &mut facade_lines);
                    }
                }
            }
            _ => panic!("stepper_profiles re-exports {source:?}, from none of the crates"),
        }
    }
    let mut text = String::from(
        "# The public API of profile-core (firmware), profile-codegen (hosts) and\n\
         # stepper-profiles (both): `kind path (features)`.\n\
         # tests/public_api.rs writes it with UPDATE_GOLDEN=1; review what changed.\n",
    );
    for line in lines.iter().chain(&codegen_lines).chain(&facade_lines) {
        text.push_str(line);
        text.push('\n');
    }
    text
}

/// The most paths `profile-core`, the crate firmware depends on, may make
/// public: what a firmware author reads to use it.
const FIRMWARE_PATHS: usize = 60;

#[test]
fn the_firmware_face_fits_in_the_head() {
    let surface = surface();
    let core: Vec<&str> = surface
        .lines()
        .filter(|l| {
            l.split(' ')
                .nth(1)
                .is_some_and(|p| p.starts_with("profile_core::"))
        })
        .collect();
    assert!(
        core.len() > 40,
        "{} paths read: the reader is broken",
        core.len()
    );
    assert!(
        core.len() <= FIRMWARE_PATHS,
        "profile-core makes {} paths public, more than {FIRMWARE_PATHS}:\n{}",
        core.len(),
        core.join("\n")
    );
}

#[test]
fn the_public_api_is_the_listed_one() {
    let path: PathBuf = root().join("tests/public-api.txt");
    let actual = surface();
    if std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1") {
        fs::write(&path, &actual).unwrap();
        return;
    }
    let expected = fs::read_to_string(&path).unwrap_or_default();
    let (old, new): (BTreeSet<&str>, BTreeSet<&str>) =
        (expected.lines().collect(), actual.lines().collect());
    let gone: Vec<&&str> = old.difference(&new).collect();
    let added: Vec<&&str> = new.difference(&old).collect();
    assert!(
        gone.is_empty() && added.is_empty(),
        "the public API changed (bless with `UPDATE_GOLDEN=1 cargo test --test public_api` \
         and review tests/public-api.txt):\nno longer public:\n{gone:#?}\nnewly public:\n{added:#?}"
    );
}

/// The reader itself, on a crate written here: what is public, what is
/// hidden, what a re-export names.
#[test]
fn the_reader_sees_what_is_public() {
    let src = "pub mod a { pub struct S; pub(crate) struct T; pub fn f() {} \
               #[doc(hidden)] pub fn g() {} mod inner { pub struct U; } pub use inner::U as V; } \
               mod b { pub enum E { X } } pub use b::E; #[doc(hidden)] pub mod __private {} \
               #[cfg(feature = \"std\")] pub use a::S as Owned; #[cfg(test)] mod tests {}";
    let file = syn::parse_file(src).unwrap();
    let mut tree = Tree::new();
    read(&mut tree, Vec::new(), &file.items, Path::new("."));
    let krate = Crate { tree };
    let mut out = BTreeSet::new();
    krate.public(&[], "k", &[], &mut out);
    let expected: BTreeSet<String> = [
        "enum k::E",
        "fn k::a::f",
        "mod k::a",
        "struct k::Owned (feature std)",
        "struct k::a::S",
        "struct k::a::V",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    assert_eq!(out, expected);
}
