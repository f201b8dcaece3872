//! The accepted range of every number a user sets, in one place, shared by the command line
//! and the machine and material profile readers.
//!
//! A [`Limit`] names a setting twice: as the command-line option (`--kerf`) and as the
//! profile key (`kerf_mm`, dotted inside its table), so that the same value is refused with
//! the same words whichever way it came in: "expected a number from 0 to 5 mm, got 1e300". The
//! command line calls [`Limit::parse`] (clap then names the option), the profile readers
//! [`Limit::check`] (they name the file and key). Settings that depend on each other (the
//! shortest dash against the dash, the web against the bridge) are checked by
//! `machine::Perforation::check_limits` once the command line has been laid over the material.
//!
//! Ranges are inclusive. Lengths are millimetres, speeds mm/min, power a fraction of the
//! machine's range; the upper bounds are far beyond any real sheet or machine, and are there
//! so that no later step (offsets, dash layouts, rasters) meets a number it cannot work with.

/// Largest coordinate magnitude accepted anywhere, in millimetres (or units for unitless
/// patterns): 1e9 mm is a thousand kilometres, far beyond any sheet, and keeps products of
/// coordinates well inside f64 precision.
pub const MAX_COORDINATE: f64 = 1e9;

/// One real-valued setting: its option, its profile key, its range and unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limit {
    /// Command-line option (`--kerf`), empty when there is none.
    pub option: &'static str,
    /// Profile key, dotted within its file (`perforation.cut_mm`), empty when there is none.
    pub key: &'static str,
    /// Smallest value accepted.
    pub min: f64,
    /// Largest value accepted.
    pub max: f64,
    /// Unit named in messages (`mm`, `mm/min`, …).
    pub unit: &'static str,
}

/// One whole-number setting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CountLimit {
    /// Command-line option, empty when there is none.
    pub option: &'static str,
    /// Profile key, empty when there is none.
    pub key: &'static str,
    /// Smallest value accepted.
    pub min: u64,
    /// Largest value accepted.
    pub max: u64,
    /// What is counted, for messages (`cells`, `passes`).
    pub unit: &'static str,
}

/// A setting outside its range, or two settings that contradict each other.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{setting} {value}: {message}")]
pub struct LimitError {
    /// The option or key (or both: `--dash (perforation.cut_mm)`).
    pub setting: String,
    /// The value given, as written.
    pub value: String,
    /// What was expected.
    pub message: String,
}

impl Limit {
    /// "a number from MIN to MAX UNIT".
    pub fn expected(&self) -> String {
        format!(
            "a number from {} to {} {}",
            show(self.min),
            show(self.max),
            self.unit
        )
    }

    /// `value` when it is finite and inside the range; otherwise "expected …, got …".
    pub fn check(&self, value: f64) -> Result<f64, String> {
        if value.is_finite() && value >= self.min && value <= self.max {
            Ok(value)
        } else {
            Err(format!("expected {}, got {}", self.expected(), show(value)))
        }
    }

    /// Parses a command-line value and checks it (the message is the one [`Limit::check`]
    /// gives, so clap prints the option, the value and the range).
    pub fn parse(&self, text: &str) -> Result<f64, String> {
        let value: f64 = text
            .trim()
            .parse()
            .map_err(|_| format!("expected {}, got {text:?}", self.expected()))?;
        self.check(value)
    }

    /// The option and the key, for messages about either (`--dash (perforation.cut_mm)`).
    pub fn name(&self) -> String {
        setting_name(self.option, self.key)
    }
}

/// `OPTION (KEY)`, or whichever of the two there is.
fn setting_name(option: &str, key: &str) -> String {
    match (option.is_empty(), key.is_empty()) {
        (false, false) => format!("{option} ({key})"),
        (false, true) => option.to_string(),
        _ => key.to_string(),
    }
}

impl CountLimit {
    /// The option and the key, for messages about either (`--remesh (remesh_faces)`).
    pub fn name(&self) -> String {
        setting_name(self.option, self.key)
    }

    /// "a whole number from MIN to MAX UNIT".
    pub fn expected(&self) -> String {
        format!(
            "a whole number from {} to {} {}",
            self.min, self.max, self.unit
        )
    }

