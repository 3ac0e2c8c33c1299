//! The one quantizer: exact periods to integer ticks, checked against the
//! word, with the figures of what was emitted. Per-step tables and segment
//! tables round through it.

use crate::base::error::Error;
use crate::base::modes::Rounding;
use crate::base::timer::Timer;
use crate::table::spec::Spec;

/// What a generated table amounts to. Times in seconds, frequencies in Hz
/// (steps/s), acceleration in Hz/s, jerk in Hz/s².
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Figures {
    /// Number of entries.
    pub len: u32,
    /// First entry, in ticks.
    pub first_ticks: u32,
    /// Last entry, in ticks.
    pub last_ticks: u32,
    /// Shortest entry, in ticks.
    pub min_ticks: u32,
    /// Longest entry, in ticks.
    pub max_ticks: u32,
    /// Sum of all entries, in ticks.
    pub total_ticks: u64,
    /// Ramp duration as played: `total_ticks * ticks_per_step / timer_hz`.
    pub duration_s: f64,
    /// Step frequency of the first entry.
    pub start_hz: f64,
    /// Step frequency of the last entry.
    pub final_hz: f64,
    /// Largest acceleration of the integer table, averaged as a rotor
    /// feels it ([`AccelWindows`]): between the mean step frequencies of
    /// consecutive windows, over the time between their centres, each window
    /// long enough that one tick of rounding cannot read as more than 5 % of
    /// the curve's acceleration there (`sqrt(40 f / (a scale))` s at step
    /// frequency `f` and acceleration `a`, `scale` ticks per second), at
    /// most a quarter of the ramp. Between single entries at high step
    /// frequencies, one tick of rounding would read as acceleration; where
    /// the table follows the curve within half a tick, this follows the
    /// curve's acceleration. (A table of one entry reads 0.)
    pub max_accel_hz_s: f64,
    /// Largest acceleration of the curve itself: between the unrounded
    /// periods of consecutive steps.
    pub curve_max_accel_hz_s: f64,
    /// Largest jerk of the curve itself, from the same unrounded periods.
    /// (The integer table's own jerk is this plus rounding noise that grows
    /// with the cube of the step frequency: not a figure of the ramp.)
    pub curve_max_jerk_hz_s2: f64,
    /// Largest distance of a step edge from its unrounded time under the
    /// chosen discretization, in timer ticks. A step edge is the running sum
    /// of the entries, times `ticks_per_step`: with `ticks_per_step = 2`
    /// each entry is a half period the timer plays twice, step edges fall
    /// on every other tick, and `diffuse` keeps them within one tick (half
    /// a tick of the entries' sum).
    pub max_edge_error_ticks: f64,
    /// Last step edge minus its unrounded time, in timer ticks (the drift).
    pub total_error_ticks: f64,
    /// Ticks left between the longest entry and the largest value the word holds.
    pub overflow_margin_ticks: u32,
}

/// An integer table's acceleration as a rotor feels it: between the mean
/// step frequencies of consecutive windows of entries, each long enough that
/// one tick of rounding cannot read as more than 5 % of the curve's
/// acceleration where the window closes ([`AccelWindows::needed`]), and at
/// most `longest` ticks. The figures' [`Figures::max_accel_hz_s`] and the
/// command-line tool's plots read it. A last window cut short by the
/// table's end gives no reading.
#[derive(Clone, Copy, Debug)]
pub struct AccelWindows {
    longest: f64,
    /// The open window: entries and ticks.
    count: u32,
    ticks: f64,
    /// The last closed window: its mean frequency and its ticks.
    last: Option<(f64, f64)>,
    max_accel: f64,
}

impl AccelWindows {
    /// Windows of at most `longest` ticks (a quarter of the ramp, say).
    pub fn new(longest: f64) -> Self {
        AccelWindows {
            longest,
            count: 0,
            ticks: 0.0,
            last: None,
            max_accel: 0.0,
        }
    }

    /// The ticks a window needs at step frequency `f` and the curve's
    /// acceleration `accel` (`scale` ticks per second). With every edge
    /// within half a tick of the curve, a window of `T` s is within a tick
    /// of its exact length, which moves its mean frequency by up to
    /// `f / (T scale)` and the acceleration between two windows by up to
    /// `2 f / (T² scale)`: at most 5 % of `accel` from
    /// `T = sqrt(40 f / (accel scale))`.
    pub fn needed(&self, f: f64, accel: f64, scale: f64) -> f64 {
        let needed = libm::sqrt(40.0 * f / (libm::fabs(accel) * scale)) * scale;
        if needed.is_nan() {
            self.longest
        } else {
            needed.min(self.longest)
        }
    }

