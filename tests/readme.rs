//! The README and the guide's pages (`src/guide/*.md`, rendered as
//! `stepper_profiles::guide`; their Rust examples are doc tests): the
//! examples that cannot run on the host are files CI builds, shown as they
//! are, every page is a module of the guide, and every link to one names a
//! page that exists.

use std::fs;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// What the step-interrupt examples in `rigs/firmware/examples` hold after
/// the guide's block: the harness that times its step pin in QEMU, and nothing
/// else.
const HARNESS: &str = "

// Not in the guide: the harness that times the step pin in QEMU.
#[path = \"harness/step_interrupt.rs\"]
mod harness;";

/// The step-interrupt firmwares of the guide's RTIC and firmware pages are
/// `rigs/firmware/examples/rtic_step.rs` (the RTIC task) and
/// `step_interrupt.rs` (the hand-rolled handover), which CI runs on a
/// Cortex-M3 in QEMU: the guide's code, then the harness.
#[test]
fn the_step_interrupt_examples_are_the_files_ci_builds() {
    for (page, marker, example) in [
        ("src/guide/rtic.md", "#[rtic::app(", "rtic_step.rs"),
        ("src/guide/firmware.md", "fn SysTick()", "step_interrupt.rs"),
    ] {
        let readme = read(page);
        let file = fs::read_to_string(root().join("rigs/firmware/examples").join(example)).unwrap();
        let block = readme
            .split("```rust,ignore\n")
            .find(|b| b.split("\n```").next().is_some_and(|b| b.contains(marker)))
            .and_then(|b| b.split("\n```").next())
            .unwrap_or_else(|| panic!("a `rust,ignore` block with `{marker}` in {page}"));
        assert_eq!(
            format!("{}{}", block.trim_end(), HARNESS),
            file.trim_end(),
            "the guide's step interrupt differs from rigs/firmware/examples/{example}"
        );
    }
}

/// The PIO and RMT pages show their examples as written: each `rust,ignore`
/// block a passage of the example's files, and the PIO program's text the
/// one in `pio_step.rs`'s documentation.
#[test]
fn the_pio_and_rmt_pages_show_the_examples_as_they_are() {
    for (page, dir, files, blocks) in [
        (
            "src/guide/pio.md",
            "examples/hal/rp2040/src",
            ["bin/pio.rs", "pio_step.rs"],
            2,
        ),
        (
            "src/guide/rmt.md",
            "examples/hal/esp32c3/src",
            ["bin/rmt.rs", "rmt_step.rs"],
            2,
        ),
    ] {
        let text = read(page);
        let dir = root().join(dir);
        let files: String = files
            .iter()
            .map(|f| fs::read_to_string(dir.join(f)).unwrap())
            .collect();
        let fenced = |fence: &str| -> Vec<String> {
            text.split(fence)
                .skip(1)
                .filter_map(|b| b.split("\n```").next())
                .map(String::from)
                .collect()
        };
        let rust = fenced("```rust,ignore\n");
        assert_eq!(rust.len(), blocks, "Rust blocks in {page}");
        for block in rust {
            // As in the file, or a passage of a function's body.
            let indented: Vec<String> = block.lines().map(|l| format!("    {l}")).collect();
            let found = files.contains(&block) || files.contains(&indented.join("\n"));
            assert!(found, "{page}: not in the example, as written:\n{block}");
        }
        if page.ends_with("pio.md") {
            let [program] = &fenced("```text\n")[..] else {
                panic!("one program in {page}");
            };
            let documented: String = fs::read_to_string(dir.join("pio_step.rs"))
                .unwrap()
                .lines()
                .filter_map(|l| l.strip_prefix("//! ").or(l.strip_prefix("//!")))
                .collect::<Vec<_>>()
                .join("\n");
            assert!(
                documented.contains(program.as_str()),
                "the program differs from pio_step.rs's:\n{program}"
            );
        }
    }
}

/// The README and the pages it sends readers to: the guide's pages, which
/// rustdoc renders as `stepper_profiles::guide`, and the notes in `docs/`.
fn pages() -> Vec<(String, String)> {
    let mut pages = vec![("README.md".to_string(), read("README.md"))];
    for dir in ["src/guide", "docs"] {
        let mut names: Vec<String> = fs::read_dir(root().join(dir))
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|name| name.ends_with(".md"))
            .collect();
        names.sort_unstable();
        for name in names {
            let path = format!("{dir}/{name}");
            let text = read(&path);
            pages.push((path, text));
        }
    }
    pages
}

fn read(path: &str) -> String {
    fs::read_to_string(root().join(path)).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Every figure the README and its pages show is in `docs/` (they link them
/// by their address on the main branch, which renders on GitHub and on
/// docs.rs alike), and every figure there is shown.
#[test]
fn the_documented_figures_are_in_docs() {
    let prefix = "https://raw.githubusercontent.com/stepper-profiles/stepper-profiles/main/docs/";
    let pages = pages();
    let mut shown: Vec<&str> = pages
        .iter()
        .flat_map(|(_, text)| text.split(prefix).skip(1))
        .map(|rest| rest.split(')').next().unwrap())
        .collect();
    shown.sort_unstable();
    shown.dedup();
    let mut files: Vec<String> = fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| !name.ends_with(".md"))
        .collect();
    files.sort_unstable();
    assert_eq!(shown, files);
}

/// The names of the guide's pages, `src/guide/NAME.md`, sorted.
fn guide_pages() -> Vec<String> {
    pages()
        .into_iter()
        .filter_map(|(path, _)| {
            let name = path.strip_prefix("src/guide/")?.strip_suffix(".md")?;
            Some(name.to_string())
        })
        .collect()
}

/// Every page in `src/guide` is a module of `src/guide.rs`, so that rustdoc
/// renders it and runs its examples; every module there is a page.
#[test]
fn every_guide_page_is_a_module() {
    let modules = read("src/guide.rs");
    let mut included: Vec<String> = modules
        .split("include_str!(\"guide/")
        .skip(1)
        .map(|rest| rest.split(".md\")").next().unwrap().to_string())
        .collect();
    included.sort_unstable();
    let pages = guide_pages();
    assert_eq!(included, pages);
    for page in &pages {
        assert!(
            modules.contains(&format!(
                "include_str!(\"guide/{page}.md\")]\npub mod {page} {{}}"
            )),
            "src/guide/{page}.md is not the page of `pub mod {page}`"
        );
    }
}

/// The README links each page by its address on docs.rs (which works on
/// GitHub, crates.io and docs.rs alike); every such link names a page of
/// the guide, and every page of the guide is linked from the README.
#[test]
fn the_readme_links_every_guide_page() {
    let readme = read("README.md");
    let prefix = "https://docs.rs/stepper-profiles/latest/stepper_profiles/guide/";
    let mut linked: Vec<&str> = readme
        .split(prefix)
        .skip(1)
        .map(|rest| rest.split("/index.html").next().unwrap())
        .collect();
    linked.sort_unstable();
    linked.dedup();
    let pages = guide_pages();
    assert_eq!(linked, pages, "the guide's pages linked from README.md");
}
