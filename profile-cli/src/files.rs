//! The files behind the plots: an SVG and a CSV per profile, the torque of
//! each motor-bound profile, an overview; and the README's figures.

use std::path::{Path, PathBuf};

use plotters::style::RGBColor;
use profile_core::build::Profiles;
use profile_core::emit::Profile;
use profile_core::{Discretization, Generated, Table};

use crate::plots::{self, Series};

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
    plots::torque(path, &p.name, &edges, motor.torque_curve.points())
}

fn series(label: &str, color: RGBColor, t: &Table) -> Series {
    let tps = t.spec.timer.timer_hz as f64 / t.spec.timer.ticks_per_step as f64;
    Series::from_periods(label, color, &t.periods, tps)
}

/// Writes `NAME.svg` (frequency and acceleration against time), `NAME.csv`
/// (step, period, edge time, frequency) and, for a profile that names a
/// motor, `NAME_torque.svg` for every profile, and `overview.svg`, into
/// `out`, creating it; returns the files written.
pub fn write_plots(
    profiles: &Profiles,
    out: &Path,
) -> Result<Vec<PathBuf>, Box<dyn std::error::Error>> {
    std::fs::create_dir_all(out)?;
    let mut written = Vec::new();
    let mut overview = Vec::new();
    let colors = colors(profiles);
    for (p, &color) in profiles.profiles().iter().zip(&colors) {
        let periods = p.table.step_periods();
        let spec = p.table.spec();
        let tps = spec.timer.timer_hz as f64 / spec.timer.ticks_per_step as f64;
        let s = Series::from_periods(&p.name, color, &periods, tps).with_curve(spec);
        let svg = out.join(format!("{}.svg", p.name));
        plots::profile(&svg, &p.name, &s)?;
        written.push(svg);
        let mut csv = String::from("step,period_ticks,start_s,frequency_hz\n");
        for (k, (&period, &(t, f))) in periods.iter().zip(&s.steps).enumerate() {
            csv.push_str(&format!("{k},{period},{t:.9},{f:.6}\n"));
        }
        let csv_path = out.join(format!("{}.csv", p.name));
        std::fs::write(&csv_path, csv)?;
        written.push(csv_path);
        if p.motor.is_some() {
            let torque = out.join(format!("{}_torque.svg", p.name));
            write_torque_plot(p, &torque)?;
            written.push(torque);
        }
        overview.push(s);
    }
    let path = out.join("overview.svg");
    plots::overlay(
        &path,
        "All profiles: frequency against time",
        &overview,
        false,
    )?;
    written.push(path);
    Ok(written)
}

/// The README's figures: the S-curve article's four example calls, three
/// discretizations of one curve, and the motor check of the worked example.
pub fn write_docs(profiles: &Profiles, docs: &Path) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all(docs)?;
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
        &docs.join("s_curve_article.svg"),
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
        &docs.join("discretizations.svg"),
        "One sigmoid (500 -> 64000 Hz, 1000 steps, flexible 8), three discretizations",
        &sides,
    )?;
    // The README's worked example: a real motor on the jerk-limited ramp.
    let Some(worked) = profiles
        .profiles()
        .iter()
        .find(|p| p.name == "jerk_limited" && p.motor.is_some())
    else {
        return Err("profile `jerk_limited` with a motor is missing from the file".into());
    };
    write_torque_plot(worked, &docs.join("motor_torque.svg"))?;
    Ok(())
}
