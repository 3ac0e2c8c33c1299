//! The targets queued after the move that follows the one playing, on an
//! [`Axis`](crate::player::Axis) ([`Axis::queue`](crate::player::Axis::queue))
//! or [`Axes`](crate::player::Axes) ([`Axes::queue`](crate::player::Axes::queue)):
//! a ring of [`QUEUE`] targets.

/// The targets a queue holds beyond the move playing and the one after
/// it: with those two, ten moves. On an [`Axis`](crate::player::Axis) each
/// is a reversal of the one before (a target that goes on the same way as
/// the last queued one takes no place: it moves that one out); on
/// [`Axes`](crate::player::Axes), each a line.
pub const QUEUE: usize = 8;

/// A queue had no place for another move: [`QUEUE`] wait after the next.
/// `T` is the target refused: a position (`i64`) for an
/// [`Axis`](crate::player::Axis), one per axis (`[i64; N]`) for
/// [`Axes`](crate::player::Axes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct QueueFull<T = i64> {
    /// The target refused.
    pub target: T,
}

impl<T: core::fmt::Debug> core::fmt::Display for QueueFull<T> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "the queue is full ({QUEUE} moves wait after the next): {:?} waits for one to play",
            self.target
        )
    }
}

/// Targets after the move that follows the one playing, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Targets<T> {
    targets: [T; QUEUE],
    head: u8,
    len: u8,
}

impl<T: Copy> Targets<T> {
    /// No target, the ring's places holding `fill`.
    pub(crate) const fn empty(fill: T) -> Self {
        Targets {
            targets: [fill; QUEUE],
            head: 0,
            len: 0,
        }
    }

    /// Puts `target` back in front (the place it was taken from).
    pub(crate) fn push_front(&mut self, target: T) {
        self.head = ((usize::from(self.head) + QUEUE - 1) % QUEUE) as u8;
        self.targets[usize::from(self.head)] = target;
        self.len += 1;
    }

    /// Drops every target.
    pub(crate) fn clear(&mut self) {
        self.len = 0;
    }

    pub(crate) fn len(&self) -> usize {
        usize::from(self.len)
    }

    fn slot(&self, i: usize) -> usize {
        (usize::from(self.head) + i) % QUEUE
    }

    /// The first target, taken out.
    pub(crate) fn pop(&mut self) -> Option<T> {
        if self.len == 0 {
            return None;
        }
        let target = self.targets[usize::from(self.head)];
        self.head = ((usize::from(self.head) + 1) % QUEUE) as u8;
        self.len -= 1;
        Some(target)
    }

    pub(crate) fn push(&mut self, target: T) -> Result<(), QueueFull<T>> {
        if self.len() == QUEUE {
            return Err(QueueFull { target });
        }
        let slot = self.slot(self.len());
        self.targets[slot] = target;
        self.len += 1;
        Ok(())
    }

    /// The last two targets, the last first.
    pub(crate) fn last_two(&self) -> (Option<T>, Option<T>) {
        let at =
            |back: usize| (self.len() >= back).then(|| self.targets[self.slot(self.len() - back)]);
        (at(1), at(2))
    }

    pub(crate) fn replace_last(&mut self, target: T) {
        let slot = self.slot(self.len() - 1);
        self.targets[slot] = target;
    }

    /// The `i`-th target.
    pub(crate) fn get(&self, i: usize) -> Option<&T> {
        (i < self.len()).then(|| &self.targets[self.slot(i)])
    }

    /// The `i`-th target, to be changed in place.
    pub(crate) fn get_mut(&mut self, i: usize) -> Option<&mut T> {
        let slot = self.slot(i);
        (i < self.len()).then(|| &mut self.targets[slot])
    }

    /// The targets in order.
    pub(crate) fn iter(&self) -> impl DoubleEndedIterator<Item = T> + '_ {
        (0..self.len()).map(|i| self.targets[self.slot(i)])
    }
}
