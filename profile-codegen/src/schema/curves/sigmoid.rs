//! `curve = sigmoid`: the keys it takes and how they are read and
//! described.

use profile_core::{Key, Sigmoid};

use super::{Param, Reader, Schema};

impl Schema for Sigmoid {
    const NAME: &'static str = "sigmoid";
    const KEYS: &'static [Key] = &[Key::LEN, Key::FMIN, Key::FMAX, Key::FLEXIBLE];
    const REQUIRED: &'static [Key] = Self::KEYS;

    fn read(r: &mut dyn Reader) -> Option<Self> {
        let (len, fmin, fmax) = (r.len(), r.number(Key::FMIN), r.number(Key::FMAX));
        let flexible = r.number(Key::FLEXIBLE);
        Some(Sigmoid {
            fmin: fmin?,
            fmax: fmax?,
            flexible: flexible?,
            len: len?,
        })
    }

    fn describe(&self, out: &mut dyn FnMut(Key, Param)) {
        out(Key::LEN, Param::Count(self.len));
        out(Key::FMIN, Param::Number(self.fmin));
        out(Key::FMAX, Param::Number(self.fmax));
        out(Key::FLEXIBLE, Param::Number(self.flexible));
    }
}
