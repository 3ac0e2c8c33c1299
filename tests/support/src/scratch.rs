//! Scratch user crates: a folder under the target's `tmp` holding a crate
//! that depends on this package by path, as a user's would, built by Cargo
//! on its own into one target directory that every such test shares (the
//! dependencies build once).

use std::fs;
use std::path::PathBuf;
use std::process::Command;

/// A user crate on disk.
pub struct ScratchCrate {
    /// Its folder.
    pub dir: PathBuf,
}

/// The target directory the scratch crates share.
pub fn target_dir() -> PathBuf {
    crate::paths::target_tmpdir().join("rebuild-target")
}

impl ScratchCrate {
    /// `<target>/tmp/name` with `files` (relative path, contents;
    /// `@ROOT@` stands for this package's folder), written only where they
    /// changed so that Cargo rebuilds nothing it need not; and, the first
    /// time, this workspace's `Cargo.lock`: the same, already downloaded,
    /// versions (Cargo prunes what the crate does not use).
    pub fn new(name: &str, files: &[(&str, &str)]) -> Self {
        let dir = crate::paths::target_tmpdir().join(name);
        let scratch = ScratchCrate { dir };
        for (path, contents) in files {
            scratch.write(
                path,
                &contents.replace("@ROOT@", &crate::paths::root().display().to_string()),
            );
        }
        let lock = scratch.dir.join("Cargo.lock");
        if !lock.exists() {
            fs::copy(crate::paths::root().join("Cargo.lock"), lock).unwrap();
        }
        scratch
    }

    /// Writes `contents` to `path` in the crate (creating folders) unless it
    /// holds them already.
    pub fn write(&self, path: &str, contents: &str) {
        let path = self.dir.join(path);
        if fs::read_to_string(&path).ok().as_deref() != Some(contents) {
            fs::create_dir_all(path.parent().unwrap()).unwrap();
            fs::write(&path, contents).unwrap();
        }
    }

    /// `cargo` in the crate, into the shared target directory, without the
    /// settings of the test run that would leak into the user's build.
    pub fn cargo(&self) -> Command {
        let mut command = Command::new(env!("CARGO"));
        command
            .current_dir(&self.dir)
            .env("CARGO_TARGET_DIR", target_dir());
        for var in [
            "CARGO_BUILD_TARGET_DIR",
            "RUSTC_WORKSPACE_WRAPPER",
            "RUSTFLAGS",
            "UPDATE_GOLDEN",
        ] {
            command.env_remove(var);
        }
        command
    }
}
