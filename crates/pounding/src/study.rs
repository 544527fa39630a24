//! The paper's parametric stick/slip study (filled in by the study work item).