    /// `value` when it is inside the range; otherwise "expected …, got …".
    pub fn check(&self, value: i64) -> Result<u64, String> {
        match u64::try_from(value) {
            Ok(v) if (self.min..=self.max).contains(&v) => Ok(v),
            _ => Err(format!("expected {}, got {value}", self.expected())),
        }
    }

    /// Parses a command-line value and checks it.
    pub fn parse(&self, text: &str) -> Result<u64, String> {
        let value: i64 = text
            .trim()
            .parse()
            .map_err(|_| format!("expected {}, got {text:?}", self.expected()))?;
        self.check(value)
    }
}

/// Magnitudes [`show`] writes in plain decimals: from 0.0001 (four zeros after the point at
/// most) up to 10¹⁵ (sixteen digits, all exact in an f64).
const PLAIN: std::ops::Range<f64> = 1e-4..1e15;

/// A number as a person writes it: plain between 1e-4 and 1e15, else in exponent form
/// (`1e300`, not three hundred digits).
pub fn show(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || PLAIN.contains(&x.abs()) {
        x.to_string()
    } else {
        format!("{x:e}")
    }
}

const fn mm(option: &'static str, key: &'static str, min: f64, max: f64) -> Limit {
    Limit {
        option,
        key,
        min,
        max,
        unit: "mm",
    }
}

/// Width of the cut: `--kerf`, material `kerf_mm`.
pub const KERF: Limit = mm("--kerf", "kerf_mm", 0.0, 5.0);
/// Sheet thickness: material `thickness_mm`.
pub const THICKNESS: Limit = mm("", "thickness_mm", 0.01, 50.0);
/// Perforation dash: `--dash`, material `perforation.cut_mm`.
pub const DASH: Limit = mm("--dash", "perforation.cut_mm", 0.01, 1000.0);
/// Perforation bridge (material left between dashes): `--bridge`, `perforation.bridge_mm`.
pub const BRIDGE: Limit = mm("--bridge", "perforation.bridge_mm", 0.01, 1000.0);
/// Shortest dash worth cutting: `--min-dash`, `perforation.min_dash_mm` (at most the dash).
pub const MIN_DASH: Limit = mm("--min-dash", "perforation.min_dash_mm", 0.01, 1000.0);
/// Least material between two cuts: `--min-web`, `perforation.min_web_mm` (at most the
/// bridge).
pub const MIN_WEB: Limit = mm("--min-web", "perforation.min_web_mm", 0.01, 1000.0);
/// Uncut clearance around every vertex: `--clearance`, `perforation.vertex_clearance_mm`.
pub const CLEARANCE: Limit = mm("--clearance", "perforation.vertex_clearance_mm", 0.0, 100.0);
/// Holding-tab width: `--tabs`.
pub const TAB_WIDTH: Limit = mm("--tabs", "", 0.01, 100.0);
/// Spacing between holding tabs: `--tab-spacing`.
pub const TAB_SPACING: Limit = mm("--tab-spacing", "", 1.0, 10_000.0);
/// Lead-in length: `--lead-in`.
pub const LEAD_IN: Limit = mm("--lead-in", "", 0.01, 100.0);
/// Distance from the bed origin: `--margin`.
pub const MARGIN: Limit = mm("--margin", "", 0.0, 10_000.0);

/// Feed of one operation: material `settings.OP.speed_mm_min`.
pub const SPEED: Limit = Limit {
    option: "",
    key: "speed_mm_min",
    min: 1.0,
    max: 1e6,
    unit: "mm/min",
};
/// Power of one operation as a fraction of the machine's range: `settings.OP.power`.
pub const POWER: Limit = Limit {
    option: "",
    key: "power",
    min: 0.0,
    max: 1.0,
    unit: "(fraction of full power)",
};
/// Repetitions of one operation: `settings.OP.passes`.
pub const PASSES: CountLimit = CountLimit {
    option: "",
    key: "passes",
    min: 1,
    max: 100,
    unit: "passes",
};
/// Fastest feed of a machine: `max_feed_mm_min` (`travel_feed_mm_min` at most that).
pub const FEED: Limit = Limit {
    option: "",
    key: "max_feed_mm_min",
    min: 1.0,
    max: 1e6,
    unit: "mm/min",
};
/// Bed width and height: `bed.width_mm`, `bed.height_mm`.
pub const BED_SIZE: Limit = mm("", "bed.width_mm", 1.0, 10_000.0);
/// Smallest step of a machine: `resolution_mm`.
pub const MACHINE_RESOLUTION: Limit = mm("", "resolution_mm", 1e-5, 0.1);

