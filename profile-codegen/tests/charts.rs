//! The pull-out torque derived from a motor's windings against the
//! pull-out charts makers publish, with what each chart was measured on:
//! the motor's datasheet figures, the driver's supply and current setting
//! (RMS or peak, as its manual gives it), the drive (a sine, or half steps).
//! Every model figure not on a datasheet is left at its default.
//!
//! Every chart is an image; its points were read off it, each with the
//! reading error given beside it. Speeds are in rpm of a 1.8° motor.
//!
//! Three kinds of chart:
//!
//! - within ±10 % at every point: StepperOnline's 23HS45-4204S (half steps),
//!   23HE45-4204S (a DM556T, sine, at two currents) and 23HS32-4004S (a
//!   DM542T, sine, at two supplies), the budget motors whose charts the
//!   model's two losses were fitted to;
//! - never more than 10 % over: TRINAMIC's QSH4218 in half steps, whose
//!   iron loses less than the default assumes (the model is then on the safe
//!   side: a ramp it passes the motor follows);
//! - outside the model, printed and not held to it: charts whose driver or
//!   current is not known.
//!
//! `cargo test -p profile-codegen --test charts -- --nocapture` prints every
//! point.

use profile_codegen::motor::{CurrentSetting, Drive, Motor, Windings};

/// What a chart is held to.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Held {
    /// Within ±10 % at every point.
    Within,
    /// Never more than 10 % above a point.
    NotAbove,
    /// Outside the model, for this reason.
    Outside(&'static str),
}

struct Chart {
    /// The motor and what drove it.
    name: &'static str,
    /// Where the chart is, and where its points were read.
    source: &'static str,
    windings: Windings,
    /// Table steps per full step: 2 in half steps; a microstepping
    /// driver's setting.
    microsteps: u32,
    /// `(rpm, N·m)`.
    points: &'static [(f64, f64)],
    /// The points' reading error, N·m.
    reading: f64,
    held: Held,
}

/// StepperOnline's 23HS45-4204S: 1.8°, 3.0 N·m at 4.2 A, 0.88 Ω, 3.4 mH
/// (its 23HE45-4204S is the same body: 0.9 Ω ± 10 %, 3.8 mH ± 20 % as
/// listed for it, the same windings within the tolerances).
fn stepperonline_23hs45() -> Windings {
    Windings::new(0.88, 3.4e-3, 4.2, 3.0, 36.0)
}

/// StepperOnline's 23HS32-4004S (its drawing's table): 1.8°, 2.4 N·m at
/// 4.0 A, 0.65 Ω, 3.2 mH at 1 kHz, on a DM542T at its 4.2 A peak (3.0 A
/// RMS) setting.
fn stepperonline_23hs32(volts: f64) -> Windings {
    Windings::new(0.65, 3.2e-3, 4.0, 2.4, volts).with_driver_current(4.2, CurrentSetting::Peak)
}

/// TRINAMIC's QSH4218 (the manual's Table 2.1), 24 V, half steps.
fn qsh4218(r: f64, l: f64, amps: f64, holding: f64, detent: f64) -> Windings {
    Windings::new(r, l, amps, holding, 24.0)
        .with_detent_torque(detent)
        .with_drive(Drive::HalfStep)
}

const TRINAMIC_2007: &str = "TRINAMIC, QMot QSH4218 Manual V1.03 (2007) and V1.06 (2011): \
    SyedSiddiqShakir/powtech_laser_stepper QSH4218_manual.pdf (681e0c90), \
    thomasarmel/arduino_polytech_2019_2020 datasheets/QSH4218_manual.pdf (1437bba5); \
    markers read by colour, calibrated on the gridlines";

