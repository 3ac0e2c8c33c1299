//! `curve = jerk_limited`: the keys it takes and how they are read and
//! described.

use profile_core::{JerkLimited, Key};

use super::{Param, Reader, Schema};

impl Schema for JerkLimited {
    const NAME: &'static str = "jerk_limited";
    const KEYS: &'static [Key] = &[Key::FMIN, Key::FMAX, Key::ACCEL, Key::JERK];
    const REQUIRED: &'static [Key] = Self::KEYS;
    const UNITS: &'static [(Key, &'static str)] = &[(Key::JERK, "Hz/s²")];

    fn read(r: &mut dyn Reader) -> Option<Self> {
        let (fmin, fmax) = (r.number(Key::FMIN), r.number(Key::FMAX));
        let (accel, jerk) = (r.number(Key::ACCEL), r.number(Key::JERK));
        Some(JerkLimited {
            fmin: fmin?,
            fmax: fmax?,
            accel: accel?,
            jerk: jerk?,
        })
    }

    fn describe(&self, out: &mut dyn FnMut(Key, Param)) {
        for (key, value) in [
            (Key::FMIN, self.fmin),
            (Key::FMAX, self.fmax),
            (Key::ACCEL, self.accel),
            (Key::JERK, self.jerk),
        ] {
            out(key, Param::Number(value));
        }
    }
}