    /// Adds an entry of `ticks` (`scale` ticks per second) where the curve
    /// runs at `f` Hz and accelerates at `accel` Hz/s. When it closes a
    /// window that follows another: the acceleration between the two, in
    /// Hz/s, read at the edge between them.
    pub fn push(&mut self, ticks: f64, scale: f64, f: f64, accel: f64) -> Option<f64> {
        self.count += 1;
        self.ticks += ticks;
        // `ticks < needed(..)`, without its square root and divisions: the
        // window is open while shorter than `longest` and than
        // `sqrt(40 f / (|accel| scale))` s, that is while `ticks² |accel|
        // < 40 f scale` (always for a NaN, which `needed` reads as no
        // bound).
        let (lhs, rhs) = (
            self.ticks * self.ticks * libm::fabs(accel),
            40.0 * f * scale,
        );
        let unbounded = lhs.is_nan() || rhs.is_nan() || (lhs == 0.0 && rhs == 0.0);
        if self.ticks < self.longest && (unbounded || lhs < rhs) {
            return None;
        }
        let mean = self.count as f64 * scale / self.ticks;
        let reading = self.last.map(|(before, ticks_before)| {
            let dt = (ticks_before + self.ticks) / 2.0 / scale;
            (mean - before) / dt
        });
        if let Some(accel) = reading {
            self.max_accel = self.max_accel.max(libm::fabs(accel));
        }
        self.last = Some((mean, self.ticks));
        (self.count, self.ticks) = (0, 0.0);
        reading
    }

    /// The ticks of the window still open: the reading of the next one is
    /// at the edge that many ticks back.
    pub fn open_ticks(&self) -> f64 {
        self.ticks
    }
}

/// Entries kept by a [`Slope`]: two windows of one entry.
const W: usize = 1;

/// Acceleration and jerk of a sequence of periods: between single periods
/// (`window` 1) or between the means of windows of periods. Keeps the last
/// `2 W` periods and `W` accelerations; allocates nothing.
#[derive(Clone, Copy)]
struct Slope {
    window: usize,
    periods: [f64; 2 * W],
    accels: [(f64, f64); W],
    count: usize,
    /// Time at the end of the last period, in ticks.
    now: f64,
    max_accel: f64,
    max_jerk: f64,
}

impl Slope {
    fn new(window: usize) -> Self {
        Slope {
            window,
            periods: [0.0; 2 * W],
            accels: [(0.0, 0.0); W],
            count: 0,
            now: 0.0,
            max_accel: 0.0,
            max_jerk: 0.0,
        }
    }

    /// Adds a period of `ticks`; `scale` is ticks per second. Returns the
    /// acceleration it reads, once two windows are seen.
    fn push(&mut self, ticks: f64, scale: f64) -> Option<f64> {
        let w = self.window;
        self.periods[self.count % (2 * w)] = ticks;
        self.now += ticks;
        self.count += 1;
        if self.count < 2 * w {
            return None;
        }
        let sum = |from: usize| -> f64 {
            (from..from + w)
                .map(|i| self.periods[i % (2 * w)])
                .sum::<f64>()
        };
        // The older window starts 2w periods back, the newer w back.
        let older = sum(self.count - 2 * w);
        let newer = sum(self.count - w);
        // `(f_new - f_old) / dt` with `f = w scale / ticks` and `dt = (older +
        // newer) / 2 scale`, in one division.
        let accel =
            2.0 * w as f64 * scale * scale * (older - newer) / (older * newer * (older + newer));
        self.max_accel = self.max_accel.max(libm::fabs(accel));
        // The edge between the two windows, in seconds.
        let at = (self.now - newer) / scale;
        let slot = (self.count - 2 * w) % w;
        if self.count >= 3 * w {
            let (a_then, t_then) = self.accels[slot];
            if at > t_then {
                let jerk = (accel - a_then) / (at - t_then);
                self.max_jerk = self.max_jerk.max(libm::fabs(jerk));
            }
        }
        self.accels[slot] = (accel, at);
        Some(accel)
    }
}

/// Turns exact periods into integers and keeps the figures.
pub(crate) struct Quantizer {
    rounding: Rounding,
    timer: Timer,
    /// `reload_offset`: what each stored entry adds to its period.
    offset: i32,
    scale: f64,
    exact_edge: f64,
    emitted: u64,
    /// The integer table's acceleration.
    windowed: AccelWindows,
    /// The unrounded periods: the curve's acceleration and jerk, entry by
    /// entry.
    curve: Slope,
    figures: Figures,
    /// `false`: no figures are kept, the periods alone are checked.
    keep: bool,
}

