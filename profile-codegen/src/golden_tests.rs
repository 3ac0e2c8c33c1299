//! The golden format: reading back what was written, and the differences.

use super::*;
use std::fs;

use super::file::{compare_as, difference, parse};
use super::render::render;

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
    let segments = [(900u16, 2u16)].entries();
    assert_eq!(difference(&old, &segments), "its layout changed");
}

/// A scratch folder of its own for a test's files.
fn scratch(name: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("profile-core-golden-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn spacing_alone_is_no_change() {
    let table = timed(&[900u16, 700, 600], 1_000_000);
    let path = scratch("spacing").join("ramp.txt");
    let text = render(&table.entries());
    // Tabs for spaces, trailing blanks, Windows line ends, a blank line.
    let respaced = text
        .replace("       1         700", "1\t700")
        .replace('\n', "  \r\n")
        + "\r\n";
    fs::write(&path, respaced).unwrap();
    assert_eq!(compare_as(&path, &table, false), Ok(()));
    let _ = fs::remove_dir_all(path.parent().unwrap());
}

#[test]
fn a_line_that_changed_beside_the_same_entries_is_named() {
    let table = timed(&[900u16, 700, 600], 1_000_000);
    let path = scratch("edited").join("ramp.txt");
    let text = render(&table.entries());
    let bless = "if the change is intended, rerun with UPDATE_GOLDEN=1 and review the diff";
    let edited = |from: &str, to: &str| {
        assert!(text.contains(from), "{from}");
        fs::write(&path, text.replace(from, to)).unwrap();
        compare_as(&path, &table, false).unwrap_err()
    };
    // A hand edit of the edge column, which the periods make.
    assert_eq!(
        edited("1600      1600.000", "1601      1600.000"),
        format!(
            "{}:9: the entries are unchanged, but entry 1's edge (ticks) reads 1601, the table \
             gives 1600; {bless}",
            path.display()
        )
    );
    assert_eq!(
        edited("2200      2200.000", "2200      2200.001"),
        format!(
            "{}:10: the entries are unchanged, but entry 2's edge (us) reads 2200.001, the \
             table gives 2200.000; {bless}",
            path.display()
        )
    );
    // A figure.
    assert_eq!(
        edited("# total_ticks = 2200", "# total_ticks = 2300"),
        format!(
            "{}:5: the entries are unchanged, but `total_ticks` reads 2300, the table gives \
             2200; {bless}",
            path.display()
        )
    );
    // A segment's end.
    let segments = [(500u16, 2u16), (400, 3)];
    let text = render(&segments.entries());
    fs::write(&path, text.replace("3          2200", "3          2199")).unwrap();
    assert_eq!(
        compare_as(&path, &segments, false).unwrap_err(),
        format!(
            "{}:8: the entries are unchanged, but segment 1's end (ticks) reads 2199, the table \
             gives 2200; {bless}",
            path.display()
        )
    );
    let text = render(&table.entries());
    let edited = |from: &str, to: &str| {
        fs::write(&path, text.replace(from, to)).unwrap();
        compare_as(&path, &table, false).unwrap_err()
    };
    // A line gone, and one too many.
    assert_eq!(
        edited("# timer_hz = 1 MHz\n", ""),
        format!(
            "{}:4: the entries are unchanged, but the line reads `# total_ticks = 2200`, the \
             table gives `# timer_hz = 1 MHz`; {bless}",
            path.display()
        )
    );
    assert_eq!(
        edited("2200.000\n", "2200.000\n# end\n"),
        format!(
            "{}:11: the entries are unchanged, but the file goes on after the table's last \
             line with `# end`; {bless}",
            path.display()
        )
    );
    let _ = fs::remove_dir_all(path.parent().unwrap());
}

#[test]
fn a_failed_bless_leaves_nothing_behind() {
    let dir = scratch("partial");
    // A folder where the file should be: the rename onto it fails.
    let path = dir.join("ramp.txt");
    fs::create_dir_all(&path).unwrap();
    let table = timed(&[900u16, 700, 600], 1_000_000);
    let error = compare_as(&path, &table, true).unwrap_err();
    assert!(
        error.starts_with(&format!("cannot write {}: ", path.display())),
        "{error}"
    );
    let left: Vec<_> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["ramp.txt"]);
    let _ = fs::remove_dir_all(&dir);
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
    let runs = [profile_core::runs::LinearRun {
        count: 3,
        interval: 700 << 16,
        add: -(50 << 16),
    }
    .encode()];
    let stored = [profile_core::runs::with_offset(&runs[0], -1)];
    let back = timed(&stored, 1_000_000).with_reload_offset(-1).entries();
    assert_eq!(back.body, Body::Runs(runs.to_vec()));
    let pairs = timed(&[(499u32, 3u32)], 1_000_000)
        .with_reload_offset(-1)
        .entries();
    assert_eq!(pairs.body, Body::Segments(std::vec![(500, 3)]));
}
