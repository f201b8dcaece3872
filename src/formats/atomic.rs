//! Atomic file output: write a temporary file in the target's folder, then rename it over the
//! target, so readers see either the old file or the complete new one.
//!
//! A command with several outputs (a pattern, a picture, an animation) gathers them in an
//! [`OutputSet`] and commits them together: every temporary is written first, and only when
//! all of them succeeded are they renamed over their targets, so a failure (a missing folder,
//! a full disk) leaves every existing file as it was. Temporaries not yet renamed are listed
//! in a process-wide registry; a signal handler calls [`remove_pending_temporaries`] so a run
//! stopped by Ctrl-C or SIGTERM leaves nothing behind.
//!
//! Limit: the renames themselves run one after another; if one of them fails (a target that
//! became a folder meanwhile), the outputs renamed before it stay renamed.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Temporaries written but not yet renamed or removed, for [`remove_pending_temporaries`].
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    PENDING
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Removes every temporary file written by this process and not yet renamed. Safe to call
/// from a signal handler's thread (such as the one `ctrlc` runs); later commits still work.
pub fn remove_pending_temporaries() {
    for tmp in pending().drain(..) {
        let _ = std::fs::remove_file(tmp);
    }
}

/// The temporary name beside `path`: `.NAME.PID.tmp` in the same folder (so the rename never
/// crosses file systems), numbered when one commit writes the same folder more than once.
fn temporary_for(path: &Path, index: usize) -> std::io::Result<PathBuf> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = path
        .file_name()
        .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a file path"))?;
    let mut tmp_name = std::ffi::OsString::from(".");
    tmp_name.push(name);
    tmp_name.push(format!(".{}.{index}.tmp", std::process::id()));
    Ok(dir.join(tmp_name))
}

/// Writes and syncs `bytes` to the new file `tmp`, registered as pending from its creation.
fn write_temporary(tmp: &Path, bytes: &[u8]) -> std::io::Result<()> {
    // `create_new` never follows a link planted at the temporary name; a stale file left by a
    // crashed run with the same process id is removed once.
    let open = || {
        std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(tmp)
    };
    let mut f = match open() {
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
            std::fs::remove_file(tmp)?;
            open()?
        }
        other => other?,
    };
    pending().push(tmp.to_path_buf());
    f.write_all(bytes)?;
    f.sync_all()
}

/// Removes `tmp` and forgets it.
fn discard(tmp: &Path) {
    let _ = std::fs::remove_file(tmp);
    pending().retain(|p| p != tmp);
}

/// Writes `bytes` to `path` atomically. On error the target is untouched and the temporary
/// file is removed.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut set = OutputSet::new();
    set.add(path, bytes.to_vec());
    set.commit().map_err(|e| e.source)
}

/// An output that could not be written: which file, and why.
#[derive(Debug, thiserror::Error)]
#[error("{}: {source}", path.display())]
pub struct OutputError {
    /// The target file.
    pub path: PathBuf,
    /// The cause.
    #[source]
    pub source: std::io::Error,
}

/// Files written together: all of them, or (on any failure before the renames) none.
#[derive(Debug, Default)]
pub struct OutputSet {
    files: Vec<(PathBuf, Vec<u8>)>,
}

impl OutputSet {
    /// An empty set.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a file to write; a later `add` of the same path replaces the earlier bytes.
    pub fn add(&mut self, path: impl Into<PathBuf>, bytes: impl Into<Vec<u8>>) {
        let path = path.into();
        let bytes = bytes.into();
        match self.files.iter_mut().find(|(p, _)| *p == path) {
            Some(slot) => slot.1 = bytes,
            None => self.files.push((path, bytes)),
        }
    }

    /// The targets, in the order they were added.
    pub fn paths(&self) -> impl Iterator<Item = &Path> {
        self.files.iter().map(|(p, _)| p.as_path())
    }

