//! The fastest ramp a motor allows: the acceleration its torque leaves at
//! every speed ([`TorqueLimited`]).

use crate::motor::{Motor, MotorError};
use crate::table::computed::SpecTables;
use profile_core::{AccelCurve, Curve, MAX_ACCEL_POINTS, TorqueLimited};
use profile_core::{Spec, Timer};

/// Points a derived pull-out curve is sampled at over the ramp.
const SAMPLES: usize = 32;

/// The shares of the torque a ramp is planned on, in turn, until its
/// table passes the check: the check reads the acceleration off rounded
/// periods, over windows of whole periods of the rotor's natural swing,
/// which stands a little off the ramp's own where the torque bends or the
/// periods are few ticks long.
const SHARES: [f64; 8] = [1.0, 0.995, 0.99, 0.98, 0.97, 0.95, 0.9, 0.8];

impl Motor {
    /// The fastest ramp this motor allows from `fmin` (the model's fastest
    /// start from rest, times `margin`, when `None`) to `fmax`, with
    /// `margin`, for a table of `timer`'s periods: at every step frequency
    /// `f`, the acceleration
    ///
    /// ```text
    /// a(f) = (s · margin · pull_out(f') / safety - friction - damping · θ · f') / (J · θ)
    /// ```
    ///
    /// in table steps per second², `θ` the angle of a table step, `J` the
    /// rotor's and the load's inertia: all the torque the motor gives with
    /// its safety factor divided by `margin`, less what the load takes, as
    /// the motor check counts them, so that no ramp whose edges pass the
    /// check of the motor with `safety / margin` is faster at any speed.
    /// The torque is taken one step ahead, at `f' = f + a / f` (up to
    /// `fmax`), where the check judges a step's acceleration. The share
    /// `s` is the largest of 1, 0.995, 0.99, 0.98, 0.97, 0.95, 0.9 and 0.8
    /// with which the table of `timer`'s periods (exact, diffuse rounding)
    /// passes that check at every edge; its start from rest is the
    /// motor's own check's. A torque curve's points are the acceleration
    /// curve's (it is straight between them as the torque is); a curve
    /// derived from the windings is sampled at 32 frequencies over the
    /// ramp, each point lowered by twice the most the straight lines beside
    /// it stand above the curve at their middles.
    ///
    /// Errors: the motor's own ([`Motor::validate`]); no torque to spare
    /// at some frequency up to `fmax` ([`MotorError::NoSpareTorque`]); a
    /// table that does not pass at `safety / margin` even on 0.8 of the
    /// torque ([`MotorError::MarginUnkept`]: its periods too few ticks
    /// long for the little torque there is to spare). The ramp's own
    /// figures (`fmin` below `fmax`, `margin` above 0 and at most 0.99, the
    /// table's length) are checked with its spec.
    ///
    /// ```
    /// use profile_codegen::motor::{Motor, MotorError, TorqueCurve};
    /// use profile_core::{Curve, Spec, Timer};
    ///
    /// let curve = TorqueCurve::new(&[(0.0, 0.40), (8000.0, 0.30), (16_000.0, 0.15)]).unwrap();
    /// let motor = Motor::new(1.8, 4, 6.8e-6)
    ///     .with_torque_curve(curve)
    ///     .with_load_inertia(1.36e-5)
    ///     .with_friction(0.02)
    ///     .with_damping_ratio(0.1);
    /// let timer = Timer::new(1_000_000);
    /// let ramp = motor.torque_limited(Some(1000.0), 12_000.0, 0.7, timer).unwrap();
    /// let spec = Spec::new(Curve::TorqueLimited(ramp), timer);
    /// let mut periods = vec![0u16; spec.len() as usize];
    /// spec.generate(&mut periods).unwrap();
    /// // The motor's check passes, and every edge passes with the safety
    /// // factor over the margin.
    /// let periods: Vec<u32> = periods.iter().map(|&p| u32::from(p)).collect();
    /// assert!(motor.check(&spec, &periods).is_ok());
    /// let strict = motor.with_safety(motor.safety / 0.7);
    /// assert!(!matches!(strict.check(&spec, &periods), Err(MotorError::Torque { .. })));
    /// ```
    pub fn torque_limited(
        &self,
        fmin: Option<f64>,
        fmax: f64,
        margin: f64,
        timer: Timer,
    ) -> Result<TorqueLimited, MotorError> {
        let strict = self.with_safety(self.safety / margin);
        let mut refused = None;
        for share in SHARES {
            let ramp = self.planned(fmin, fmax, margin, share)?;
            let spec = Spec::new(Curve::TorqueLimited(ramp), timer);
            // The spec's own mistakes are its to report.
            let Ok(table) = spec.table() else {
                return Ok(ramp);
            };
            match strict.check(&spec, &table.periods) {
                Err(MotorError::Torque {
                    step,
                    hz,
                    needed_nm,
                    available_nm,
                    ..
                }) => refused = Some((step, hz, needed_nm, available_nm)),
                // Every edge passed: a start from rest the motor cannot
                // make is the motor check's to report (or, without
                // `fmin`, a slower start's to mend), not a smaller share's.
                _ => return Ok(ramp),
            }
        }
        let (step, hz, needed_nm, available_nm) = refused.unwrap_or_default();
        Err(MotorError::MarginUnkept {
            step,
            hz,
            needed_nm,
            available_nm,
        })
    }

