//! Motion time: how long a machine takes to run a sequence of moves.
//!
//! Baseline model (constant feed, no acceleration); the simulated-machine work replaces it with
//! trapezoidal moves and GRBL's junction-deviation cornering.

use glam::DVec2;

use super::MachineProfile;

/// One straight move.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Move {
    /// Target position, machine coordinates, mm.
    pub to: DVec2,
    /// Feed, mm/min (ignored for rapids, which use the machine's travel feed).
    pub feed_mm_min: f64,
    /// A rapid (tool-off travel) move.
    pub rapid: bool,
}

/// Seconds to run `moves` from `start`.
pub fn job_time(start: DVec2, moves: &[Move], machine: &MachineProfile) -> f64 {
    let mut at = start;
    let mut t = 0.0;
    for m in moves {
        let feed = if m.rapid {
            machine.travel_feed_mm_min
        } else {
            m.feed_mm_min.min(machine.max_feed_mm_min)
        };
        if feed > 0.0 {
            t += at.distance(m.to) / feed * 60.0;
        }
        at = m.to;
    }
    t
}
