//! Files written all together or not at all.
//!
//! A command writes its files into a hidden folder inside the folder they
//! are for, then moves them into place once every one is written. If
//! anything fails, the folder is left as it was: no new file, the files a
//! command would have replaced unchanged, no folder it made for them.

use std::ffi::{OsStr, OsString};
use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// The files of one command, written aside until [`commit`](Self::commit).
pub struct Staging {
    /// The folder the files are for.
    dir: PathBuf,
    /// The hidden folder they are written into, inside `dir`.
    aside: PathBuf,
    /// The folders made for `dir`, the outermost first.
    made: Vec<PathBuf>,
    /// The files' names, in the order they were asked for.
    names: Vec<OsString>,
    committed: bool,
}

impl Staging {
    /// Prepares to write into `dir` (the current folder when empty), making
    /// it and its parents if missing.
    pub fn new(dir: &Path) -> Result<Self, String> {
        let mut made: Vec<PathBuf> = dir
            .ancestors()
            .take_while(|d| !d.as_os_str().is_empty() && !d.exists())
            .map(Path::to_path_buf)
            .collect();
        made.reverse();
        let aside = dir.join(format!(".stepper-profiles-{}.partial", std::process::id()));
        // Dropped on a failure below, it removes what it made.
        let staging = Staging {
            dir: dir.to_path_buf(),
            aside,
            made,
            names: Vec::new(),
            committed: false,
        };
        fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create the folder `{}`: {e}", dir.display()))?;
        // A folder a killed run left under the same name goes first.
        let _ = fs::remove_dir_all(&staging.aside);
        fs::create_dir(&staging.aside)
            .map_err(|e| format!("cannot write into `{}`: {e}", dir.display()))?;
        Ok(staging)
    }

    /// Where to write the file `name` for now.
    pub fn path(&mut self, name: impl AsRef<OsStr>) -> PathBuf {
        self.names.push(name.as_ref().to_os_string());
        self.aside.join(name.as_ref())
    }

    /// Writes `contents` as the file `name`.
    pub fn write(&mut self, name: impl AsRef<OsStr>, contents: &str) -> Result<(), String> {
        let path = self.path(&name);
        fs::write(&path, contents).map_err(|e| self.cannot_write(name.as_ref(), &e))
    }

    fn cannot_write(&self, name: &OsStr, e: &dyn std::fmt::Display) -> String {
        format!("cannot write `{}`: {e}", self.dir.join(name).display())
    }

    /// Moves every file into place and returns where each went. A file in
    /// the way is replaced; a folder in the way fails the whole, before any
    /// file is moved.
    pub fn commit(mut self) -> Result<Vec<PathBuf>, String> {
        for name in &self.names {
            if self.dir.join(name).is_dir() {
                return Err(self.cannot_write(name, &"it is a folder"));
            }
        }
        let old = self.aside.join(".old");
        fs::create_dir(&old)
            .map_err(|e| format!("cannot write into `{}`: {e}", self.dir.display()))?;
        // Each file moved: where it is, and where the one it replaced went.
        let mut moved: Vec<(PathBuf, Option<PathBuf>)> = Vec::new();
        for name in &self.names {
            let target = self.dir.join(name);
            if let Err(e) = place(&self.aside.join(name), &target, &old.join(name), &mut moved) {
                for (target, replaced) in moved.into_iter().rev() {
                    match replaced {
                        Some(replaced) => {
                            let _ = fs::rename(replaced, &target);
                        }
                        None => {
                            let _ = fs::remove_file(&target);
                        }
                    }
                }
                return Err(self.cannot_write(name, &e));
            }
        }
        self.committed = true;
        Ok(self.names.iter().map(|n| self.dir.join(n)).collect())
    }
}

/// Moves `staged` to `target`, the file there (if any) to `keep` first;
/// records the move.
fn place(
    staged: &Path,
    target: &Path,
    keep: &Path,
    moved: &mut Vec<(PathBuf, Option<PathBuf>)>,
) -> io::Result<()> {
    let replaced = if target.exists() {
        fs::rename(target, keep)?;
        Some(keep.to_path_buf())
    } else {
        None
    };
    if let Err(e) = fs::rename(staged, target) {
        if let Some(keep) = &replaced {
            let _ = fs::rename(keep, target);
        }
        return Err(e);
    }
    moved.push((target.to_path_buf(), replaced));
    Ok(())
}

impl Drop for Staging {
    fn drop(&mut self) {
        let _ = fs::remove_dir_all(&self.aside);
        if !self.committed {
            // Only folders left empty: `remove_dir` refuses any other.
            for dir in self.made.iter().rev() {
                let _ = fs::remove_dir(dir);
            }
        }
    }
}
