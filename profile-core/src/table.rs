//! Owned tables, for hosts.

use std::vec::Vec;

use crate::error::Error;
use crate::generate::Figures;
use crate::spec::Spec;

/// A generated table with its spec and figures.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// What the table was computed from.
    pub spec: Spec,
    /// The periods, in ticks; each fits `spec.timer.word`.
    pub periods: Vec<u32>,
    /// What the table amounts to.
    pub figures: Figures,
}

impl Spec {
    /// Computes the table into a new vector.
    pub fn table(&self) -> Result<Table, Error> {
        self.validate()?;
        let mut periods = Vec::with_capacity(self.len() as usize);
        let figures = self.for_each_period(|_, ticks| periods.push(ticks))?;
        Ok(Table {
            spec: *self,
            periods,
            figures,
        })
    }
}
