//! A C program compiled with the system C compiler (`cc`, or `$CC`), once per
//! test process, and run.
//!
//! A missing C compiler is a failure, not a skip: CI has one, and a silently
//! skipped compatibility test promises nothing.

use std::ffi::OsStr;
use std::fmt::Display;
use std::fs;
use std::path::PathBuf;
use std::process::Command;
use std::sync::OnceLock;

/// A C program: its source, how to compile it, and what it is, for messages.
pub struct CProgram {
    /// The folder under the target's `tmp` it is built in.
    pub dir: &'static str,
    /// The executable's name (the source is `{name}-{pid}.c` while it builds).
    pub name: &'static str,
    /// The C source.
    pub source: &'static str,
    /// Compiler flags, before `-o executable source`.
    pub flags: &'static [&'static str],
    /// Libraries, after the source.
    pub libs: &'static [&'static str],
    /// What a failed compilation names: "seed 000's C function".
    pub what: &'static str,
    /// What a missing compiler names, as "this test compiles {}".
    pub what_in_full: &'static str,
    /// The executable, once compiled: `OnceLock::new()`.
    pub executable: OnceLock<PathBuf>,
}

impl CProgram {
    /// Runs the program with `args` for `call`, compiling it first if this
    /// test process has not yet, and returns what it printed.
    #[track_caller]
    pub fn run<I, S>(&self, args: I, call: &dyn Display) -> String
    where
        I: IntoIterator<Item = S>,
        S: AsRef<OsStr>,
    {
        let program = self.executable.get_or_init(|| self.compile());
        let output = Command::new(program)
            .args(args)
            .output()
            .unwrap_or_else(|e| panic!("cannot run {}: {e}", program.display()));
        assert!(
            output.status.success(),
            "expected the C program to succeed for {call}, got {}:\n{}",
            output.status,
            String::from_utf8_lossy(&output.stderr)
        );
        String::from_utf8(output.stdout).expect("the C program prints ASCII")
    }

    /// Writes and compiles the program, and returns the executable.
    fn compile(&self) -> PathBuf {
        let dir = crate::paths::target_tmpdir().join(self.dir);
        fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("cannot create {}: {e}", dir.display()));
        // Build under per-process names, then rename into place, so that
        // concurrent test runs never execute a half-written file.
        let pid = std::process::id();
        let source = dir.join(format!("{}-{pid}.c", self.name));
        let built = dir.join(format!("{}-{pid}", self.name));
        fs::write(&source, self.source)
            .unwrap_or_else(|e| panic!("cannot write {}: {e}", source.display()));
        let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_owned());
        let output = Command::new(&cc)
            .args(self.flags)
            .arg("-o")
            .arg(&built)
            .arg(&source)
            .args(self.libs)
            .output()
            .unwrap_or_else(|e| {
                panic!(
                    "cannot run the C compiler `{cc}` ({e}): this test compiles {} to check bit \
                     compatibility and needs a C compiler such as gcc (set CC to use another \
                     one); it fails rather than skips",
                    self.what_in_full
                )
            });
        assert!(
            output.status.success(),
            "expected `{cc}` to compile {}, got {}:\n{}",
            self.what,
            output.status,
            String::from_utf8_lossy(&output.stderr)
        );
        let program = dir.join(self.name);
        fs::rename(&built, &program)
            .unwrap_or_else(|e| panic!("cannot move {} into place: {e}", built.display()));
        let _ = fs::remove_file(&source);
        program
    }
}
