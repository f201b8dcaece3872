//! Group-code/value pairs, the lines of a DXF file.

use std::fmt::{Display, Write};

use super::super::number::Grid;

/// A DXF text under construction.
pub struct Pairs<'g> {
    text: String,
    grid: &'g Grid,
}

impl<'g> Pairs<'g> {
    /// An empty file printing coordinates on `grid`.
    pub fn new(grid: &'g Grid) -> Self {
        Pairs {
            text: String::new(),
            grid,
        }
    }

    /// One pair: the group code right-aligned in three columns, then the value.
    pub fn pair(&mut self, code: u16, value: impl Display) -> &mut Self {
        // Writing to a String cannot fail.
        let _ = write!(self.text, "{code:>3}\n{value}\n");
        self
    }

    /// A handle (group 5, or 105 for DIMSTYLE) or a pointer to one: upper-case hex.
    pub fn handle(&mut self, code: u16, handle: u32) -> &mut Self {
        self.pair(code, format_args!("{handle:X}"))
    }

    /// A point from grid counts: groups `code` (x) and `code + 10` (y).
    pub fn point(&mut self, code: u16, (x, y): (i64, i64)) -> &mut Self {
        let (x, y) = (self.grid.print(x), self.grid.print(y));
        self.pair(code, x).pair(code + 10, y)
    }

    /// A 3D point at z = 0 from grid counts: groups `code`, `code + 10`, `code + 20`.
    pub fn point3(&mut self, code: u16, p: (i64, i64)) -> &mut Self {
        self.point(code, p).pair(code + 20, "0.0")
    }

    /// `0 SECTION`, `2 name`.
    pub fn section(&mut self, name: &str) -> &mut Self {
        self.pair(0, "SECTION").pair(2, name)
    }

    /// `0 ENDSEC`.
    pub fn end_section(&mut self) -> &mut Self {
        self.pair(0, "ENDSEC")
    }

    /// The finished text, with `0 EOF`.
    pub fn finish(mut self) -> String {
        self.pair(0, "EOF");
        self.text
    }
}