    /// The ramp planned on `share` of the torque `margin` allows.
    fn planned(
        &self,
        fmin: Option<f64>,
        fmax: f64,
        margin: f64,
        share: f64,
    ) -> Result<TorqueLimited, MotorError> {
        self.validate()?;
        let fmin = match fmin {
            Some(hz) => hz,
            None => self.start_limit(fmax).hz() * margin,
        };
        let theta = self.step_radians();
        let inertia = self.rotor_inertia + self.load_inertia;
        // The torque left for accelerating at `hz`, N·m.
        let spare_at = |hz: f64| -> Result<f64, MotorError> {
            let available_nm = share * margin * self.available(hz);
            let load_nm = self.friction + self.damping * theta * hz;
            let spare = available_nm - load_nm;
            // Torque to spare within the rounding of the figures it is
            // the difference of (or a NaN) is none: the ramp would take
            // forever to get past it.
            if spare.is_nan() || spare <= 1e-9 * available_nm.max(load_nm) {
                return Err(MotorError::NoSpareTorque {
                    hz,
                    available_nm,
                    load_nm,
                });
            }
            Ok(spare)
        };
        // The same, taken where the check judges the step that leaves
        // `hz`: one step's gain of speed ahead, up to `fmax`.
        let spare = |hz: f64| -> Result<f64, MotorError> {
            let here = spare_at(hz)?;
            if hz <= 0.0 {
                return Ok(here);
            }
            let ahead = (hz + here / (inertia * theta) / hz).min(fmax.max(hz));
            Ok(spare_at(ahead)?.min(here))
        };
        let mut points = [(0.0, 0.0); MAX_ACCEL_POINTS];
        let mut n = 0;
        // Frequencies only where the ramp is (a bad `fmin` or `fmax` is
        // the spec's to report): the ends, and between them the curve's
        // points or the samples.
        if fmin.is_finite() && fmax.is_finite() && fmin < fmax && fmin >= 0.0 {
            let mut push = |hz: f64, nm: f64| {
                if n < MAX_ACCEL_POINTS {
                    points[n] = (hz, nm);
                    n += 1;
                }
            };
            push(fmin, spare(fmin)?);
            match &self.torque_curve {
                // Straight between its points, as the torque is.
                Some(curve) => {
                    for &(hz, _) in curve.points() {
                        if hz > fmin && hz < fmax {
                            push(hz, spare(hz)?);
                        }
                    }
                }
                None => {
                    for k in 1..SAMPLES - 1 {
                        let hz = fmin + (fmax - fmin) * k as f64 / (SAMPLES - 1) as f64;
                        push(hz, spare(hz)?);
                    }
                }
            }
            push(fmax, spare(fmax)?);
            if self.torque_curve.is_none() {
                lower_below(&mut points[..n], &spare)?;
            }
        }
        for p in &mut points[..n] {
            p.1 /= inertia * theta;
        }
        Ok(TorqueLimited {
            fmin,
            fmax,
            margin,
            accel: AccelCurve::new(&points[..n]).unwrap_or(AccelCurve::EMPTY),
        })
    }
}

/// Lowers each sample of a smooth curve by the most that the straight
/// lines on either side of it stand above the curve at their middles, so
/// that the lines stay below the curve between the samples. Fails as the
/// curve does, where it has nothing to spare.
fn lower_below(
    points: &mut [(f64, f64)],
    spare: &dyn Fn(f64) -> Result<f64, MotorError>,
) -> Result<(), MotorError> {
    let mut above = [0.0f64; MAX_ACCEL_POINTS];
    for (i, w) in points.windows(2).enumerate() {
        let ((fa, ta), (fb, tb)) = (w[0], w[1]);
        let gap = (0.5 * (ta + tb) - spare(0.5 * (fa + fb))?).max(0.0);
        above[i] = above[i].max(gap);
        above[i + 1] = above[i + 1].max(gap);
    }
    for (p, &gap) in points.iter_mut().zip(&above) {
        p.1 -= 2.0 * gap;
        if p.1.is_nan() || p.1 <= 0.0 {
            return Err(MotorError::NoSpareTorque {
                hz: p.0,
                available_nm: p.1 + 2.0 * gap,
                load_nm: 2.0 * gap,
            });
        }
    }
    Ok(())
}
