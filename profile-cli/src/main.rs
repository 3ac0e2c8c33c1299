//! `stepper-profiles`: stepper-motor acceleration tables from a profiles
//! file, for C and Rust firmware alike.
//!
//! ```text
//! stepper-profiles report [FILE] [-o DIR]   figures of every profile
//! stepper-profiles check FILE...            exit 1 on a mistake, file:line:col
//! stepper-profiles header FILE [-o OUT]     the C (--split: OUT.h and OUT.c)
//! stepper-profiles rust FILE [-o OUT]       the Rust modules
//! stepper-profiles plot FILE [-o DIR]       SVG plots and CSV tables
//! stepper-profiles trace PROFILE --move N   a move's exact edges as VCD
//! stepper-profiles compare PROFILE CAPTURE --move N   a capture against them
//! ```

mod files;
mod plots;
mod report;
mod staging;

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::mpsc;
use std::time::Duration;

use clap::{Parser, Subcommand};
use profile_codegen::capture::{Capture, Edges, Reference, Timing};
use profile_codegen::profiles::{CStyle, Profiles};
use staging::Staging;

/// Stepper-motor acceleration tables from a profiles file: report their
/// figures, check the file, write the C or the Rust, plot them.
///
/// A profiles file declares one table per `[profiles.NAME]` section (see
/// the `profiles.toml` shipped with stepper-profiles). A mistake in it is
/// printed as `file:line:col: message` with the line and a caret, and the
/// command exits with status 1.
#[derive(Debug, Parser)]
#[command(name = "stepper-profiles", version, max_term_width = 100)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Print every profile's parameters and figures, each motor's figures as
    /// the check reads them, the accuracy of every discretization and
    /// rounding, and the motor check
    Report {
        /// The profiles file
        #[arg(default_value = "profiles.toml")]
        file: PathBuf,
        /// Also write the plots, a CSV per profile and `profiles.h` into DIR
        #[arg(short, long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Regenerate the guide's figures (docs/) into DIR (needs the shipped file)
        #[arg(long, value_name = "DIR", hide = true)]
        docs: Option<PathBuf>,
    },
    /// Check profiles files: print each mistake as `file:line:col` with the
    /// line and a caret, and exit with status 1 if there is one
    Check {
        /// The profiles files
        #[arg(required = true)]
        files: Vec<PathBuf>,
    },
    /// Write the C: every table and its figures, as one header or, with
    /// `--split`, a header of `extern` declarations and one source file
    ///
    /// The header carries a move player for each kind of table it holds;
    /// define `NAME_NO_PLAYER`, `NAME_NO_PLAYER32` or `NAME_NO_RUNS_PLAYER`
    /// (NAME the `--prefix` in capitals) before including it to leave one
    /// out.
    Header {
        /// The profiles file
        file: PathBuf,
        /// Where to write the header, its folder created if missing (standard output without it;
        /// a reader that closes it before the end is an error)
        #[arg(short, long, value_name = "OUT.h")]
        out: Option<PathBuf>,
        /// Declarations in OUT.h, the tables defined once in OUT.c
        #[arg(long, requires = "out")]
        split: bool,
        /// Words written before each array's element type that qualify it,
        /// e.g. `__code` (SDCC) or `__flash` (AVR GCC); not `const` or
        /// `static`, which the header writes itself
        #[arg(long, value_name = "WORDS")]
        storage: Option<String>,
        /// Written after each array's name: words, each with balanced
        /// parentheses if any, e.g. `PROGMEM` or
        /// `'__attribute__((section(".ramps")))'`
        #[arg(long, value_name = "TEXT")]
        attribute: Option<String>,
        /// The header's name in C, a C identifier: its include guard
        /// `STEPPER_PROFILES_NAME_H` and its run player `NAME_runs_*` (by
        /// default the output's name, `x_axis` for `x_axis.h`, or the
        /// profiles file's without `-o`)
        #[arg(long, value_name = "NAME")]
        prefix: Option<String>,
    },
    /// Write the Rust: one module per profile, as `include_profiles!`
    /// expands to and a build script writes
    Rust {
        /// The profiles file
        file: PathBuf,
        /// Where to write it, its folder created if missing (standard output without it; a
        /// reader that closes it before the end is an error)
        #[arg(short, long, value_name = "OUT.rs")]
        out: Option<PathBuf>,
    },
    /// Draw every profile (frequency and acceleration against time), the
    /// torque of profiles that name a motor and an overview as SVG, and each
    /// table as CSV
    Plot {
        /// The profiles file
        file: PathBuf,
        /// The folder to write into (created if missing)
        #[arg(short, long, value_name = "DIR", default_value = "plots")]
        out: PathBuf,
    },
    /// Write a move's exact step edges as a VCD file, the reference a
    /// logic analyzer's capture is compared with (PulseView and sigrok-cli
    /// read it): STEP high at each step, for the driver's step pulse
    Trace {
        /// The profile, by its name in the file
        profile: String,
        #[command(flatten)]
        mv: MoveArgs,
        /// Where to write the VCD, its folder created if missing (standard
        /// output without it)
        #[arg(short, long, value_name = "OUT.vcd")]
        out: Option<PathBuf>,
    },
    /// Compare a capture of the step pin (VCD, or sigrok-cli's CSV) with a
    /// move's exact edges: the first step edge lined up with the move's,
    /// each step's error in ticks, the largest, the first out of the
    /// tolerance; exit status 1 past it or when steps are missing
    Compare {
        /// The profile, by its name in the file
        profile: String,
        /// The capture: a VCD file, or the CSV `sigrok-cli -O csv` writes
        capture: PathBuf,
        #[command(flatten)]
        mv: MoveArgs,
        /// The step channel's name (by default the one named like `step`,
        /// or else the one that changes most)
        #[arg(long, value_name = "NAME")]
        channel: Option<String>,
        /// The transitions that are steps: `rising`, or `both` for a pin
        /// that toggles once a step
        #[arg(long, value_name = "EDGES", default_value = "rising", value_parser = ["rising", "both"])]
        edges: String,
        /// The largest error a step may have, in ticks
        #[arg(long, value_name = "TICKS", default_value_t = 0.5)]
        tolerance: f64,
        /// Print the summary only, not every step
        #[arg(long)]
        summary: bool,
    },
}

