//! The front end, embedded in the binary: plain ES modules and a style sheet from `studio/`,
//! and three.js r169 (MIT, `studio/vendor/three-LICENSE`) for the 3D view. A fresh machine
//! needs neither node nor a network to build or run the studio.

/// One embedded file: its URL name, content type and bytes.
struct Asset {
    name: &'static str,
    mime: &'static str,
    bytes: &'static [u8],
}

macro_rules! asset {
    ($name:literal, $mime:literal) => {
        Asset {
            name: $name,
            mime: $mime,
            bytes: include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/studio/", $name)),
        }
    };
}

static ASSETS: &[Asset] = &[
    asset!("index.html", "text/html; charset=utf-8"),
    asset!("style.css", "text/css; charset=utf-8"),
    asset!("app.js", "text/javascript; charset=utf-8"),
    asset!("api.js", "text/javascript; charset=utf-8"),
    asset!("cp.js", "text/javascript; charset=utf-8"),
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

#[cfg(test)]
mod tests {
    use super::*;

    const JS: &str = "text/javascript; charset=utf-8";

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
