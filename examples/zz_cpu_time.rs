use foldcam::design::folding::{Fold, Folding, Layers, Turn};
use glam::{DVec2, DVec3};
fn cpu_secs() -> f64 {
    let s = std::fs::read_to_string("/proc/self/stat").unwrap();
    let f: Vec<&str> = s.rsplit(')').next().unwrap().split_whitespace().collect();
    (f[11].parse::<f64>().unwrap() + f[12].parse::<f64>().unwrap()) / 100.0
}
fn main() {
    let side = 100.0;
    let mut f = Folding::new(&[DVec2::ZERO, DVec2::new(side, 0.0), DVec2::new(side, side), DVec2::new(0.0, side)]).unwrap();
    let (mut w, mut h) = (side, side);
    let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
    for k in 0..10 {
        let fold = if k % 2 == 0 { w /= 2.0; Fold { line: [p(w, 0.0), p(w, h)], moving: p(w * 1.5, h / 2.0), turn: Turn::Angle(180.0), layers: Layers::All } }
        else { h /= 2.0; Fold { line: [p(0.0, h), p(w, h)], moving: p(w / 2.0, h * 1.5), turn: Turn::Angle(-180.0), layers: Layers::All } };
        f.fold(&fold, None).unwrap();
    }
    let s = w;
    let folds = [
        ("all_layers", Fold { line: [p(0.0, 0.0), p(s, s)], moving: p(s * 0.9, s * 0.1), turn: Turn::Angle(180.0), layers: Layers::All }),
        ("outer_layer", Fold { line: [p(s * 0.5, 0.0), p(s, s * 0.5)], moving: p(s * 0.95, s * 0.05), turn: Turn::Angle(180.0), layers: Layers::Outer(1) }),
    ];
    let n = 2000;
    let t0 = cpu_secs();
    let mut keep = 0;
    for _ in 0..n { let c = f.current().clone(); keep += c.faces.len(); }
    println!("clone: {:.3} ms ({keep})", (cpu_secs() - t0) / n as f64 * 1e3);
    for (name, fold) in &folds {
        let n = 2000;
        let t0 = cpu_secs();
        for _ in 0..n { f.fold(fold, None).unwrap(); f.undo().unwrap(); }
        let t = cpu_secs() - t0;
        println!("{name}: {:.3} ms CPU per fold ({} faces)", t / n as f64 * 1e3, f.current().faces.len());
    }
}
