//! A tuck-in the layers do not allow (§2.1, §4.1 ④): a stationary layer lying between the two
//! moving halves covers the place they would fold to. It is refused with
//! [`FoldError::TuckBlocked`] and the state stays as it was; the same tuck without that layer,
//! or a shallower one that misses it, is made.

use foldcam::design::folding::layer_problems;
use foldcam::design::folding::{Fold, FoldError, Folding, Layers, Turn};
use foldcam::design::folding::{parse_script, run_script};
use glam::DVec3;

use super::{foldcam, square};

fn p(x: f64, y: f64) -> DVec3 {
    DVec3::new(x, y, 0.0)
}

fn bend(x: f64, moving: f64) -> Fold {
    Fold {
        line: [p(x, 0.0), p(x, 100.0)],
        moving: p(moving, 50.0),
        turn: Turn::Angle(180.0),
        layers: Layers::All,
    }
}

/// A tuck-in (inside reverse fold) along the vertical line `x`, moving the part right of it.
fn tuck(x: f64) -> Fold {
    Fold {
        line: [p(x, 0.0), p(x, 100.0)],
        moving: p(x + 2.0, 50.0),
        turn: Turn::Tuck,
        layers: Layers::All,
    }
}

/// A 100 mm square folded in half across x = 50 (the right half on top); with `strip`, the
/// left 20 mm were first bent over onto x ∈ [20, 40], so that strip lies between the halves.
fn folded_in_half(strip: bool) -> Folding {
    let mut f = square(100.0);
    if strip {
        f.fold(&bend(20.0, 10.0), None).expect("strip bent over");
    }
    f.fold(&bend(50.0, 75.0), None).expect("folded in half");
    f
}

/// Every face's x extent in the layer plane.
fn x_extent(f: &Folding) -> (f64, f64) {
    let (lo, hi) = super::bounds(f);
    (lo.x, hi.x)
}

#[test]
fn a_tuck_into_a_layer_in_the_way_is_refused_and_changes_nothing() {
    // Without the strip the tuck at x = 42 is made: the spine [42, 50] goes inside, between
    // the halves, onto [34, 42].
    let mut open = folded_in_half(false);
    open.fold(&tuck(42.0), None).expect("nothing in the way");
    assert!(layer_problems(&open, open.current()).is_empty());
    let (_, hi) = x_extent(&open);
    assert!((hi - 42.0).abs() < 1e-9, "{hi}");

    // With the strip between the halves at x ∈ [20, 40], the spine would land on it.
    let mut f = folded_in_half(true);
    let stack = &f.current().groups[0].stack;
    assert_eq!(stack.len(), 3, "base, strip, base");
    let before = f.clone();
    let err = f
        .fold(&tuck(42.0), None)
        .expect_err("the strip is in the way");
    assert_eq!(err, FoldError::TuckBlocked);
    assert!(err.to_string().contains("do not allow"), "{err}");
    assert_eq!(f, before);

    // A shallower tuck (landing on [40, 45], only touching the strip) is allowed.
    f.fold(&tuck(45.0), None).expect("lands beside the strip");
    assert!(layer_problems(&f, f.current()).is_empty());
    assert!((x_extent(&f).1 - 45.0).abs() < 1e-9);
}

const BLOCKED: &str = r#"
[sheet]
square = 100

[[step]]
name = "strip over"
bend = { line = [[20, 0], [20, 100]], moving = [10, 50] }

[[step]]
name = "in half"
bend = { line = [[50, 0], [50, 100]], moving = [75, 50] }

[[step]]
name = "spine in"
tuck = { line = [[42, 0], [42, 100]], moving = [46, 50] }
"#;

#[test]
fn a_script_with_a_blocked_tuck_names_the_step_and_exits_non_zero() {
    let script = parse_script(BLOCKED).expect("parses");
    let msg = run_script(&script).expect_err("blocked").to_string();
    assert!(
        msg.contains("step 3") && msg.contains("spine in") && msg.contains("do not allow"),
        "{msg}"
    );
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("blocked.toml"), BLOCKED).expect("write");
    let o = foldcam(&["fold", "blocked.toml", "-o", "b.fold"], dir.path());
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("blocked.toml") && err.contains("do not allow"),
        "{err}"
    );
    assert!(!dir.path().join("b.fold").exists());
}
