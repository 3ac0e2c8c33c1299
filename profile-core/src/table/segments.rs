//! The exponential-ramp article's compact layout: the ramp cut into
//! equal-time segments, each a (timer period, step count) pair.
//!
//! A segment table spends `2 n` words of flash instead of `len`, and pays in
//! accuracy: every step of a segment has the same period, so pulse edges
//! drift from the curve within a segment. [`CompactFigures`] reports both.

use crate::base::error::Error;
use crate::base::key::Key;
use crate::base::modes::Discretization;
use crate::base::solve::{EDGE_TOLERANCE_TICKS, Edges, edge_time};
use crate::base::timer::TableWord;
use crate::table::quantize::Quantizer;
use crate::table::runs::Expand;
use crate::table::spec::{CheckedSpec, Spec};

/// What a compact layout amounts to: a segment table or a compressed table
/// of runs ([`CompactFigures::of_runs`]), against the per-step table of the
/// same ramp.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct CompactFigures {
    /// The layout: `"segments"` or `"runs"`.
    pub kind: &'static str,
    /// Its entries: segments, or runs.
    pub entries: u32,
    /// Steps in the ramp: the sum of the entries' step counts.
    pub steps: u32,
    /// Flash of the table, in bytes (two words a segment, 10 per run).
    pub flash_bytes: u32,
    /// Flash of the per-step table of the same ramp, in bytes.
    pub per_step_flash_bytes: u32,
    /// Sum of the played periods, in ticks of the entries (with
    /// `ticks_per_step = 2` the timer counts twice this).
    pub total_ticks: u64,
    /// Ramp duration as played, in s.
    pub duration_s: f64,
    /// Largest distance of a played step edge from the curve's exact edge,
    /// in timer ticks (with `ticks_per_step = 2`, twice the distance of the
    /// periods' running sum); for runs at most `tolerance_ticks`.
    pub max_edge_error_ticks: f64,
    /// Last played step edge minus the exact end of the ramp, in timer ticks.
    pub total_error_ticks: f64,
    /// The largest step-edge error the runs were fitted to (`compress`), in
    /// timer ticks; `None` for segments.
    pub tolerance_ticks: Option<f64>,
}

impl CompactFigures {
    /// The figures of `runs` (see [`runs`](crate::runs)), played and
    /// compared with `exact`, the curve's exact step edges in ticks of the
    /// entries, on a timer of `scale` ticks a second whose step is `repeat`
    /// entries (`ticks_per_step`), fitted to `tolerance_ticks`.
    pub fn of_runs(
        runs: &[[u16; 5]],
        exact: &[f64],
        tolerance_ticks: f64,
        scale: f64,
        repeat: f64,
    ) -> Self {
        let (mut edge, mut worst, mut last) = (0u64, 0.0f64, 0.0);
        for (period, t) in Expand::new(runs).zip(exact) {
            edge += u64::from(period);
            last = edge as f64 - t;
            worst = worst.max(libm::fabs(last));
        }
        let steps = exact.len() as u32;
        CompactFigures {
            kind: "runs",
            entries: runs.len() as u32,
            steps,
            flash_bytes: runs.len() as u32 * 10,
            per_step_flash_bytes: steps * 2,
            total_ticks: edge,
            duration_s: edge as f64 / scale,
            max_edge_error_ticks: worst * repeat,
            total_error_ticks: last * repeat,
            tolerance_ticks: Some(tolerance_ticks),
        }
    }
}

impl CheckedSpec {
    /// Checks that the table can be cut into `segments` equal-time segments
    /// (`discretization = exact`, from one segment up to one per step).
    pub fn check_segments(&self, segments: u32) -> Result<(), Error> {
        let discretization = self.spec().discretization;
        if discretization != Discretization::Exact {
            return Err(Error::SegmentsNeedTime { discretization });
        }
        if segments == 0 {
            return Err(Error::Zero { key: Key::SEGMENTS });
        }
        // Every segment must hold a step; checked here, before any buffer
        // of `segments` pairs is allocated.
        if segments > self.len() {
            return Err(Error::TooLarge {
                key: Key::SEGMENTS,
                value: segments as f64,
                max: self.len() as f64,
            });
        }
        Ok(())
    }

    /// Computes the segment table into `out` (one `(period, count)` pair per
    /// segment, the period plus [`reload_offset`](Spec::reload_offset)) and
    /// returns its figures.
    pub fn generate_segments<W: TableWord>(
        &self,
        out: &mut [(W, W)],
    ) -> Result<CompactFigures, Error> {
        if W::WORD != self.word() {
            return Err(Error::WordMismatch {
                expected: self.word(),
                got: W::WORD,
            });
        }
        let n = u32::try_from(out.len()).unwrap_or(u32::MAX);
        let spec = self.spec();
        self.for_each_segment(n, |i, period, count| {
            if let Some(slot) = out.get_mut(i as usize) {
                *slot = (W::from_ticks(spec.stored(period)), W::from_ticks(count));
            }
        })
    }

