//! The tools the check runs: gcc for the harness, avr-gcc for the client,
//! and the harness (simavr) with a time limit.

use std::fs::{self, File};
use std::path::Path;
use std::process::{Command, Stdio};
use std::thread;
use std::time::{Duration, Instant};

/// Runs `command` in `dir`, failing on an error exit or a missing program,
/// with what it printed; returns its standard output.
pub fn run(command: &mut Command, dir: &Path, what: &str) -> Result<String, String> {
    let output = command
        .current_dir(dir)
        .output()
        .map_err(|e| missing(command, what, e))?;
    let stderr = String::from_utf8_lossy(&output.stderr);
    if !output.status.success() {
        return Err(format!("{what} failed ({}):\n{stderr}", output.status));
    }
    Ok(String::from_utf8_lossy(&output.stdout).into_owned())
}

/// Runs `command` in `dir` for at most `limit`, killing it then; returns
/// its standard output (written to `dir/out`, which a pipe could not hold
/// unread).
pub fn run_for(
    command: &mut Command,
    dir: &Path,
    out: &str,
    limit: Duration,
    what: &str,
) -> Result<String, String> {
    let file = File::create(dir.join(out)).map_err(|e| e.to_string())?;
    let mut child = command
        .current_dir(dir)
        .stdout(file)
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| missing(command, what, e))?;
    let started = Instant::now();
    loop {
        if child.try_wait().map_err(|e| e.to_string())?.is_some() {
            break;
        }
        if started.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("{what} ran over {limit:?} and was stopped"));
        }
        thread::sleep(Duration::from_millis(20));
    }
    let output = child.wait_with_output().map_err(|e| e.to_string())?;
    if !output.status.success() {
        return Err(format!(
            "{what} failed ({}):\n{}",
            output.status,
            String::from_utf8_lossy(&output.stderr)
        ));
    }
    fs::read_to_string(dir.join(out)).map_err(|e| e.to_string())
}

fn missing(command: &Command, what: &str, e: std::io::Error) -> String {
    format!(
        "cannot run `{}` for {what} ({e}): install gcc, gcc-avr, avr-libc, simavr and \
         libsimavr-dev (apt-get install -y gcc gcc-avr avr-libc simavr libsimavr-dev)",
        command.get_program().to_string_lossy()
    )
}
