//! Stack high-water mark: the free RAM below the stack is painted with a
//! pattern at start-up; the lowest overwritten word is the deepest the stack
//! went.

use core::ptr;

const PATTERN: u32 = 0x5AC5_5AC5;
/// Left unpainted below the stack pointer of `paint`'s caller, for `paint`'s
/// own frame.
const MARGIN: usize = 256;

unsafe extern "C" {
    /// Top of the stack (end of RAM), from cortex-m-rt's `link.x`.
    static _stack_start: u32;
    /// Lowest address the stack may use (end of `.bss` and `.uninit`).
    static _stack_end: u32;
}

fn top() -> usize {
    (&raw const _stack_start) as usize
}

fn bottom() -> usize {
    (&raw const _stack_end) as usize
}

/// Bytes between the end of static RAM and the top of RAM.
pub fn size() -> usize {
    top() - bottom()
}

/// Paints the unused stack; call first thing in `main`.
#[inline(never)]
pub fn paint() {
    let sp = cortex_m::register::msp::read() as usize;
    let mut address = bottom();
    while address + MARGIN < sp {
        // SAFETY: the words between the end of static RAM and the stack
        // pointer (less a margin for this function's frame) belong to no
        // live object; they are aligned, inside RAM, and written only here.
        unsafe { ptr::write_volatile(address as *mut u32, PATTERN) };
        address += 4;
    }
}

/// The deepest the stack has gone since [`paint`], in bytes.
pub fn peak() -> usize {
    let mut address = bottom();
    // SAFETY: as in `paint`: aligned words of RAM below the stack.
    while address < top() && unsafe { ptr::read_volatile(address as *const u32) } == PATTERN {
        address += 4;
    }
    top() - address
}
