//! Property tests of the ramp player over random tables and moves.
//!
//! `PROPTEST_CASES` sets the number of cases (default 256 per property here).

use profile_core::player::{Player, Ramp};
use proptest::prelude::*;

/// A non-increasing table (slow to fast), as generated tables are.
fn table() -> impl Strategy<Value = Vec<u16>> {
    (1usize..120, 100u16..=u16::MAX).prop_flat_map(|(len, start)| {
        proptest::collection::vec(0u16..400, len).prop_map(move |drops| {
            let mut p = start as u32;
            drops
                .iter()
                .map(|d| {
                    let v = p as u16;
                    p = p.saturating_sub(*d as u32).max(1);
                    v
                })
                .collect()
        })
    })
}

/// Largest difference between consecutive entries.
fn max_step(t: &[u16]) -> u32 {
    t.windows(2)
        .map(|w| (w[0] as i32 - w[1] as i32).unsigned_abs())
        .max()
        .unwrap_or(0)
}

/// Plays a move, calling `at(step, player)` before each step; `None` when
/// the player yields more than `limit` periods.
fn play(
    player: &mut Player<'_, u16>,
    limit: usize,
    mut at: impl FnMut(usize, &mut Player<'_, u16>),
) -> Option<Vec<u32>> {
    let mut out = Vec::new();
    loop {
        at(out.len(), player);
        match player.next_period() {
            Some(p) => out.push(p as u32),
            None => return Some(out),
        }
        if out.len() > limit {
            return None;
        }
    }
}

fn expand(t: &[u16], hold: u32) -> Vec<u32> {
    t.iter()
        .flat_map(|&p| std::iter::repeat_n(p as u32, hold.max(1) as usize))
        .collect()
}

/// Cases per property: `PROPTEST_CASES`, or 256.
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(256)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Exactly S steps, never faster than the fastest entry, jumps no larger
    /// than the tables', ending at the deceleration table's slowest entry.
    #[test]
    fn moves_have_exactly_s_steps(
        accel in table(), decel in table(), symmetric in any::<bool>(),
        hold in 1u32..4, steps in 0u32..1500,
    ) {
        let decel = if symmetric { accel.clone() } else { decel };
        let mut player = Player::with_decel(Ramp::held(&accel, hold), Ramp::held(&decel, hold));
        player.start(steps);
        let periods = play(&mut player, steps as usize, |_, _| {}).expect("move does not end");
        prop_assert_eq!(periods.len(), steps as usize);
        let fastest = accel.iter().chain(&decel).copied().min().unwrap() as u32;
        prop_assert!(periods.iter().all(|&p| p >= fastest));
        let bound = max_step(&accel).max(max_step(&decel));
        for w in periods.windows(2) {
            prop_assert!((w[0] as i64 - w[1] as i64).unsigned_abs() <= bound as u64, "{:?}", w);
        }
        // Ends at rest: no faster than the deceleration table's slowest entry.
        if let Some(&last) = periods.last() {
            prop_assert!(last >= decel[0] as u32);
        }
        // A move long enough plays both halves whole: the acceleration table
        // forwards, then the deceleration table backwards, each limited by the
        // other's top speed (the cruise speed is the slower of the two tops).
        let (a, d) = (expand(&accel, hold), expand(&decel, hold));
        if steps as usize >= a.len() + d.len() {
            let a_top = *a.last().unwrap();
            let d_top = *d.iter().min().unwrap();
            let head: Vec<u32> = a.iter().map(|&v| v.max(d_top)).collect();
            prop_assert_eq!(&periods[..a.len()], &head[..]);
            let tail: Vec<u32> = d.iter().rev().map(|&v| v.max(a_top)).collect();
            prop_assert_eq!(&periods[periods.len() - d.len()..], &tail[..]);
            prop_assert_eq!(*periods.last().unwrap(), (decel[0] as u32).max(a_top));
        }
    }

    /// A stop at any step ends at rest, with no jump larger than the tables'
    /// and no more steps than the move had.
    #[test]
    fn stop_ends_at_rest(
        accel in table(), decel in table(), hold in 1u32..3,
        steps in 1u32..1500, stop_at in 0usize..1500,
    ) {
        let mut player = Player::with_decel(Ramp::held(&accel, hold), Ramp::held(&decel, hold));
        player.start(steps);
        let periods = play(&mut player, steps as usize, |i, p| if i == stop_at { p.stop() })
            .expect("move does not end");
        prop_assert!(periods.len() <= steps as usize);
        let bound = max_step(&accel).max(max_step(&decel));
        for w in periods.windows(2) {
            prop_assert!((w[0] as i64 - w[1] as i64).unsigned_abs() <= bound as u64, "{:?}", w);
        }
        // At rest: the deceleration table's slowest entry, or slower still
        // when the move never got that fast.
        if let Some(&last) = periods.last() {
            prop_assert!(last >= decel[0] as u32);
            prop_assert!(last == decel[0] as u32 || accel.contains(&(last as u16)));
        }
    }

    /// A new cruise speed mid-move walks the table to it.
    #[test]
    fn cruise_changes_walk_the_table(
        accel in table(), steps in 1u32..1500, at in 0usize..1500, cruise in 0u32..200,
    ) {
        let mut player = Player::new(Ramp::steps(&accel));
        player.start(steps);
        let periods = play(&mut player, steps as usize, |i, p| if i == at { p.set_cruise(cruise) })
            .expect("move does not end");
        prop_assert_eq!(periods.len(), steps as usize);
        let bound = max_step(&accel);
        for w in periods.windows(2) {
            prop_assert!((w[0] as i64 - w[1] as i64).unsigned_abs() <= bound as u64);
        }
        // Set before the first step: never faster than the cruise entry.
        let target = accel[(cruise as usize).min(accel.len() - 1)] as u32;
        if at == 0 {
            prop_assert!(periods.iter().all(|&p| p >= target));
        }
    }

    /// Segment tables play exactly as the per-step tables they stand for.
    #[test]
    fn segments_play_like_their_expansion(
        periods in table(), counts in proptest::collection::vec(0u16..5, 120),
        steps in 0u32..700, stop_at in 0usize..700,
    ) {
        let pairs: Vec<(u16, u16)> = periods.iter().zip(&counts).map(|(&p, &c)| (p, c)).collect();
        let expanded: Vec<u16> = pairs
            .iter()
            .flat_map(|&(p, c)| std::iter::repeat_n(p, c as usize))
            .collect();
        let mut seg = Player::new(Ramp::segments(&pairs));
        let mut flat = Player::new(Ramp::steps(&expanded));
        seg.start(steps);
        flat.start(steps);
        let a = play(&mut seg, steps as usize, |i, p| if i == stop_at { p.stop() });
        let b = play(&mut flat, steps as usize, |i, p| if i == stop_at { p.stop() });
        prop_assert_eq!(a, b);
    }
}

