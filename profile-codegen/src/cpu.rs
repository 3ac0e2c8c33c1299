//! The step interrupt's budget: what share of the CPU the interrupt that
//! plays a table takes at the table's fastest entry, and whether it ends
//! before the next one is due.
//!
//! A profile that names its core and clock (`core = "cortex-m3"`,
//! `cpu_hz = 72MHz`, and `axes`, `cpu_load` where the defaults do not hold)
//! has its shortest period checked at compile time ([`Cpu::check`]):
//! the interrupt's mean cost may take at most `cpu_load` of the CPU (50 % by
//! default), and its largest step must end within the period.
//!
//! The costs are the project's own measured figures ([`Core::cost`]):
//! instructions from SysTick's vector to its return of the guide's step
//! interrupt on each Cortex-M, counted in QEMU, turned into cycles at a
//! bound of cycles an instruction plus the core's exception entry and
//! return; and on the AVR the C player's cycles from the compare match to
//! the end of `reti`, counted in simavr.
//!
//! ```
//! use profile_codegen::cpu::{Cpu, Core};
//! use profile_codegen::cpu::Layout;
//!
//! // A Cortex-M3 at 72 MHz, one axis, a per-step table: about 60 cycles a
//! // step on average, half the CPU at 599 000 steps/s; but its largest
//! // step (176 cycles) must end before the next, which bounds it first.
//! let cpu = Cpu::new(Core::CortexM3, 72e6);
//! let cost = cpu.cost(Layout::Steps);
//! assert_eq!((cost.mean.round(), cost.largest), (60.0, 176.0));
//! assert_eq!(cpu.max_rate(Layout::Steps).round(), 409_091.0);
//! ```

use std::format;
use std::string::String;

use profile_core::Timer;

use crate::table::computed::Generated;

/// The cores whose step interrupt the project measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Core {
    /// Armv6-M (`thumbv6m-none-eabi`): RP2040, STM32F0, SAMD21.
    CortexM0,
    /// Armv7-M (`thumbv7m-none-eabi`): STM32F1, LPC1768.
    CortexM3,
    /// Armv7E-M with its FPU (`thumbv7em-none-eabihf`): STM32F4, nRF52.
    CortexM4F,
    /// The 8-bit AVR (ATmega328P), playing with the C player.
    Avr,
}

/// `core = NAME`: the names and the cores.
pub const CORES: [(&str, Core); 4] = [
    ("cortex-m0", Core::CortexM0),
    ("cortex-m3", Core::CortexM3),
    ("cortex-m4f", Core::CortexM4F),
    ("avr", Core::Avr),
];

/// How a table is laid out, as the interrupt's cost depends on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// One period per step.
    Steps,
    /// Equal-time segments of `(period, count)`.
    Segments,
    /// Compressed runs.
    Runs,
}

impl Layout {
    /// The layout of `table`.
    pub fn of(table: &Generated) -> Self {
        match table {
            Generated::Steps(_) => Layout::Steps,
            Generated::Segments(_) => Layout::Segments,
            Generated::Runs(_) => Layout::Runs,
        }
    }
}

/// The most axes one interrupt steps (`axes`).
pub const MAX_AXES: u32 = 16;

/// A step interrupt's cost, in CPU cycles an interrupt.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cost {
    /// The mean over a move's steps.
    pub mean: f64,
    /// The largest step (where the move changes stretch, or a run ends).
    pub largest: f64,
}

/// Instructions of the guide's step interrupt from the vector to its
/// return on a Cortex-M (`rigs/measure`, the accelerating phase: mean and
/// largest), what another layout adds to the player's step, what each
/// axis after the first adds, and the cycles around them.
struct Measured {
    /// The guide's interrupt, a per-step table: (mean, largest).
    interrupt: (f64, f64),
    /// What equal-time segments add over a per-step table.
    segments: (f64, f64),
    /// What compressed runs add.
    runs: (f64, f64),
    /// What each follower of `Axes` adds.
    follower: (f64, f64),
    /// Cycles an instruction, at most for this code: loads, stores and
    /// taken branches take 2 on the M3 and M4, a taken branch 3 on the M0.
    cycles_per_instruction: f64,
    /// The exception's entry and return, cycles.
    entry_and_return: f64,
}

impl Core {
    /// The core `name` names ([`CORES`]).
    pub fn named(name: &str) -> Option<Core> {
        CORES.iter().find(|(n, _)| *n == name).map(|(_, c)| *c)
    }

