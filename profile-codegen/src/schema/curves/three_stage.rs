//! `curve = three_stage`: the keys it takes and how they are read and
//! described.

use profile_core::{Key, ThreeStage};

use super::{Param, Reader, Schema};

impl Schema for ThreeStage {
    const NAME: &'static str = "three_stage";
    const KEYS: &'static [Key] = &[
        Key::FMIN,
        Key::FMAX,
        Key::ACCEL,
        Key::F1,
        Key::F2,
        Key::SHAPE,
    ];

    const REQUIRED: &'static [Key] = Self::KEYS;
    const UNITS: &'static [(Key, &'static str)] = &[
        (Key::F1, "Hz (steps/s)"),
        (Key::F2, "Hz (steps/s)"),
        (Key::SHAPE, "1/s"),
    ];

    fn read(r: &mut dyn Reader) -> Option<Self> {
        let (fmin, fmax, accel) = (
            r.number(Key::FMIN),
            r.number(Key::FMAX),
            r.number(Key::ACCEL),
        );
        let (f1, f2, shape) = (r.number(Key::F1), r.number(Key::F2), r.number(Key::SHAPE));
        Some(ThreeStage {
            fmin: fmin?,
            fmax: fmax?,
            accel: accel?,
            f1: f1?,
            f2: f2?,
            shape: shape?,
        })
    }

    fn describe(&self, out: &mut dyn FnMut(Key, Param)) {
        for (key, value) in [
            (Key::FMIN, self.fmin),
            (Key::FMAX, self.fmax),
            (Key::ACCEL, self.accel),
            (Key::F1, self.f1),
            (Key::F2, self.f2),
            (Key::SHAPE, self.shape),
        ] {
            out(key, Param::Number(value));
        }
    }
}
