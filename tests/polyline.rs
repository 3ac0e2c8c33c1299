//! The guide's polyline (`examples/polyline.rs`): queued, its six lines
//! join at speed and take at least 30 % less time than the same lines
//! stopping at every vertex, on the same lead steps.

#[allow(dead_code)]
#[path = "../examples/polyline.rs"]
mod polyline;

#[test]
fn the_polyline_joined_is_at_least_30_percent_shorter() {
    let (stopping, edges) = polyline::play(false);
    let (joined, joined_edges) = polyline::play(true);
    assert_eq!(edges, joined_edges);
    assert!(
        joined * 10 <= stopping * 7,
        "joined {joined} ticks, stopping {stopping}"
    );
}
