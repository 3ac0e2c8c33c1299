//! Tests of [`Player::next_period`]'s path against [`Player::step`]'s.

extern crate std;
use super::*;
use crate::table::runs::RunIndex;
use std::vec::Vec;

/// How a player is played: by `next_period`, by `step`, or the two in
/// turn.
#[derive(Clone, Copy)]
enum By {
    NextPeriod,
    Step,
    Alternating,
}

/// One move's periods, `by` one path or the other, the same planning calls
/// at the same steps (a new cruise, a new target, a stop, a run and its
/// stop, each where `calls` says), then a call past the end; with the steps
/// left after each period.
fn play<L: Layout>(mut player: Player<'_, u16, L>, by: By, calls: [u32; 4]) -> Vec<(u16, u32)> {
    let mut out = Vec::new();
    for (i, steps) in [40, 7, 1].into_iter().enumerate() {
        player.start(steps);
        if i == 2 {
            player.run();
        }
        for k in 0.. {
            match k {
                _ if k == calls[0] => player.set_cruise(1),
                _ if k == calls[1] => {
                    player.retarget(player.remaining() + 5);
                }
                _ if k == calls[2] && i == 0 => player.stop(),
                _ if k == calls[3].min(50) && i == 2 => player.stop(),
                _ => {}
            }
            let next = match (by, k % 2) {
                (By::NextPeriod, _) | (By::Alternating, 0) => player.next_period(),
                _ => {
                    let mut period = None;
                    let played = player.step(|p| period = Some(p));
                    assert_eq!(played, period.is_some());
                    period
                }
            };
            match next {
                Some(p) => out.push((p, player.remaining())),
                None => break,
            }
        }
        // Past the end, again and again: nothing, either way.
        assert_eq!(player.next_period(), None);
        assert!(!player.step(|_| panic!("no period past the end")));
        assert_eq!(player.next_period(), None);
    }
    out
}

/// The three ways hand out the same periods, every layout, every call.
fn same<L: Layout + Clone>(player: Player<'_, u16, L>) {
    for calls in [[u32::MAX; 4], [5, 12, 20, 30], [0, 1, 2, 3], [9, 3, 15, 60]] {
        let stepped = play(player.clone(), By::Step, calls);
        assert!(!stepped.is_empty());
        assert_eq!(play(player.clone(), By::NextPeriod, calls), stepped);
        assert_eq!(play(player.clone(), By::Alternating, calls), stepped);
    }
}

#[test]
fn next_period_hands_out_what_step_does() {
    static STEPS: [u16; 6] = [5000, 4000, 3200, 2600, 2200, 2000];
    static DECEL: [u16; 3] = [4500, 3000, 2100];
    static SEGMENTS: [(u16, u16); 3] = [(4000, 3), (3000, 2), (2000, 4)];
    static RUNS: [[u16; 5]; 2] = [[3, 4000, 0x8000, 0xFE0C, 0], [2, 2000, 0, 0, 0]];
    static INDEX: RunIndex<2> = RunIndex::new(&RUNS);
    same(Player::new(Ramp::steps(&STEPS)));
    same(Player::new(Ramp::steps(&STEPS)).with_decel(Ramp::steps(&DECEL)));
    same(Player::new(Ramp::held(&STEPS, 3)));
    same(Player::new(Ramp::segments(&SEGMENTS)));
    same(Player::new(Ramp::runs(&RUNS)));
    same(Player::new(Ramp::runs(&RUNS)).with_decel(Ramp::steps(&DECEL)));
    same(Player::<u16, _>::new(&RUNS));
    same(Player::<u16, _>::new(&INDEX));
}
