//! Finding, reading and parsing profiles: shipped names or files on disk.
//!
//! A name without a path separator and without a `.toml` ending is looked up among the
//! shipped profiles (embedded in the binary); anything else is a file path. Files larger than
//! 1 MiB are refused (a profile is a few kilobytes). The profile's name is the file stem.

use std::io::Read;
use std::path::Path;

use toml::Table;

use super::locate::line_of;
use super::read_machine::machine_from_table;
use super::read_material::material_from_table;
use super::{MachineProfile, Material, ProfileError, shipped};

/// Largest profile file read, bytes.
const MAX_FILE_BYTES: u64 = 1 << 20;

/// The machine `name_or_path`: a shipped name (see [`shipped_machines`]) or a `.toml` file.
///
/// # Errors
/// An unknown name (the error lists the shipped names), an unreadable file, or any problem
/// [`parse_machine`] reports.
pub fn load_machine(name_or_path: &str) -> Result<MachineProfile, ProfileError> {
    let (text, source) = find(name_or_path, &shipped::MACHINES, "machines/", "machine")?;
    parse_machine(&text, &source)
}

/// The material `name_or_path`: a shipped name (see [`shipped_materials`]) or a `.toml` file.
///
/// # Errors
/// As [`load_machine`], with [`parse_material`].
pub fn load_material(name_or_path: &str) -> Result<Material, ProfileError> {
    let (text, source) = find(
        name_or_path,
        &shipped::MATERIALS,
        "machines/materials/",
        "material",
    )?;
    parse_material(&text, &source)
}

/// Names of the shipped machines, sorted.
pub fn shipped_machines() -> Vec<&'static str> {
    shipped::MACHINES.iter().map(|(name, _)| *name).collect()
}

/// Names of the shipped materials, sorted.
pub fn shipped_materials() -> Vec<&'static str> {
    shipped::MATERIALS.iter().map(|(name, _)| *name).collect()
}

/// Parses and validates a machine profile; `source_name` (a path or `shipped:…`) names it in
/// errors and gives the profile its name (its file stem).
///
/// # Errors
/// A [`ProfileError`] naming `source_name`, the dotted key and the value: TOML syntax (key
/// `file`, with line and column), a missing or unknown key, a wrong type, a number out of range
/// or not finite, an unknown name among fixed choices, inconsistent settings.
pub fn parse_machine(text: &str, source_name: &str) -> Result<MachineProfile, ProfileError> {
    let table = parse_toml(text, source_name)?;
    machine_from_table(&stem(source_name), source_name, &table).map_err(|e| with_line(e, text))
}

/// Parses and validates a material profile; see [`parse_machine`].
///
/// # Errors
/// As [`parse_machine`].
pub fn parse_material(text: &str, source_name: &str) -> Result<Material, ProfileError> {
    let table = parse_toml(text, source_name)?;
    material_from_table(&stem(source_name), source_name, &table).map_err(|e| with_line(e, text))
}

/// `e` with the line of its key in `text` appended, when the key is written there.
fn with_line(mut e: ProfileError, text: &str) -> ProfileError {
    if let Some(line) = line_of(text, &e.key) {
        e.message = format!("{} (line {line})", e.message);
    }
    e
}

/// Text and source name of a shipped profile or a file.
fn find(
    name_or_path: &str,
    shipped: &[(&str, &'static str)],
    folder: &str,
    what: &str,
) -> Result<(String, String), ProfileError> {
    if is_path(name_or_path) {
        return read_file(name_or_path).map(|text| (text, name_or_path.to_string()));
    }
    match shipped.iter().find(|(name, _)| *name == name_or_path) {
        Some((name, text)) => Ok((text.to_string(), format!("shipped:{folder}{name}.toml"))),
        None => Err(unknown_name(name_or_path, shipped, what)),
    }
}

/// True when `s` names a file rather than a shipped profile.
fn is_path(s: &str) -> bool {
    s.contains('/') || s.contains('\\') || s.ends_with(".toml")
}

fn unknown_name(name: &str, shipped: &[(&str, &str)], what: &str) -> ProfileError {
    let names: Vec<&str> = shipped.iter().map(|(n, _)| *n).collect();
    ProfileError {
        source_name: name.to_string(),
        key: "name".to_string(),
        message: format!(
            "no shipped {what} of this name; shipped: {} (or give a path to a .toml file)",
            names.join(", ")
        ),
    }
}

fn read_file(path: &str) -> Result<String, ProfileError> {
    let error = |message: String| ProfileError {
        source_name: path.to_string(),
        key: "file".to_string(),
        message,
    };
    let file = std::fs::File::open(path).map_err(|e| error(format!("cannot open: {e}")))?;
    let mut bytes = Vec::new();
    file.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| error(format!("cannot read: {e}")))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(error(format!(
            "larger than {MAX_FILE_BYTES} bytes; not a profile"
        )));
    }
    String::from_utf8(bytes).map_err(|e| error(format!("not UTF-8 text: {e}")))
}

