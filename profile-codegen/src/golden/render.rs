//! A golden file's text: its header, then one line per entry (segment,
//! run) with the edge it ends on, in ticks and microseconds.

use core::fmt::Write;
use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

use super::{Body, Entries};
use profile_core::Key;

/// Pulse-edge times, in ticks: after each step.
pub(super) fn edges(body: &Body, ticks_per_step: u8) -> Vec<u64> {
    let mut t = 0u64;
    body.steps()
        .iter()
        .map(|&p| {
            t += u64::from(p) * u64::from(ticks_per_step);
            t
        })
        .collect()
}

pub(super) fn micros(ticks: u64, timer_hz: u32) -> f64 {
    ticks as f64 * 1e6 / f64::from(timer_hz)
}

/// The golden file's text.
pub(super) fn render(e: &Entries) -> String {
    let mut out = String::from("# stepper-profiles golden table: UPDATE_GOLDEN=1 rewrites it\n");
    let kind = match e.body {
        Body::Periods(_) => "per step",
        Body::Segments(_) => "segments",
        Body::Runs(_) => "runs",
    };
    let edges = edges(&e.body, e.ticks_per_step);
    let mut header = std::vec![
        ("table".to_string(), kind.to_string()),
        ("entries".to_string(), e.body.len().to_string()),
    ];
    if e.header.is_empty() {
        if let Some(hz) = e.timer_hz {
            header.push((
                Key::TIMER_HZ.name().to_string(),
                crate::schema::units::show(Key::TIMER_HZ, f64::from(hz)),
            ));
        }
    }
    header.extend(e.header.iter().cloned());
    // The sum of the entries, as `TOTAL_TICKS` and the figures count it.
    let total: u64 = e.body.steps().iter().map(|&p| u64::from(p)).sum();
    header.push(("total_ticks".to_string(), total.to_string()));
    for (k, v) in &header {
        let _ = writeln!(out, "# {k} = {v}");
    }
    out.push_str("#\n");
    render_body(&mut out, e, &edges);
    out
}

/// The entry lines of a golden file, with their edges (and microseconds
/// when the timer is known).
fn render_body(out: &mut String, e: &Entries, edges: &[u64]) {
    let us = |t: u64| e.timer_hz.map(|hz| format!("  {:>12.3}", micros(t, hz)));
    let us_title = if e.timer_hz.is_some() {
        "     edge (us)"
    } else {
        ""
    };
    match &e.body {
        Body::Periods(p) => {
            let _ = writeln!(
                out,
                "# {:>6}  {:>10}  {:>12}{us_title}",
                "entry", "period", "edge (ticks)"
            );
            for (i, (p, t)) in p.iter().zip(edges).enumerate() {
                let _ = writeln!(
                    out,
                    "{i:>8}  {p:>10}  {t:>12}{}",
                    us(*t).unwrap_or_default()
                );
            }
        }
        Body::Segments(s) => {
            let _ = writeln!(
                out,
                "# {:>6}  {:>10}  {:>6}  {:>12}{}",
                "seg",
                "period",
                "count",
                "end (ticks)",
                us_title.replace("edge", " end")
            );
            let mut step = 0usize;
            for (i, &(p, c)) in s.iter().enumerate() {
                step += c as usize;
                let t = if step == 0 { 0 } else { edges[step - 1] };
                let _ = writeln!(
                    out,
                    "{i:>8}  {p:>10}  {c:>6}  {t:>12}{}",
                    us(t).unwrap_or_default()
                );
            }
        }
        Body::Runs(r) => {
            let _ = writeln!(
                out,
                "# {:>6}  {:>6}  {:>9}  {:>9}  {:>6}  {:>6}  {:>12}{}",
                "run",
                "count",
                "int_hi",
                "int_lo",
                "add_hi",
                "add_lo",
                "end (ticks)",
                us_title.replace("edge", " end")
            );
            let mut step = 0usize;
            for (i, w) in r.iter().enumerate() {
                step += w[0] as usize;
                let t = if step == 0 { 0 } else { edges[step - 1] };
                let _ = writeln!(
                    out,
                    "{i:>8}  {:>6}  {:>9}  {:>9}  {:>6}  {:>6}  {t:>12}{}",
                    w[0],
                    w[1],
                    w[2],
                    w[3],
                    w[4],
                    us(t).unwrap_or_default()
                );
            }
        }
    }
}
