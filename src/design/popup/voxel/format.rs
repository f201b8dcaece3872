//! The voxel card text format (`.voxel.txt`), read by [`parse_voxel_card`].
//!
//! ```text
//! # a comment; blank lines are ignored
//! cell_mm 5        # edge of one cell in millimetres
//! depth 12         # ny: cells of base sheet in front of the fold
//! height 16        # nz: cells of back sheet above the fold
//! margin_mm 10     # optional: flat paper around the cells (default 0)
//! rows             # the front elevation follows, top row first
//! 0 0 2  2w 2 0 0
//! 0 3 3  3  3 3 0
//! ```
//!
//! After `rows`, each line is one height level, the highest first and the last line z = 0;
//! levels above the first line are empty. Each token is a column's depth in cells (the row's
//! filled cells are `y < depth`); a trailing `w` makes the row's front face a window (Mitani, Suzuki & Uno 2003, eq. 5),
//! a trailing `t` leaves out the row's top face (§3.3), both may follow one depth (`3wt`).
//! Every line has the same number of tokens, which is the card's width `nx`. Depths must not
//! grow upwards (eq. 4) nor exceed `depth`. Errors name the line.

use thiserror::Error;

use super::{VoxelCard, VoxelError};

/// A voxel card file that cannot be read.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum VoxelFormatError {
    /// A line that is not understood.
    #[error("line {line}: {message}")]
    Syntax {
        /// 1-based line number.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A header key is missing.
    #[error("missing key `{0}` before `rows`")]
    MissingKey(&'static str),
    /// No line reads `rows`, so no elevation follows the header.
    #[error(
        "no line reads `rows`: the header (cell_mm, depth, height) must be followed by `rows` and the front elevation"
    )]
    NoRows,
    /// The card itself is invalid.
    #[error("line {line}: {source}")]
    Card {
        /// 1-based line number.
        line: usize,
        /// The model's complaint.
        source: VoxelError,
    },
}

#[derive(Default)]
struct Header {
    cell_mm: Option<f64>,
    depth: Option<usize>,
    height: Option<usize>,
    margin_mm: Option<(usize, f64)>,
}

/// Parses the text format of the module docs.
pub fn parse_voxel_card(text: &str) -> Result<VoxelCard, VoxelFormatError> {
    let mut header = Header::default();
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.split('#').next().unwrap_or("").trim()))
        .filter(|(_, l)| !l.is_empty());
    let mut rows_line = None;
    for (n, line) in lines.by_ref() {
        if line == "rows" {
            rows_line = Some(n);
            break;
        }
        header_line(&mut header, n, line)?;
    }
    let rows_line = rows_line.ok_or(VoxelFormatError::NoRows)?;
    let rows: Vec<(usize, Vec<Token>)> = lines
        .map(|(n, l)| row_line(n, l).map(|r| (n, r)))
        .collect::<Result<_, _>>()?;
    build(&header, rows_line, &rows)
}

fn syntax(line: usize, message: impl Into<String>) -> VoxelFormatError {
    VoxelFormatError::Syntax {
        line,
        message: message.into(),
    }
}

fn header_line(h: &mut Header, n: usize, line: &str) -> Result<(), VoxelFormatError> {
    let mut parts = line.split_whitespace();
    let (Some(key), Some(value), None) = (parts.next(), parts.next(), parts.next()) else {
        return Err(syntax(n, format!("expected `key value`, got `{line}`")));
    };
    let bad = |what: &str| syntax(n, format!("`{key}` needs {what}, got `{value}`"));
    match key {
        "cell_mm" => h.cell_mm = Some(value.parse().map_err(|_| bad("a number"))?),
        "depth" => h.depth = Some(value.parse().map_err(|_| bad("a cell count"))?),
        "height" => h.height = Some(value.parse().map_err(|_| bad("a cell count"))?),
        "margin_mm" => h.margin_mm = Some((n, value.parse().map_err(|_| bad("a number"))?)),
        _ => return Err(syntax(n, format!("unknown key `{key}`"))),
    }
    Ok(())
}

/// One column of a row: depth, window, top face left out.
type Token = (usize, bool, bool);

fn row_line(n: usize, line: &str) -> Result<Vec<Token>, VoxelFormatError> {
    line.split_whitespace()
        .map(|t| {
            let digits = t.trim_end_matches(['w', 't']);
            let flags = &t[digits.len()..];
            let (window, top) = (flags.contains('w'), flags.contains('t'));
            if flags.len() > usize::from(window) + usize::from(top) {
                return Err(syntax(n, format!("`{t}` repeats a flag")));
            }
            digits
                .parse()
                .map(|d| (d, window, top))
                .map_err(|_| syntax(n, format!("`{t}` is not a depth (like `3`, `3w` or `3t`)")))
        })
        .collect()
}

/// Writes `card` in the text format (every row, the highest first), so that
/// [`parse_voxel_card`] reads back the same card.
pub fn format_voxel_card(card: &VoxelCard) -> String {
    use std::fmt::Write;
    let mut out = String::from("# foldcam voxel card (see examples/popup/README.txt)\n");
    let _ = writeln!(out, "cell_mm {}", card.cell_mm());
    let _ = writeln!(out, "depth {}", card.ny());
    let _ = writeln!(out, "height {}", card.nz());
    let _ = writeln!(out, "margin_mm {}", card.margin_mm());
    out.push_str("rows\n");
    for z in (0..card.nz()).rev() {
        for x in 0..card.nx() {
            if x > 0 {
                out.push(' ');
            }
            let _ = write!(out, "{}", card.depth(x, z));
            if card.is_hole(x, z) {
                out.push('w');
            }
            if card.is_top_omitted(x, z) {
                out.push('t');
            }
        }
        out.push('\n');
    }
    out
}

fn build(
    h: &Header,
    rows_line: usize,
    rows: &[(usize, Vec<Token>)],
) -> Result<VoxelCard, VoxelFormatError> {
    let cell_mm = h.cell_mm.ok_or(VoxelFormatError::MissingKey("cell_mm"))?;
    let ny = h.depth.ok_or(VoxelFormatError::MissingKey("depth"))?;
    let nz = h.height.ok_or(VoxelFormatError::MissingKey("height"))?;
    let nx = rows.first().map_or(0, |r| r.1.len());
    let mut card =
        VoxelCard::new(nx, ny, nz, cell_mm).map_err(|source| VoxelFormatError::Card {
            line: rows_line,
            source,
        })?;
    if let Some((line, margin)) = h.margin_mm {
        let err = |source| VoxelFormatError::Card { line, source };
        card.set_margin_mm(margin).map_err(err)?;
    }
    if rows.len() > nz {
        return Err(syntax(
            rows_line,
            format!("{} rows but height is {nz}", rows.len()),
        ));
    }
    if let Some((n, row)) = rows.iter().find(|(_, row)| row.len() != nx) {
        return Err(syntax(
            *n,
            format!("{} columns, the first row has {nx}", row.len()),
        ));
    }
    // Bottom-up, so each row is checked against the one below it (eq. 4).
    for (i, (n, row)) in rows.iter().enumerate().rev() {
        let z = rows.len() - 1 - i;
        for (x, &(depth, window, top)) in row.iter().enumerate() {
            let card_err = |source| VoxelFormatError::Card { line: *n, source };
            card.set_depth(x, z, depth).map_err(card_err)?;
            card.set_hole(x, z, window).map_err(card_err)?;
            card.set_top_omitted(x, z, top).map_err(card_err)?;
        }
    }
    Ok(card)
}
