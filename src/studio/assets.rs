//! The front end, embedded in the binary: plain ES modules and a style sheet from `studio/`,
//! and three.js r169 (MIT, `studio/vendor/three-LICENSE`) for the 3D view. A fresh machine
//! needs neither node nor a network to build or run the studio.
//!
//! Files of at least [`GZIP_FROM`] bytes are also sent gzipped to browsers that accept it,
//! compressed once at their first request ([`gzipped`]): three.js goes from 687 KB to about
//! 170 KB (169 894 bytes).

use std::io::Write;
use std::sync::OnceLock;

use axum::http::{HeaderMap, header};

/// Smallest file sent gzipped, bytes.
pub const GZIP_FROM: usize = 1024;

/// One embedded file: its URL name, content type and bytes.
struct Asset {
    name: &'static str,
    mime: &'static str,
    bytes: &'static [u8],
    /// The bytes gzipped, made at the first request that accepts them.
    gzipped: OnceLock<Option<Vec<u8>>>,
}

macro_rules! asset {
    ($name:literal, $mime:literal) => {
        Asset {
            name: $name,
            mime: $mime,
            bytes: include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/studio/", $name)),
            gzipped: OnceLock::new(),
        }
    };
}

static ASSETS: [Asset; 19] = [
    asset!("index.html", "text/html; charset=utf-8"),
    asset!("style.css", "text/css; charset=utf-8"),
    asset!("app.js", "text/javascript; charset=utf-8"),
    asset!("api.js", "text/javascript; charset=utf-8"),
    asset!("cp.js", "text/javascript; charset=utf-8"),
    asset!("segments.js", "text/javascript; charset=utf-8"),
    asset!("edit.js", "text/javascript; charset=utf-8"),
    asset!("flat.js", "text/javascript; charset=utf-8"),
    asset!("fold.js", "text/javascript; charset=utf-8"),
    asset!("folding.js", "text/javascript; charset=utf-8"),
    asset!("craft.js", "text/javascript; charset=utf-8"),
    asset!("machine.js", "text/javascript; charset=utf-8"),
    asset!("scene3d.js", "text/javascript; charset=utf-8"),
    asset!("tessellate.js", "text/javascript; charset=utf-8"),
    asset!("voxel.js", "text/javascript; charset=utf-8"),
    asset!("popup.js", "text/javascript; charset=utf-8"),
    asset!("start.js", "text/javascript; charset=utf-8"),
    asset!(
        "vendor/three.module.min.js",
        "text/javascript; charset=utf-8"
    ),
    asset!("vendor/three-LICENSE", "text/plain; charset=utf-8"),
];

/// The embedded file named exactly `name` (no leading `/`), with its content type.
pub fn get(name: &str) -> Option<(&'static [u8], &'static str)> {
    ASSETS
        .iter()
        .find(|a| a.name == name)
        .map(|a| (a.bytes, a.mime))
}

/// The embedded file named `name` gzipped (best compression), or `None` when there is no
/// such file, it is smaller than [`GZIP_FROM`] or compressing it failed.
pub fn gzipped(name: &str) -> Option<&'static [u8]> {
    let asset = ASSETS.iter().find(|a| a.name == name)?;
    asset
        .gzipped
        .get_or_init(|| {
            (asset.bytes.len() >= GZIP_FROM)
                .then(|| gzip(asset.bytes))
                .flatten()
        })
        .as_deref()
}

fn gzip(bytes: &[u8]) -> Option<Vec<u8>> {
    let mut encoder = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    encoder.write_all(bytes).ok()?;
    encoder.finish().ok()
}

/// Whether the request's `Accept-Encoding` lists `gzip` (or `*`) with a weight above zero.
pub fn accepts_gzip(headers: &HeaderMap) -> bool {
    headers
        .get_all(header::ACCEPT_ENCODING)
        .iter()
        .filter_map(|v| v.to_str().ok())
        .flat_map(|v| v.split(','))
        .any(|item| {
            let mut parts = item.split(';').map(str::trim);
            let coding = parts.next().unwrap_or_default().to_ascii_lowercase();
            let refused = parts.any(|p| {
                p.strip_prefix("q=")
                    .and_then(|q| q.trim().parse::<f64>().ok())
                    .is_some_and(|q| q <= 0.0)
            });
            (coding == "gzip" || coding == "*") && !refused
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    const JS: &str = "text/javascript; charset=utf-8";

    #[test]
    fn gzip_only_when_accepted() {
        use axum::http::HeaderValue;
        let mut h = HeaderMap::new();
        assert!(!accepts_gzip(&h));
        for (sent, ok) in [
            ("gzip, deflate, br", true),
            ("br;q=1.0, gzip;q=0.5", true),
            ("gzip;q=0", false),
            ("identity", false),
            ("*", true),
        ] {
            h.insert(header::ACCEPT_ENCODING, HeaderValue::from_static(sent));
            assert_eq!(accepts_gzip(&h), ok, "{sent}");
        }
        let three = gzipped("vendor/three.module.min.js").unwrap();
        assert!(three.len() * 3 < get("vendor/three.module.min.js").unwrap().0.len());
        assert!(gzipped("no-such-file").is_none());
    }

    #[test]
    fn every_module_the_page_imports_is_embedded() {
        let html = std::str::from_utf8(get("index.html").unwrap().0).unwrap();
        assert!(html.contains("app.js"));
        for a in ASSETS
            .iter()
            .filter(|a| a.mime == JS && !a.name.starts_with("vendor/"))
        {
            let text = std::str::from_utf8(a.bytes).unwrap();
            for line in text.lines().filter(|l| l.starts_with("import ")) {
                let target = line.rsplit(['\'', '"']).nth(1).unwrap();
                let name = target.trim_start_matches("./");
                assert!(
                    get(name).is_some(),
                    "{} imports {target}, not embedded",
                    a.name
                );
            }
        }
    }
}
