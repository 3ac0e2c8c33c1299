//! Golden tests for your own tables: pin a table in a readable text file and
//! fail when it changes.
//!
//! ```no_run
//! # use profile_codegen as stepper_profiles;
//! use stepper_profiles::golden;
//!
//! # const RAMP: [u16; 3] = [900, 700, 600];
//! // In a test: blessed by `UPDATE_GOLDEN=1 cargo test`, compared by `cargo test`.
//! golden::check("tests/golden/ramp.txt", &golden::timed(&RAMP, 1_000_000));
//! ```
//!
//! With `UPDATE_GOLDEN=1` in the environment, [`check`] writes the file
//! (creating its folder); otherwise it reads it and panics when the table
//! differs, with the number of differing entries, the first of them (index,
//! old and new period) and the largest shift of a pulse edge in ticks and,
//! when the timer's rate is known, in microseconds. A file whose entries
//! are the table's but another line differs (a figure, a hand edit of the
//! edge column) fails at that line, `file:line`, with what it reads and what
//! the table gives; one that differs only in spacing (tabs, blanks at the
//! ends of lines, blank lines, line endings) passes. A relative path is
//! relative to the directory `cargo test` runs the test in: the package's
//! root.
//!
//! The file holds the table's parameters and figures as `# key = value`
//! lines, then one entry per line with the time of the pulse edge it ends,
//! so that `git diff` shows what moved:
//!
//! ```text
//! # stepper-profiles golden table: UPDATE_GOLDEN=1 rewrites it
//! # table = per step
//! # entries = 3
//! # timer_hz = 1 MHz
//! # total_ticks = 2200
//! #
//! #  entry      period  edge (ticks)     edge (us)
//!        0         900           900       900.000
//!        1         700          1600      1600.000
//!        2         600          2200      2200.000
//! ```
//!
//! A table can be an array or slice of `u16` or `u32` periods, an array or
//! slice of `(period, count)` segments, either with its timer
//! ([`timed`]), a table computed on the host ([`Generated`], with its
//! parameters and figures), or every profile of a profiles file at once
//! ([`check_file`]).

use std::format;
use std::path::{Path, PathBuf};
use std::string::{String, ToString};
use std::vec::Vec;

use crate::profiles::Profiles;
use crate::schema::describe;
use crate::table::computed::Generated;
use profile_core::CompactFigures;
use profile_core::Key;

pub(crate) mod file;
mod lines;
mod render;

use file::{Body, Entries, compare};

/// Anything [`check`] can pin: the tables listed above. Implemented by this
/// crate only: what a golden file holds is not API.
pub trait Golden {
    /// The table as a golden file holds it.
    #[doc(hidden)]
    fn entries(&self) -> Entries;
}

fn plain(body: Body) -> Entries {
    Entries {
        header: Vec::new(),
        body,
        timer_hz: None,
        ticks_per_step: 1,
    }
}

macro_rules! words {
    ($($w:ty),*) => {$(
        impl Golden for [$w] {
            fn entries(&self) -> Entries {
                plain(Body::Periods(self.iter().map(|&p| u32::from(p)).collect()))
            }
        }
        impl<const N: usize> Golden for [$w; N] {
            fn entries(&self) -> Entries {
                self[..].entries()
            }
        }
        impl Golden for [($w, $w)] {
            fn entries(&self) -> Entries {
                plain(Body::Segments(
                    self.iter().map(|&(p, c)| (u32::from(p), u32::from(c))).collect(),
                ))
            }
        }
        impl<const N: usize> Golden for [($w, $w); N] {
            fn entries(&self) -> Entries {
                self[..].entries()
            }
        }
    )*};
}
words!(u16, u32);

impl Golden for [[u16; 5]] {
    fn entries(&self) -> Entries {
        plain(Body::Runs(self.to_vec()))
    }
}

impl<const N: usize> Golden for [[u16; 5]; N] {
    fn entries(&self) -> Entries {
        self[..].entries()
    }
}