impl Quantizer {
    pub(crate) fn new(spec: &Spec) -> Self {
        Quantizer {
            rounding: spec.rounding,
            timer: spec.timer,
            offset: spec.reload_offset,
            scale: spec.timer.frequency_scale(),
            exact_edge: 0.0,
            emitted: 0,
            windowed: AccelWindows::new(f64::INFINITY),
            curve: Slope::new(1),
            figures: Figures {
                len: 0,
                first_ticks: 0,
                last_ticks: 0,
                min_ticks: u32::MAX,
                max_ticks: 0,
                total_ticks: 0,
                duration_s: 0.0,
                start_hz: 0.0,
                final_hz: 0.0,
                max_accel_hz_s: 0.0,
                curve_max_accel_hz_s: 0.0,
                curve_max_jerk_hz_s2: 0.0,
                max_edge_error_ticks: 0.0,
                total_error_ticks: 0.0,
                overflow_margin_ticks: 0,
            },
            keep: true,
        }
    }

    /// The same quantizer, keeping no figures: the periods are rounded and
    /// checked alike, and [`finish`](Self::finish) returns figures of
    /// nothing.
    pub(crate) fn without_figures(mut self) -> Self {
        self.keep = false;
        self
    }

    /// `true` unless made [`without_figures`](Self::without_figures).
    pub(crate) fn keeps_figures(&self) -> bool {
        self.keep
    }

    /// Bounds the windows of the table's acceleration to a quarter of a
    /// ramp of `duration` exact ticks; before any entry is pushed.
    pub(crate) fn set_duration(&mut self, duration: f64) {
        self.windowed = AccelWindows::new(duration / 4.0);
    }

    /// Quantizes entry `index`, whose exact length is `entry` ticks and whose
    /// exact end is `edge` ticks from the start (the running sum of entries when
    /// `None`), and records it in the figures.
    pub(crate) fn push(&mut self, index: u32, entry: f64, edge: Option<f64>) -> Result<u32, Error> {
        let ticks = self.round(index, entry, edge, 1)?;
        self.stored(index, ticks, "entry")?;
        self.record(index, ticks, entry);
        Ok(ticks)
    }

    /// Entry `index` of a quantizer keeping no figures, rounded by
    /// diffusion, whose end is `edge` ticks from the start as the nearest
    /// tick to the exact edge ([`push`](Self::push) with that edge gives
    /// the same period): `None`, changing nothing, where that period does
    /// not fit the word, for `push` to say why.
    pub(crate) fn push_nearest_edge(&mut self, index: u32, edge: u64) -> Option<u32> {
        debug_assert!(!self.keep && self.rounding == Rounding::Diffuse);
        let ticks = u32::try_from(edge.checked_sub(self.emitted)?).ok()?;
        if ticks == 0 || ticks > self.timer.word.max() || self.stored(index, ticks, "").is_err() {
            return None;
        }
        self.exact_edge = edge as f64;
        self.emitted = edge;
        Some(ticks)
    }

    /// Rounds an entry of `entry` exact ticks that is played `repeat` times
    /// in a row, the last time ending `edge` ticks from the start (the
    /// running sum of exact entries when `None`), and checks it against the
    /// word. `diffuse` rounds the running sum: the entry's plays end as near
    /// their exact end as whole ticks allow.
    pub(crate) fn round(
        &mut self,
        index: u32,
        entry: f64,
        edge: Option<f64>,
        repeat: u32,
    ) -> Result<u32, Error> {
        self.exact_edge = match edge {
            Some(edge) => edge,
            None => self.exact_edge + entry * repeat as f64,
        };
        let rounded = match self.rounding {
            Rounding::Truncate => libm::trunc(entry),
            Rounding::Nearest => libm::round(entry),
            Rounding::Diffuse if repeat == 1 => libm::round(self.exact_edge) - self.emitted as f64,
            Rounding::Diffuse => {
                libm::round((self.exact_edge - self.emitted as f64) / repeat as f64)
            }
        };
        let ticks = self.check(index, rounded, entry)?;
        self.emitted += ticks as u64 * repeat as u64;
        Ok(ticks)
    }

    /// Refuses, before any pulse time is solved, a curve whose every period
    /// (between `1 / f_start` and `1 / f_end`) is too long for the word or
    /// rounds to 0 ticks: entry 0 is then out of range whatever the curve.
    pub(crate) fn reachable(&self, f_start: f64, f_end: f64) -> Result<(), Error> {
        let (shortest, longest) = (self.scale / f_end, self.scale / f_start);
        if shortest.is_nan() || shortest > self.timer.word.max() as f64 + 1.0 {
            return Err(Error::PeriodOverflow {
                index: 0,
                ticks: longest,
                word: self.timer.word,
                timer_hz: self.timer.timer_hz,
                lowest_hz: self.timer.lowest_frequency(),
            });
        }
        if longest.is_nan() || longest < 0.5 {
            return Err(Error::PeriodZero {
                index: 0,
                highest_hz: self.scale,
            });
        }
        Ok(())
    }

