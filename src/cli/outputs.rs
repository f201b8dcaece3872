//! The one way every command writes its files: the outputs are named first ([`target`]: `-`
//! is standard output), checked together before the work starts ([`check`]: not an input,
//! not a folder, in a folder that exists, no two alike), staged as they are made ([`stage`],
//! [`stage_image`], or straight into the [`OutputSet`]) and written together by [`commit`]:
//! all of them or none, the one given as `-` on standard output once the files are written.

use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use foldcam::formats::{self, OutputSet};
use foldcam::pattern::{CreasePattern, FoldedState};

/// An output path as given: `-` becomes the name standing for standard output (`-.EXT` with
/// the extension `--to` names), anything else stays as it is.
pub fn target(path: &Path) -> Result<PathBuf> {
    super::pipe::output(path)
}

/// [`target`] of an optional output.
pub fn optional(path: Option<&PathBuf>) -> Result<Option<PathBuf>> {
    path.map(|p| target(p)).transpose()
}

/// Refuses `-` for an output that is several files or a folder (`what` says which).
pub fn no_stdout(path: &Path, what: &str) -> Result<()> {
    if super::pipe::is_stdio(path) || super::pipe::is_stdout(path) {
        bail!("-: {what} cannot go to standard output: name a file or folder instead");
    }
    Ok(())
}

/// Checks the outputs of a command before it starts its work (so a long run does not end on
/// a name that could never be written): none is one of `inputs` (it would be overwritten
/// before it is read again), each is a file in a folder that exists, and no two are the same
/// file (see [`formats::check_targets`]). At most one is standard output. [`commit`] checks
/// them again, with the file names only known once the work is done. Outputs not asked for
/// are `None`.
pub fn check<P: AsRef<Path>>(outputs: &[Option<P>], inputs: &[&Path]) -> Result<()> {
    let given: Vec<&Path> = outputs.iter().flatten().map(AsRef::as_ref).collect();
    check_all(&given, inputs)
}

/// [`check`] of the outputs given.
fn check_all(outputs: &[&Path], inputs: &[&Path]) -> Result<()> {
    let same = |a: &Path, b: &Path| match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    for out in outputs {
        if let Some(input) = inputs.iter().find(|i| same(out, i)) {
            bail!(
                "{}: the output would overwrite the input {}: choose another name",
                out.display(),
                input.display()
            );
        }
    }
    let piped = outputs.iter().filter(|p| super::pipe::is_stdout(p)).count();
    if piped > 1 {
        bail!("-: {piped} outputs are given as standard output: at most one can be");
    }
    formats::check_targets(
        outputs
            .iter()
            .copied()
            .filter(|p| !super::pipe::is_stdout(p)),
    )?;
    Ok(())
}

/// Adds a pattern file (format from its extension) to `outputs`, written by [`commit`].
pub fn stage(
    outputs: &mut OutputSet,
    path: &Path,
    cp: &CreasePattern,
    folded: Option<&FoldedState>,
) -> Result<()> {
    outputs.add(path, formats::encode(path, cp, folded)?);
    let drops_angles = formats::Format::from_path(path).is_some_and(|f| !f.keeps_fold_angles());
    if let Some(lost) = drops_angles
        .then(|| foldcam::check::fold_angles_lost(cp))
        .flatten()
    {
        errln!("foldcam: warning: {}: {lost}", path.display());
    }
    Ok(())
}

/// Refuses a file name whose extension is not `ext` for an output of that kind (`what`, e.g.
/// "the picture"), so PNG data never lands in `x.jpg`.
pub fn require_extension(path: &Path, ext: &str, what: &str) -> Result<()> {
    let matches = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case(ext));
    if !matches {
        bail!(
            "{}: {what} is written as .{ext}: name it with the .{ext} extension",
            path.display()
        );
    }
    Ok(())
}

/// Adds an image to `outputs`, refusing a file name whose extension is not `ext`.
pub fn stage_image(outputs: &mut OutputSet, path: &Path, bytes: Vec<u8>, ext: &str) -> Result<()> {
    let what = format!("this output is a {} image and", ext.to_ascii_uppercase());
    require_extension(path, ext, &what)?;
    outputs.add(path, bytes);
    Ok(())
}

/// Writes every staged output, or none of them when one fails; refuses an output that is one
/// of `inputs`. The output given as `-` goes to standard output after the files are written.
/// Names each file written.
pub fn commit(outputs: OutputSet, inputs: &[&Path]) -> Result<()> {
    let paths: Vec<PathBuf> = outputs.paths().map(Path::to_path_buf).collect();
    let refs: Vec<&Path> = paths.iter().map(PathBuf::as_path).collect();
    check_all(&refs, inputs)?;
    let mut outputs = outputs;
    let piped = paths
        .iter()
        .find(|p| super::pipe::is_stdout(p))
        .and_then(|p| outputs.take(p));
    outputs.commit()?;
    for path in paths.iter().filter(|p| !super::pipe::is_stdout(p)) {
        note!("foldcam: wrote {}", path.display());
    }
    if let Some(bytes) = piped {
        super::pipe::write_stdout(&bytes)?;
    }
    Ok(())
}

/// Writes one file (see [`commit`]).
pub fn write_one(path: &Path, bytes: Vec<u8>, inputs: &[&Path]) -> Result<()> {
    let mut outputs = OutputSet::new();
    outputs.add(path, bytes);
    commit(outputs, inputs)
}
