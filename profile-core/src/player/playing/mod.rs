//! Playing a planned move, a step at a time: the step paths (`step.rs`),
//! filling a buffer for DMA (`fill.rs`), reload registers that take effect
//! at the next wrap (`buffered.rs`), an axis with its position
//! (`axis.rs`), moves queued on it that join at speed (`queue.rs`, the
//! ring of queued targets in `targets.rs`), coordinated axes (`axes.rs`,
//! the followers' steps in `edges.rs`), lines queued on them that join at
//! speed (`junctions.rs`, each line's figures in `lines.rs`, in fixed
//! point by the roots of `fixed.rs`), and ramps
//! and periods typed by their timer's rate (`rated.rs`).

pub(in crate::player) mod axes;
pub(in crate::player) mod axis;
pub(in crate::player) mod buffered;
pub(in crate::player) mod edges;
pub(in crate::player) mod fill;
pub(in crate::player) mod fixed;
pub(in crate::player) mod junctions;
pub(in crate::player) mod lines;
pub(in crate::player) mod queue;
pub(in crate::player) mod rated;
pub(in crate::player) mod step;
pub(in crate::player) mod targets;