impl<T: Golden + ?Sized> Golden for &T {
    fn entries(&self) -> Entries {
        (**self).entries()
    }
}

/// A table with its timer's tick rate: edges in microseconds too.
#[derive(Clone, Copy, Debug)]
pub struct Timed<'a, T: ?Sized> {
    table: &'a T,
    timer_hz: u32,
    reload_offset: i32,
}

/// `table` played by a timer of `timer_hz` ticks per second (a module of
/// `include_profiles!` has it as `TIMER_HZ`).
pub fn timed<T: Golden + ?Sized>(table: &T, timer_hz: u32) -> Timed<'_, T> {
    Timed {
        table,
        timer_hz,
        reload_offset: 0,
    }
}

impl<T: ?Sized> Timed<'_, T> {
    /// The table stores each period plus `reload_offset` (a module's
    /// `RELOAD_OFFSET`): the file pins the periods, the offset taken off,
    /// and says the offset.
    pub fn with_reload_offset(mut self, reload_offset: i32) -> Self {
        self.reload_offset = reload_offset;
        self
    }
}

impl<T: Golden + ?Sized> Golden for Timed<'_, T> {
    fn entries(&self) -> Entries {
        let mut e = self.table.entries();
        e.timer_hz = Some(self.timer_hz);
        let offset = self.reload_offset;
        if offset != 0 {
            let period = |stored: u32| stored.wrapping_add_signed(offset.wrapping_neg());
            e.body = match e.body {
                Body::Periods(p) => Body::Periods(p.into_iter().map(period).collect()),
                Body::Segments(s) => {
                    Body::Segments(s.into_iter().map(|(p, c)| (period(p), c)).collect())
                }
                Body::Runs(r) => Body::Runs(
                    r.iter()
                        .map(|w| profile_core::runs::with_offset(w, offset.wrapping_neg()))
                        .collect(),
                ),
            };
            e.header
                .push((Key::RELOAD_OFFSET.name().to_string(), offset.to_string()));
        }
        e
    }
}

impl Golden for Generated {
    fn entries(&self) -> Entries {
        let spec = self.spec();
        let mut header: Vec<(String, String)> = describe(spec)
            .into_iter()
            .map(|(k, v)| (k.name().to_string(), v))
            .collect();
        let figure = |k: &str, v: String| (k.to_string(), v);
        let body = match self {
            Generated::Steps(t) => {
                let f = &t.figures;
                header.extend([
                    figure("first_ticks", f.first_ticks.to_string()),
                    figure("last_ticks", f.last_ticks.to_string()),
                ]);
                header.extend(timing(
                    f.duration_s,
                    f.max_edge_error_ticks,
                    f.total_error_ticks,
                ));
                Body::Periods(t.periods.clone())
            }
            Generated::Segments(t) => Body::Segments(t.pairs.clone()),
            Generated::Runs(t) => Body::Runs(t.runs.clone()),
        };
        if let Some(c) = self.compact() {
            header.extend(compact(&c));
        }
        Entries {
            header,
            body,
            timer_hz: Some(spec.timer.timer_hz),
            ticks_per_step: spec.timer.ticks_per_step,
        }
    }
}

/// The figures of a compact layout (segments, runs): the steps it plays,
/// its flash, then the timing.
fn compact(c: &CompactFigures) -> impl Iterator<Item = (String, String)> {
    [
        ("steps".to_string(), c.steps.to_string()),
        ("flash_bytes".to_string(), c.flash_bytes.to_string()),
    ]
    .into_iter()
    .chain(timing(
        c.duration_s,
        c.max_edge_error_ticks,
        c.total_error_ticks,
    ))
}

/// The figures every layout has: how long it plays and how far its edges
/// are from the curve.
fn timing(duration_s: f64, max_edge: f64, total_error: f64) -> [(String, String); 3] {
    [
        ("duration_s".to_string(), format!("{duration_s:.9}")),
        ("max_edge_error_ticks".to_string(), format!("{max_edge:.6}")),
        ("total_error_ticks".to_string(), format!("{total_error:.6}")),
    ]
}

