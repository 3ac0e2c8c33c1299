//! How a curve becomes integer periods: discretization, rounding, arithmetic.

/// How a continuous curve becomes one entry per step (DESIGN section 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Discretization {
    /// Entry `k` is `t(k+1) - t(k)` where `N(t(k)) = k`: pulse edges land where
    /// the continuous curve puts them. The default.
    #[default]
    Exact,
    /// Entry `k` is `1 / f(t(k))`: the frequency at the start of the step
    /// (too long while accelerating).
    LeftEndpoint,
    /// Entry `k` is `1 / f(x = k)`: the curve's x axis is the step index
    /// (the S-curve and S3C4510 articles' tables).
    Index,
}

impl Discretization {
    /// The name used in macro arguments and TOML.
    pub const fn name(self) -> &'static str {
        match self {
            Discretization::Exact => "exact",
            Discretization::LeftEndpoint => "left_endpoint",
            Discretization::Index => "index",
        }
    }
}

/// How exact periods (in fractional ticks) become integers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Rounding {
    /// Drop the fraction, as C's `(unsigned short)` cast does. Drifts short.
    Truncate,
    /// Round each entry to the nearest tick (halves away from zero).
    Nearest,
    /// Round the running sum of exact times and emit the differences: every
    /// pulse edge within 0.5 tick of its exact time. The default.
    #[default]
    Diffuse,
}

impl Rounding {
    /// The name used in macro arguments and TOML.
    pub const fn name(self) -> &'static str {
        match self {
            Rounding::Truncate => "truncate",
            Rounding::Nearest => "nearest",
            Rounding::Diffuse => "diffuse",
        }
    }
}

/// The floating-point arithmetic the curve is evaluated in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Arithmetic {
    /// Double precision (the default).
    #[default]
    F64,
    /// Single precision, operation for operation as the C function
    /// `CalculateSModelLine` of "Stepper Motor S-curve Acceleration and
    /// Deceleration Algorithm and Implementation", so tables migrated from C keep their bits.
    /// Applies to `curve = sigmoid` with `discretization = index`.
    F32,
    /// Integer arithmetic, operation for operation as `pulse()` of "Stepper
    /// motor acceleration/deceleration control based on ARM chip S3C4510":
    /// `A = (fmax - fmin)(fmax + fmin) / (2 trans)`, `f[i] = isqrt(2 A i + fmin²)`,
    /// `reload = timer_hz / (ticks_per_step f[i])`, all integer divisions. Applies
    /// to `curve = linear` with `discretization = index` and `rounding = truncate`;
    /// where the article's 16-bit variables would overflow, an error.
    Integer,
}

impl Arithmetic {
    /// The name used in macro arguments and TOML.
    pub const fn name(self) -> &'static str {
        match self {
            Arithmetic::F64 => "f64",
            Arithmetic::F32 => "f32",
            Arithmetic::Integer => "integer",
        }
    }
}
