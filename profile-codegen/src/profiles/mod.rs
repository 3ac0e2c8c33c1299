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
//! profile is ignored for it: a key its curve does not take (`flexible` for
//! a linear ramp), `len` where the profile sets its length by `accel` or
//! `tau`, `compress` where it gives `segments`, and the reverse.
//!
//! One key is the file's alone: `emergency = "NAME"` names another profile
//! of the file as the profile's emergency ramp (`Player::with_emergency`,
//! `Player::abort`). The file checks that it stops the profile (the same
//! timer, word and `reload_offset`; compressed when the profile is; as fast
//! at its top; within the profile's motor when it names none of its own)
//! and gives the profile's module `STOP_STEPS`, the steps an abort plays
//! after each step of its ramp (`NAME_STOP_STEPS` in C).
//!
//! In a build script, one call reads the file, writes `OUT_DIR/profiles.rs`,
//! asks Cargo to rerun when the file changes and reports a mistake as
//! Cargo's own `error:` lines:
//!
//! ```no_run
//! // build.rs, in `fn main`:
//! if let Some(profiles) = profile_codegen::profiles::build_script("profiles.toml") {
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

use crate::emit;
pub use crate::emit::c::{CStyle, CStyleError, Split};
pub use crate::emit::{Emergency, Profile};
use crate::pipeline::{self, Budget, Options};
use crate::schema::Diagnostic;

mod emergency;
mod file;
mod render;

pub use render::LoadError;
use render::render;