    /// Computes `segments` segments, calling `sink(index, period, count)` for
    /// each (the period without [`reload_offset`](Spec::reload_offset),
    /// which must keep it in the word: checked here).
    ///
    /// Segment `i` spans `[i T/n, (i+1) T/n]` of the ramp's duration `T`. Its
    /// count is the difference of the rounded step counts at its ends, so the
    /// counts sum to the ramp's steps exactly; its period is the segment's
    /// duration over its count, rounded through the same quantizer as a
    /// per-step table: `truncate` and `nearest` round that period, `diffuse`
    /// rounds so that the segment's last step ends as near its exact edge as
    /// whole ticks allow, making up for what the segments before it left
    /// over. A segment that holds no step is an error: use fewer.
    ///
    /// The segments stand for the per-step table of the same curve (their
    /// figures are measured against it): a step whose period that table
    /// cannot hold in the word is refused here as there, with the same
    /// error, though a segment's average might fit.
    pub fn for_each_segment<F: FnMut(u32, u32, u32)>(
        &self,
        segments: u32,
        mut sink: F,
    ) -> Result<CompactFigures, Error> {
        self.check_segments(segments)?;
        let spec = self.spec();
        let len = self.len();
        let scale = spec.timer.frequency_scale();
        let repeat = f64::from(spec.timer.ticks_per_step);
        let word = spec.timer.word;
        let model = spec.curve.time_model();
        let c = model.curve();
        let duration = edge_time(c, len)?;
        let dt = duration / segments as f64;
        let mut quantizer = Quantizer::new(spec);
        // The per-step table, step by step, as `for_each_period` rounds it.
        let mut per_step = Quantizer::new(spec).without_offset();
        per_step.reachable(c.freq(0.0), c.end_freq())?;
        let mut step_start = 0.0;
        let mut edges = Edges::new(c, EDGE_TOLERANCE_TICKS / scale);

        let (mut steps_before, mut step, mut played) = (0u32, 0u32, 0u64);
        let (mut max_error, mut last_error) = (0.0f64, 0.0);
        for i in 0..segments {
            let steps_after = if i + 1 == segments {
                len
            } else {
                libm::round(c.steps((i + 1) as f64 * dt)).clamp(0.0, len as f64) as u32
            };
            let count = steps_after.saturating_sub(steps_before);
            if count == 0 {
                return Err(Error::EmptySegment {
                    index: i,
                    steps: len,
                });
            }
            if count > word.max() {
                return Err(Error::SegmentTooLong {
                    index: i,
                    count,
                    word,
                });
            }
            let exact = dt * scale / count as f64;
            let end = edge_time(c, steps_after)? * scale;
            let period = quantizer.round(step, exact, Some(end), count)?;
            quantizer.stored(i, period, "segment")?;
            for _ in 0..count {
                played += period as u64;
                step += 1;
                let next = edges.time(step)?;
                per_step.push(step - 1, (next - step_start) * scale, Some(next * scale))?;
                step_start = next;
                let error = (played as f64 - next * scale) * repeat;
                max_error = max_error.max(libm::fabs(error));
                last_error = error;
            }
            sink(i, period, count);
            steps_before = steps_after;
        }
        let word_bytes = word.bytes();
        Ok(CompactFigures {
            kind: "segments",
            entries: segments,
            steps: len,
            flash_bytes: 2 * word_bytes * segments,
            per_step_flash_bytes: word_bytes * len,
            total_ticks: played,
            duration_s: played as f64 / scale,
            max_edge_error_ticks: max_error,
            total_error_ticks: last_error,
            tolerance_ticks: None,
        })
    }
}

impl Spec {
    /// Checks the spec and that it can be cut into `segments` segments
    /// ([`CheckedSpec::check_segments`]).
    pub fn check_segments(&self, segments: u32) -> Result<(), Error> {
        self.check()?.check_segments(segments)
    }

    /// Checks the spec and computes its segment table into `out`
    /// ([`CheckedSpec::generate_segments`]).
    pub fn generate_segments<W: TableWord>(
        &self,
        out: &mut [(W, W)],
    ) -> Result<CompactFigures, Error> {
        self.check()?.generate_segments(out)
    }

    /// Checks the spec and computes `segments` segments
    /// ([`CheckedSpec::for_each_segment`]).
    pub fn for_each_segment<F: FnMut(u32, u32, u32)>(
        &self,
        segments: u32,
        sink: F,
    ) -> Result<CompactFigures, Error> {
        self.check()?.for_each_segment(segments, sink)
    }
}