    /// Removes the file staged for `path` and returns its bytes, for a target written some
    /// other way (standard output); `None` if nothing was staged for it.
    pub fn take(&mut self, path: &Path) -> Option<Vec<u8>> {
        let i = self.files.iter().position(|(p, _)| p == path)?;
        Some(self.files.remove(i).1)
    }

    /// Whether nothing was added.
    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// Writes every file to its temporary, then renames them all over their targets. An error
    /// while writing removes every temporary and leaves all targets untouched; the error names
    /// the file.
    pub fn commit(self) -> Result<(), OutputError> {
        let mut written: Vec<(PathBuf, PathBuf)> = Vec::with_capacity(self.files.len());
        for (index, (path, bytes)) in self.files.iter().enumerate() {
            let staged = temporary_for(path, index).and_then(|tmp| {
                let result = write_temporary(&tmp, bytes);
                if result.is_err() {
                    discard(&tmp);
                }
                result.map(|()| tmp)
            });
            match staged {
                Ok(tmp) => written.push((tmp, path.clone())),
                Err(source) => {
                    for (tmp, _) in &written {
                        discard(tmp);
                    }
                    return Err(OutputError {
                        path: path.clone(),
                        source,
                    });
                }
            }
        }
        let mut renames = written.iter();
        for (tmp, path) in renames.by_ref() {
            if let Err(source) = std::fs::rename(tmp, path) {
                discard(tmp);
                for (rest, _) in renames {
                    discard(rest);
                }
                return Err(OutputError {
                    path: path.clone(),
                    source,
                });
            }
            pending().retain(|p| p != tmp);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `remove_pending_temporaries` removes every pending temporary of the process, so the
    /// tests that stage files take turns (the test harness runs them on parallel threads; a
    /// removal during another test's commit made that commit fail).
    static STAGING: std::sync::Mutex<()> = std::sync::Mutex::new(());

    fn take_turn() -> std::sync::MutexGuard<'static, ()> {
        STAGING.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn listing(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn a_set_with_one_bad_target_writes_nothing() {
        let _turn = take_turn();
        let dir = tempfile::tempdir().unwrap();
        let good = dir.path().join("a.fold");
        std::fs::write(&good, "OLD").unwrap();
        let mut set = OutputSet::new();
        set.add(&good, b"NEW".to_vec());
        set.add(dir.path().join("no/such/b.png"), b"PNG".to_vec());
        let err = set.commit().unwrap_err();
        assert!(err.path.ends_with("no/such/b.png"), "{err}");
        assert_eq!(std::fs::read_to_string(&good).unwrap(), "OLD");
        assert_eq!(listing(dir.path()), vec!["a.fold"]);
        assert!(pending().iter().all(|p| !p.starts_with(dir.path())));
    }

    #[test]
    fn a_set_writes_every_file_and_leaves_no_temporary() {
        let _turn = take_turn();
        let dir = tempfile::tempdir().unwrap();
        let mut set = OutputSet::new();
        set.add(dir.path().join("a.fold"), b"A".to_vec());
        set.add(dir.path().join("b.png"), b"first".to_vec());
        set.add(dir.path().join("b.png"), b"B".to_vec());
        assert_eq!(set.paths().count(), 2);
        set.commit().unwrap();
        assert_eq!(listing(dir.path()), vec!["a.fold", "b.png"]);
        assert_eq!(std::fs::read(dir.path().join("b.png")).unwrap(), b"B");
    }

    #[test]
    fn pending_temporaries_are_removed_on_request() {
        let _turn = take_turn();
        let dir = tempfile::tempdir().unwrap();
        let tmp = temporary_for(&dir.path().join("x.fold"), 0).unwrap();
        write_temporary(&tmp, b"partial").unwrap();
        assert!(tmp.exists());
        remove_pending_temporaries();
        assert!(!tmp.exists());
        assert_eq!(listing(dir.path()), Vec::<String>::new());
    }
}
