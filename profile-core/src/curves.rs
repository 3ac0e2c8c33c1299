//! Dispatch over the curves' time-domain models, and table lengths.

use crate::exponential::ExponentialInTime;
use crate::jerk::JerkInTime;
use crate::linear::LinearInTime;
use crate::sigmoid::SigmoidInTime;
use crate::solve::TimeCurve;
use crate::spec::{Curve, ExponentialExtent, LinearExtent};
use crate::three_stage::ThreeStageInTime;

/// A curve's time-domain model, for the `exact` and `left_endpoint` discretizations.
pub(crate) enum TimeModel {
    Sigmoid(SigmoidInTime),
    Exponential(ExponentialInTime),
    Linear(LinearInTime),
    ThreeStage(ThreeStageInTime),
    Jerk(JerkInTime),
}

impl TimeModel {
    /// The model of a validated curve.
    pub(crate) fn new(curve: &Curve) -> Self {
        match curve {
            Curve::Sigmoid(c) => TimeModel::Sigmoid(SigmoidInTime::new(c)),
            Curve::Exponential(c) => TimeModel::Exponential(ExponentialInTime::new(c)),
            Curve::Linear(c) => TimeModel::Linear(LinearInTime::new(c)),
            Curve::ThreeStage(c) => TimeModel::ThreeStage(ThreeStageInTime::new(c)),
            Curve::JerkLimited(c) => TimeModel::Jerk(JerkInTime::new(c)),
        }
    }

    pub(crate) fn curve(&self) -> &dyn TimeCurve {
        match self {
            TimeModel::Sigmoid(c) => c,
            TimeModel::Exponential(c) => c,
            TimeModel::Linear(c) => c,
            TimeModel::ThreeStage(c) => c,
            TimeModel::Jerk(c) => c,
        }
    }
}

/// The steps the curve takes to reach `fmax`, as a real number, and whether
/// that count is given (`len`) rather than derived from the parameters.
pub(crate) fn ramp_steps(curve: &Curve, index: bool) -> (f64, bool) {
    match curve {
        Curve::Sigmoid(c) => (c.len as f64, true),
        Curve::Exponential(c) => match c.extent {
            ExponentialExtent::Len(len) => (len as f64, true),
            ExponentialExtent::Tau(_) => (ExponentialInTime::new(c).ramp_steps(), false),
        },
        Curve::Linear(c) => match c.extent {
            LinearExtent::Len(len) => (len as f64, true),
            LinearExtent::Accel(_) => (c.ramp_steps(index), false),
        },
        Curve::ThreeStage(c) => (ThreeStageInTime::new(c).ramp_steps(), false),
        Curve::JerkLimited(c) => (JerkInTime::new(c).ramp_steps(), false),
    }
}

/// Entries of a table whose ramp takes `steps` (a real number) steps: the
/// steps rounded up, plus one over the index of a linear ramp (`trans + 1`
/// entries). Rounding forgives a relative 1e-9, so a ramp of 120.000000001
/// steps is 120 entries. 0 for a non-finite or non-positive count.
pub(crate) fn entries(steps: f64, given: bool, linear_index: bool) -> u32 {
    if given {
        return steps as u32;
    }
    if !(steps.is_finite() && steps > 0.0) {
        return 0;
    }
    let whole = libm::ceil(steps - 1e-9 * steps.max(1.0)).max(1.0);
    let whole = whole + if linear_index { 1.0 } else { 0.0 };
    if whole > u32::MAX as f64 {
        u32::MAX
    } else {
        whole as u32
    }
}
