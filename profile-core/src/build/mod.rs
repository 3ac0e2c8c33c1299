//! `profiles.toml`: profiles declared in a file, for build scripts and the
//! `include_profiles!` macro.
//!
//! ```toml
//! [defaults]            # optional: any key, applied where a profile omits it
//! timer_hz = 10_000_000
//!
//! [profiles.orange]     # one table per profile; the name becomes a module
//! curve = "sigmoid"
//! len = 1000
//! fmin = 500
//! fmax = 64000
//! flexible = 8
//! ```
//!
//! A profile takes exactly the keys of `period_table!`; names (`curve`,
//! `rounding`, ...) are strings. A default that does not apply to a
//! profile's curve (`flexible` for a linear ramp) is ignored for it.
//!
//! In a build script, one call reads the file, writes `OUT_DIR/profiles.rs`,
//! asks Cargo to rerun when the file changes and reports a mistake as
//! Cargo's own `error:` lines:
//!
//! ```no_run
//! // build.rs, in `fn main`:
//! if let Some(profiles) = profile_core::build::build_script("profiles.toml") {
//!     // Optional: a C header too, under OUT_DIR.
//!     profiles.write_c_header("profiles.h").expect("OUT_DIR is writable");
//! }
//! ```
//!
//! and in the crate: `include!(concat!(env!("OUT_DIR"), "/profiles.rs"));`.
//! Every mistake in the file is reported as `profiles.toml:LINE:COL: message`
//! with the line and a caret under the offending text.

use std::format;
use std::path::{Path, PathBuf};
use std::println;
use std::string::{String, ToString};
use std::vec::Vec;

use proc_macro2::TokenStream;

use crate::emit::{self, Profile};
use crate::pipeline::{self, Budget, Options};

mod file;
mod render;

pub use render::LoadError;
use render::render;

/// The most entries (steps, summed over every profile) one profiles file may
/// generate: four tables of [`MAX_LEN`](crate::MAX_LEN), 512 KiB of `u16`
/// flash. It bounds the work and memory of one `include_profiles!` or build
/// script; a file above it is refused before its tables are computed.
pub const MAX_FILE_ENTRIES: u32 = 4 * crate::MAX_LEN;

/// The profiles of one file, checked and computed.
#[derive(Clone, Debug, PartialEq)]
pub struct Profiles {
    file: String,
    path: Option<PathBuf>,
    profiles: Vec<Profile>,
}

impl Profiles {
    /// Reads, checks and computes every profile of the file at `path`.
    pub fn load(path: impl AsRef<Path>) -> Result<Self, LoadError> {
        let path = path.as_ref();
        let source = std::fs::read_to_string(path).map_err(|e| LoadError {
            text: format!("cannot read `{}`: {e}", path.display()),
        })?;
        let mut profiles = Self::parse(&path.display().to_string(), &source)?;
        profiles.path = Some(path.to_path_buf());
        Ok(profiles)
    }

    /// Checks and computes the profiles in `source`; `file` names it in messages.
    pub fn parse(file: &str, source: &str) -> Result<Self, LoadError> {
        let read = file::read(source).map_err(|d| render(file, source, &[d]))?;
        let mut diagnostics = read.diagnostics;
        let mut budget = Budget {
            used: 0,
            limit: MAX_FILE_ENTRIES as u64,
        };
        let mut profiles = Vec::new();
        for p in read.profiles {
            let options = Options {
                assumed: &read.meant,
                budget: Some(&mut budget),
                profile: Some(&p.name),
            };
            match pipeline::compile(&p.args, &p.whole, options) {
                Ok(compiled) => profiles.push(Profile::new(p.name, compiled)),
                Err(mut d) => diagnostics.append(&mut d),
            }
        }
        if !diagnostics.is_empty() {
            // In source order, and once: a mistake in `[defaults]` reaches
            // every profile that uses it.
            diagnostics.sort_by_key(|d| (d.loc.start, d.loc.end));
            diagnostics.dedup();
            return Err(render(file, source, &diagnostics));
        }
        Ok(Profiles {
            file: file.to_string(),
            path: None,
            profiles,
        })
    }

