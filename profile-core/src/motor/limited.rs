//! The fastest ramp a motor allows: the acceleration its torque leaves at
//! every speed ([`TorqueLimited`]).

use crate::curves::public::{AccelCurve, MAX_ACCEL_POINTS, TorqueLimited};
use crate::motor::{Motor, MotorError};

/// Points a derived pull-out curve is sampled at over the ramp: enough that
/// the straight lines between them stay within a small part of the margin
/// of the smooth curve they follow.
const SAMPLES: usize = 32;

impl Motor {
    /// The fastest ramp this motor allows from `fmin` (the model's fastest
    /// start from rest, times `margin`, when `None`) to `fmax`, with
    /// `margin`: at every step frequency `f`, the acceleration
    ///
    /// ```text
    /// a(f) = margin · (pull_out(f) / safety - friction - damping · θ · f) / (J · θ)
    /// ```
    ///
    /// in table steps per second², `θ` the angle of a table step, `J` the
    /// rotor's and the load's inertia: the share `margin` of the torque
    /// the motor has to spare, as the motor check counts it. A torque
    /// curve's points are the acceleration curve's (it is straight between
    /// them as the torque is); a curve derived from the windings is
    /// sampled at 32 frequencies over the ramp.
    ///
    /// Errors: the motor's own ([`Motor::validate`]); no torque to spare
    /// at some frequency up to `fmax` ([`MotorError::NoSpareTorque`]). The
    /// ramp's own figures (`fmin` below `fmax`, `margin` above 0 and at
    /// most 0.99) are checked with its spec.
    ///
    /// ```
    /// use profile_core::motor::{Motor, TorqueCurve};
    /// use profile_core::{Curve, Spec, Timer};
    ///
    /// let curve = TorqueCurve::new(&[(0.0, 0.40), (8000.0, 0.30), (16_000.0, 0.15)]).unwrap();
    /// let motor = Motor::new(1.8, 4, 6.8e-6)
    ///     .with_torque_curve(curve)
    ///     .with_load_inertia(1.36e-5)
    ///     .with_friction(0.02)
    ///     .with_damping_ratio(0.1);
    /// let ramp = motor.torque_limited(Some(1000.0), 12_000.0, 0.7).unwrap();
    /// let spec = Spec::new(Curve::TorqueLimited(ramp), Timer::new(1_000_000));
    /// let mut periods = vec![0u16; spec.len() as usize];
    /// spec.generate(&mut periods).unwrap();
    /// // The check passes with the rest of the torque to spare.
    /// let periods: Vec<u32> = periods.iter().map(|&p| u32::from(p)).collect();
    /// assert!(motor.check(&spec, &periods).unwrap().min_margin_nm > 0.0);
    /// ```
    pub fn torque_limited(
        &self,
        fmin: Option<f64>,
        fmax: f64,
        margin: f64,
    ) -> Result<TorqueLimited, MotorError> {
        self.validate()?;
        let fmin = match fmin {
            Some(hz) => hz,
            None => self.start_limit(fmax).hz() * margin,
        };
        let theta = self.step_radians();
        let inertia = self.rotor_inertia + self.load_inertia;
        let accel = |hz: f64| -> Result<(f64, f64), MotorError> {
            let available_nm = self.available(hz);
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
            Ok((hz, margin * spare / (inertia * theta)))
        };
        let mut points = [(0.0, 0.0); MAX_ACCEL_POINTS];
        let mut n = 0;
        let mut push = |p: (f64, f64)| {
            if n < MAX_ACCEL_POINTS {
                points[n] = p;
                n += 1;
            }
        };
        // Frequencies only where the ramp is (a bad `fmin` or `fmax` is
        // the spec's to report): the ends, and between them the curve's
        // points or the samples.
        if fmin.is_finite() && fmax.is_finite() && fmin < fmax && fmin >= 0.0 {
            push(accel(fmin)?);
            match &self.torque_curve {
                Some(curve) => {
                    for &(hz, _) in curve.points() {
                        if hz > fmin && hz < fmax {
                            push(accel(hz)?);
                        }
                    }
                }
                None => {
                    for k in 1..SAMPLES - 1 {
                        let hz = fmin + (fmax - fmin) * k as f64 / (SAMPLES - 1) as f64;
                        push(accel(hz)?);
                    }
                }
            }
            push(accel(fmax)?);
        }
        Ok(TorqueLimited {
            fmin,
            fmax,
            margin,
            accel: AccelCurve::new(&points[..n]).unwrap_or(AccelCurve::EMPTY),
        })
    }
}
