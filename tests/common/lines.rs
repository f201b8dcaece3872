//! Crease patterns compared as sets of lines: each segment's ends rounded to a tolerance and
//! sorted, with its assignment letter, the whole list sorted. Two files, or a file and a
//! drawing, agree when they hold the same creases, whatever their vertex and edge order.
#![allow(dead_code)]

use serde_json::Value;

/// Lines as (ends sorted, each rounded to the tolerance; assignment letter), sorted.
pub type Lines = Vec<([[i64; 2]; 2], String)>;

/// One line from its ends `[x1, y1, x2, y2]` (mm), rounded to `tolerance` (mm).
pub fn line(ends: [f64; 4], letter: &str, tolerance: f64) -> ([[i64; 2]; 2], String) {
    let round = |v: f64| (v / tolerance).round() as i64;
    let mut e = [
        [round(ends[0]), round(ends[1])],
        [round(ends[2]), round(ends[3])],
    ];
    e.sort();
    (e, letter.to_string())
}

/// The lines of a FOLD file's top-level frame, rounded to `tolerance` (mm).
pub fn fold_lines(fold: &Value, tolerance: f64) -> Lines {
    let coords = fold["vertices_coords"].as_array().unwrap();
    let xy = |i: &Value| {
        let c = &coords[i.as_u64().unwrap() as usize];
        [c[0].as_f64().unwrap(), c[1].as_f64().unwrap()]
    };
    let mut out: Lines = fold["edges_vertices"]
        .as_array()
        .unwrap()
        .iter()
        .zip(fold["edges_assignment"].as_array().unwrap())
        .map(|(e, a)| {
            let (p, q) = (xy(&e[0]), xy(&e[1]));
            line([p[0], p[1], q[0], q[1]], a.as_str().unwrap(), tolerance)
        })
        .collect();
    out.sort();
    out
}