fn parse_toml(text: &str, source_name: &str) -> Result<Table, ProfileError> {
    text.parse::<Table>().map_err(|e| {
        let at = e
            .span()
            .map(|s| line_column(text, s.start))
            .unwrap_or_default();
        ProfileError {
            source_name: source_name.to_string(),
            key: "file".to_string(),
            message: format!("not valid TOML{at}: {}", e.message().trim()),
        }
    })
}

/// " at line L, column C" for byte `offset` of `text` (both 1-based).
fn line_column(text: &str, offset: usize) -> String {
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    format!(" at line {line}, column {column}")
}

/// The profile name for `source_name`: its file name without the `.toml` ending (only that
/// ending is removed, so `stainless-0.5` stays whole).
fn stem(source_name: &str) -> String {
    let path = source_name.strip_prefix("shipped:").unwrap_or(source_name);
    let file = Path::new(path)
        .file_name()
        .and_then(|s| s.to_str())
        .unwrap_or(path);
    let name = file.strip_suffix(".toml").unwrap_or(file);
    if name.is_empty() {
        path.to_string()
    } else {
        name.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_name_is_the_file_name_without_toml() {
        assert_eq!(
            stem("shipped:machines/materials/stainless-0.5.toml"),
            "stainless-0.5"
        );
        assert_eq!(stem("stainless-0.5"), "stainless-0.5");
        assert_eq!(stem("/tmp/my.laser.toml"), "my.laser");
        assert_eq!(stem(".toml"), ".toml");
    }

    #[test]
    fn syntax_errors_count_lines_and_columns_from_one() {
        assert_eq!(line_column("a = 1\nb = = 2", 10), " at line 2, column 5");
        assert_eq!(line_column("x", 0), " at line 1, column 1");
        assert_eq!(line_column("é", 1), " at line 1, column 2");
    }

    #[test]
    fn names_and_paths_are_told_apart() {
        assert!(!is_path("grbl-diode"));
        assert!(!is_path("stainless-0.5"));
        assert!(is_path("my.toml"));
        assert!(is_path("./grbl-diode"));
        assert!(is_path(r"C:\profiles\x"));
    }
}

/// Machine or material profiles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProfileKind {
    /// `machines/NAME.toml`.
    Machine,
    /// `machines/materials/NAME.toml`.
    Material,
}

/// One shipped profile: its name, description and the file it was embedded from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CatalogueEntry {
    /// The name to give `--machine` or `--material`.
    pub name: String,
    /// The profile's one-line description.
    pub description: String,
    /// Where it comes from, e.g. `shipped: machines/grbl-diode.toml`.
    pub source: String,
    /// For a material, what it sets when nothing overrides it ([`Material::defaults`]); empty
    /// for a machine.
    pub defaults: String,
}

/// The shipped profiles of `kind`, sorted by name, each read and checked.
///
/// # Errors
/// A [`ProfileError`] if a shipped profile does not read (a build defect).
pub fn profile_catalogue(kind: ProfileKind) -> Result<Vec<CatalogueEntry>, ProfileError> {
    match kind {
        ProfileKind::Machine => shipped_machines()
            .into_iter()
            .map(|name| {
                let m = load_machine(name)?;
                Ok(CatalogueEntry {
                    name: name.to_string(),
                    description: m.description,
                    source: format!("shipped: machines/{name}.toml"),
                    defaults: String::new(),
                })
            })
            .collect(),
        ProfileKind::Material => shipped_materials()
            .into_iter()
            .map(|name| {
                let m = load_material(name)?;
                Ok(CatalogueEntry {
                    name: name.to_string(),
                    defaults: m.defaults(),
                    description: m.description,
                    source: format!("shipped: machines/materials/{name}.toml"),
                })
            })
            .collect(),
    }
}