/// The move `trace` and `compare` play.
#[derive(Debug, clap::Args)]
struct MoveArgs {
    /// The profiles file
    #[arg(short, long, value_name = "FILE", default_value = "profiles.toml")]
    file: PathBuf,
    /// The move's steps, from rest (up the table, at its top, down)
    #[arg(long = "move", value_name = "N")]
    steps: u32,
    /// Stop the move (down the table from where it stands) after K steps
    #[arg(long, value_name = "K")]
    stop_at: Option<u32>,
    /// Each step edge ends its period (a timer's compare output that
    /// toggles at the match, the period written before it starts), rather
    /// than starting it (a step interrupt that pulses, then loads the next)
    #[arg(long)]
    edge_ends_period: bool,
}

/// A failure, already worded for the user.
struct Failure(String);

impl<E: std::fmt::Display> From<E> for Failure {
    fn from(e: E) -> Self {
        Failure(e.to_string())
    }
}

/// A line on standard error; a closed one (`2>&-`) loses it, as it should,
/// rather than failing the command.
fn note(line: &str) {
    let _ = writeln!(std::io::stderr(), "{line}");
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure(message)) => {
            let _ = std::io::stdout().flush();
            note(message.trim_end());
            ExitCode::FAILURE
        }
    }
}

fn run(command: Command) -> Result<(), Failure> {
    match command {
        Command::Report { file, out, docs } => report(&file, out.as_deref(), docs.as_deref()),
        Command::Check { files } => check(&files),
        Command::Header {
            file,
            out,
            split,
            storage,
            attribute,
            prefix,
        } => {
            let style = CStyle {
                storage,
                attribute,
                prefix,
            };
            header(&file, out.as_deref(), split, &style)
        }
        Command::Rust { file, out } => emit(
            out.as_deref(),
            &load(&file)?.rust_source(),
            "the Rust modules",
        ),
        Command::Plot { file, out } => plot(&file, &out),
        Command::Trace { profile, mv, out } => {
            let reference = reference(&profile, &mv)?;
            emit(out.as_deref(), &reference.vcd(), "the VCD")
        }
        Command::Compare {
            profile,
            capture,
            mv,
            channel,
            edges,
            tolerance,
            summary,
        } => {
            let edges = match edges.as_str() {
                "both" => Edges::Both,
                _ => Edges::Rising,
            };
            compare(
                &profile,
                &capture,
                &mv,
                channel.as_deref(),
                edges,
                tolerance,
                summary,
            )
        }
    }
}

