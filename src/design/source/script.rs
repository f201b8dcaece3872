//! Fold scripts (TOML: a sheet, then bend, fold, tuck and drag steps) run on the origami
//! simulator of Miyazaki et al. (1992): the crease pattern (mountain/valley from the final
//! state) and the folded state after every step — what `foldcam fold` does before it writes
//! anything.

use super::summary::SummaryLine;
use super::{DesignFile, DesignKind, Progress, SourceError};
use crate::design::folding::Folding;
use crate::design::folding::crease::{SheetPattern, crease_pattern, step_states};
use crate::design::folding::layers::{LayerProblem, layer_problems};
use crate::design::folding::script::{Script, parse_script, run_script};
use crate::pattern::FoldedState;

/// A folded script.
#[derive(Clone, Debug)]
pub struct ScriptDesign {
    /// The script's name, as given.
    pub name: String,
    /// The script as read.
    pub script: Script,
    /// The folding, every step kept.
    pub folding: Folding,
    /// The crease pattern (titled as the script), with each pattern face's cell.
    pub sheet: SheetPattern,
    /// The folded state after each step on the pattern's topology (the first is the flat
    /// sheet).
    pub states: Vec<FoldedState>,
    /// Layer-order problems of the final state.
    pub warnings: Vec<LayerProblem>,
    /// What `foldcam fold` prints once written, up to where it names the output
    /// ("… written to FILE" follows).
    pub summary: SummaryLine,
}

impl ScriptDesign {
    /// As one design: the crease pattern, folded as after the last step.
    pub fn into_design(self) -> super::Design {
        let mut summary: Vec<SummaryLine> = self
            .warnings
            .iter()
            .map(|&problem| SummaryLine::LayerWarning {
                file: self.name.clone(),
                problem,
            })
            .collect();
        summary.push(self.summary);
        super::Design {
            kind: DesignKind::FoldScript,
            made: "fold sequence (Miyazaki et al. 1992)",
            pattern: self.sheet.pattern,
            folded: None,
            summary,
            sheets: 1,
        }
    }
}

/// Runs the script `file`.
///
/// # Errors
/// Bad input naming the file: a bad script, or the step that cannot be folded.
pub fn build(
    file: &DesignFile<'_>,
    progress: &mut dyn Progress,
) -> Result<ScriptDesign, SourceError> {
    let name = file.display();
    let at = |e: &dyn std::fmt::Display| SourceError::Input {
        file: name.clone(),
        message: e.to_string(),
    };
    let script = parse_script(file.text()?).map_err(|e| at(&e))?;
    progress.busy("folding");
    let folding = run_script(&script);
    progress.idle();
    let folding = folding.map_err(|e| at(&e))?;
    let mut sheet = crease_pattern(&folding);
    sheet.pattern.meta.title = script.title.clone();
    let states = step_states(&folding, &sheet);
    let warnings = layer_problems(&folding, folding.current());
    let cp = &sheet.pattern;
    let summary = SummaryLine::FoldSequence {
        file: name.clone(),
        steps: folding.steps().len() - 1,
        faces: folding.current().faces.len(),
        vertices: cp.vertices.len(),
        edges: cp.edges.len(),
    };
    Ok(ScriptDesign {
        name,
        script,
        folding,
        sheet,
        states,
        warnings,
        summary,
    })
}
