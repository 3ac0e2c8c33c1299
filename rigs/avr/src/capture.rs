//! simavr's trace of the step pin read as a user reads a logic analyzer's
//! capture: `profile_codegen::capture` (what `stepper-profiles compare`
//! runs) against the move's exact edges, and again on a client whose table
//! has one entry a tick longer, where it must name that step.

use profile_codegen::capture::{Capture, Comparison, Edges, Reference};

/// The compare-output pin toggles once a step.
const CHANNEL: &str = "OC1A";

/// The capture `vcd` against `reference`, half a tick allowed.
pub fn compare(reference: &Reference, vcd: &str) -> Result<Comparison, String> {
    Capture::parse(vcd)
        .and_then(|c| c.compare(reference, Some(CHANNEL), Edges::Both, 0.5))
        .map_err(|e| format!("the trace as a capture: {e}"))
}

/// The first move of the trace, every step within half a tick of the
/// reference (simavr stamps in 10 ns: a sixth of a tick at 16 MHz).
pub fn whole(reference: &Reference, vcd: &str) -> Result<bool, String> {
    let c = compare(reference, vcd)?;
    println!(
        "  as a capture (`stepper-profiles compare`): {}",
        c.summary()
    );
    if !c.passes() {
        println!("  FAIL: the trace is not the move within half a tick");
    }
    Ok(c.passes())
}

/// `header` with entry `k` of the array `name` one more.
pub fn edit_entry(header: &str, name: &str, k: usize) -> Result<String, String> {
    let start = header
        .find(&format!("{name}["))
        .and_then(|i| header[i..].find('{').map(|j| i + j + 1))
        .ok_or_else(|| format!("the header has no array {name}"))?;
    let end = start
        + header[start..]
            .find('}')
            .ok_or("an array without its end")?;
    let mut entries: Vec<u64> = header[start..end]
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.parse().map_err(|_| format!("`{s}` in {name}")))
        .collect::<Result<_, _>>()?;
    *entries.get_mut(k).ok_or("no such entry")? += 1;
    let body: Vec<String> = entries.iter().map(u64::to_string).collect();
    Ok(format!(
        "{}\n    {},\n{}",
        &header[..start],
        body.join(", "),
        &header[end..]
    ))
}

/// The edited client's trace: the comparison must name step `k` first.
pub fn edited(reference: &Reference, vcd: &str, k: usize) -> Result<bool, String> {
    let c = compare(reference, vcd)?;
    let found = c.first_out() == Some(k);
    println!(
        "  entry {k} a tick longer in the client's table, as a capture: {}{}",
        c.summary(),
        if found { "" } else { "  FAIL: not that step" }
    );
    Ok(found)
}
