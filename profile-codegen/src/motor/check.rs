//! The check of a table against the motor: every edge's torque need,
//! judged on the acceleration the rotor feels, against the pull-out torque
//! over the safety factor; then the ends of a move (`start`).

use crate::motor::{Motor, MotorError, TorqueFigures};
use profile_core::Spec;

impl Motor {
    /// Checks that the motor can follow `periods` (a table of `spec`): every
    /// edge's torque need against the pull-out curve, and the start frequency.
    pub fn check(&self, spec: &Spec, periods: &[u32]) -> Result<TorqueFigures, MotorError> {
        self.check_with(spec, periods, |_, _, _, _| {})
    }

    /// [`Motor::check`], also calling `each(step, hz, needed, available)` for
    /// every edge (step 0 is the start from rest), for plots.
    pub fn check_with<F: FnMut(u32, f64, f64, f64)>(
        &self,
        spec: &Spec,
        periods: &[u32],
        mut each: F,
    ) -> Result<TorqueFigures, MotorError> {
        self.validate()?;
        let per_second = spec.timer.timer_hz as f64 / spec.timer.ticks_per_step as f64;
        let inertia = self.rotor_inertia + self.load_inertia;
        let theta = self.step_radians();
        // The start is an edge too: from rest to the first entry's speed.
        // Pulling in from rest is judged above; what the check asks of the
        // first step here is the torque to keep that speed.
        let Some(&first) = periods.first() else {
            return Err(MotorError::EmptyTable);
        };
        let hz = per_second / first as f64;
        let mut worst = self.judge(0, hz, self.friction + self.damping * theta * hz, &mut each)?;

        // Speeds are averaged on each side of an edge over the shortest
        // window of at least one full step (`microsteps` entries) that lasts
        // at least the rotor's `1 / ω_n` (fewer at the ends of the table).
        let m = (self.microsteps as usize).max(1);
        let least = self.felt_window() * per_second;
        let n = periods.len();
        // Window a = entries [a_start, k + 1), window b = [k + 1, b_end).
        let (mut sum_a, mut a_start, mut sum_b, mut b_end) = (0u64, 0usize, 0u64, 1usize);
        for (k, w) in periods.windows(2).enumerate() {
            sum_a += w[0] as u64;
            // Drop the oldest entry while the window stays long enough.
            while k + 1 - a_start > m && (sum_a - periods[a_start] as u64) as f64 >= least {
                sum_a -= periods[a_start] as u64;
                a_start += 1;
            }
            if k > 0 {
                sum_b -= w[0] as u64;
            }
            while b_end < n && (b_end < k + 1 + m || (sum_b as f64) < least) {
                sum_b += periods[b_end] as u64;
                b_end += 1;
            }
            let (mut sum_b, mut lb) = (sum_b as f64, (b_end - k - 1) as f64);
            if b_end == n {
                // Past the table's end the player cruises at its last
                // period: the window goes on at that speed.
                let last = periods[n - 1] as f64;
                let more = (m as f64 - lb)
                    .max(libm::ceil((least - sum_b) / last))
                    .max(0.0);
                (sum_b, lb) = (sum_b + more * last, lb + more);
            }
            let (ta, tb) = (sum_a as f64 / per_second, sum_b / per_second);
            let la = (k + 1 - a_start) as f64;
            // Angular acceleration between the two windows' mean speeds, a
            // time apart of half of both windows (with one entry per window:
            // between the two steps' speeds, half of both periods apart).
            let alpha = theta * (lb / tb - la / ta) / ((ta + tb) / 2.0);
            let (fa, fb) = (per_second / w[0] as f64, per_second / w[1] as f64);
            // Less torque at higher frequency: judge at the faster step.
            let hz = fa.max(fb);
            let needed = inertia * alpha + self.friction + self.damping * theta * hz;
            let figures = self.judge(k as u32 + 1, hz, needed, &mut each)?;
            if figures.min_margin_nm < worst.min_margin_nm {
                worst = figures;
            }
        }
        // Then the ends of a move, from the model: the start from rest and
        // the stop.
        let hz = per_second / first as f64;
        if !self.starts_at(hz) {
            return Err(MotorError::Start {
                hz,
                limit: self.start_limit(hz),
            });
        }
        self.check_ends(per_second, periods)?;
        Ok(worst)
    }

    /// The least time over which [`Motor::check`] averages the table's speed
    /// on each side of an edge, in s: `1 / ω_n`, with `ω_n = sqrt(K / J)`
    /// the rotor's natural angular frequency ([`Motor::stiffness`]). The
    /// rotor is a spring and mass that filters the field's motion: a change
    /// of speed `Δω` in a shorter time pulls it with at most the torque
    /// `J Δω ω_n` of the spring, which is the window's `J Δω / (1 / ω_n)`;
    /// and a tick of rounding, which moves the field by a small fraction of
    /// a step, reads as next to no acceleration over it. 0 where `ω_n` is
    /// not a finite number above 0.
    pub fn felt_window(&self) -> f64 {
        let window = libm::sqrt((self.rotor_inertia + self.load_inertia) / self.stiffness());
        if window.is_finite() && window > 0.0 {
            window
        } else {
            0.0
        }
    }

    /// One edge: the torque `needed` at step frequency `hz` against what the
    /// motor gives there.
    fn judge<F: FnMut(u32, f64, f64, f64)>(
        &self,
        step: u32,
        hz: f64,
        needed: f64,
        each: &mut F,
    ) -> Result<TorqueFigures, MotorError> {
        let available = self.available_of_valid(hz);
        for (value, what) in [(needed, "needed"), (available, "available")] {
            if !value.is_finite() {
                return Err(MotorError::NotFinite { step, what });
            }
        }
        each(step, hz, needed, available);
        if needed > available {
            return Err(MotorError::Torque {
                step,
                hz,
                needed_nm: needed,
                available_nm: available,
                beyond_curve: self.torque_curve.is_some_and(|c| hz > c.top()),
                from_windings: match (&self.torque_curve, &self.windings) {
                    (None, Some(w)) => Some(w.drive),
                    _ => None,
                },
            });
        }
        let margin = available - needed;
        if !margin.is_finite() {
            return Err(MotorError::NotFinite {
                step,
                what: "margin",
            });
        }
        Ok(TorqueFigures {
            min_margin_nm: margin,
            step,
            hz,
            needed_nm: needed,
            available_nm: available,
        })
    }
}
