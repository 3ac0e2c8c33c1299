//! The golden format: reading back what was written, and the differences.

use super::*;

#[test]
fn a_file_shows_each_entry_with_its_edge() {
    let text = render(&timed(&[900u16, 700, 600], 1_000_000).entries());
    assert_eq!(
        text,
        "# stepper-profiles golden table: UPDATE_GOLDEN=1 rewrites it
# table = per step
# entries = 3
# timer_hz = 1 MHz
# total_ticks = 2200
#
#  entry      period  edge (ticks)     edge (us)
       0         900           900       900.000
       1         700          1600      1600.000
       2         600          2200      2200.000
"
    );
    let segments = render(&[(500u16, 2u16), (400, 3)].entries());
    assert!(segments.ends_with(
        "#    seg      period   count   end (ticks)
       0         500       2          1000
       1         400       3          2200
"
    ));
    assert_eq!(
        parse(&segments, &Body::Segments(Vec::new())),
        Ok(Body::Segments(std::vec![(500, 2), (400, 3)]))
    );
}

#[test]
fn a_difference_names_the_count_the_first_and_the_shift() {
    let old = Body::Periods(std::vec![900, 700, 600, 500]);
    let new = timed(&[900u16, 702, 600, 499], 2_000_000).entries();
    assert_eq!(
        difference(&old, &new),
        "2 of 4 entries differ, the first at entry 1: was 700 ticks, now 702; the largest \
             shift of a pulse edge is 2 ticks (1.000 us)"
    );
    let longer = [900u16, 700, 600, 500, 450].entries();
    assert_eq!(
        difference(&old, &longer),
        "5 entries, was 4; the largest shift of a pulse edge is 0 ticks"
    );
    let same = [900u16, 700, 600, 500].entries();
    assert_eq!(
        difference(&old, &same),
        "its parameters or figures changed; the largest shift of a pulse edge is 0 ticks"
    );
    let segments = [(900u16, 2u16)].entries();
    assert_eq!(difference(&old, &segments), "its layout changed");
}

/// A table of register values pins the periods, as the table of the
/// periods does, and says its offset.
#[test]
fn an_offset_table_pins_its_periods() {
    let periods = timed(&[900u16, 700, 600], 1_000_000).entries();
    let arr = timed(&[899u16, 699, 599], 1_000_000)
        .with_reload_offset(-1)
        .entries();
    assert_eq!(arr.body, periods.body);
    assert_eq!(
        arr.header,
        std::vec![("reload_offset".to_string(), "-1".to_string())]
    );
    let runs = [crate::runs::Run {
        count: 3,
        interval: 700 << 16,
        add: -(50 << 16),
    }
    .encode()];
    let stored = [crate::runs::with_offset(&runs[0], -1)];
    let back = timed(&stored, 1_000_000).with_reload_offset(-1).entries();
    assert_eq!(back.body, Body::Runs(runs.to_vec()));
    let pairs = timed(&[(499u32, 3u32)], 1_000_000)
        .with_reload_offset(-1)
        .entries();
    assert_eq!(pairs.body, Body::Segments(std::vec![(500, 3)]));
}
