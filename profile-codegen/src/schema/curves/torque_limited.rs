//! `curve = torque_limited`: the keys it takes and how they are read and
//! described.

use profile_core::{AccelCurve, Key, TorqueLimited};

use super::{Param, Reader, Schema};

impl Schema for TorqueLimited {
    const NAME: &'static str = "torque_limited";
    const KEYS: &'static [Key] = &[Key::FMIN, Key::FMAX, Key::MARGIN];
    const REQUIRED: &'static [Key] = &[Key::FMAX, Key::MARGIN];

    fn read(r: &mut dyn Reader) -> Option<Self> {
        // The start and the acceleration come from the motor, once it is
        // read: the start when `fmin` is not given.
        let fmin = if r.has(Key::FMIN) {
            r.number(Key::FMIN)
        } else {
            Some(f64::NAN)
        };
        let (fmax, margin) = (r.number(Key::FMAX), r.number(Key::MARGIN));
        Some(TorqueLimited {
            fmin: fmin?,
            fmax: fmax?,
            margin: margin?,
            accel: AccelCurve::EMPTY,
        })
    }

    fn describe(&self, out: &mut dyn FnMut(Key, Param)) {
        out(Key::FMIN, Param::Number(self.fmin));
        out(Key::FMAX, Param::Number(self.fmax));
        out(Key::MARGIN, Param::Number(self.margin));
    }
}
