//! [`Motor`]'s constructor and its `with_*` methods, `const` so that a motor
//! can be a `const` item.

use crate::motor::{Motor, TorqueCurve, Windings};

impl Motor {
    /// A motor of `step_angle` degrees per full step, driven at
    /// `microsteps` per full step (the table's steps are microsteps), its
    /// rotor of `rotor_inertia` kg·m², with nothing else: no torque curve,
    /// no windings, no load inertia, friction or damping (all 0), a safety
    /// factor of 1 and no known start frequency.
    ///
    /// A motor needs a torque curve ([`with_torque_curve`]) or windings
    /// ([`with_windings`]) before it validates; [`validate`] says
    /// [`MotorError::NoTorque`] until it has one. The `with_*` methods set
    /// the rest.
    ///
    /// ```
    /// use profile_codegen::motor::{Motor, Windings};
    ///
    /// /// A NEMA 17 on a 24 V chopper at 1/8 steps, with a load of twice
    /// /// its rotor's inertia and 0.02 N·m of friction.
    /// const NEMA17: Motor = Motor::new(1.8, 8, 6.8e-6)
    ///     .with_windings(Windings::new(0.5, 0.6e-3, 2.8, 0.40, 24.0))
    ///     .with_load_inertia(1.36e-5)
    ///     .with_friction(0.02)
    ///     .with_damping_ratio(0.1)
    ///     .with_safety(1.5);
    ///
    /// assert_eq!(NEMA17.validate(), Ok(()));
    /// assert_eq!(
    ///     Motor::new(1.8, 8, 6.8e-6).validate(),
    ///     Err(profile_codegen::motor::MotorError::NoTorque)
    /// );
    /// ```
    ///
    /// [`with_torque_curve`]: Motor::with_torque_curve
    /// [`with_windings`]: Motor::with_windings
    /// [`validate`]: Motor::validate
    /// [`MotorError::NoTorque`]: crate::motor::MotorError::NoTorque
    #[must_use]
    pub const fn new(step_angle: f64, microsteps: u32, rotor_inertia: f64) -> Self {
        Motor {
            step_angle,
            microsteps,
            rotor_inertia,
            load_inertia: 0.0,
            torque_curve: None,
            windings: None,
            friction: 0.0,
            damping: 0.0,
            damping_ratio: 0.0,
            safety: 1.0,
            max_start_hz: None,
        }
    }

    /// The same motor with a measured pull-out torque curve, `(step
    /// frequency in Hz, torque in N·m)` points: the torque the check and
    /// the simulation use, before any windings ([`Motor::torque_curve`]).
    #[must_use]
    pub const fn with_torque_curve(mut self, curve: TorqueCurve) -> Self {
        self.torque_curve = Some(curve);
        self
    }

    /// The same motor with windings and a driver, from which the pull-out
    /// torque is derived when there is no torque curve
    /// ([`Motor::windings`]).
    #[must_use]
    pub const fn with_windings(mut self, windings: Windings) -> Self {
        self.windings = Some(windings);
        self
    }

    /// The same motor with a load inertia seen at the shaft, in kg·m².
    #[must_use]
    pub const fn with_load_inertia(mut self, load_inertia: f64) -> Self {
        self.load_inertia = load_inertia;
        self
    }

    /// The same motor with a constant load and friction torque, in N·m.
    #[must_use]
    pub const fn with_friction(mut self, friction: f64) -> Self {
        self.friction = friction;
        self
    }

    /// The same motor with viscous damping, in N·m·s/rad: a drag of
    /// `damping · ω` on the rotor's speed ([`Motor::damping`]).
    #[must_use]
    pub const fn with_damping(mut self, damping: f64) -> Self {
        self.damping = damping;
        self
    }

    /// The same motor with electromagnetic damping as a ratio of critical
    /// damping, `ζ`, from 0 to 1 (dimensionless; [`Motor::damping_ratio`]).
    #[must_use]
    pub const fn with_damping_ratio(mut self, damping_ratio: f64) -> Self {
        self.damping_ratio = damping_ratio;
        self
    }

    /// The same motor with a safety factor (dimensionless, at least 1): the
    /// available torque is divided by it.
    #[must_use]
    pub const fn with_safety(mut self, safety: f64) -> Self {
        self.safety = safety;
        self
    }

    /// The same motor with a known maximum no-load start frequency, in Hz
    /// of the table's steps ([`Motor::max_start_hz`]).
    #[must_use]
    pub const fn with_max_start_hz(mut self, hz: f64) -> Self {
        self.max_start_hz = Some(hz);
        self
    }
}
