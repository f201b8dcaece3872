//! A folder's index page: the machine jobs written into it, each with its machine, material,
//! times, file and toolpath picture, and the previews beside them, as one static HTML page
//! (no script, no style sheet to fetch; every link relative to the folder). The page is also
//! well-formed XML (void elements closed, `<img … />`), so an XML reader can check it.
//!
//! Limits: names are shown and linked as given (escaped for HTML, file names used as relative
//! links without further encoding, so they should be plain names as foldcam writes them).

use std::fmt::Write as _;

use super::Job;

/// One machine job of the index.
#[derive(Clone, Debug, PartialEq)]
pub struct IndexJob {
    /// What was cut: the pattern's or design's name.
    pub pattern: String,
    /// The machine profile's name.
    pub machine: String,
    /// The material profile's name.
    pub material: String,
    /// The plan's time estimate, seconds.
    pub planned_s: f64,
    /// The simulated machine's time for the program, seconds, when it ran.
    pub simulated_s: Option<f64>,
    /// The job's file name, relative to the index.
    pub file: String,
    /// The toolpath picture's file name, relative to the index.
    pub picture: Option<String>,
}

impl IndexJob {
    /// The index entry of the first job of a planned `job` of `pattern`, written as `file`
    /// with its toolpath drawn in `picture`; the simulated time when it was verified.
    pub fn of(job: &Job<'_>, pattern: &str, file: &str, picture: Option<&str>) -> Self {
        IndexJob {
            pattern: pattern.to_string(),
            machine: job.machine.name.clone(),
            material: job.plan.about.material.clone(),
            planned_s: job.plan.stats.time_s,
            simulated_s: job.readback.first().map(|r| r.sim.time_s),
            file: file.to_string(),
            picture: picture.map(str::to_string),
        }
    }
}

/// A picture listed under the jobs (a pattern's preview, a folded view, an animation).
#[derive(Clone, Debug, PartialEq)]
pub struct IndexPicture {
    /// The file name, relative to the index.
    pub file: String,
    /// What it shows.
    pub caption: String,
}

/// The index page titled `title`: a table of `jobs` (pattern, machine, material, planned and
/// simulated time, file, toolpath picture), then `pictures` with their captions.
pub fn index_html(title: &str, jobs: &[IndexJob], pictures: &[IndexPicture]) -> String {
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n\
         <title>{t}</title>\n</head>\n<body>\n<h1>{t}</h1>\n",
        t = escape(title)
    );
    let _ = write!(
        h,
        "<h2>Machine jobs</h2>\n<table border=\"1\" cellpadding=\"4\">\n<tr><th>pattern</th>\
         <th>machine</th><th>material</th><th>planned time</th><th>simulated time</th>\
         <th>file</th><th>toolpath</th></tr>\n"
    );
    for j in jobs {
        let simulated = j.simulated_s.map_or("not run".to_string(), duration);
        let picture = j.picture.as_deref().map_or("none".to_string(), |p| {
            format!(
                "<a href=\"{p}\"><img src=\"{p}\" width=\"240\" alt=\"toolpath of {f}\"/></a>",
                p = escape(p),
                f = escape(&j.file)
            )
        });
        let _ = writeln!(
            h,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>\
             <td><a href=\"{f}\">{f}</a></td><td>{picture}</td></tr>",
            escape(&j.pattern),
            escape(&j.machine),
            escape(&j.material),
            duration(j.planned_s),
            simulated,
            f = escape(&j.file)
        );
    }
    h.push_str("</table>\n<h2>Pictures</h2>\n");
    for p in pictures {
        let _ = writeln!(
            h,
            "<figure><a href=\"{f}\"><img src=\"{f}\" width=\"360\" alt=\"{c}\"/></a>\
             <figcaption>{c} ({f})</figcaption></figure>",
            f = escape(&p.file),
            c = escape(&p.caption)
        );
    }
    h.push_str("</body>\n</html>\n");
    h
}

/// Seconds as `1 min 05 s` or `42 s`.
fn duration(s: f64) -> String {
    let whole = s.max(0.0).round() as u64;
    if whole >= 60 {
        format!("{} min {:02} s", whole / 60, whole % 60)
    } else {
        format!("{whole} s")
    }
}

/// `text` with HTML's special characters as entities.
fn escape(text: &str) -> String {
    text.chars().fold(String::new(), |mut s, c| {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&#39;"),
            c => s.push(c),
        }
        s
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_escaped_and_times_read_in_minutes() {
        let job = IndexJob {
            pattern: "a<b".into(),
            machine: "m".into(),
            material: "x&y".into(),
            planned_s: 65.2,
            simulated_s: None,
            file: "a.m.x.gcode".into(),
            picture: Some("a.m.x.toolpath.png".into()),
        };
        let h = index_html("demo", &[job], &[]);
        assert!(h.contains("a&lt;b") && h.contains("x&amp;y"), "{h}");
        assert!(h.contains("1 min 05 s") && h.contains("not run"), "{h}");
        assert!(h.contains("href=\"a.m.x.gcode\"") && h.contains("src=\"a.m.x.toolpath.png\""));
    }
}
