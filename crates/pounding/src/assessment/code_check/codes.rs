//! The codes whose seat-length requirements are checked, in the tables' column order.

/// A code of [`super`], in the table's column order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Code {
    /// EN 1998-2 §6.6.4.
    Ec8,
    /// AASHTO LRFD 4.7.4.4.
    AashtoLrfd,
    /// AASHTO Guide Specifications for LRFD Seismic Bridge Design §4.12.
    AashtoGuide,
    /// Caltrans Seismic Design Criteria 1.7.
    Caltrans,
    /// JRA Specifications for Highway Bridges Part V §16.2.
    Jra,
}

/// Every code, in column order.
pub const CODES: [Code; 5] = [
    Code::Ec8,
    Code::AashtoLrfd,
    Code::AashtoGuide,
    Code::Caltrans,
    Code::Jra,
];

impl Code {
    /// Column name: `ec8`, `aashto_lrfd`, `aashto_guide`, `caltrans`, `jra`.
    pub fn name(self) -> &'static str {
        match self {
            Code::Ec8 => "ec8",
            Code::AashtoLrfd => "aashto_lrfd",
            Code::AashtoGuide => "aashto_guide",
            Code::Caltrans => "caltrans",
            Code::Jra => "jra",
        }
    }
    /// The code and clause, for people.
    pub fn title(self) -> &'static str {
        match self {
            Code::Ec8 => "EN 1998-2 §6.6.4",
            Code::AashtoLrfd => "AASHTO LRFD 4.7.4.4",
            Code::AashtoGuide => "AASHTO Guide Spec §4.12",
            Code::Caltrans => "Caltrans SDC 1.7",
            Code::Jra => "JRA V §16.2",
        }
    }
}
