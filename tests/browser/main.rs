//! The studio in headless Chromium over WebDriver (Debian's `chromium` and `chromium-driver`):
//! pointer drags, panels and the README's screenshots.
//!
//! One test binary: each module is the tests of one part, so the crate is linked once.

#[path = "../common/bin.rs"]
mod bin;
#[path = "../common/browser.rs"]
mod browser;
#[path = "../common/lines.rs"]
mod lines;
#[path = "../common/studio.rs"]
mod studio;

mod studio_browser;
mod studio_browser_canvas;
mod studio_browser_craft;
mod studio_browser_guard;
mod studio_browser_popup;
mod studio_browser_save;
mod studio_browser_tessellate;
mod studio_browser_voxel;