fn charts() -> Vec<Chart> {
    vec![
        Chart {
            name: "23HS45-4204S, 36 V, 4.2 A, half steps",
            source: "StepperOnline 23HS45-4204S_Torque_Curve.pdf, read in \
                contrerassma-eng/3d-generator research_motores_drivers.md (9a216907) and \
                seankd3/machine-frame-lab src/catalog/motion.ts (4d5fab4f), within ±5 %",
            windings: stepperonline_23hs45().with_drive(Drive::HalfStep),
            microsteps: 2,
            points: &[
                (60.0, 2.50),
                (150.0, 2.31),
                (300.0, 2.07),
                (360.0, 1.97),
                (420.0, 1.84),
            ],
            reading: 0.1,
            held: Held::Within,
        },
        Chart {
            name: "23HE45-4204S, 36 V, DM556T at 4.1 A RMS",
            source: "StepperOnline 23HE45-4204S_Torque_Curve.pdf, read in \
                contrerassma-eng/3d-generator research_motores_drivers.md (9a216907), \
                Table 2a-1, within ±5 %",
            windings: stepperonline_23hs45().with_driver_current(4.1, CurrentSetting::Rms),
            microsteps: 10,
            points: &[(300.0, 2.40), (390.0, 2.01), (510.0, 1.63), (600.0, 1.30)],
            reading: 0.1,
            held: Held::Within,
        },
        Chart {
            name: "23HE45-4204S, 36 V, DM556T at 3.1 A RMS",
            source: "the same chart's second curve, the same reading",
            windings: stepperonline_23hs45().with_driver_current(3.1, CurrentSetting::Rms),
            microsteps: 10,
            points: &[(300.0, 2.15), (600.0, 1.31)],
            reading: 0.1,
            held: Held::Within,
        },
        Chart {
            name: "23HS32-4004S, 36 V, DM542T at 4.2 A peak",
            source: "StepperOnline 23HS32-4004S_Torque_Curve.pdf: jmpz63/APM \
                .../joint_datasheets/joint2/ (a953cbf7); markers read by colour, two hidden \
                under the 48 V ones at 90 and 210 rpm (±0.01 N·m)",
            windings: stepperonline_23hs32(36.0),
            microsteps: 10,
            points: &[
                (90.0, 1.83),
                (210.0, 1.78),
                (300.0, 1.64),
                (390.0, 1.39),
                (510.0, 1.23),
                (600.0, 1.03),
            ],
            reading: 0.005,
            held: Held::Within,
        },
        Chart {
            name: "23HS32-4004S, 48 V, DM542T at 4.2 A peak",
            source: "the same chart's 48 V curve (a second reading by hand, in a public \
                file, agrees within 0.01 N·m)",
            windings: stepperonline_23hs32(48.0),
            microsteps: 10,
            points: &[
                (90.0, 1.84),
                (210.0, 1.82),
                (300.0, 1.78),
                (390.0, 1.73),
                (510.0, 1.50),
                (600.0, 1.33),
            ],
            reading: 0.005,
            held: Held::Within,
        },
        Chart {
            name: "QSH4218-35-10-027, 24 V, 1.0 A, half steps",
            source: TRINAMIC_2007,
            windings: qsh4218(5.3, 6.6e-3, 1.0, 0.27, 0.022),
            microsteps: 2,
            points: &[
                (75.0, 0.220),
                (150.0, 0.200),
                (225.0, 0.196),
                (300.0, 0.200),
                (375.0, 0.190),
                (450.0, 0.190),
                (600.0, 0.164),
                (750.0, 0.144),
                (900.0, 0.120),
            ],
            reading: 0.001,
            held: Held::NotAbove,
        },
        Chart {
            name: "QSH4218-41-10-035, 24 V, 1.0 A, half steps",
            source: TRINAMIC_2007,
            windings: qsh4218(4.5, 7.5e-3, 1.0, 0.35, 0.025),
            microsteps: 2,
            points: &[
                (75.0, 0.281),
                (150.0, 0.299),
                (300.0, 0.273),
                (450.0, 0.235),
                (600.0, 0.178),
                (750.0, 0.130),
                (900.0, 0.110),
                (1050.0, 0.101),
                (1200.0, 0.093),
                (1350.0, 0.078),
                (1500.0, 0.057),
            ],
            reading: 0.002,
            held: Held::NotAbove,
        },
        Chart {
            name: "QSH4218-51-10-049, 24 V, 1.0 A, half steps",
            source: TRINAMIC_2007,
            windings: qsh4218(5.0, 8.0e-3, 1.0, 0.49, 0.028),
            microsteps: 2,
            points: &[
                (30.0, 0.396),
                (150.0, 0.375),
                (300.0, 0.317),
                (450.0, 0.235),
                (600.0, 0.153),
                (750.0, 0.130),
                (900.0, 0.110),
                (1050.0, 0.092),
                (1200.0, 0.078),
                (1350.0, 0.078),
                (1500.0, 0.064),
            ],
            reading: 0.001,
            held: Held::NotAbove,
        },
        Chart {
            name: "QSH4218-47-28-040, 24 V, 2.8 A, half steps",
            source: "TRINAMIC, QMot QSH4218 Manual V1.06 (2011), Figure 5.4: \
                thomasarmel/arduino_polytech_2019_2020 (1437bba5); the manual's text, \
                \"0.25Nm torque at 1200 RPM with a 24V supply\", agrees",
            windings: qsh4218(0.5, 0.6e-3, 2.8, 0.40, 0.0),
            microsteps: 2,
            points: &[
                (150.0, 0.404),
                (300.0, 0.404),
                (450.0, 0.389),
                (600.0, 0.375),
                (750.0, 0.344),
                (900.0, 0.308),
                (1050.0, 0.281),
                (1200.0, 0.255),
                (1350.0, 0.245),
                (1500.0, 0.235),
            ],
            reading: 0.002,
            held: Held::NotAbove,
        },
        Chart {
            name: "17HS24-0644S, 24 V, 0.64 A, half steps",
            source: "StepperOnline 17HS24-0644S_Torque_Curve.pdf: jmpz63/APM \
                .../joint_datasheets/joint1/ (a953cbf7)",
            windings: Windings::new(14.5, 35e-3, 0.6, 0.65, 24.0)
                .with_drive(Drive::HalfStep)
                .with_driver_current(0.64, CurrentSetting::Rms),
            microsteps: 2,
            points: &[
                (60.0, 0.509),
                (90.0, 0.500),
                (120.0, 0.431),
                (150.0, 0.373),
                (180.0, 0.305),
                (210.0, 0.246),
                (240.0, 0.187),
                (270.0, 0.148),
                (300.0, 0.109),
                (330.0, 0.090),
                (360.0, 0.070),
                (390.0, 0.056),
                (420.0, 0.032),
            ],
            reading: 0.002,
            held: Held::Outside(
                "the driver is not named, and the drawing calls the motor unipolar in one \
                 table and wires it bipolar in another",
            ),
        },
        Chart {
            name: "17HE19-2004S, 24 V, 2.2 A, 1/8 steps",
            source: "StepperOnline's torque-curve image: \
                rlneumiller/2StageCompoundCycloidalTorqueCalculator TorqueCurve_17HE19-2004S.png \
                (75613b5f)",
            windings: Windings::new(1.3, 2.4e-3, 2.0, 0.55, 24.0)
                .with_driver_current(2.2, CurrentSetting::Peak),
            microsteps: 8,
            points: &[
                (100.0, 0.416),
                (200.0, 0.402),
                (300.0, 0.404),
                (400.0, 0.424),
                (500.0, 0.420),
                (600.0, 0.378),
                (700.0, 0.344),
                (800.0, 0.304),
                (900.0, 0.274),
                (1000.0, 0.242),
                (1100.0, 0.182),
                (1200.0, 0.142),
            ],
            reading: 0.002,
            held: Held::Outside(
                "neither the driver nor whether its 2.2 A is RMS or peak is given (the \
                 torque at low speed says peak, taken here)",
            ),
        },
    ]
}

