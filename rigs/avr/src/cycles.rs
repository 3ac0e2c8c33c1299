//! The cycles the harness (`sim.c`) counted in simavr: per step interrupt,
//! and per call of a planning function.

/// Cycles the ATmega328P takes to respond to an interrupt (pushing the
/// return address, the datasheet's "minimum of four clock cycles"), which
/// simavr 1.6 does not charge: added to every figure.
pub const RESPONSE: u64 = 4;

/// One Timer1 compare-A interrupt.
#[derive(Clone, Copy, Debug)]
pub struct Isr {
    /// The cycle of the vector's first instruction.
    pub vector: u64,
    /// The cycle of the epilogue's first instruction.
    pub epilogue: u64,
    /// The cycle after `reti`.
    pub end: u64,
}

impl Isr {
    /// From the compare match to the end of `reti`: the response, the
    /// vector's `jmp`, the prologue, the body, the epilogue and `reti`.
    pub fn until_reti(self) -> u64 {
        RESPONSE + self.end - self.vector
    }

    /// From the compare match to the end of the interrupt's body (before
    /// the registers are restored).
    pub fn until_body_end(self) -> u64 {
        RESPONSE + self.epilogue - self.vector
    }
}

/// One call of a function the harness was asked to watch.
#[derive(Clone, Debug)]
pub struct Call {
    pub name: String,
    /// From its first instruction to the end of its `ret`.
    pub cycles: u64,
}

/// The harness's lines: `isr MATCH VECTOR EPILOGUE END`, `call NAME ENTRY
/// RETURN`; simavr's own lines are passed over.
pub fn parse(text: &str) -> Result<(Vec<Isr>, Vec<Call>), String> {
    let (mut isrs, mut calls) = (Vec::new(), Vec::new());
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        let number = |w: &str| w.parse::<u64>().map_err(|e| format!("`{line}`: {e}"));
        match words[..] {
            ["isr", _match, vector, epilogue, end] => isrs.push(Isr {
                vector: number(vector)?,
                epilogue: number(epilogue)?,
                end: number(end)?,
            }),
            ["call", name, entry, ret] => calls.push(Call {
                name: name.to_string(),
                cycles: number(ret)? - number(entry)?,
            }),
            _ => {}
        }
    }
    Ok((isrs, calls))
}

/// A mean and a maximum.
#[derive(Clone, Copy, Debug)]
pub struct Stats {
    pub count: usize,
    pub mean: f64,
    pub max: u64,
}

impl Stats {
    pub fn of(values: impl IntoIterator<Item = u64>) -> Stats {
        let (mut count, mut sum, mut max) = (0usize, 0u64, 0u64);
        for v in values {
            count += 1;
            sum += v;
            max = max.max(v);
        }
        Stats {
            count,
            mean: if count == 0 {
                0.0
            } else {
                sum as f64 / count as f64
            },
            max,
        }
    }
}
