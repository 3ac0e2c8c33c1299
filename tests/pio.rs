//! The RP2040 PIO example's program (`examples/hal/rp2040/src/pio_step.rs`)
//! run on the host, instruction by instruction, by an interpreter of the
//! RP2040 datasheet's encodings written here (section 3.4: JMP with its
//! `X--` and `Y--` conditions, OUT to X with autopull, a side-set bit and
//! delay cycles): the step pin's rising edges for the words of a move as
//! `Player::fill` hands them to DMA must be the table's periods (computed
//! without the offset) to the cycle, the pulse `PULSE` cycles, the shortest
//! period `OVERHEAD`, and Y the steps.

#[path = "../examples/hal/rp2040/src/pio_step.rs"]
#[allow(dead_code)]
mod pio_step;

use pio_step::{DIVIDER, OVERHEAD, PIO_HZ, PROGRAM, PULSE, RAMP, SYS_HZ, WRAP_SOURCE, WRAP_TARGET};
use stepper_profiles::period_table;
use stepper_profiles::player::{Player, Ramp};

/// One state machine: its registers, the pin it side-sets, its TX FIFO.
struct Machine<'a> {
    pc: u8,
    x: u32,
    y: u32,
    pin: bool,
    cycle: u64,
    fifo: std::slice::Iter<'a, u32>,
}

/// What a run saw: the cycle of every rising and falling edge.
#[derive(Default)]
struct Edges {
    rising: Vec<u64>,
    falling: Vec<u64>,
}

impl Machine<'_> {
    /// Runs until `out` finds the FIFO empty (the program stalls there).
    fn run(&mut self, program: &[u16]) -> Edges {
        let mut edges = Edges::default();
        loop {
            let word = program[usize::from(self.pc)];
            // One side-set bit, not optional: bit 12; the delay bits 11..8.
            let side = word >> 12 & 1 == 1;
            let delay = u64::from(word >> 8 & 0xF);
            let mut next = if self.pc == WRAP_SOURCE {
                WRAP_TARGET
            } else {
                self.pc + 1
            };
            match word >> 13 {
                // OUT: destination bits 7..5 (X is 1), count bits 4..0 (0 is
                // 32); autopull refills the empty OSR from the FIFO, or the
                // instruction stalls.
                0b011 => {
                    assert_eq!((word >> 5 & 7, word & 0x1F), (1, 0), "only `out x, 32`");
                    match self.fifo.next() {
                        Some(&w) => self.x = w,
                        None => return edges,
                    }
                }
                // JMP: condition bits 7..5 (X-- is 2, Y-- is 4), address
                // bits 4..0: jumps when the register was not 0, and
                // decrements it either way.
                0b000 => {
                    let register = match word >> 5 & 7 {
                        2 => &mut self.x,
                        4 => &mut self.y,
                        c => panic!("condition {c} not in the program"),
                    };
                    if *register != 0 {
                        next = (word & 0x1F) as u8;
                    }
                    *register = register.wrapping_sub(1);
                }
                op => panic!("opcode {op:03b} not in the program"),
            }
            // The side-set takes effect with the instruction's first cycle.
            if side != self.pin {
                match side {
                    true => edges.rising.push(self.cycle),
                    false => edges.falling.push(self.cycle),
                }
                self.pin = side;
            }
            self.cycle += 1 + delay;
            self.pc = next;
        }
    }
}

/// The words of a move of `steps` from `table`, as `Player::fill` hands
/// them to DMA, 64 at a time.
fn words(table: &[u32], steps: u32) -> Vec<u32> {
    let mut player = Player::new(Ramp::steps(table));
    player.start(steps);
    let mut out = Vec::new();
    let mut buffer = [0u32; 64];
    loop {
        let n = player.fill(&mut buffer);
        out.extend_from_slice(&buffer[..n]);
        if n < buffer.len() {
            return out;
        }
    }
}

fn machine(words: &[u32]) -> Machine<'_> {
    Machine {
        pc: 0,
        x: 0,
        y: 0,
        pin: false,
        cycle: 0,
        fifo: words.iter(),
    }
}

/// The same ramp without the offset: the periods themselves.
static PERIODS: [u32; 400] = period_table!(
    curve = sigmoid,
    len = 400,
    fmin = 500,
    fmax = 20kHz,
    flexible = 8,
    timer_hz = 5MHz,
    word = u32,
);

#[test]
fn every_step_is_its_period_to_the_cycle() {
    assert_eq!((SYS_HZ / u32::from(DIVIDER), OVERHEAD), (PIO_HZ, 12));
    // The move the example plays: 400 steps up, 1200 at the top, 400 down.
    let steps = 2000;
    let words = words(&RAMP, steps);
    assert_eq!(words.len(), steps as usize);
    let mut sm = machine(&words);
    let edges = sm.run(&PROGRAM);
    // Each rising edge a step, each step's period (to the next edge) the
    // table's: up, at the top, down; the last one played out after the last
    // edge.
    assert_eq!(edges.rising.len(), steps as usize);
    let top = PERIODS[399];
    let want: Vec<u64> = PERIODS
        .iter()
        .chain(std::iter::repeat_n(&top, 1200))
        .chain(PERIODS.iter().rev())
        .map(|&p| u64::from(p))
        .collect();
    let got: Vec<u64> = edges.rising.windows(2).map(|w| w[1] - w[0]).collect();
    let first_off = got.iter().zip(&want).position(|(g, w)| g != w);
    assert_eq!(
        first_off,
        None,
        "the first step off: {:?}",
        first_off.map(|k| (got[k], want[k]))
    );
    assert_eq!(got.len(), want.len() - 1);
    assert_eq!(
        sm.cycle - edges.rising[steps as usize - 1],
        want[want.len() - 1] - 1
    );
    // High for PULSE cycles each step, and Y decremented once a step.
    assert!(
        edges
            .rising
            .iter()
            .zip(&edges.falling)
            .all(|(r, f)| f - r == u64::from(PULSE))
    );
    assert_eq!(0u32.wrapping_sub(sm.y), steps);
    // The first step one `out` after the first word.
    assert_eq!(edges.rising[0], 1);
}

#[test]
fn the_shortest_period_is_the_overhead() {
    let words = [0, 0, 0, 5];
    let edges = machine(&words).run(&PROGRAM);
    let periods: Vec<u64> = edges.rising.windows(2).map(|w| w[1] - w[0]).collect();
    assert_eq!(periods, [12, 12, 12]);
    // The last word's period is played out before the program stalls at
    // `out`: the four steps take 3 x 12 + 17 cycles.
    let mut sm = machine(&words);
    sm.run(&PROGRAM);
    assert_eq!(sm.cycle, 3 * 12 + 17);
}