    /// Records entry `index` already rounded by the curve's own arithmetic;
    /// `entry` gives its unrounded length, asked for only by the figures
    /// and the errors.
    pub(crate) fn push_rounded(
        &mut self,
        index: u32,
        ticks: u64,
        entry: impl Fn() -> f64,
    ) -> Result<u32, Error> {
        let ticks = match u32::try_from(ticks) {
            Ok(t) if t >= 1 && t <= self.timer.word.max() => t,
            _ => self.check(index, ticks as f64, entry())?,
        };
        self.stored(index, ticks, "entry")?;
        self.emitted += ticks as u64;
        if self.keep {
            let entry = entry();
            self.exact_edge += entry;
            self.record(index, ticks, entry);
        }
        Ok(ticks)
    }

    /// The word's limits: a period that does not fit, or rounds to 0.
    fn check(&self, index: u32, rounded: f64, entry: f64) -> Result<u32, Error> {
        let max = self.timer.word.max();
        if !rounded.is_finite() || rounded > max as f64 {
            return Err(Error::PeriodOverflow {
                index,
                ticks: entry,
                word: self.timer.word,
                timer_hz: self.timer.timer_hz,
                lowest_hz: self.timer.lowest_frequency(),
            });
        }
        if rounded < 1.0 {
            return Err(Error::PeriodZero {
                index,
                highest_hz: self.scale,
            });
        }
        Ok(rounded as u32)
    }

    /// The word's limits on what is stored: a period of `ticks` plus
    /// `reload_offset`, from 1 to the word's largest value; `what` (`entry`,
    /// `segment`) and `index` say which, as the error does.
    pub(crate) fn stored(&self, index: u32, ticks: u32, what: &'static str) -> Result<u32, Error> {
        self.timer.word.stored(ticks, self.offset, what, index)
    }

    /// The quantizer of the same spec, storing the periods as they are: for
    /// the per-step table a segment table stands for, whose periods are not
    /// stored.
    pub(crate) fn without_offset(mut self) -> Self {
        self.offset = 0;
        self
    }

    /// Records entry `index`: `ticks` as emitted, `entry` unrounded.
    fn record(&mut self, index: u32, ticks: u32, entry: f64) {
        if !self.keep {
            return;
        }
        let fig = &mut self.figures;
        let error = (self.emitted as f64 - self.exact_edge) * f64::from(self.timer.ticks_per_step);
        fig.max_edge_error_ticks = fig.max_edge_error_ticks.max(libm::fabs(error));
        fig.total_error_ticks = error;
        fig.min_ticks = fig.min_ticks.min(ticks);
        fig.max_ticks = fig.max_ticks.max(ticks);
        if index == 0 {
            fig.first_ticks = ticks;
        }
        // The curve's own frequency and acceleration here, between this
        // unrounded entry and the one before: what the windows resolve.
        let accel = self.curve.push(entry, self.scale).unwrap_or(0.0);
        self.windowed
            .push(ticks as f64, self.scale, self.scale / entry, accel);
        fig.last_ticks = ticks;
        fig.len = index + 1;
    }

    pub(crate) fn finish(mut self) -> Figures {
        let fig = &mut self.figures;
        fig.total_ticks = self.emitted;
        fig.duration_s = self.emitted as f64 / self.scale;
        fig.start_hz = self.scale / fig.first_ticks as f64;
        fig.final_hz = self.scale / fig.last_ticks as f64;
        fig.overflow_margin_ticks = self.timer.word.max() - fig.max_ticks;
        fig.max_accel_hz_s = self.windowed.max_accel;
        fig.curve_max_accel_hz_s = self.curve.max_accel;
        fig.curve_max_jerk_hz_s2 = self.curve.max_jerk;
        self.figures
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `push` closes a window by `ticks² |accel| < 40 f scale`, without the
    /// square root of `needed`: the two rules must close the same windows.
    #[test]
    fn push_closes_a_window_where_needed_says() {
        let scale = 10_000_000.0;
        for (f, accel) in [
            (500.0, 20_000.0),
            (64_000.0, 3e6),
            (1000.0, 0.0),
            (2e5, -4e4),
        ] {
            for longest in [50.0, 1e9] {
                let needed = AccelWindows::new(longest).needed(f, accel, scale);
                for ticks in [1.0, 7.0, 100.0, 1e3, 1e4, 1e5, 1e6] {
                    let mut w = AccelWindows::new(longest);
                    w.push(ticks, scale, f, accel);
                    let closed = w.open_ticks() == 0.0;
                    assert_eq!(closed, ticks >= needed, "{f} {accel} {longest} {ticks}");
                }
            }
        }
    }
}