/// The most entries (steps, summed over every profile) one profiles file may
/// generate: four tables of [`MAX_LEN`](profile_core::MAX_LEN), 512 KiB of `u16`
/// flash. It bounds the work and memory of one `include_profiles!` or build
/// script; a file above it is refused before its tables are computed.
pub const MAX_FILE_ENTRIES: u32 = 4 * profile_core::MAX_LEN;

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
        let bytes = std::fs::read(path).map_err(|e| LoadError {
            text: format!("cannot read `{}`: {e}", path.display()),
        })?;
        let mut profiles = Self::parse_bytes(&path.display().to_string(), &bytes)?;
        profiles.path = Some(path.to_path_buf());
        Ok(profiles)
    }

    /// [`Profiles::parse`] on a file's bytes: a byte that is not UTF-8 is a
    /// mistake at its `file:line:col`.
    pub fn parse_bytes(file: &str, bytes: &[u8]) -> Result<Self, LoadError> {
        match core::str::from_utf8(bytes) {
            Ok(source) => Self::parse(file, source),
            Err(e) => {
                // The text up to the byte is read as it is; the byte (and
                // the rest of its sequence) shows as one U+FFFD.
                let at = e.valid_up_to();
                let source = String::from_utf8_lossy(bytes);
                let byte = bytes.get(at).copied().unwrap_or(0);
                let message = format!(
                    "byte 0x{byte:02X} is not UTF-8 text: a profiles file is UTF-8 (TOML's \
                     encoding); save it as UTF-8"
                );
                let d = Diagnostic {
                    loc: at..at + char::REPLACEMENT_CHARACTER.len_utf8(),
                    message,
                };
                Err(render(file, &source, &[d]))
            }
        }
    }

    /// Checks and computes the profiles in `source`; `file` names it in messages.
    pub fn parse(file: &str, source: &str) -> Result<Self, LoadError> {
        let read = file::read(source).map_err(|d| render(file, source, &[d]))?;
        let mut diagnostics = read.diagnostics;
        let mut budget = Budget {
            used: 0,
            limit: MAX_FILE_ENTRIES as u64,
        };
        let (mut profiles, mut emergencies, mut failed) = (Vec::new(), Vec::new(), Vec::new());
        for p in read.profiles {
            let options = Options {
                assumed: &read.meant,
                budget: Some(&mut budget),
                profile: Some(&p.name),
            };
            match pipeline::compile(&p.args, &p.whole, options) {
                Ok(compiled) => {
                    profiles.push(Profile::new(p.name, compiled));
                    emergencies.push(p.emergency);
                }
                Err(mut d) => {
                    diagnostics.append(&mut d);
                    failed.push(p.name);
                }
            }
        }
        diagnostics.extend(emergency::resolve(&mut profiles, &emergencies, &failed));
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

    /// One C header with every profile's table (`static const`) and
    /// figures (`#define`s), and the players of its kinds of table (a move
    /// player with `Player`'s semantics per kind, the run expander);
    /// compiles as C89 and C99. Its guard and players are named after the
    /// profiles file (`STEPPER_PROFILES_RAMPS_H`, `ramps_player_*` and
    /// `ramps_runs_*` for `ramps.toml`); [`c_header_named`](Self::c_header_named)
    /// names them after the header's own file.
    pub fn c_header(&self) -> String {
        self.c_header_with(&CStyle::default())
    }

    /// [`c_header`](Self::c_header) with the arrays placed by `style`
    /// (`__code`, `PROGMEM`, a linker section) and named by its `prefix`,
    /// if any. `style` is pasted as it is: [`CStyle::check`] it first (the
    /// `write_` functions do).
    pub fn c_header_with(&self, style: &CStyle) -> String {
        emit::c::header(
            &stem(&self.file),
            &self.source_name(),
            &self.profiles,
            style,
        )
    }

    /// The C header to be written as `header_name` (`x_axis.h`): its guard
    /// and players named after it (`STEPPER_PROFILES_X_AXIS_H`,
    /// `x_axis_player_*`, `x_axis_runs_*`), unless `style.prefix` names them, so that the
    /// headers of two files, however those are named, go in one program.
    pub fn c_header_named(&self, header_name: &str, style: &CStyle) -> String {
        emit::c::header(
            &stem(header_name),
            &self.source_name(),
            &self.profiles,
            style,
        )
    }

    /// A C header of `extern` declarations and figures, and the source file
    /// that defines the tables once; the source includes the header as
    /// `header_name`, after which the header's guard and players are
    /// named unless `style.prefix` names them.
    pub fn c_split(&self, header_name: &str, style: &CStyle) -> Split {
        emit::c::split(
            &stem(header_name),
            &self.source_name(),
            header_name,
            &self.profiles,
            style,
        )
    }

    /// The file's name without its folder, for generated comments.
    fn source_name(&self) -> String {
        Path::new(&self.file)
            .file_name()
            .map_or(self.file.clone(), |s| s.to_string_lossy().into_owned())
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
    /// the folder; its guard and players are named after the file
    /// ([`c_header_named`](Self::c_header_named)). In a build script
    /// (`OUT_DIR` set) a relative path is under `OUT_DIR`, never in the
    /// source tree; give an absolute path to write elsewhere.
    pub fn write_c_header(&self, path: impl AsRef<Path>) -> Result<PathBuf, LoadError> {
        self.write_c_header_with(path, &CStyle::default())
    }

    /// [`write_c_header`](Self::write_c_header), placed and named by
    /// `style`, which is checked first.
    pub fn write_c_header_with(
        &self,
        path: impl AsRef<Path>,
        style: &CStyle,
    ) -> Result<PathBuf, LoadError> {
        check(style)?;
        let path = out_path(path.as_ref());
        write(&path, &self.c_header_named(&file_name(&path), style))?;
        Ok(path)
    }

    /// Writes the C header of `extern` declarations to `header` and the
    /// definitions beside it, with the extension `.c` (`ramps.h` and
    /// `ramps.c`), placed by `style`; returns both paths. Relative paths are
    /// under `OUT_DIR` in a build script, as for
    /// [`write_c_header`](Self::write_c_header).
    pub fn write_c_split(
        &self,
        header: impl AsRef<Path>,
        style: &CStyle,
    ) -> Result<(PathBuf, PathBuf), LoadError> {
        check(style)?;
        let header = out_path(header.as_ref());
        let source = header.with_extension("c");
        let files = self.c_split(&file_name(&header), style);
        write_all(&[(&header, &files.header), (&source, &files.source)])?;
        Ok((header, source))
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

/// A style the C can hold, or why not.
fn check(style: &CStyle) -> Result<(), LoadError> {
    style.check().map_err(|e| LoadError {
        text: format!("the C {e}"),
    })
}

/// The stem of a file's name: `x_axis` for `out/x_axis.h`.
fn stem(file: &str) -> String {
    Path::new(file)
        .file_stem()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned())
}

/// A path's file name, `profiles.h` if it has none.
fn file_name(path: &Path) -> String {
    path.file_name()
        .map_or("profiles.h".into(), |n| n.to_string_lossy().into_owned())
}

/// `path` under `OUT_DIR` when it is relative and a build script runs.
fn out_path(path: &Path) -> PathBuf {
    match std::env::var_os("OUT_DIR") {
        Some(out) if path.is_relative() => Path::new(&out).join(path),
        _ => path.to_path_buf(),
    }
}

fn write(path: &Path, contents: &str) -> Result<(), LoadError> {
    write_all(&[(path, contents)])
}

/// Writes every file or none, creating their folders: each is written
/// beside its place under a hidden name, and moved there once all are.
fn write_all(files: &[(&Path, &str)]) -> Result<(), LoadError> {
    let cannot = |path: &Path, e: &dyn core::fmt::Display| LoadError {
        text: format!("cannot write `{}`: {e}", path.display()),
    };
    let mut aside = Vec::new();
    let mut written = Ok(());
    for &(path, contents) in files {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            if let Err(e) = std::fs::create_dir_all(dir) {
                written = Err(LoadError {
                    text: format!("cannot create the folder `{}`: {e}", dir.display()),
                });
                break;
            }
        }
        if path.is_dir() {
            written = Err(cannot(path, &"it is a folder"));
            break;
        }
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        let temp = path.with_file_name(format!(".{name}.{}.partial", std::process::id()));
        aside.push(temp.clone());
        if let Err(e) = std::fs::write(&temp, contents) {
            written = Err(cannot(path, &e));
            break;
        }
    }
    if written.is_ok() {
        for (&(path, _), temp) in files.iter().zip(&aside) {
            if let Err(e) = std::fs::rename(temp, path) {
                written = Err(cannot(path, &e));
                break;
            }
        }
    }
    // What was not moved into place.
    for temp in aside.iter().filter(|t| t.exists()) {
        let _ = std::fs::remove_file(temp);
    }
    written
}