    /// Its name in `core = NAME`.
    pub fn name(self) -> &'static str {
        CORES
            .iter()
            .find(|(_, c)| *c == self)
            .map_or("", |(n, _)| n)
    }

    /// The Cortex-M figures, `None` on the AVR (measured in cycles).
    fn measured(self) -> Option<Measured> {
        // rigs/measure: the guide's interrupt (vector to return), `Player`
        // and its segments and compressed runs, `Axes` with two followers,
        // accelerating, mean (largest).
        let (interrupt, player, segments, runs, axes, cpi, entry_and_return) = match self {
            Core::CortexM0 => (
                (23.06, 84.0),
                (16.06, 76.0),
                (26.27, 176.0),
                (21.25, 185.0),
                (28.61, 104.0),
                3.0,
                32.0,
            ),
            Core::CortexM3 => (
                (18.05, 76.0),
                (15.05, 66.0),
                (23.68, 149.0),
                (19.80, 151.0),
                (24.21, 90.0),
                2.0,
                24.0,
            ),
            Core::CortexM4F => (
                (18.05, 76.0),
                (15.05, 66.0),
                (23.68, 149.0),
                (18.76, 147.0),
                (24.21, 92.0),
                2.0,
                24.0,
            ),
            Core::Avr => return None,
        };
        let over = |(m, l): (f64, f64)| (m - player.0, l - player.1);
        let (fm, fl) = over(axes);
        Some(Measured {
            interrupt,
            segments: over(segments),
            runs: over(runs),
            follower: (fm / 2.0, fl / 2.0),
            cycles_per_instruction: cpi,
            entry_and_return,
        })
    }

    /// The step interrupt's cycles for a table of `layout` stepping `axes`
    /// axes. On the AVR, the C player's measured cycles (one axis: it
    /// steps one; segments are played as runs are, at their cost).
    pub fn cost(self, layout: Layout, axes: u32) -> Cost {
        let Some(m) = self.measured() else {
            // rigs/avr: compare match to the end of `reti`, every step,
            // mean (largest).
            let (mean, largest) = match layout {
                Layout::Steps => (88.24, 175.0),
                _ => (139.38, 473.0),
            };
            return Cost { mean, largest };
        };
        let (lm, ll) = match layout {
            Layout::Steps => (0.0, 0.0),
            Layout::Segments => m.segments,
            Layout::Runs => m.runs,
        };
        let followers = f64::from(axes.saturating_sub(1));
        let instructions = |base: f64, layout: f64, follower: f64| {
            (base + layout + followers * follower) * m.cycles_per_instruction + m.entry_and_return
        };
        Cost {
            mean: instructions(m.interrupt.0, lm, m.follower.0),
            largest: instructions(m.interrupt.1, ll, m.follower.1),
        }
    }
}

/// A profile's core, clock, axes and the share of the CPU its step
/// interrupt may take.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cpu {
    /// The core (`core`).
    pub core: Core,
    /// Its clock, Hz (`cpu_hz`).
    pub cpu_hz: f64,
    /// The axes one interrupt steps (`axes`, 1 by default).
    pub axes: u32,
    /// The largest share of the CPU the interrupt may take at the table's
    /// fastest entry (`cpu_load`, 0.5 by default).
    pub max_load: f64,
}

/// A table too fast for its step interrupt.
#[derive(Clone, Debug, PartialEq)]
pub struct CpuError {
    /// The first entry the interrupt cannot serve.
    pub index: usize,
    /// Its period, in ticks.
    pub ticks: u32,
    /// The step rate it plays, in steps/s.
    pub rate: f64,
    /// The interrupt's cost, cycles.
    pub cost: Cost,
    /// The CPU's cycles in that period.
    pub cycles: f64,
    /// The fastest step rate the interrupt serves, in steps/s.
    pub max_rate: f64,
}

impl Cpu {
    /// One axis, at most half the CPU.
    pub fn new(core: Core, cpu_hz: f64) -> Self {
        Cpu {
            core,
            cpu_hz,
            axes: 1,
            max_load: 0.5,
        }
    }

    /// The interrupt's cost for a table of `layout`.
    pub fn cost(&self, layout: Layout) -> Cost {
        self.core.cost(layout, self.axes)
    }

    /// The most interrupts a second it serves within its load and with its
    /// largest step ending before the next interrupt: the fastest step
    /// rate, steps/s, with one interrupt a step (`ticks_per_step = 1`).
    pub fn max_rate(&self, layout: Layout) -> f64 {
        let cost = self.cost(layout);
        (self.cpu_hz * self.max_load / cost.mean).min(self.cpu_hz / cost.largest)
    }

    /// The share of the CPU the interrupt takes with one every `ticks`
    /// ticks of `timer`.
    pub fn load(&self, timer: &Timer, layout: Layout, ticks: u32) -> f64 {
        self.cost(layout).mean / self.cycles(timer, ticks)
    }

    /// The CPU's cycles in `ticks` ticks of `timer`.
    fn cycles(&self, timer: &Timer, ticks: u32) -> f64 {
        f64::from(ticks) * self.cpu_hz / timer.timer_hz as f64
    }