#[test]
fn empty_tables_play_nothing() {
    let empty: [u16; 0] = [];
    let mut player = Player::new(Ramp::steps(&empty));
    player.start(10);
    assert_eq!(player.next_period(), None);
    let none: [(u16, u16); 2] = [(100, 0), (50, 0)];
    let mut player = Player::new(Ramp::segments(&none));
    player.start(10);
    assert_eq!(player.next_period(), None);
}

#[test]
fn short_symmetric_move_is_a_triangle() {
    let table = [1000u16, 800, 600, 500, 400];
    let mut player = Player::new(Ramp::steps(&table));
    player.start(5);
    let periods: Vec<u16> = std::iter::from_fn(|| player.next_period()).collect();
    assert_eq!(periods, [1000, 800, 600, 800, 1000]);
}

#[test]
fn divider_holds_each_entry() {
    let table = [1000u16, 500];
    let mut player = Player::new(Ramp::held(&table, 3));
    player.start(14);
    let periods: Vec<u16> = std::iter::from_fn(|| player.next_period()).collect();
    assert_eq!(
        periods,
        [
            1000, 1000, 1000, 500, 500, 500, 500, 500, 500, 500, 500, 1000, 1000, 1000
        ]
    );
}

#[test]
fn stop_enters_the_deceleration_table_at_the_current_speed() {
    let accel = [1000u16, 800, 600, 500, 400];
    let decel = [2000u16, 1500, 1000, 700, 450, 300];
    let mut player = Player::with_decel(Ramp::steps(&accel), Ramp::steps(&decel));
    player.start(100);
    let mut periods = Vec::new();
    for _ in 0..4 {
        periods.push(player.next_period().unwrap());
    }
    // Now at 500 ticks: the slowest decel entry not faster than 500 is 700.
    player.stop();
    periods.extend(std::iter::from_fn(|| player.next_period()));
    assert_eq!(periods, [1000, 800, 600, 500, 700, 1000, 1500, 2000]);
}

/// Tables rounded by diffusion tie by a tick near the top (`..., 156, 157,
/// 156`): a long move must still play them exactly as written, up and down,
/// so their pulse edges keep their half-tick accuracy.
#[test]
fn diffused_tables_play_exactly() {
    use profile_core::{Curve, Sigmoid, Spec, Timer};
    let spec = Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        }),
        Timer::new(10_000_000),
    );
    let mut table = [0u16; 1000];
    let figures = spec.generate(&mut table).unwrap();
    assert!(
        table.windows(2).any(|w| w[1] > w[0]),
        "the table should have diffusion ties for this test to mean something"
    );
    let cruise = 500;
    let mut player = Player::new(Ramp::steps(&table));
    player.start(2000 + cruise);
    let played: Vec<u16> = std::iter::from_fn(|| player.next_period()).collect();
    assert_eq!(&played[..1000], &table[..]);
    let down: Vec<u16> = table.iter().rev().copied().collect();
    assert_eq!(&played[1000 + cruise as usize..], &down[..]);
    assert!(
        played[1000..1000 + cruise as usize]
            .iter()
            .all(|&p| p == table[999])
    );
    let total: u64 = played.iter().map(|&p| p as u64).sum();
    assert_eq!(
        total,
        2 * figures.total_ticks + cruise as u64 * table[999] as u64
    );
}