/// Pop-up cell size: `popup voxel --cell-mm`.
pub const CELL: Limit = mm("--cell-mm", "", 0.1, 1000.0);
/// Pop-up card width: `popup voxel --card-width`.
pub const CARD_WIDTH: Limit = mm("--card-width", "", 1.0, 10_000.0);
/// Cells along the fold of a pop-up made from a mesh: `popup voxel --resolution`.
pub const RESOLUTION: CountLimit = CountLimit {
    option: "--resolution",
    key: "",
    min: 4,
    max: 4000,
    unit: "cells",
};
/// Most entity copies the DXF reader places through block inserts, all inserts of a drawing
/// together and nested arrays multiplied (a 300 × 300 array of a block holding a 300 × 300
/// array is 8.1e9 copies, each under the per-array cap): a copy costs its entities, a copy of
/// an empty block one. As many as the most segments read.
pub const MAX_BLOCK_COPIES: u64 = 10_000_000;

/// Faces of a re-triangulation (`tessellate --remesh`, `remesh_faces` in a `.tess.toml`, the
/// studio's tessellation): at most 50,000, about 2 GB for one solve at the solver's measured
/// 38 kB per face (`design::tessellation::estimate`); at least the 24 a disk needs.
pub const REMESH_FACES: CountLimit = CountLimit {
    option: "--remesh",
    key: "remesh_faces",
    min: 24,
    max: 50_000,
    unit: "faces",
};

/// Most transitivity constraints of the layer-order solver (three faces of one stack): 80
/// million, about 48 bytes each with the solver's rows (`check::layers`); Imai's Shrimp v2
/// has 67.5 million. A pattern whose deepest stack alone passes it is refused at once.
pub const MAX_LAYER_TRIPLES: usize = 80_000_000;

/// A studio tessellation solve whose page has not asked for its progress for this long is
/// cancelled, seconds (the page asks several times a second; a browser wakes a hidden tab's
/// timers at least once a minute): a closed tab does not keep a core busy.
pub const STUDIO_ABANDONED_SECONDS: u64 = 90;

/// Longest the studio's layer-order searches run, seconds: a request never holds a worker
/// longer (the command line has `--time-limit`, without a default).
pub const STUDIO_LAYER_SECONDS: u64 = 60;

/// The side of the studio's blank sheet (`POST /api/blank?side=MM`): from 1 mm to 10 m, the
/// largest sheet a machine bed or a roll of paper holds.
pub const STUDIO_BLANK_SIDE: Limit = mm("", "side", 1.0, 10_000.0);

/// Most cells of a voxel pop-up card along any axis (`popup voxel`, the studio's editor).
pub const VOXEL_CELLS_PER_AXIS: usize = 20_000;

/// Most cells of a voxel card's crease pattern, `nx × (ny + nz)`, on the command line: the
/// conversion needs about 28 bytes per cell (`design::popup::voxel::estimate`), the crease
/// pattern of a card with a step in every cell up to 3 kB.
pub const VOXEL_PATTERN_CELLS: usize = 50_000_000;

/// Most pattern cells of a voxel card in the studio, whose every reply carries the card and
/// its faults: a million, at most [`STUDIO_BYTES_PER_PATTERN_CELL`] each (1 GB), so that two
/// such cards fit in [`STUDIO_MEMORY_BYTES`] at once.
pub const STUDIO_VOXEL_PATTERN_CELLS: usize = 1_000_000;

/// Memory of a voxel card in the studio per pattern cell, bytes: measured 830 on a 400³ card
/// with a step in every other column (the debug build, 277 MB), rounded up.
pub const STUDIO_BYTES_PER_PATTERN_CELL: u64 = 1_000;

/// Memory the studio lets its large requests (voxel cards, tessellation solves) hold at once,
/// bytes, by their estimates: a request that would pass it is refused before it allocates
/// (and may be sent again when others are done).
pub const STUDIO_MEMORY_BYTES: u64 = 2_000_000_000;

