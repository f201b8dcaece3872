//! Layer names and colours per operation, shared by the DXF and SVG writers.
//!
//! Colours follow LightBurn's layer palette, where a colour *is* a layer, so an imported file
//! lands one operation per layer: 00 `#000000` black, 01 `#0000FF` blue, 02 `#FF0000` red,
//! 03 `#00E000` green, …, 07 `#FF00FF` magenta. The DXF layers carry the nearest AutoCAD
//! Color Index (ACI 7 black/white, 5 blue, 1 red, 3 green, 6 magenta).
//!
//! | operation | layer (DXF / SVG) | LightBurn | hex | ACI |
//! | --- | --- | --- | --- | --- |
//! | cut | `CUT` / `cut` | 02 red | `#FF0000` | 1 |
//! | perforate | `PERFORATE` / `perforate` | 03 green | `#00E000` | 3 |
//! | score | `SCORE` / `score` | 01 blue | `#0000FF` | 5 |
//! | mark | `MARK` / `mark` | 00 black | `#000000` | 7 |
//! | plot | `PLOT` / `plot` | 07 magenta | `#FF00FF` | 6 |

use crate::fab::Operation;

/// How one operation's layer looks in a drawing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LayerStyle {
    /// DXF layer name (upper case).
    pub dxf_name: &'static str,
    /// AutoCAD Color Index of the DXF layer.
    pub aci: u8,
    /// SVG stroke colour, `#RRGGBB` (a LightBurn palette entry).
    pub hex: &'static str,
    /// LightBurn layer number of `hex`.
    pub lightburn: u8,
}

/// The layer style of `op` (see the table in the module docs).
pub fn layer_style(op: Operation) -> LayerStyle {
    let (dxf_name, aci, hex, lightburn) = match op {
        Operation::Cut => ("CUT", 1, "#FF0000", 2),
        Operation::Perforate => ("PERFORATE", 3, "#00E000", 3),
        Operation::Score => ("SCORE", 5, "#0000FF", 1),
        Operation::Mark => ("MARK", 7, "#000000", 0),
        Operation::Plot => ("PLOT", 6, "#FF00FF", 7),
    };
    LayerStyle {
        dxf_name,
        aci,
        hex,
        lightburn,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_operation_has_its_own_colour_and_name() {
        let styles: Vec<_> = Operation::ALL.iter().map(|&op| layer_style(op)).collect();
        for (i, a) in styles.iter().enumerate() {
            for b in &styles[i + 1..] {
                assert_ne!(a.hex, b.hex);
                assert_ne!(a.aci, b.aci);
                assert_ne!(a.dxf_name, b.dxf_name);
            }
        }
        for op in Operation::ALL {
            assert_eq!(layer_style(op).dxf_name, op.name().to_uppercase());
        }
    }
}
