//! The files behind the plots: an SVG and a CSV per profile, the torque of
//! each motor-bound profile, an overview; and the figures the README and the guide show.

use std::path::Path;

use plotters::style::{BLACK, RGBColor};
use profile_codegen::profiles::Profile;
use profile_codegen::profiles::Profiles;
use profile_codegen::{Generated, SpecTables, Table};
use profile_core::{Discretization, Spec};

use crate::plots::{self, Line, Series};
use crate::staging::Staging;

/// The S-curve article's four example curves, in the article's colours.
const ARTICLE: [(&str, RGBColor); 4] = [
    ("yellow", RGBColor(0xe6, 0xb8, 0x00)),
    ("orange", RGBColor(0xff, 0x8c, 0x00)),
    ("blue", RGBColor(0x1f, 0x5f, 0xd0)),
    ("gray", RGBColor(0x80, 0x80, 0x80)),
];

/// Colours for every other profile, none of them near the article's.
const PALETTE: [RGBColor; 12] = [
    RGBColor(0xd6, 0x27, 0x28),
    RGBColor(0x2c, 0xa0, 0x2c),
    RGBColor(0x94, 0x67, 0xbd),
    RGBColor(0x8c, 0x56, 0x4b),
    RGBColor(0xe3, 0x77, 0xc2),
    RGBColor(0x17, 0xbe, 0xcf),
    RGBColor(0xbc, 0xbd, 0x22),
    RGBColor(0x00, 0x00, 0x80),
    RGBColor(0x80, 0x00, 0x00),
    RGBColor(0x00, 0x5f, 0x5f),
    RGBColor(0x76, 0x2a, 0x83),
    RGBColor(0x4d, 0x92, 0x21),
];

/// One colour per profile, the same on every plot: a profile named after
/// one of the article's curves (`sigmoid_orange`) in that curve's colour,
/// the others through [`PALETTE`] in file order.
fn colors(profiles: &Profiles) -> Vec<RGBColor> {
    let mut next = 0;
    profiles
        .profiles()
        .iter()
        .map(|p| {
            let named = ARTICLE
                .iter()
                .find(|(word, _)| p.name.split('_').any(|part| part == *word));
            named.map_or_else(
                || {
                    next += 1;
                    PALETTE[(next - 1) % PALETTE.len()]
                },
                |(_, color)| *color,
            )
        })
        .collect()
}

/// Needed and available torque at every edge of a motor-bound profile.
fn write_torque_plot(p: &Profile, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let Some(motor) = &p.motor else {
        return Ok(());
    };
    let mut edges = Vec::new();
    motor.check_with(
        p.table.spec(),
        &p.table.step_periods(),
        |step, hz, needed, available| edges.push((step, hz, needed, available)),
    )?;
    let mut curves = pull_out_curves(motor, &edges);
    if let profile_core::Curve::TorqueLimited(ramp) = p.table.spec().curve {
        // What the fastest ramp plans on: `margin` of the available torque.
        let planned = edges.iter().map(|e| (e.1, ramp.margin * e.3)).collect();
        curves.push(("planned: margin × pull-out / safety", planned));
    }
    plots::torque(path, &p.name, &edges, &curves)
}

/// The pull-out curves to plot: the typed one, and the one the windings
/// give (sampled finely up to the ramp's fastest step), under each other.
fn pull_out_curves(
    motor: &profile_codegen::motor::Motor,
    edges: &[(u32, f64, f64, f64)],
) -> Vec<(&'static str, Vec<(f64, f64)>)> {
    let mut curves = Vec::new();
    if let Some(curve) = &motor.torque_curve {
        curves.push(("pull-out curve", curve.points().to_vec()));
    }
    let top = edges.iter().map(|e| e.1).fold(0.0, f64::max);
    if motor.windings.is_some() {
        let samples = (0..=200)
            .filter_map(|k| {
                let hz = top * k as f64 / 200.0;
                motor.derived_pull_out(hz).map(|nm| (hz, nm))
            })
            .collect();
        curves.push(("pull-out from the windings", samples));
    }
    curves
}

