//! Why the studio cannot do what a request asks, as data: the stage that failed, the file or
//! document it concerns, and the library's reason. `Display` is the message `foldcam` prints
//! for the same input; the API answers with it and the fields (`{"error", "stage", "file"}`).

use serde::Serialize;

/// What the studio was doing when it failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    /// Reading a pattern file or an upload.
    Read,
    /// Building a design file (a card, a script, a paper craft, a tessellation).
    Design,
    /// Cleaning a pattern into a planar graph.
    Clean,
    /// Folding: a fold script's step, a flat folding's layer order, a folded form.
    Fold,
    /// Loading a machine or material profile.
    Profile,
    /// Planning toolpaths (the plan settings or the planner).
    Plan,
    /// A request's own value out of its range.
    Request,
}

/// A studio failure: see the module docs.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error, Serialize)]
#[error("{}{reason}", file.as_deref().map(|f| format!("{f}: ")).unwrap_or_default())]
pub struct StudioError {
    /// What failed.
    pub stage: Stage,
    /// The file or document it concerns, when the reason does not name it itself.
    pub file: Option<String>,
    /// The library's reason.
    pub reason: String,
}

impl StudioError {
    /// A failure about `file`, for a reason that does not name it.
    pub fn about(stage: Stage, file: impl Into<String>, reason: impl std::fmt::Display) -> Self {
        StudioError {
            stage,
            file: Some(file.into()),
            reason: reason.to_string(),
        }
    }

    /// A failure whose reason names its file itself (the readers' and builders' errors).
    pub fn named(stage: Stage, reason: impl std::fmt::Display) -> Self {
        StudioError {
            stage,
            file: None,
            reason: reason.to_string(),
        }
    }

    /// A request value out of its range.
    pub fn request(reason: impl std::fmt::Display) -> Self {
        StudioError::named(Stage::Request, reason)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_message_names_the_file_once_and_the_fields_are_data() {
        let e = StudioError::about(Stage::Clean, "bird.fold", "edge 3 has zero length");
        assert_eq!(e.to_string(), "bird.fold: edge 3 has zero length");
        let json = serde_json::to_value(&e).unwrap();
        assert_eq!(json["stage"], "clean");
        assert_eq!(json["file"], "bird.fold");
        let named = StudioError::named(Stage::Read, "bird.fold: line 2: not JSON");
        assert_eq!(named.to_string(), "bird.fold: line 2: not JSON");
        assert!(named.file.is_none());
    }
}