/// The derived torque over the chart at each point, less one: `+0.05` is
/// 5 % above the chart.
fn errors(chart: &Chart) -> Vec<(f64, f64, f64)> {
    let motor = Motor::new(1.8, chart.microsteps, 5.0e-5).with_windings(chart.windings);
    chart
        .points
        .iter()
        .map(|&(rpm, nm)| {
            let hz = rpm / 60.0 * 200.0 * f64::from(chart.microsteps);
            let derived = motor.pull_out(hz);
            (rpm, derived, derived / nm - 1.0)
        })
        .collect()
}

#[test]
fn the_derived_torque_against_published_charts() {
    let mut failures = Vec::new();
    for chart in charts() {
        println!("{} ({})", chart.name, chart.source);
        println!(
            "  read within ±{} N·m; held: {:?}",
            chart.reading, chart.held
        );
        let mut worst = (f64::INFINITY, f64::NEG_INFINITY);
        for ((rpm, derived, off), &(_, nm)) in errors(&chart).into_iter().zip(chart.points) {
            println!(
                "  {rpm:>6} rpm: chart {nm:.3} N·m, derived {derived:.3} N·m ({:+.1} %)",
                off * 100.0
            );
            worst = (worst.0.min(off), worst.1.max(off));
            let fails = match chart.held {
                Held::Within => off.abs() > 0.10,
                Held::NotAbove => off > 0.10,
                Held::Outside(_) => false,
            };
            if fails {
                failures.push(format!(
                    "{} at {rpm} rpm: {:+.1} %",
                    chart.name,
                    off * 100.0
                ));
            }
        }
        println!(
            "  from {:+.1} % to {:+.1} %\n",
            worst.0 * 100.0,
            worst.1 * 100.0
        );
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The charts held to ±10 % cover both drive kinds, three motors and
/// two supplies: the model's defaults are not fitted to one chart.
#[test]
fn the_charts_held_to_ten_percent_span_drives_and_motors() {
    let held: Vec<Chart> = charts()
        .into_iter()
        .filter(|c| c.held == Held::Within)
        .collect();
    let motors: std::collections::BTreeSet<&str> = held
        .iter()
        .map(|c| c.name.split(',').next().unwrap_or(""))
        .collect();
    assert_eq!(motors.len(), 3, "{motors:?}");
    assert!(held.iter().any(|c| c.windings.drive == Drive::Sine));
    assert!(held.iter().any(|c| c.windings.drive == Drive::HalfStep));
    let points: usize = held.iter().map(|c| c.points.len()).sum();
    assert_eq!(points, 23);
}

/// A driver set below the motor's rating gives less torque in the model,
/// not by a holding torque rescaled by hand: the 23HE45-4204S at 3.1 A of
/// its 4.2 A holds 3.1 / 4.2 of its holding torque at rest, and at 600 rpm,
/// where the supply limits both, within a tenth of what it gives at 4.1 A,
/// as its chart shows (1.31 and 1.30 N·m).
#[test]
fn a_lower_driver_current_scales_the_torque() {
    let at = |amps: f64, rpm: f64| {
        let w = stepperonline_23hs45().with_driver_current(amps, CurrentSetting::Rms);
        Motor::new(1.8, 10, 5.0e-5)
            .with_windings(w)
            .pull_out(rpm / 60.0 * 2000.0)
    };
    assert!((at(3.1, 0.0) - 3.0 * 3.1 / 4.2).abs() < 1e-12);
    assert!((at(4.2, 0.0) - 3.0).abs() < 1e-12);
    let (low, high) = (at(3.1, 600.0), at(4.1, 600.0));
    assert!((low / high - 1.0).abs() < 0.10, "{low} against {high}");
}