/// The move `mv` of the profile named `name`.
fn reference(name: &str, mv: &MoveArgs) -> Result<Reference, Failure> {
    let profiles = load(&mv.file)?;
    let profile = profiles
        .profiles()
        .iter()
        .find(|p| p.name == name)
        .ok_or_else(|| {
            let names: Vec<&str> = profiles
                .profiles()
                .iter()
                .map(|p| p.name.as_str())
                .collect();
            format!(
                "`{}` has no profile `{name}`; its profiles: {}",
                mv.file.display(),
                names.join(", ")
            )
        })?;
    let timing = match mv.edge_ends_period {
        true => Timing::Ends,
        false => Timing::Starts,
    };
    Ok(Reference::of(profile, mv.steps, mv.stop_at, timing)?)
}

/// `compare`: the capture against the move, every step (or the summary)
/// on standard output; a failure past the tolerance.
fn compare(
    name: &str,
    capture: &Path,
    mv: &MoveArgs,
    channel: Option<&str>,
    edges: Edges,
    tolerance: f64,
    summary: bool,
) -> Result<(), Failure> {
    if !(tolerance >= 0.0 && tolerance.is_finite()) {
        return Err(Failure(format!(
            "`--tolerance {tolerance}`: expected ticks, 0 or more"
        )));
    }
    let reference = reference(name, mv)?;
    let text = std::fs::read_to_string(capture)
        .map_err(|e| format!("cannot read `{}`: {e}", capture.display()))?;
    let result = Capture::parse(&text)
        .and_then(|c| c.compare(&reference, channel, edges, tolerance))
        .map_err(|e| format!("`{}`: {e}", capture.display()))?;
    if !summary {
        stdout(&result.table())?;
    }
    stdout(&format!("{}\n", result.summary()))?;
    if result.passes() {
        Ok(())
    } else {
        Err(Failure(format!(
            "`{}` is not the move of `{name}` within {tolerance} ticks",
            capture.display()
        )))
    }
}

/// `report`: the figures of `file` on standard output; with `out`, the
/// plots, the CSVs and `profiles.h` written there; with `docs`, the
/// guide's figures.
fn report(file: &Path, out: Option<&Path>, docs: Option<&Path>) -> Result<(), Failure> {
    let profiles = load(file)?;
    stdout(&report::text(&file.display().to_string(), &profiles)?)?;
    if let Some(out) = out {
        let mut files = Staging::new(out)?;
        files::write_plots(&profiles, &mut files)
            .map_err(|e| format!("cannot write into `{}`: {e}", out.display()))?;
        let header = profiles.c_header_named("profiles.h", &CStyle::default());
        files.write("profiles.h", &header)?;
        let written = files.commit()?;
        stdout(&format!(
            "\nwrote {} files to {}\n",
            written.len(),
            out.display()
        ))?;
    }
    if let Some(docs) = docs {
        let mut files = Staging::new(docs)?;
        files::write_docs(&profiles, &mut files)
            .map_err(|e| format!("cannot write the guide's figures: {e}"))?;
        files.commit()?;
        stdout(&format!(
            "wrote the guide's figures to {}\n",
            docs.display()
        ))?;
    }
    Ok(())
}

/// `check`: each file read and computed, a line for each that holds no
/// mistake; the mistakes of all of them in one failure.
fn check(files: &[PathBuf]) -> Result<(), Failure> {
    let mut failed = Vec::new();
    for file in files {
        match Profiles::load(file) {
            Ok(p) => stdout(&format!(
                "{}: {} profiles, no mistakes\n",
                file.display(),
                p.profiles().len()
            ))?,
            Err(e) => failed.push(e.to_string()),
        }
    }
    if failed.is_empty() {
        Ok(())
    } else {
        Err(Failure(failed.join("\n")))
    }
}

