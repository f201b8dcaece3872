//! Up-front estimates of long design steps (time and memory), printed before the work starts
//! so that a user can stop a run that would take hours: the voxel pop-up conversion
//! ([`super::popup::voxel::estimate`]) and the tessellation solve
//! ([`super::tessellation::estimate`]).

/// How long a step should take and how much memory it should use.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// Seconds.
    pub seconds: f64,
    /// Bytes.
    pub bytes: f64,
}

impl std::fmt::Display for Estimate {
    /// "about 2 min and 120 MB".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} and {:.0} MB", about(self.seconds), self.bytes / 1e6)
    }
}

/// An estimated time in units a person uses: "under a second", "about 3 s", "about 2 min",
/// "about 2.5 h".
pub(crate) fn about(seconds: f64) -> String {
    let s = seconds.max(0.0);
    if s < 1.0 {
        "under a second".to_string()
    } else if s < 120.0 {
        format!("about {s:.0} s")
    } else if s < 7200.0 {
        format!("about {:.0} min", s / 60.0)
    } else {
        format!("about {:.1} h", s / 3600.0)
    }
}

#[cfg(test)]
mod tests {
    use super::Estimate;

    #[test]
    fn estimates_read_in_units_a_person_uses() {
        let e = |seconds, bytes| Estimate { seconds, bytes }.to_string();
        assert_eq!(e(150.0, 1.2e8), "about 2 min and 120 MB");
        assert_eq!(e(0.2, 9e6), "under a second and 9 MB");
        assert_eq!(e(9000.0, 2e9), "about 2.5 h and 2000 MB");
    }
}
