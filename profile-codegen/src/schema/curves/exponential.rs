//! `curve = exponential`: the keys it takes and how they are read and
//! described.

use profile_core::{Exponential, ExponentialExtent, Key};

use super::{Param, Reader, Schema};

impl Schema for Exponential {
    const NAME: &'static str = "exponential";
    const KEYS: &'static [Key] = &[Key::FMIN, Key::FMAX, Key::F_INF, Key::LEN, Key::TAU];
    const REQUIRED: &'static [Key] = &[Key::FMIN, Key::FMAX, Key::F_INF];
    const ONE_OF: Option<[Key; 2]> = Some([Key::LEN, Key::TAU]);
    const UNITS: &'static [(Key, &'static str)] = &[(Key::F_INF, "Hz (steps/s)"), (Key::TAU, "s")];

    fn read(r: &mut dyn Reader) -> Option<Self> {
        let (fmin, fmax, f_inf) = (
            r.number(Key::FMIN),
            r.number(Key::FMAX),
            r.number(Key::F_INF),
        );
        let extent = if r.has(Key::LEN) {
            ExponentialExtent::Len(r.len()?)
        } else {
            ExponentialExtent::Tau(r.number(Key::TAU)?)
        };
        Some(Exponential {
            fmin: fmin?,
            fmax: fmax?,
            f_inf: f_inf?,
            extent,
        })
    }

    fn describe(&self, out: &mut dyn FnMut(Key, Param)) {
        out(Key::FMIN, Param::Number(self.fmin));
        out(Key::FMAX, Param::Number(self.fmax));
        out(Key::F_INF, Param::Number(self.f_inf));
        match self.extent {
            ExponentialExtent::Len(n) => out(Key::LEN, Param::Count(n)),
            ExponentialExtent::Tau(t) => out(Key::TAU, Param::Number(t)),
        }
    }
}