/// `header`: the C of `file` in `style`, the style checked before the file
/// is read: one header to `out` or standard output, or with `split` a
/// header and a `.c` beside it.
fn header(file: &Path, out: Option<&Path>, split: bool, style: &CStyle) -> Result<(), Failure> {
    style
        .check()
        .map_err(|e| format!("`--{}` {}", e.field, e.problem))?;
    let profiles = load(file)?;
    match (out, split) {
        (Some(out), true) => header_split(&profiles, out, style),
        (Some(out), false) => {
            let (_, name) = folder_and_name(out)?;
            let header = profiles.c_header_named(&name.to_string_lossy(), style);
            emit(Some(out), &header, "the C header")
        }
        (None, _) => whole(&profiles.c_header_with(style), "the C header"),
    }
}

/// `header --split`: the header `out`, which must end in `.h`, and the
/// `.c` beside it, written together.
fn header_split(profiles: &Profiles, out: &Path, style: &CStyle) -> Result<(), Failure> {
    if out.extension().is_none_or(|e| e != "h") {
        return Err(Failure(format!(
            "`--split` writes a header and a `.c` beside it: give the header a \
             name ending in `.h` (got `{}`)",
            out.display()
        )));
    }
    let (dir, name) = folder_and_name(out)?;
    let files = profiles.c_split(&name.to_string_lossy(), style);
    let mut staging = Staging::new(dir)?;
    staging.write(name, &files.header)?;
    staging.write(Path::new(name).with_extension("c"), &files.source)?;
    let written = staging.commit()?;
    note(&format!(
        "wrote {} and {}",
        written[0].display(),
        written[1].display()
    ));
    Ok(())
}

/// `plot`: the plots and CSVs of `file` written into `out`.
fn plot(file: &Path, out: &Path) -> Result<(), Failure> {
    let profiles = load(file)?;
    let mut files = Staging::new(out)?;
    files::write_plots(&profiles, &mut files)
        .map_err(|e| format!("cannot write into `{}`: {e}", out.display()))?;
    let written = files.commit()?;
    stdout(&format!(
        "wrote {} files to {}\n",
        written.len(),
        out.display()
    ))?;
    Ok(())
}

/// Reads and computes a profiles file, saying so if it takes a while.
fn load(path: &Path) -> Result<Profiles, Failure> {
    let (done, waiting) = mpsc::channel::<()>();
    let notice = std::thread::spawn(move || {
        if waiting.recv_timeout(Duration::from_secs(1)).is_err() {
            note("computing tables...");
        }
    });
    let loaded = Profiles::load(path);
    let _ = done.send(());
    let _ = notice.join();
    Ok(loaded?)
}

/// Writes `text`, the file `what` names, to `out`, creating its folder, or
/// to standard output, whole or with an error.
fn emit(out: Option<&Path>, text: &str, what: &str) -> Result<(), Failure> {
    match out {
        Some(path) => {
            let (dir, name) = folder_and_name(path)?;
            let mut staging = Staging::new(dir)?;
            staging.write(name, text)?;
            staging.commit()?;
            note(&format!("wrote {}", path.display()));
            Ok(())
        }
        None => whole(text, what),
    }
}

/// The folder a file goes into and its name.
fn folder_and_name(path: &Path) -> Result<(&Path, &std::ffi::OsStr), Failure> {
    match (path.parent(), path.file_name()) {
        (Some(dir), Some(name)) => Ok((dir, name)),
        _ => Err(Failure(format!(
            "cannot write `{}`: give the name of a file",
            path.display()
        ))),
    }
}

/// Writes a generated file to standard output, all of it or an error. A
/// reader that closes the pipe early (`| head`) cuts the file short, which
/// is an error here and not for a report (see [`stdout`]). A descriptor
/// closed before the command starts (`>&-`) is standard output no more:
/// Rust opens `/dev/null` in its place, which takes everything, as with
/// `> /dev/null`.
fn whole(text: &str, what: &str) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| {
            let why = match e.kind() {
                std::io::ErrorKind::BrokenPipe => "its reader closed it before the end".to_string(),
                _ => e.to_string(),
            };
            Failure(format!("cannot write {what} to standard output: {why}"))
        })
}

/// Writes `text`, a report or a note, to standard output. A reader that
/// closed the pipe (`stepper-profiles report | head`) has all it wanted:
/// not an error. A generated file is written by [`whole`].
fn stdout(text: &str) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(Failure(format!("cannot write to standard output: {e}")))
        }
        _ => Ok(()),
    }
}
