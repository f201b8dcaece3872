//! Where a running layer search is, for a front end to show while it waits: the stage, and
//! while counting, the component and the states found in it so far. The solver writes it
//! (relaxed atomics: a reading may lag by a step, never tear), anyone holding the `Arc` reads.

use std::sync::atomic::{AtomicU8, AtomicU64, AtomicUsize, Ordering};

/// The states count that stands for "counting by splitting".
const SPLITTING: u64 = u64::MAX;

/// The stages of a layer search, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LayerStage {
    /// Not started.
    Waiting,
    /// Folding the faces and overlaying them into cells.
    Arranging,
    /// Building the taco/tortilla and transitivity constraints.
    Constraining,
    /// Counting the independent components' states.
    Counting,
    /// Done (counted, refused or stopped).
    Finished,
}

/// A running layer search's progress; give one to [`super::LayerOptions::progress`] and read
/// it from another thread ([`LayerProgress::describe`]).
#[derive(Debug, Default)]
pub struct LayerProgress {
    stage: AtomicU8,
    component: AtomicUsize,
    components: AtomicUsize,
    variables: AtomicUsize,
    states: AtomicU64,
}

impl PartialEq for LayerProgress {
    /// Every progress reporter compares equal: it watches a search and changes nothing in its
    /// result (so [`super::LayerOptions`] with and without one are the same options).
    fn eq(&self, _: &LayerProgress) -> bool {
        true
    }
}

impl LayerProgress {
    /// The stage the search is in.
    pub fn stage(&self) -> LayerStage {
        match self.stage.load(Ordering::Relaxed) {
            1 => LayerStage::Arranging,
            2 => LayerStage::Constraining,
            3 => LayerStage::Counting,
            4 => LayerStage::Finished,
            _ => LayerStage::Waiting,
        }
    }

    /// The search's state in a few words: "arranging the folded layers", "counting
    /// component 3 of 12 (410 variables): 52000 states so far".
    pub fn describe(&self) -> String {
        match self.stage() {
            LayerStage::Waiting => "starting".into(),
            LayerStage::Arranging => "arranging the folded layers".into(),
            LayerStage::Constraining => "building the layer constraints".into(),
            LayerStage::Counting => {
                let found = match self.states.load(Ordering::Relaxed) {
                    0 => String::new(),
                    SPLITTING => ": counting by splitting into sub-components".into(),
                    states => format!(": {states} states so far"),
                };
                format!(
                    "counting component {} of {} ({} variables){found}",
                    self.component.load(Ordering::Relaxed) + 1,
                    self.components.load(Ordering::Relaxed),
                    self.variables.load(Ordering::Relaxed),
                )
            }
            LayerStage::Finished => "done".into(),
        }
    }

    pub(crate) fn set_stage(&self, stage: LayerStage) {
        let code = match stage {
            LayerStage::Waiting => 0,
            LayerStage::Arranging => 1,
            LayerStage::Constraining => 2,
            LayerStage::Counting => 3,
            LayerStage::Finished => 4,
        };
        self.stage.store(code, Ordering::Relaxed);
    }

    pub(crate) fn set_component(&self, index: usize, of: usize, variables: usize) {
        self.component.store(index, Ordering::Relaxed);
        self.components.store(of, Ordering::Relaxed);
        self.variables.store(variables, Ordering::Relaxed);
        self.states.store(0, Ordering::Relaxed);
    }

    /// The search left enumeration for counting by splitting (states are no longer found
    /// one by one).
    pub(crate) fn splitting(&self) {
        self.states.store(SPLITTING, Ordering::Relaxed);
    }

    pub(crate) fn add_state(&self) {
        self.states.fetch_add(1, Ordering::Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_description_follows_the_stages() {
        let p = LayerProgress::default();
        assert_eq!(p.describe(), "starting");
        p.set_stage(LayerStage::Constraining);
        assert_eq!(p.stage(), LayerStage::Constraining);
        p.set_stage(LayerStage::Counting);
        p.set_component(2, 12, 410);
        p.add_state();
        p.add_state();
        assert_eq!(
            p.describe(),
            "counting component 3 of 12 (410 variables): 2 states so far"
        );
        p.splitting();
        assert!(
            p.describe()
                .ends_with("counting by splitting into sub-components")
        );
    }
}
