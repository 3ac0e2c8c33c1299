//! The timer a table is for: its tick rate, its reload register's width.

/// The width of one table entry, which is the width of the timer's reload register.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Word {
    /// 16-bit timer (the default): periods from 1 to 65 535 ticks.
    U16,
    /// 32-bit timer: periods from 1 to 4 294 967 295 ticks.
    U32,
}

impl Word {
    /// The largest period this word holds, in ticks.
    pub const fn max(self) -> u32 {
        match self {
            Word::U16 => u16::MAX as u32,
            Word::U32 => u32::MAX,
        }
    }

    /// Bytes of flash one entry takes.
    pub const fn bytes(self) -> u32 {
        match self {
            Word::U16 => 2,
            Word::U32 => 4,
        }
    }

    /// The Rust (and TOML) name: `u16` or `u32`.
    pub const fn name(self) -> &'static str {
        match self {
            Word::U16 => "u16",
            Word::U32 => "u32",
        }
    }
}

/// How the timer turns ticks into step pulses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timer {
    /// Tick rate of the timer after its prescaler, in Hz. Must not be 0.
    pub timer_hz: u32,
    /// Width of the reload register, and so of each table entry.
    pub word: Word,
    /// Timer reloads per step: 1 for compare/PWM output, 2 where the timer toggles
    /// the pin and overflows twice per pulse (each entry is then a half period).
    pub ticks_per_step: u8,
}

impl Timer {
    /// A timer at `timer_hz` with the defaults: `u16` word, one reload per step.
    pub const fn new(timer_hz: u32) -> Self {
        Timer {
            timer_hz,
            word: Word::U16,
            ticks_per_step: 1,
        }
    }

    /// What turns an entry into its step's frequency and period:
    /// `timer_hz / ticks_per_step`, in Hz. A step whose entry is `p` ticks
    /// is a step at `frequency_scale() / p` Hz, lasting
    /// `p / frequency_scale()` s (with `ticks_per_step = 2` the timer plays
    /// each entry twice).
    ///
    /// ```
    /// use profile_core::Timer;
    ///
    /// let timer = Timer { ticks_per_step: 2, ..Timer::new(1_000_000) };
    /// assert_eq!(timer.frequency_scale(), 500_000.0);
    /// // An entry of 500 ticks: a step at 1 kHz.
    /// assert_eq!(timer.frequency_scale() / 500.0, 1000.0);
    /// ```
    pub fn frequency_scale(&self) -> f64 {
        self.timer_hz as f64 / self.ticks_per_step as f64
    }

    /// The lowest step frequency whose period still fits the word, in Hz.
    pub fn lowest_frequency(&self) -> f64 {
        self.frequency_scale() / self.word.max() as f64
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for u16 {}
    impl Sealed for u32 {}
}

/// An integer type a table can be generated into: `u16` or `u32`.
pub trait TableWord: Copy + sealed::Sealed {
    /// The [`Word`] this type is.
    const WORD: Word;
    /// Converts a period already checked to fit.
    fn from_ticks(ticks: u32) -> Self;
    /// The value as `u32`.
    fn into_ticks(self) -> u32;
}

impl TableWord for u16 {
    const WORD: Word = Word::U16;
    fn from_ticks(ticks: u32) -> Self {
        ticks as u16
    }
    fn into_ticks(self) -> u32 {
        self as u32
    }
}

impl TableWord for u32 {
    const WORD: Word = Word::U32;
    fn from_ticks(ticks: u32) -> Self {
        ticks
    }
    fn into_ticks(self) -> u32 {
        self
    }
}
