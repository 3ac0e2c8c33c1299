//! The turning points an [`Axis`](crate::player::Axis) keeps after the
//! move that follows the one playing ([`Axis::queue`](crate::player::Axis::queue)):
//! a ring of [`QUEUE`] targets.

/// The turning points an [`Axis`](crate::player::Axis) holds beyond the move playing and the
/// one after it: with those two, ten moves, each a reversal of the one
/// before (a target that goes on the same way as the last queued one
/// takes no place: it moves that one out).
pub const QUEUE: usize = 8;

/// [`Axis::queue`](crate::player::Axis::queue) had no place for another turning point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct QueueFull {
    /// The target refused.
    pub target: i64,
}

impl core::fmt::Display for QueueFull {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "the queue holds {QUEUE} reversals after the next move: {} waits for one to play",
            self.target
        )
    }
}

/// Targets after the move that follows the one playing, in order: each
/// the other way from the one before it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Targets {
    targets: [i64; QUEUE],
    head: u8,
    len: u8,
}

impl Targets {
    pub(crate) const EMPTY: Targets = Targets {
        targets: [0; QUEUE],
        head: 0,
        len: 0,
    };

    pub(crate) fn len(&self) -> usize {
        usize::from(self.len)
    }

    fn slot(&self, i: usize) -> usize {
        (usize::from(self.head) + i) % QUEUE
    }

    /// The first target, taken out.
    pub(crate) fn pop(&mut self) -> Option<i64> {
        if self.len == 0 {
            return None;
        }
        let target = self.targets[usize::from(self.head)];
        self.head = ((usize::from(self.head) + 1) % QUEUE) as u8;
        self.len -= 1;
        Some(target)
    }

    pub(crate) fn push(&mut self, target: i64) -> Result<(), QueueFull> {
        if self.len() == QUEUE {
            return Err(QueueFull { target });
        }
        let slot = self.slot(self.len());
        self.targets[slot] = target;
        self.len += 1;
        Ok(())
    }

    /// The last two targets, the last first.
    pub(crate) fn last_two(&self) -> (Option<i64>, Option<i64>) {
        let at =
            |back: usize| (self.len() >= back).then(|| self.targets[self.slot(self.len() - back)]);
        (at(1), at(2))
    }

    pub(crate) fn replace_last(&mut self, target: i64) {
        let slot = self.slot(self.len() - 1);
        self.targets[slot] = target;
    }
}
