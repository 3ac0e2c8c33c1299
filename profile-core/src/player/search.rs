//! Searching along ramps that are ordered slow to fast but for a tick or
//! two: exact, in far fewer probes than a walk.
//!
//! A planner's question is "the first of these steps where ...": the first
//! step where the deceleration ramp is not faster than the acceleration
//! side, the first entry not slower than a period. On ramps ordered slow to
//! fast the answer is a boundary, found by bisection. Generated tables are
//! ordered only within a tick or two (rounding by diffusion lets neighbours
//! differ by a tick either way), so a probe can say three things: the step
//! answers, or it fails and so does every step before it (it is far enough
//! from the boundary that the ramps' slack cannot reach it), or it fails
//! alone. The search bisects on the first two and, on the third, looks
//! first before the probe and then after it: the answer is the one a walk
//! from the first step would find, on any ramp, and the probes are the
//! bisection's and the few steps within the slack of the boundary.

/// What a probe says of a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Probe {
    /// The step answers.
    Found,
    /// The step fails, and so does every step before it.
    Before,
    /// The step fails; the steps before it may answer.
    Fails,
}

/// The first step of `lo..hi` that `test` finds, or `hi` when none is.
pub(crate) fn first(lo: u32, hi: u32, test: &mut impl FnMut(u32) -> Probe) -> u32 {
    within(lo, hi, test).unwrap_or(hi)
}

/// The first step of `lo..hi` that `test` finds. Each level of recursion
/// at least halves the range: at most 32 deep.
fn within(mut lo: u32, mut hi: u32, test: &mut impl FnMut(u32) -> Probe) -> Option<u32> {
    let mut found = None;
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        match test(mid) {
            Probe::Found => {
                found = Some(mid);
                hi = mid;
            }
            Probe::Before => lo = mid + 1,
            Probe::Fails => {
                if let Some(j) = within(lo, mid, test) {
                    return Some(j);
                }
                lo = mid + 1;
            }
        }
    }
    found
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec;

    /// Against a walk, on every sequence of length up to 9 of steps that
    /// answer (1), fail (2) and fail saying so of all before where that is
    /// true (0).
    #[test]
    fn finds_what_a_walk_finds() {
        for len in 0..9u32 {
            for code in 0..3u32.pow(len) {
                let mut c = code;
                let marks: Vec<u32> = (0..len)
                    .map(|_| {
                        let m = c % 3;
                        c /= 3;
                        m
                    })
                    .collect();
                let walk = marks.iter().position(|&m| m == 1).map_or(len, |i| i as u32);
                // "Before" only where no step up to it is found.
                let mut probes = 0;
                let got = first(0, len, &mut |j| {
                    probes += 1;
                    match marks[j as usize] {
                        1 => Probe::Found,
                        0 if walk > j => Probe::Before,
                        _ => Probe::Fails,
                    }
                });
                assert_eq!(got, walk, "{marks:?}");
                assert!(probes <= len, "{marks:?}: {probes} probes");
            }
        }
    }
}
