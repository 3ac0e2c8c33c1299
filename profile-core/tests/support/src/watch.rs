//! What a test knows of an axis's motion, step by step, checked against
//! rules computed from its table alone: the position counted one step at a
//! time by the pin's direction is the axis's; the speed never jumps (each
//! period is the one before, or the entry next to it in the table); a
//! reversal happens only at rest (the slowest entry on both sides); a move
//! starts and ends at the slowest entry.

use profile_core::player::{Axis, Direction};

/// The positions of the table holding `period`.
pub fn positions(table: &[u16], period: u16) -> impl Iterator<Item = usize> + '_ {
    table
        .iter()
        .enumerate()
        .filter(move |&(_, &p)| p == period)
        .map(|(i, _)| i)
}

/// `y` follows `x` without a jump: the same, or entries next to each other.
pub fn neighbours(table: &[u16], x: u16, y: u16) -> bool {
    x == y || positions(table, x).any(|i| positions(table, y).any(|j| i.abs_diff(j) <= 1))
}

/// What the test knows of the motion so far.
pub struct Watch<'t> {
    pub table: &'t [u16],
    pub position: i64,
    /// The last step's period and direction; `None` at rest.
    pub last: Option<(u16, Direction)>,
    pub steps: u64,
}

impl<'t> Watch<'t> {
    /// At rest at `position`.
    pub fn new(table: &'t [u16], position: i64) -> Self {
        Watch {
            table,
            position,
            last: None,
            steps: 0,
        }
    }

    /// One step played, its period `period`, the pin's direction `dir`.
    pub fn step(&mut self, period: u16, dir: Direction, axis_position: i64) -> Result<(), String> {
        let slowest = self.table[0];
        self.position += dir.sign();
        self.steps += 1;
        if axis_position != self.position {
            return Err(format!(
                "step {}: the axis says {axis_position}, the steps counted {}",
                self.steps, self.position
            ));
        }
        match self.last {
            None if period != slowest => Err(format!(
                "step {}: from rest at {period}, not the slowest entry {slowest}",
                self.steps
            )),
            Some((before, turned)) if turned != dir && (before != slowest || period != slowest) => {
                Err(format!(
                    "step {}: reversed between {before} and {period}, not at rest ({slowest})",
                    self.steps
                ))
            }
            Some((before, _)) if !neighbours(self.table, before, period) => Err(format!(
                "step {}: a jump from {before} to {period}",
                self.steps
            )),
            _ => {
                self.last = Some((period, dir));
                Ok(())
            }
        }
    }

    /// The move ended: at rest, after the slowest entry.
    pub fn rest(&mut self) -> Result<(), String> {
        if let Some((period, _)) = self.last.take() {
            if period != self.table[0] {
                return Err(format!(
                    "step {}: ended at {period}, not at rest",
                    self.steps
                ));
            }
        }
        Ok(())
    }
}

/// Plays up to `n` steps; stops early when the axis is done.
pub fn play(axis: &mut Axis<'_, u16>, watch: &mut Watch<'_>, n: u32) -> Result<Vec<u16>, String> {
    let mut periods = vec![];
    for _ in 0..n {
        let mut period = 0;
        // What the direction pin is set to a period ahead of the step.
        let pin = axis.next_direction();
        if !axis.step(|p| period = p) {
            watch.rest()?;
            break;
        }
        if axis.direction() != pin {
            return Err(format!(
                "step {}: next_direction said {pin:?} a step ahead, the step went {:?}",
                periods.len(),
                axis.direction()
            ));
        }
        watch.step(period, axis.direction(), axis.position())?;
        periods.push(period);
    }
    Ok(periods)
}
