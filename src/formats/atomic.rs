//! Atomic file output: write a temporary file in the target's folder, then rename it over the
//! target, so readers see either the old file or the complete new one.
//!
//! A command with several outputs (a pattern, a picture, an animation) gathers them in an
//! [`OutputSet`] and commits them together, all of them or none:
//! 1. every target is checked first ([`check_targets`]): a file name, a folder that exists, not
//!    itself a folder, and no two outputs naming one file;
//! 2. every temporary is written and synced; a failure (a full disk, a folder without write
//!    permission) removes them all;
//! 3. the temporaries are renamed over their targets, each existing target first kept as a
//!    hard link (a copy where the file system has no links); if a rename fails, the renames
//!    before it are undone from those, so the targets end as they were.
//!
//! Temporaries and kept targets not yet renamed or removed are listed in a process-wide
//! registry; a signal handler calls [`remove_pending_temporaries`] so a run stopped by Ctrl-C
//! or SIGTERM leaves nothing behind. Limit: a run killed during step 3 (between two renames)
//! keeps the renames done so far.

use std::io::{Error, ErrorKind, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Temporaries written and targets kept, not yet renamed or removed, for
/// [`remove_pending_temporaries`].
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

/// The folder a target is written in (`.` for a bare file name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// A name beside `path`: `.NAME.PID.INDEX.SUFFIX` in the same folder (so a rename never
/// crosses file systems), numbered by the target's place in its set.
fn beside(path: &Path, index: usize, suffix: &str) -> std::io::Result<PathBuf> {
    let name = path
        .file_name()
        .ok_or_else(|| Error::new(ErrorKind::InvalidInput, "not a file path"))?;
    let mut tmp_name = std::ffi::OsString::from(".");
    tmp_name.push(name);
    tmp_name.push(format!(".{}.{index}.{suffix}", std::process::id()));
    Ok(folder_of(path).join(tmp_name))
}

/// The temporary name beside `path`.
fn temporary_for(path: &Path, index: usize) -> std::io::Result<PathBuf> {
    beside(path, index, "tmp")
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
        Err(e) if e.kind() == ErrorKind::AlreadyExists => {
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
    forget(tmp);
}

/// Forgets `tmp` (renamed, or to be kept).
fn forget(tmp: &Path) {
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

impl OutputError {
    fn new(path: &Path, kind: ErrorKind, message: String) -> OutputError {
        OutputError {
            path: path.to_path_buf(),
            source: Error::new(kind, message),
        }
    }
}

/// Which file `path` names, for telling two outputs apart: its folder resolved (links,
/// `.` and `..`) when the folder exists, joined with its file name.
fn identity(path: &Path) -> PathBuf {
    let folder = folder_of(path);
    match (folder.canonicalize(), path.file_name()) {
        (Ok(dir), Some(name)) => dir.join(name),
        _ => path.to_path_buf(),
    }
}

/// Checks the targets of one set of outputs before anything is written: each names a file
/// (not a folder, nor `..`), in a folder that exists, and no two name the same file. Whether
/// the folder lets us write is learnt when the temporaries are written, still before any
/// target changes.
///
/// # Errors
/// The first target that fails, and why.
pub fn check_targets<'a>(paths: impl IntoIterator<Item = &'a Path>) -> Result<(), OutputError> {
    let mut seen: Vec<(PathBuf, &Path)> = Vec::new();
    for path in paths {
        if path.file_name().is_none() {
            return Err(OutputError::new(
                path,
                ErrorKind::InvalidInput,
                "names a folder, not a file: give a file name".into(),
            ));
        }
        let folder = folder_of(path);
        match std::fs::metadata(folder) {
            Ok(m) if m.is_dir() => {}
            Ok(_) => {
                return Err(OutputError::new(
                    path,
                    ErrorKind::NotADirectory,
                    format!("{} is not a folder", folder.display()),
                ));
            }
            Err(e) => {
                return Err(OutputError::new(
                    path,
                    e.kind(),
                    format!("the folder {} cannot be used: {e}", folder.display()),
                ));
            }
        }
        if std::fs::metadata(path).is_ok_and(|m| m.is_dir()) {
            return Err(OutputError::new(
                path,
                ErrorKind::IsADirectory,
                "is a folder: give the name of a file to write".into(),
            ));
        }
        let id = identity(path);
        if let Some((_, first)) = seen.iter().find(|(other, _)| *other == id) {
            return Err(OutputError::new(
                path,
                ErrorKind::InvalidInput,
                format!(
                    "named for two outputs (also as {}): give each output its own file",
                    first.display()
                ),
            ));
        }
        seen.push((id, path));
    }
    Ok(())
}

/// Files written together: all of them, or none (see the module docs).
#[derive(Debug, Default)]
pub struct OutputSet {
    files: Vec<(PathBuf, Vec<u8>)>,
}

/// A target renamed over by [`OutputSet::commit`], and how to put it back.
struct Renamed<'a> {
    target: &'a Path,
    /// The old target kept under another name; `None` when there was none.
    kept: Option<PathBuf>,
}

impl OutputSet {
    /// An empty set.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a file to write. Two files for one path are refused by [`OutputSet::check`] and
    /// [`OutputSet::commit`].
    pub fn add(&mut self, path: impl Into<PathBuf>, bytes: impl Into<Vec<u8>>) {
        self.files.push((path.into(), bytes.into()));
    }

    /// The targets, in the order they were added.
    pub fn paths(&self) -> impl Iterator<Item = &Path> {
        self.files.iter().map(|(p, _)| p.as_path())
    }

    /// Removes the files staged for `path` and returns the bytes of the first, for a target
    /// written some other way (standard output); `None` if nothing was staged for it.
    pub fn take(&mut self, path: &Path) -> Option<Vec<u8>> {
        let i = self.files.iter().position(|(p, _)| p == path)?;
        Some(self.files.remove(i).1)
    }

    /// Whether nothing was added.
    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// Checks every target ([`check_targets`]) without writing anything.
    ///
    /// # Errors
    /// The first target that cannot be written, and why.
    pub fn check(&self) -> Result<(), OutputError> {
        check_targets(self.paths())
    }

    /// Checks the targets, writes every file to its temporary, then renames them all over
    /// their targets (see the module docs). On any error every target is as it was and no
    /// temporary is left; the error names the file.
    pub fn commit(self) -> Result<(), OutputError> {
        self.check()?;
        let mut written: Vec<(PathBuf, &Path)> = Vec::with_capacity(self.files.len());
        for (index, (path, bytes)) in self.files.iter().enumerate() {
            let staged = temporary_for(path, index).and_then(|tmp| {
                let result = write_temporary(&tmp, bytes);
                if result.is_err() {
                    discard(&tmp);
                }
                result.map(|()| tmp)
            });
            match staged {
                Ok(tmp) => written.push((tmp, path)),
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
        rename_all(&written)
    }
}

/// Renames every temporary over its target (`written`: temporary, target), keeping each old
/// target until all are renamed; on a failure, removes the temporaries left and puts back the
/// targets already renamed over.
fn rename_all(written: &[(PathBuf, &Path)]) -> Result<(), OutputError> {
    let mut renamed: Vec<Renamed<'_>> = Vec::with_capacity(written.len());
    for (index, (tmp, target)) in written.iter().enumerate() {
        let step = keep_old(target, index).and_then(|kept| match std::fs::rename(tmp, target) {
            Ok(()) => Ok(kept),
            Err(e) => {
                if let Some(k) = &kept {
                    discard(k);
                }
                Err(e)
            }
        });
        match step {
            Ok(kept) => {
                forget(tmp);
                renamed.push(Renamed { target, kept });
            }
            Err(source) => {
                for (rest, _) in &written[index..] {
                    discard(rest);
                }
                undo(&renamed);
                return Err(OutputError {
                    path: target.to_path_buf(),
                    source,
                });
            }
        }
    }
    for r in &renamed {
        if let Some(k) = &r.kept {
            discard(k);
        }
    }
    Ok(())
}

/// Keeps the file at `target`, when there is one, under a name beside it (a hard link, else
/// a copy), registered as pending; `None` when there is no file to keep.
fn keep_old(target: &Path, index: usize) -> std::io::Result<Option<PathBuf>> {
    match std::fs::symlink_metadata(target) {
        Err(e) if e.kind() == ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(e),
        Ok(_) => {}
    }
    let kept = beside(target, index, "old")?;
    let _ = std::fs::remove_file(&kept);
    pending().push(kept.clone());
    let linked =
        std::fs::hard_link(target, &kept).or_else(|_| std::fs::copy(target, &kept).map(|_| ()));
    match linked {
        Ok(()) => Ok(Some(kept)),
        Err(e) => {
            discard(&kept);
            Err(e)
        }
    }
}

/// Puts back every target of `renamed`, last first: the kept file renamed over it, or the new
/// file removed where there was none.
fn undo(renamed: &[Renamed<'_>]) {
    for r in renamed.iter().rev() {
        match &r.kept {
            Some(kept) => {
                if std::fs::rename(kept, r.target).is_ok() {
                    forget(kept);
                }
            }
            None => {
                let _ = std::fs::remove_file(r.target);
            }
        }
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

    /// A set of `files` (name in `dir`, contents).
    fn set_of(dir: &Path, files: &[(&str, &str)]) -> OutputSet {
        let mut set = OutputSet::new();
        for (name, bytes) in files {
            set.add(dir.join(name), bytes.as_bytes().to_vec());
        }
        set
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
        let set = set_of(dir.path(), &[("a.fold", "NEW"), ("no/such/b.png", "PNG")]);
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
        std::fs::write(dir.path().join("b.png"), "OLD").unwrap();
        let set = set_of(dir.path(), &[("a.fold", "A"), ("b.png", "B")]);
        assert_eq!(set.paths().count(), 2);
        set.commit().unwrap();
        assert_eq!(listing(dir.path()), vec!["a.fold", "b.png"]);
        assert_eq!(std::fs::read(dir.path().join("b.png")).unwrap(), b"B");
        assert!(pending().iter().all(|p| !p.starts_with(dir.path())));
    }

    #[test]
    fn two_outputs_naming_one_file_are_refused_before_anything_is_written() {
        let _turn = take_turn();
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("a.fold"), "OLD").unwrap();
        let set = set_of(
            dir.path(),
            &[("a.fold", "A"), ("x/../b.png", "B"), ("./a.fold", "PNG")],
        );
        std::fs::create_dir(dir.path().join("x")).unwrap();
        let err = set.commit().unwrap_err();
        assert!(err.to_string().contains("two outputs"), "{err}");
        assert_eq!(
            std::fs::read_to_string(dir.path().join("a.fold")).unwrap(),
            "OLD"
        );
        assert_eq!(listing(dir.path()), vec!["a.fold", "x"]);
    }

    #[test]
    fn a_folder_among_the_targets_is_refused_before_anything_is_written() {
        let _turn = take_turn();
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("keep.fold"), "OLD").unwrap();
        std::fs::create_dir(dir.path().join("d.png")).unwrap();
        let set = set_of(dir.path(), &[("keep.fold", "NEW"), ("d.png", "PNG")]);
        let err = set.commit().unwrap_err();
        assert!(err.path.ends_with("d.png"), "{err}");
        assert!(err.to_string().contains("is a folder"), "{err}");
        assert_eq!(
            std::fs::read_to_string(dir.path().join("keep.fold")).unwrap(),
            "OLD"
        );
        assert_eq!(listing(dir.path()), vec!["d.png", "keep.fold"]);
        for bad in [dir.path().join(".."), dir.path().join("keep.fold/x.png")] {
            assert!(check_targets([bad.as_path()]).is_err(), "{}", bad.display());
        }
    }

    #[test]
    fn a_rename_that_fails_puts_back_the_targets_renamed_before_it() {
        let _turn = take_turn();
        let dir = tempfile::tempdir().unwrap();
        let (kept, fresh, folder) = (
            dir.path().join("keep.fold"),
            dir.path().join("new.svg"),
            dir.path().join("d.png"),
        );
        std::fs::write(&kept, "OLD").unwrap();
        // The folder appears after the check (as when another program makes it meanwhile).
        std::fs::create_dir(&folder).unwrap();
        std::fs::write(folder.join("inside"), "x").unwrap();
        let mut written = Vec::new();
        for (i, (target, bytes)) in [(&kept, "NEW"), (&fresh, "SVG"), (&folder, "PNG")]
            .into_iter()
            .enumerate()
        {
            let tmp = temporary_for(target, i).unwrap();
            write_temporary(&tmp, bytes.as_bytes()).unwrap();
            written.push((tmp, target.as_path()));
        }
        let err = rename_all(&written).unwrap_err();
        assert!(err.path.ends_with("d.png"), "{err}");
        assert_eq!(std::fs::read_to_string(&kept).unwrap(), "OLD");
        assert!(!fresh.exists());
        assert_eq!(listing(dir.path()), vec!["d.png", "keep.fold"]);
        assert!(pending().iter().all(|p| !p.starts_with(dir.path())));
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