/// Pins `table` in the file at `path`: writes it with `UPDATE_GOLDEN=1`,
/// otherwise panics with what changed when it differs from the file.
#[track_caller]
pub fn check<T: Golden + ?Sized>(path: impl AsRef<Path>, table: &T) {
    if let Err(problem) = compare(path, table) {
        panic!("{problem}");
    }
}

/// Pins every profile of the profiles file at `file`, as `include_profiles!`
/// computes them, each in `dir/NAME.txt`. Fails with every profile that
/// changed.
#[track_caller]
pub fn check_file(dir: impl AsRef<Path>, file: impl AsRef<Path>) {
    let profiles = Profiles::load(file.as_ref()).unwrap_or_else(|e| panic!("{e}"));
    let problems: Vec<String> = profiles
        .profiles()
        .iter()
        .filter_map(|p| {
            let path: PathBuf = dir.as_ref().join(format!("{}.txt", p.name));
            compare(path, &p.table).err()
        })
        .collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[cfg(test)]
mod tests {
    //! The golden format: reading back what was written, and the differences.

    use super::*;
    use std::fs;

    use super::file::{compare_as, difference, parse};
    use super::render::render;

    #[test]
    fn a_file_shows_each_entry_with_its_edge() {
        let text = render(&timed(&[900u16, 700, 600], 1_000_000).entries());
        assert_eq!(
            text,
            "# stepper-profiles golden table: UPDATE_GOLDEN=1 rewrites it
# table = per step
# entries = 3
# timer_hz = 1 MHz
# total_ticks = 2200
#
#  entry      period  edge (ticks)     edge (us)
       0         900           900       900.000
       1         700          1600      1600.000
       2         600          2200      2200.000
"
        );
        let segments = render(&[(500u16, 2u16), (400, 3)].entries());
        assert!(segments.ends_with(
            "#    seg      period   count   end (ticks)
       0         500       2          1000
       1         400       3          2200
"
        ));
        assert_eq!(
            parse(&segments, &Body::Segments(Vec::new())),
            Ok(Body::Segments(std::vec![(500, 2), (400, 3)]))
        );
    }

    #[test]
    fn a_difference_names_the_count_the_first_and_the_shift() {
        let old = Body::Periods(std::vec![900, 700, 600, 500]);
        let new = timed(&[900u16, 702, 600, 499], 2_000_000).entries();
        assert_eq!(
            difference(&old, &new),
            "2 of 4 entries differ, the first at entry 1: was 700 ticks, now 702; the largest \
             shift of a pulse edge is 2 ticks (1.000 us)"
        );
        let longer = [900u16, 700, 600, 500, 450].entries();
        assert_eq!(
            difference(&old, &longer),
            "5 entries, was 4; the largest shift of a pulse edge is 0 ticks"
        );
        let segments = [(900u16, 2u16)].entries();
        assert_eq!(difference(&old, &segments), "its layout changed");
    }

    /// A scratch folder of its own for a test's files.
    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("profile-core-golden-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn spacing_alone_is_no_change() {
        let table = timed(&[900u16, 700, 600], 1_000_000);
        let path = scratch("spacing").join("ramp.txt");
        let text = render(&table.entries());
        // Tabs for spaces, trailing blanks, Windows line ends, a blank line.
        let respaced = text
            .replace("       1         700", "1\t700")
            .replace('\n', "  \r\n")
            + "\r\n";
        fs::write(&path, respaced).unwrap();
        assert_eq!(compare_as(&path, &table, false), Ok(()));
        let _ = fs::remove_dir_all(path.parent().unwrap());
    }

    #[test]
    fn a_line_that_changed_beside_the_same_entries_is_named() {
        let table = timed(&[900u16, 700, 600], 1_000_000);
        let path = scratch("edited").join("ramp.txt");
        let text = render(&table.entries());
        let bless = "if the change is intended, rerun with UPDATE_GOLDEN=1 and review the diff";
        let edited = |from: &str, to: &str| {
            assert!(text.contains(from), "{from}");
            fs::write(&path, text.replace(from, to)).unwrap();
            compare_as(&path, &table, false).unwrap_err()
        };
        // A hand edit of the edge column, which the periods make.
        assert_eq!(
            edited("1600      1600.000", "1601      1600.000"),
            format!(
                "{}:9: the entries are unchanged, but entry 1's edge (ticks) reads 1601, the table \
             gives 1600; {bless}",
                path.display()
            )
        );
        assert_eq!(
            edited("2200      2200.000", "2200      2200.001"),
            format!(
                "{}:10: the entries are unchanged, but entry 2's edge (us) reads 2200.001, the \
             table gives 2200.000; {bless}",
                path.display()
            )
        );
        // A figure.
        assert_eq!(
            edited("# total_ticks = 2200", "# total_ticks = 2300"),
            format!(
                "{}:5: the entries are unchanged, but `total_ticks` reads 2300, the table gives \
             2200; {bless}",
                path.display()
            )
        );
        // A segment's end.
        let segments = [(500u16, 2u16), (400, 3)];
        let text = render(&segments.entries());
        fs::write(&path, text.replace("3          2200", "3          2199")).unwrap();
        assert_eq!(
            compare_as(&path, &segments, false).unwrap_err(),
            format!(
                "{}:8: the entries are unchanged, but segment 1's end (ticks) reads 2199, the table \
             gives 2200; {bless}",
                path.display()
            )
        );
        let text = render(&table.entries());
        let edited = |from: &str, to: &str| {
            fs::write(&path, text.replace(from, to)).unwrap();
            compare_as(&path, &table, false).unwrap_err()
        };
        // A line gone, and one too many.
        assert_eq!(
            edited("# timer_hz = 1 MHz\n", ""),
            format!(
                "{}:4: the entries are unchanged, but the line reads `# total_ticks = 2200`, the \
             table gives `# timer_hz = 1 MHz`; {bless}",
                path.display()
            )
        );
        assert_eq!(
            edited("2200.000\n", "2200.000\n# end\n"),
            format!(
                "{}:11: the entries are unchanged, but the file goes on after the table's last \
             line with `# end`; {bless}",
                path.display()
            )
        );
        let _ = fs::remove_dir_all(path.parent().unwrap());
    }

    #[test]
    fn a_failed_bless_leaves_nothing_behind() {
        let dir = scratch("partial");
        // A folder where the file should be: the rename onto it fails.
        let path = dir.join("ramp.txt");
        fs::create_dir_all(&path).unwrap();
        let table = timed(&[900u16, 700, 600], 1_000_000);
        let error = compare_as(&path, &table, true).unwrap_err();
        assert!(
            error.starts_with(&format!("cannot write {}: ", path.display())),
            "{error}"
        );
        let left: Vec<_> = fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(left, ["ramp.txt"]);
        let _ = fs::remove_dir_all(&dir);
    }

    /// A table of register values pins the periods, as the table of the
    /// periods does, and says its offset.
    #[test]
    fn an_offset_table_pins_its_periods() {
        let periods = timed(&[900u16, 700, 600], 1_000_000).entries();
        let arr = timed(&[899u16, 699, 599], 1_000_000)
            .with_reload_offset(-1)
            .entries();
        assert_eq!(arr.body, periods.body);
        assert_eq!(
            arr.header,
            std::vec![("reload_offset".to_string(), "-1".to_string())]
        );
        let runs = [profile_core::runs::LinearRun {
            count: 3,
            interval: 700 << 16,
            add: -(50 << 16),
        }
        .encode()];
        let stored = [profile_core::runs::with_offset(&runs[0], -1)];
        let back = timed(&stored, 1_000_000).with_reload_offset(-1).entries();
        assert_eq!(back.body, Body::Runs(runs.to_vec()));
        let pairs = timed(&[(499u32, 3u32)], 1_000_000)
            .with_reload_offset(-1)
            .entries();
        assert_eq!(pairs.body, Body::Segments(std::vec![(500, 3)]));
    }
}