/// Each step edge of `periods` against the curve's, in timer ticks, by step.
pub fn edge_errors(spec: &Spec, periods: &[u32]) -> Result<Vec<(f64, f64)>, profile_core::Error> {
    let scale = spec.timer.frequency_scale();
    // Each entry is played `ticks_per_step` times: step edges in timer ticks.
    let repeat = f64::from(spec.timer.ticks_per_step);
    let mut played = 0u64;
    let mut errors = Vec::with_capacity(periods.len());
    spec.for_each_exact_edge(|k, t| {
        if let Some(&p) = periods.get(k as usize - 1) {
            played += u64::from(p);
            errors.push((f64::from(k), (played as f64 - t * scale) * repeat));
        }
    })?;
    Ok(errors)
}

/// A compact profile (runs or segments) over its curve: `NAME_edges.svg`.
fn write_compact_plot(
    p: &Profile,
    color: RGBColor,
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let spec = p.table.spec();
    let Some(c) = p.table.compact() else {
        return Ok(());
    };
    let (layout, bound) = (format!("{} {}", c.entries, c.kind), c.max_edge_error_ticks);
    let compact = p.table.step_periods();
    let per_step = spec.table()?.periods;
    let mut edges = vec![0.0];
    spec.for_each_exact_edge(|_, t| edges.push(t))?;
    let curve: Vec<(f64, f64)> = edges
        .windows(2)
        .map(|w| (w[0], 1.0 / (w[1] - w[0])))
        .collect();
    let played = Series::new(&layout, color, &compact, spec.timer.frequency_scale(), spec);
    let line = |label: &str, color: RGBColor, points: Vec<(f64, f64)>| Line {
        label: label.to_string(),
        color,
        points,
    };
    let last = compact.len() as f64;
    let frequency = [
        line("curve", BLACK, curve),
        line(&layout, color, played.steps),
    ];
    let errors = [
        line(
            &format!("bound: {bound:.3} ticks"),
            RGBColor(0xb0, 0xb0, 0xb0),
            vec![(1.0, bound), (last, bound), (last, -bound), (1.0, -bound)],
        ),
        line("one entry per step", BLACK, edge_errors(spec, &per_step)?),
        line(&layout, color, edge_errors(spec, &compact)?),
    ];
    plots::compact(path, &p.name, &frequency, &errors)
}

fn series(label: &str, color: RGBColor, t: &Table) -> Series {
    let tps = t.spec.timer.timer_hz as f64 / t.spec.timer.ticks_per_step as f64;
    Series::new(label, color, &t.periods, tps, &t.spec)
}

/// Writes, for every profile, `NAME.svg` (frequency and acceleration against
/// time) and `NAME.csv` (step, period, edge time, frequency); for a compact
/// layout (runs, segments) `NAME_edges.svg` (over the curve, with every
/// edge's error); for a profile that names a motor `NAME_torque.svg`; and
/// `overview.svg`, into `out`.
pub fn write_plots(
    profiles: &Profiles,
    out: &mut Staging,
) -> Result<(), Box<dyn std::error::Error>> {
    let mut overview = Vec::new();
    let colors = colors(profiles);
    for (p, &color) in profiles.profiles().iter().zip(&colors) {
        let periods = p.table.step_periods();
        let spec = p.table.spec();
        let tps = spec.timer.timer_hz as f64 / spec.timer.ticks_per_step as f64;
        let s = Series::new(&p.name, color, &periods, tps, spec);
        let bands: Vec<plots::Band> = p.avoid.map_or_else(Vec::new, |b| {
            let times = b.time_in(&spec.timer, &periods);
            b.steps()
                .into_iter()
                .zip(times)
                .map(|((lo, hi), t)| (lo, hi, t))
                .collect()
        });
        plots::profile(&out.path(format!("{}.svg", p.name)), &p.name, &s, &bands)?;
        let mut csv = String::from("step,period_ticks,start_s,frequency_hz\n");
        for (k, (&period, &(t, f))) in periods.iter().zip(&s.steps).enumerate() {
            csv.push_str(&format!("{k},{period},{t:.9},{f:.6}\n"));
        }
        std::fs::write(out.path(format!("{}.csv", p.name)), csv)?;
        if p.table.compact().is_some() {
            write_compact_plot(p, color, &out.path(format!("{}_edges.svg", p.name)))?;
        }
        if p.motor.is_some() {
            write_torque_plot(p, &out.path(format!("{}_torque.svg", p.name)))?;
        }
        overview.push(s);
    }
    plots::overlay(
        &out.path("overview.svg"),
        "All profiles: frequency against time",
        &overview,
        false,
    )?;
    Ok(())
}

