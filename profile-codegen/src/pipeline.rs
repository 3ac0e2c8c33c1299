//! The one route from arguments to everything a front end emits.
//!
//! `period_table!` and the profiles-file loader (and through it
//! `include_profiles!`, the build-script API, the C header and the report)
//! turn their syntax into [`Arg`]s and call [`compile`]: the arguments are
//! read (`schema`), the spec is checked once, the table is computed in its
//! layout, and the motor, when there is one, is checked against it. Nothing
//! else computes a table, expands segments or runs the motor check.

use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

use crate::bands::Bands;
use crate::cpu::{Cpu, Layout};
use crate::driver::Driver;
use crate::motor::{Motor, TorqueFigures};
use crate::schema::{self, Arg, Diagnostic, TableLayout, locate, locate_motor};
use crate::table::computed::{Generated, SpecTables};
use profile_core::CheckedSpec;
use profile_core::Error;
use profile_core::Key;

/// Everything a front end needs to emit a table.
#[derive(Clone, Debug, PartialEq)]
pub struct Compiled {
    /// The checked spec.
    pub spec: CheckedSpec,
    /// The table in its layout, with its figures.
    pub table: Generated,
    /// The motor it drives, when described.
    pub motor: Option<Motor>,
    /// Where that motor has the least torque to spare.
    pub torque: Option<TorqueFigures>,
    /// The step driver it plays into, when described: every period is
    /// long enough for it.
    pub driver: Option<Driver>,
    /// The step interrupt's core and clock, when described: the interrupt
    /// serves every period.
    pub cpu: Option<Cpu>,
    /// The speed bands its top stays out of, when given.
    pub avoid: Option<Bands>,
}

/// Entries a set of tables (one profiles file) may still generate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Budget {
    /// Entries the tables compiled so far hold.
    pub used: u64,
    /// The most the set may hold.
    pub limit: u64,
}

/// How to compile one table.
#[derive(Debug, Default)]
pub struct Options<'a> {
    /// Keys not to report as missing: keys another diagnostic already covers
    /// (see [`schema::read`]).
    pub assumed: &'a [Key],
    /// The entries the table's set may still hold; checked before the table
    /// is computed.
    pub budget: Option<&'a mut Budget>,
    /// The profile's name, when the table is one of a file's, for messages
    /// that must say which.
    pub profile: Option<&'a str>,
}

/// Reads `args`, checks the spec, computes the table in its layout and
/// checks the motor: every problem as a [`Diagnostic`] at its argument (or
/// at `whole`).
pub fn compile<L: Clone>(
    args: &[Arg<L>],
    whole: &L,
    options: Options<'_>,
) -> Result<Compiled, Vec<Diagnostic<L>>> {
    let request = schema::read(args, whole, options.assumed)?;
    let prefix = options
        .profile
        .map_or(String::new(), |name| format!("profile `{name}`: "));
    // A stored value out of the word depends on the table, not on the key
    // alone (which a file's `[defaults]` may give): which profile, when a
    // file's.
    let at = |e: Error| {
        let mut d = locate(&e, args, whole);
        if matches!(e, Error::ReloadOffset { .. }) {
            d.message = format!("{prefix}{}", d.message);
        }
        std::vec![d]
    };
    let spec = request.spec.check().map_err(at)?;
    match request.layout {
        TableLayout::Segments(n) => spec.check_segments(n).map_err(at)?,
        TableLayout::Runs(e) => spec.check_compress(e).map_err(at)?,
        TableLayout::Steps => {}
    }
    // A motor that cannot follow the table: which profile, when a file's.
    let motor_at = |e| {
        let mut d = locate_motor(&e, args, whole);
        d.message = format!("{prefix}{}", d.message);
        std::vec![d]
    };
    if let Some(m) = &request.motor {
        m.validate()
            .map_err(|e| std::vec![locate_motor(&e, args, whole)])?;
    }
    if let Some(budget) = options.budget {
        let total = budget.used + spec.len() as u64;
        if total > budget.limit {
            return Err(std::vec![Diagnostic {
                loc: whole.clone(),
                message: format!(
                    "{}brings the file to {total} entries, more than the {} one file may hold; \
                     split the profiles over several files",
                    options.profile.map_or(String::from("this table "), |name| {
                        format!("profile `{name}` ")
                    }),
                    budget.limit
                ),
            }]);
        }
        budget.used = total;
    }
    let table = match request.layout {
        TableLayout::Steps => spec.table().map(Generated::Steps),
        TableLayout::Segments(n) => spec.segment_table(n).map(Generated::Segments),
        TableLayout::Runs(e) => spec.run_table(e).map(Generated::Runs),
    }
    .map_err(at)?;
    // The table one period a step, for the checks that read it: made once.
    let periods = std::cell::OnceCell::new();
    let periods = || periods.get_or_init(|| table.step_periods());
    let timer = &spec.spec().timer;
    let torque = match &request.motor {
        None => None,
        Some(motor) => Some(motor.check(spec.spec(), periods()).map_err(motor_at)?),
    };
    if let Some(driver) = &request.driver {
        driver
            .check(timer, periods())
            .map_err(|e| std::vec![driver_at(&e, args, whole, &prefix)])?;
    }
    if let Some(cpu) = &request.cpu {
        cpu.check(timer, Layout::of(&table), periods())
            .map_err(|e| std::vec![cpu_at(&e, cpu, args, whole, &prefix)])?;
    }
    if let Some(bands) = &request.avoid {
        bands.check(timer, periods()).map_err(|e| {
            let message = format!("{prefix}{}", e.message());
            std::vec![schema::at_value(Some(Key::FMAX), args, whole, message)]
        })?;
    }
    Ok(Compiled {
        spec,
        table,
        motor: request.motor,
        torque,
        driver: request.driver,
        cpu: request.cpu,
        avoid: request.avoid,
    })
}

/// A table too fast for its step interrupt, at `fmax`, or at the whole
/// argument list without one.
fn cpu_at<L: Clone>(
    e: &crate::cpu::CpuError,
    cpu: &Cpu,
    args: &[Arg<L>],
    whole: &L,
    prefix: &str,
) -> Diagnostic<L> {
    let clock = if cpu.cpu_hz >= 1e6 {
        format!("{} MHz", crate::numbers::Num(cpu.cpu_hz / 1e6))
    } else {
        format!("{} kHz", crate::numbers::Num(cpu.cpu_hz / 1e3))
    };
    let what = format!("`core = \"{}\"` at {clock}", cpu.core.name());
    let message = format!("{prefix}{}", e.message(&what, cpu));
    schema::at_value(Some(Key::FMAX), args, whole, message)
}

/// A table too fast for its driver, at `fmax` (what to lower), or at the
/// whole argument list without one.
fn driver_at<L: Clone>(
    e: &crate::driver::DriverError,
    args: &[Arg<L>],
    whole: &L,
    prefix: &str,
) -> Diagnostic<L> {
    let what = match (
        args.iter().find(|a| a.key == Key::DRIVER.name()),
        e.dir_setup,
    ) {
        (Some(arg), _) => format!("`driver = \"{}\"`", arg.value),
        (None, None) => "`step_pulse` + `step_space`".to_string(),
        (None, Some(_)) => "`dir_setup`".to_string(),
    };
    // What to change: `fmax` for a step too short, `fmin` for a reversal.
    let at = if e.dir_setup.is_some() {
        Key::FMIN
    } else {
        Key::FMAX
    };
    let message = format!("{prefix}{}", e.message(&what));
    schema::at_value(Some(at), args, whole, message)
}