    /// Checks `periods` (one per step) played by an interrupt per entry:
    /// `ticks_per_step` interrupts a step.
    pub fn check(&self, timer: &Timer, layout: Layout, periods: &[u32]) -> Result<(), CpuError> {
        let cost = self.cost(layout);
        // Each step is `ticks_per_step` entries (interrupts) of its period.
        let per_step = f64::from(timer.ticks_per_step);
        let fits = |ticks: u32| {
            let cycles = self.cycles(timer, ticks);
            cost.mean <= self.max_load * cycles && cost.largest <= cycles
        };
        match periods.iter().position(|&p| !fits(p)) {
            None => Ok(()),
            Some(index) => {
                let ticks = periods[index];
                let cycles = self.cycles(timer, ticks);
                Err(CpuError {
                    index,
                    ticks,
                    rate: timer.timer_hz as f64 / (per_step * f64::from(ticks)),
                    cost,
                    cycles,
                    max_rate: self.max_rate(layout) / per_step,
                })
            }
        }
    }
}

impl CpuError {
    /// The message, naming the core and its clock (`what`: "`core =
    /// \"cortex-m3\"` at 72 MHz").
    pub fn message(&self, what: &str, cpu: &Cpu) -> String {
        let load = self.cost.mean / self.cycles;
        let why = if self.cost.largest > self.cycles {
            format!(
                "its largest step, {} cycles, does not end within the period's {}",
                crate::numbers::Num(libm::ceil(self.cost.largest)),
                crate::numbers::Num(libm::floor(self.cycles)),
            )
        } else {
            format!(
                "{} % of the CPU, above `cpu_load` = {} %",
                crate::numbers::Num(libm::ceil(load * 100.0)),
                crate::numbers::Num(cpu.max_load * 100.0),
            )
        };
        format!(
            "entry {} is {} ticks, {} steps/s: the step interrupt ({what}, {} axis{}) takes about \
             {} cycles a step there, {why}; it serves at most {} steps/s; lower `fmax`, or raise \
             `cpu_hz` or `cpu_load`",
            self.index,
            self.ticks,
            crate::numbers::Significant(self.rate),
            cpu.axes,
            if cpu.axes == 1 { "" } else { "es" },
            crate::numbers::Num(libm::ceil(self.cost.mean)),
            crate::numbers::Num(libm::floor(self.max_rate)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn costs_are_the_measured_figures_in_cycles() {
        // The M3: 18.05 instructions, 2 cycles each, 24 around them.
        let m3 = Core::CortexM3.cost(Layout::Steps, 1);
        assert!((m3.mean - (18.05 * 2.0 + 24.0)).abs() < 1e-9);
        assert!((m3.largest - (76.0 * 2.0 + 24.0)).abs() < 1e-9);
        // Two followers on the M0: the measured Axes less the Player.
        let m0 = Core::CortexM0.cost(Layout::Steps, 3);
        assert!((m0.mean - ((23.06 + 28.61 - 16.06) * 3.0 + 32.0)).abs() < 1e-9);
        // The AVR's C player, in cycles as simavr counts them.
        assert_eq!(Core::Avr.cost(Layout::Runs, 1).largest, 473.0);
        assert_eq!(Core::named("cortex-m4f"), Some(Core::CortexM4F));
        assert_eq!(Core::CortexM4F.name(), "cortex-m4f");
        assert_eq!(Core::named("cortex-m7"), None);
    }

    #[test]
    fn the_first_entry_past_the_load_is_named_with_the_rate_served() {
        // An ATmega328P at 16 MHz, timer at clk/8: 88.24 cycles a step,
        // 50 % of the CPU at 90 662 steps/s, 22 ticks.
        let cpu = Cpu::new(Core::Avr, 16e6);
        let timer = Timer::new(2_000_000);
        let e = cpu
            .check(&timer, Layout::Steps, &[100, 40, 23, 22, 21])
            .unwrap_err();
        assert_eq!((e.index, e.ticks), (3, 22));
        assert_eq!(libm::floor(e.max_rate), 90_661.0);
        assert_eq!(
            e.message("`core = \"avr\"` at 16 MHz", &cpu),
            "entry 3 is 22 ticks, 90909.1 steps/s: the step interrupt (`core = \"avr\"` at 16 MHz, \
             1 axis) takes about 89 cycles a step there, 51 % of the CPU, above `cpu_load` = 50 %; \
             it serves at most 90661 steps/s; lower `fmax`, or raise `cpu_hz` or `cpu_load`"
        );
        assert!(cpu.check(&timer, Layout::Steps, &[100, 40, 23]).is_ok());
        // The whole CPU allowed: the largest step (175 cycles) bounds it.
        let all = Cpu {
            max_load: 1.0,
            ..cpu
        };
        let e = all.check(&timer, Layout::Steps, &[30, 21]).unwrap_err();
        assert_eq!(e.index, 1);
        assert!(
            e.message("x", &all)
                .contains("its largest step, 175 cycles, does not end")
        );
    }
}
