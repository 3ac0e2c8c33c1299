//! How each curve is read from arguments and described: the keys it takes
//! besides the common ones, those it requires, the two of which exactly one
//! sets its length, its own keys' units, and [`Schema::read`] and
//! [`Schema::describe`], one file per curve. The curves themselves (their
//! parameters, checks and models) are `profile-core`'s.

use std::vec::Vec;

use profile_core::{
    Curve, Exponential, JerkLimited, Key, Linear, Sigmoid, ThreeStage, TorqueLimited,
};

mod exponential;
mod jerk_limited;
mod linear;
mod sigmoid;
mod three_stage;
mod torque_limited;

/// A parameter's value as a curve describes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Param {
    /// A real number, written as Rust writes an `f64` (`64000`, `0.5`).
    Number(f64),
    /// A whole count (`len`).
    Count(u32),
}

/// Where a curve reads its parameters from: the schema's arguments. Each
/// call reports a wrong kind of value itself and returns `None` for it.
pub(crate) trait Reader {
    /// A number, in the key's unit.
    fn number(&mut self, key: Key) -> Option<f64>;
    /// `len`, from 1 to `MAX_LEN`.
    fn len(&mut self) -> Option<u32>;
    /// Whether the key is given.
    fn has(&self, key: Key) -> bool;
}

/// A curve as arguments give it.
pub(crate) trait Schema: Sized + Into<Curve> {
    /// The name in `curve = NAME` (the curve's own, [`Curve::name`]).
    const NAME: &'static str;
    /// The keys this curve takes besides the common ones, in documentation
    /// order.
    const KEYS: &'static [Key];
    /// Those it requires (the common `timer_hz` aside).
    const REQUIRED: &'static [Key];
    /// Two keys of which exactly one is given: each sets the ramp's length.
    const ONE_OF: Option<[Key; 2]> = None;
    /// Units of the keys this curve alone takes, for messages.
    const UNITS: &'static [(Key, &'static str)] = &[];

    /// Reads the parameters; `None` when one is missing or wrong (the
    /// reader has said why).
    fn read(r: &mut dyn Reader) -> Option<Self>;
    /// The parameters as a user writes them, in documentation order.
    fn describe(&self, out: &mut dyn FnMut(Key, Param));
}

/// A curve as the schema sees it: its name, keys and how to read it.
pub(crate) struct CurveSchema {
    pub(crate) name: &'static str,
    pub(crate) keys: &'static [Key],
    pub(crate) required: &'static [Key],
    pub(crate) one_of: Option<[Key; 2]>,
    pub(crate) units: &'static [(Key, &'static str)],
    pub(crate) read: fn(&mut dyn Reader) -> Option<Curve>,
}

impl CurveSchema {
    /// The schema of the curve named `name`.
    pub(crate) fn named(name: &str) -> Option<&'static CurveSchema> {
        CURVE_SCHEMAS.iter().find(|r| r.name == name)
    }

    const fn of<C: Schema>() -> CurveSchema {
        CurveSchema {
            name: C::NAME,
            keys: C::KEYS,
            required: C::REQUIRED,
            one_of: C::ONE_OF,
            units: C::UNITS,
            read: read_as::<C>,
        }
    }
}

fn read_as<C: Schema>(r: &mut dyn Reader) -> Option<Curve> {
    C::read(r).map(Into::into)
}

/// Every curve's schema, in documentation order.
pub(crate) const CURVE_SCHEMAS: &[CurveSchema] = &[
    CurveSchema::of::<Sigmoid>(),
    CurveSchema::of::<Exponential>(),
    CurveSchema::of::<Linear>(),
    CurveSchema::of::<ThreeStage>(),
    CurveSchema::of::<JerkLimited>(),
    CurveSchema::of::<TorqueLimited>(),
];

/// `curve`'s parameters as a user writes them, in documentation order.
pub(crate) fn describe(curve: &Curve, out: &mut dyn FnMut(Key, Param)) {
    match curve {
        Curve::Sigmoid(c) => c.describe(out),
        Curve::Exponential(c) => c.describe(out),
        Curve::Linear(c) => c.describe(out),
        Curve::ThreeStage(c) => c.describe(out),
        Curve::JerkLimited(c) => c.describe(out),
        Curve::TorqueLimited(c) => c.describe(out),
        _ => {}
    }
}

/// Every key of every curve, each once, in the order of the curves.
pub(crate) fn curve_keys() -> Vec<Key> {
    let mut keys = Vec::new();
    for schema in CURVE_SCHEMAS {
        for key in schema.keys {
            if !keys.contains(key) {
                keys.push(*key);
            }
        }
    }
    keys
}

#[cfg(test)]
mod tests {
    use super::*;
    use profile_core::{AccelCurve, ExponentialExtent, LinearExtent};

    /// One curve of each kind, as `profile-core` names it.
    fn every_curve() -> [Curve; 6] {
        let (fmin, fmax) = (500.0, 20_000.0);
        [
            Curve::Sigmoid(Sigmoid {
                fmin,
                fmax,
                flexible: 4.0,
                len: 100,
            }),
            Curve::Exponential(Exponential {
                fmin,
                fmax,
                f_inf: 25_000.0,
                extent: ExponentialExtent::Len(100),
            }),
            Curve::Linear(Linear {
                fmin,
                fmax,
                extent: LinearExtent::Len(100),
            }),
            Curve::ThreeStage(ThreeStage {
                fmin,
                fmax,
                accel: 1e5,
                f1: 2000.0,
                f2: 15_000.0,
                shape: 10.0,
            }),
            Curve::JerkLimited(JerkLimited {
                fmin,
                fmax,
                accel: 1e5,
                jerk: 1e7,
            }),
            Curve::TorqueLimited(TorqueLimited {
                fmin,
                fmax,
                margin: 0.5,
                accel: AccelCurve::EMPTY,
            }),
        ]
    }

    #[test]
    fn every_curve_has_its_schema_under_its_own_name() {
        let names: Vec<&str> = CURVE_SCHEMAS.iter().map(|s| s.name).collect();
        let curves: Vec<&str> = every_curve().iter().map(Curve::name).collect();
        assert_eq!(names, curves);
        for curve in every_curve() {
            let mut described = Vec::new();
            describe(&curve, &mut |key, _| described.push(key));
            let schema = CurveSchema::named(curve.name()).unwrap();
            assert_eq!(
                described.len(),
                described.iter().filter(|k| schema.keys.contains(k)).count()
            );
            assert!(
                schema.required.iter().all(|k| described.contains(k)),
                "{}",
                curve.name()
            );
        }
    }
}
