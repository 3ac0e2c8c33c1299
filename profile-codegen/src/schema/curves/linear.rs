//! `curve = linear`: the keys it takes and how they are read and
//! described.

use profile_core::{Key, Linear, LinearExtent};

use super::{Param, Reader, Schema};

impl Schema for Linear {
    const NAME: &'static str = "linear";
    const KEYS: &'static [Key] = &[Key::FMIN, Key::FMAX, Key::LEN, Key::ACCEL];
    const REQUIRED: &'static [Key] = &[Key::FMIN, Key::FMAX];
    const ONE_OF: Option<[Key; 2]> = Some([Key::LEN, Key::ACCEL]);

    fn read(r: &mut dyn Reader) -> Option<Self> {
        let (fmin, fmax) = (r.number(Key::FMIN), r.number(Key::FMAX));
        let extent = if r.has(Key::LEN) {
            LinearExtent::Len(r.len()?)
        } else {
            LinearExtent::Accel(r.number(Key::ACCEL)?)
        };
        Some(Linear {
            fmin: fmin?,
            fmax: fmax?,
            extent,
        })
    }

    fn describe(&self, out: &mut dyn FnMut(Key, Param)) {
        out(Key::FMIN, Param::Number(self.fmin));
        out(Key::FMAX, Param::Number(self.fmax));
        match self.extent {
            LinearExtent::Len(n) => out(Key::LEN, Param::Count(n)),
            LinearExtent::Accel(a) => out(Key::ACCEL, Param::Number(a)),
        }
    }
}