/// Most versions an open document or studio editor session keeps for undo, the shown one
/// included; the oldest go first.
pub const STUDIO_UNDO_VERSIONS: usize = 100;

/// Most bytes of earlier versions an open document or studio editor session keeps for undo,
/// by the versions' array sizes: 30 MB, so that the studio's 32 documents and 40 editor
/// sessions with undo (16 voxel cards, 16 pop-up cards, 8 paper crafts) hold at most
/// 2.2 GB of history however long a page is left open, besides the shown versions (bounded
/// by the size caps above).
pub const STUDIO_UNDO_BYTES: usize = 30_000_000;

/// The smallest merge tolerance, in the pattern's units: the least `--tolerance` accepts and the
/// floor of every tolerance computed from a pattern's size (an empty or one-point pattern has
/// none). Positive, so that "closer than the tolerance" never means "equal".
pub const MIN_TOLERANCE: f64 = 1e-12;

/// Merge tolerance of the cleaner: `convert --tolerance` (see also
/// [`check_tolerance`] against the pattern's size).
pub const TOLERANCE: Limit = Limit {
    option: "--tolerance",
    key: "",
    min: MIN_TOLERANCE,
    max: MAX_COORDINATE,
    unit: "(pattern units)",
};
/// Line-end snapping distance of drawings: `--snap` (0 turns it off).
pub const SNAP: Limit = mm("--snap", "", 0.0, 1000.0);
/// A fixed Kawasaki tolerance: `--kawasaki-tolerance`, the studio's layer-order field. Above
/// zero, since floating-point rounding alone leaves errors of about 1e-11°; an error of tens of
/// degrees is no rounding, and 90° would accept any vertex.
pub const KAWASAKI_TOLERANCE: Limit = Limit {
    option: "--kawasaki-tolerance",
    key: "",
    min: 1e-6,
    max: 45.0,
    unit: "degrees",
};

/// Largest merge tolerance as a share of the pattern's bounding-box diagonal: beyond it the
/// cleaner merges whole creases into points.
pub const MAX_RELATIVE_TOLERANCE: f64 = 0.01;

/// Refuses a merge tolerance larger than [`MAX_RELATIVE_TOLERANCE`] of the pattern's
/// bounding-box `diagonal` (same unit): the cleaner would merge the pattern away.
pub fn check_tolerance(tolerance: f64, diagonal: f64) -> Result<(), LimitError> {
    let largest = MAX_RELATIVE_TOLERANCE * diagonal;
    if tolerance <= largest || !diagonal.is_finite() {
        return Ok(());
    }
    Err(LimitError {
        setting: TOLERANCE.option.to_string(),
        value: show(tolerance),
        message: format!(
            "larger than {MAX_RELATIVE_TOLERANCE} of the pattern's diagonal ({diagonal:.6}), at \
             most {largest:.6}: every vertex would merge and nothing would be left"
        ),
    })
}

/// Checks a length that has no profile key (tabs, lead-in, margin) against `limit`.
pub fn check_length(limit: &Limit, value: f64) -> Result<f64, LimitError> {
    limit.check(value).map_err(|message| LimitError {
        setting: limit.name(),
        value: show(value),
        message,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_message_names_the_range_whichever_way_the_value_came() {
        let cli = KERF.parse("1e300").unwrap_err();
        let profile = KERF.check(1e300).unwrap_err();
        assert_eq!(cli, profile);
        assert!(cli.contains("from 0 to 5 mm"), "{cli}");
        assert!(KERF.parse("nan").is_err());
        assert!(KERF.parse("inf").is_err());
        assert_eq!(KERF.parse("0.2"), Ok(0.2));
        assert_eq!(KERF.parse("5"), Ok(5.0));
    }

    #[test]
    fn counts_refuse_negatives_and_beyond() {
        assert!(RESOLUTION.parse("-1").is_err());
        assert!(RESOLUTION.parse("4001").is_err());
        assert_eq!(RESOLUTION.parse("80"), Ok(80));
        assert!(PASSES.check(0).is_err());
    }

    #[test]
    fn a_tolerance_beyond_a_hundredth_of_the_pattern_is_refused() {
        assert!(check_tolerance(1e9, 100.0).is_err());
        assert!(check_tolerance(1.0, 100.0).is_ok());
    }
}