/// The figures the README and the guide show (`docs/`): the S-curve article's four example calls, three
/// discretizations of one curve, the motor check of the worked example and
/// the compressed microstep ramp over its curve.
pub fn write_docs(
    profiles: &Profiles,
    docs: &mut Staging,
) -> Result<(), Box<dyn std::error::Error>> {
    let calls = [
        ("sigmoid_yellow", "yellow: (1000, 56000, 16000, 4)"),
        ("sigmoid_orange", "orange: (1000, 64000, 500, 8)"),
        ("sigmoid_blue", "blue: (1000, 64000, 500, 15)"),
        ("sigmoid_gray", "gray: (1000, 40000, 500, 5)"),
    ];
    let mut article = Vec::new();
    for ((name, label), (_, color)) in calls.into_iter().zip(ARTICLE) {
        let Some(Generated::Steps(t)) = profiles
            .profiles()
            .iter()
            .find(|p| p.name == name)
            .map(|p| &p.table)
        else {
            return Err(format!("profile `{name}` is missing from the file").into());
        };
        article.push(series(label, color, t));
    }
    plots::overlay(
        &docs.path("s_curve_article.svg"),
        "CalculateSModelLine's four example calls: frequency against step",
        &article,
        true,
    )?;
    // One curve, three discretizations: the orange sigmoid.
    let Some(Generated::Steps(orange)) = profiles
        .profiles()
        .iter()
        .find(|p| p.name == "sigmoid_exact")
        .map(|p| &p.table)
    else {
        return Err("profile `sigmoid_exact` is missing from the file".into());
    };
    let mut sides = Vec::new();
    for (i, d) in [
        Discretization::Index,
        Discretization::LeftEndpoint,
        Discretization::Exact,
    ]
    .into_iter()
    .enumerate()
    {
        let t = orange.spec.with_discretization(d).table()?;
        sides.push(series(d.name(), PALETTE[i], &t));
    }
    plots::side_by_side(
        &docs.path("discretizations.svg"),
        "One sigmoid (500 -> 64000 Hz, 1000 steps, flexible 8), three discretizations",
        &sides,
    )?;
    // The motor page's worked example: a real motor on the jerk-limited ramp.
    let Some(worked) = profiles
        .profiles()
        .iter()
        .find(|p| p.name == "jerk_limited" && p.motor.is_some())
    else {
        return Err("profile `jerk_limited` with a motor is missing from the file".into());
    };
    write_torque_plot(worked, &docs.path("motor_torque.svg"))?;
    // The compressed microstep ramp over its curve.
    let colors = colors(profiles);
    let Some((compressed, &color)) = profiles
        .profiles()
        .iter()
        .zip(&colors)
        .find(|(p, _)| p.name == "microstep_runs")
    else {
        return Err("profile `microstep_runs` is missing from the file".into());
    };
    write_compact_plot(compressed, color, &docs.path("compressed_edges.svg"))?;
    Ok(())
}
