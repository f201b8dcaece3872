//! FOLD's `frame_unit`: the physical units FOLD 1.2 defines, converted to millimetres.
//!
//! `"unit"` (and a missing key, FOLD's default) means coordinates without physical size:
//! [`Units::Unitless`], factor 1. The physical units `in` (25.4 mm), `pt` (1/72 in), `m`,
//! `cm`, `mm`, `um` (also written `µm`) and `nm` give [`Units::Millimetres`] and the factor
//! that converts them to millimetres. Any other string is an error: FOLD allows custom units,
//! but foldcam cannot size a pattern in a unit it does not know.

use serde_json::Value;

use super::values::{Key, describe};
use crate::formats::ParseError;
use crate::pattern::Units;

/// The `frame_unit` key.
pub(super) const UNIT_KEY: &str = "frame_unit";

/// Millimetres per unit for FOLD's physical units.
const PHYSICAL: [(&str, f64); 8] = [
    ("in", 25.4),
    ("pt", 25.4 / 72.0),
    ("m", 1000.0),
    ("cm", 10.0),
    ("mm", 1.0),
    ("um", 1e-3),
    ("µm", 1e-3),
    ("nm", 1e-6),
];

/// The units of a frame and the factor converting its lengths to the model's unit.
pub(super) fn parse_unit(v: Option<&Value>, frame: usize) -> Result<(Units, f64), ParseError> {
    let key = Key::new(frame, UNIT_KEY);
    let Some(v) = v else {
        return Ok((Units::Unitless, 1.0));
    };
    let Some(name) = v.as_str() else {
        return Err(key.err(
            &[],
            format!("expected a unit name (a string), found {}", describe(v)),
        ));
    };
    if name == "unit" {
        return Ok((Units::Unitless, 1.0));
    }
    PHYSICAL
        .iter()
        .find(|(n, _)| *n == name)
        .map(|&(_, mm)| (Units::Millimetres, mm))
        .ok_or_else(|| {
            key.err(
                &[],
                format!("unknown unit {name:?} (FOLD 1.2 defines unit, in, pt, m, cm, mm, um, nm)"),
            )
        })
}

/// The `frame_unit` written for a pattern's units.
pub(super) fn unit_name(units: Units) -> &'static str {
    match units {
        Units::Millimetres => "mm",
        Units::Unitless => "unit",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn physical_units_convert_to_mm() {
        assert_eq!(
            parse_unit(Some(&json!("cm")), 0),
            Ok((Units::Millimetres, 10.0))
        );
        assert_eq!(
            parse_unit(Some(&json!("in")), 0),
            Ok((Units::Millimetres, 25.4))
        );
        let (_, pt) = parse_unit(Some(&json!("pt")), 0).unwrap();
        assert!((pt * 72.0 - 25.4).abs() < 1e-12);
    }

    #[test]
    fn unit_and_missing_are_unitless() {
        assert_eq!(parse_unit(None, 0), Ok((Units::Unitless, 1.0)));
        assert_eq!(
            parse_unit(Some(&json!("unit")), 0),
            Ok((Units::Unitless, 1.0))
        );
    }

    #[test]
    fn unknown_units_name_the_key() {
        let err = parse_unit(Some(&json!("furlong")), 0).unwrap_err();
        assert_eq!(err.place, "key \"frame_unit\"");
        assert!(err.message.contains("furlong"));
        assert!(parse_unit(Some(&json!(3)), 0).is_err());
    }
}
