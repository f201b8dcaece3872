//! A closed pipe (`foldcam simulate job.gcode -m grbl-diode --json | head -1`) ends the
//! program quietly with exit status 0, as Unix tools do, instead of a panic (exit 101).

/// Installs a panic hook that exits with status 0 when printing to standard output failed
/// because the reader went away, and reports every other panic as before.
pub fn quiet_on_broken_pipe() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let payload = info.payload();
        let text = payload
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| payload.downcast_ref::<&str>().copied())
            .unwrap_or("");
        if text.starts_with("failed printing to std") && text.contains("Broken pipe") {
            std::process::exit(0);
        }
        previous(info);
    }));
}