    /// The profiles, in file order.
    pub fn profiles(&self) -> &[Profile] {
        &self.profiles
    }

    /// The file's name as used in messages.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// One module per profile, as tokens: what `include_profiles!` expands to.
    pub fn rust_tokens(&self) -> TokenStream {
        emit::rust::modules(&self.profiles)
    }

    /// The same modules as Rust source, as the build script writes them.
    pub fn rust_source(&self) -> String {
        emit::print::print(self.rust_tokens())
    }

    /// A C99 header with every profile's table and figures.
    pub fn c_header(&self) -> String {
        let stem = Path::new(&self.file)
            .file_stem()
            .map_or("profiles".into(), |s| s.to_string_lossy().into_owned());
        let guard: String = stem
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() {
                    c.to_ascii_uppercase()
                } else {
                    '_'
                }
            })
            .collect();
        let source = Path::new(&self.file)
            .file_name()
            .map_or(self.file.clone(), |s| s.to_string_lossy().into_owned());
        emit::c::header(
            &format!("STEPPER_PROFILES_{guard}_H"),
            &source,
            &self.profiles,
        )
    }

    /// Writes `profiles.rs` into `out_dir` (to `include!`), creating the
    /// folder, and, for a file read with [`Profiles::load`], prints
    /// `cargo::rerun-if-changed` for it.
    pub fn write_rust(&self, out_dir: impl AsRef<Path>) -> Result<PathBuf, LoadError> {
        let target = out_dir.as_ref().join("profiles.rs");
        write(&target, &self.rust_source())?;
        if let Some(path) = &self.path {
            println!("cargo::rerun-if-changed={}", path.display());
        }
        Ok(target)
    }

    /// Writes the C header to `path` and returns where it went, creating
    /// the folder. In a build script (`OUT_DIR` set) a relative path is
    /// under `OUT_DIR`, never in the source tree; give an absolute path to
    /// write elsewhere.
    pub fn write_c_header(&self, path: impl AsRef<Path>) -> Result<PathBuf, LoadError> {
        let path = match std::env::var_os("OUT_DIR") {
            Some(out) if path.as_ref().is_relative() => Path::new(&out).join(path),
            _ => path.as_ref().to_path_buf(),
        };
        write(&path, &self.c_header())?;
        Ok(path)
    }
}

/// The one call a build script needs: reads the profiles file at `path`
/// (relative to the package, where Cargo runs build scripts), writes
/// `OUT_DIR/profiles.rs` and asks Cargo to rerun when the file changes.
///
/// A mistake is reported to Cargo as `cargo::error=` lines, the location,
/// the source line and the caret each on its own, so the build fails with
/// the message as `cargo build` prints errors; the result is then `None`.
pub fn build_script(path: impl AsRef<Path>) -> Option<Profiles> {
    let path = path.as_ref();
    println!("cargo::rerun-if-changed={}", path.display());
    let loaded = Profiles::load(path).and_then(|profiles| {
        let out_dir = std::env::var_os("OUT_DIR").ok_or_else(|| LoadError {
            text: "`OUT_DIR` is not set: `build_script` runs in a build script (build.rs)"
                .to_string(),
        })?;
        profiles.write_rust(out_dir)?;
        Ok(profiles)
    });
    match loaded {
        Ok(profiles) => Some(profiles),
        Err(e) => {
            for line in e.message().lines() {
                println!("cargo::error={line}");
            }
            None
        }
    }
}

fn write(path: &Path, contents: &str) -> Result<(), LoadError> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| LoadError {
            text: format!("cannot create the folder `{}`: {e}", dir.display()),
        })?;
    }
    std::fs::write(path, contents).map_err(|e| LoadError {
        text: format!("cannot write `{}`: {e}", path.display()),
    })
}
