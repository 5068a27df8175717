//! modelDescription.xml, generated from the variable table of
//! [`crate::variables`] with quick-xml (FMI 2.0 element order and attributes).
//!
//! The GUID is a hash (FNV-1a, 128 bit) of the XML written with an empty
//! GUID, so it changes whenever the description changes; `fmi2Instantiate`
//! checks it.

use quick_xml::events::BytesStart;
use traction_fmi_support::xml::{
    Document, LOG_STATUS_ERROR, LOG_STATUS_FATAL, LOG_STATUS_WARNING, LogCategory, Variability,
    XmlResult, XmlWriter, boolean_element, enumeration_element, real_element,
    write_scalar_variable,
};

pub use traction_fmi_support::xml::fnv1a_128;

use crate::variables::{Causality, ENUM_TYPES, Kind, UNITS, VARIABLES};

/// The FMU's model identifier: the library is `binaries/linux64/ToroidalVariator.so`.
pub const MODEL_IDENTIFIER: &str = "ToroidalVariator";

/// Log categories declared in the XML and accepted by fmi2SetDebugLogging:
/// the three of the statuses (traction-fmi-support's, the categories
/// `Status::category` names), then `logAll`.
pub const LOG_CATEGORIES: &[LogCategory] = &[
    LOG_STATUS_WARNING,
    LOG_STATUS_ERROR,
    LOG_STATUS_FATAL,
    ("logAll", "Every message"),
];

/// The description: the variator's identity around the variable table.
const DOCUMENT: Document = Document {
    model_identifier: MODEL_IDENTIFIER,
    description: "Toroidal CVT variator: input disc, n power rollers, output disc; each roller's two lubricated \
             traction contacts by the J+T elastic/plastic model (NASA report), roller speed from its torque \
             balance: disc torques, losses, efficiency and the roller side force from the disc speeds, tilt, \
             end load and inlet temperature.",
    version: env!("CARGO_PKG_VERSION"),
    generation_tool: concat!("traction-variator-fmu ", env!("CARGO_PKG_VERSION")),
    units: UNITS,
    real_types: &[],
    enum_types: ENUM_TYPES,
    log_categories: LOG_CATEGORIES,
    variables: write_model_variables,
    outputs,
};

/// `<ModelVariables>`: one ScalarVariable per row of [`VARIABLES`]; the
/// variability follows from the causality and type.
fn write_model_variables(w: &mut XmlWriter) -> XmlResult {
    for v in VARIABLES {
        let variability = match (v.causality, v.kind) {
            (Causality::Parameter, _) => Variability::Fixed,
            (Causality::Input, _) | (Causality::Output, Kind::Real { .. }) => {
                Variability::Continuous
            }
            (Causality::Output, _) => Variability::Discrete,
        };
        let element = match v.kind {
            Kind::Real { unit, start } => real_element(None, unit, None, None, start),
            Kind::Integer { start, min, max } => {
                let mut e = BytesStart::new("Integer");
                e.push_attribute(("min", min.to_string().as_str()));
                e.push_attribute(("max", max.to_string().as_str()));
                e.push_attribute(("start", start.to_string().as_str()));
                e
            }
            Kind::Enumeration { declared, start } => enumeration_element(declared, start),
            Kind::Boolean { start } => boolean_element(Some(start)),
        };
        write_scalar_variable(
            w,
            v.name,
            v.vr,
            v.description,
            v.causality,
            variability,
            element,
        )?;
    }
    Ok(())
}

/// Every output (1-based index) with its dependencies: all inputs, or only
/// `tilt_angle` for the outputs of the geometry; the same in `<Outputs>` and
/// `<InitialUnknowns>` (the parameters are not listed).
fn outputs(_initialization: bool) -> Vec<(usize, String)> {
    let index_of = |name: &str| VARIABLES.iter().position(|v| v.name == name).map(|i| i + 1);
    let all = VARIABLES
        .iter()
        .enumerate()
        .filter(|(_, v)| v.causality == Causality::Input)
        .map(|(i, _)| (i + 1).to_string())
        .collect::<Vec<_>>()
        .join(" ");
    let tilt = index_of("tilt_angle")
        .map(|i| i.to_string())
        .unwrap_or_default();
    VARIABLES
        .iter()
        .enumerate()
        .filter(|(_, v)| v.causality == Causality::Output)
        .map(|(i, v)| (i + 1, if v.tilt_only { &tilt } else { &all }.clone()))
        .collect()
}

/// The GUID: `{…}` formatted FNV-1a-128 hash of the XML with an empty GUID.
///
/// Computed once per process (writing the XML to hash it takes ≈ 0.2 ms,
/// which `fmi2Instantiate` would otherwise pay for every instance).
pub fn guid() -> String {
    static GUID: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    GUID.get_or_init(|| DOCUMENT.guid()).clone()
}

/// The complete modelDescription.xml, with the process's cached [`guid`].
///
/// # Errors
/// Only if the XML writer fails (it writes to memory, so never in practice).
pub fn model_description_xml() -> Result<String, quick_xml::Error> {
    DOCUMENT.xml_with_guid(&guid())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn guid_is_in_the_xml_and_the_table_is_complete() {
        let xml = model_description_xml().unwrap();
        assert!(xml.contains(&format!("guid=\"{}\"", guid())));
        for v in VARIABLES {
            assert!(xml.contains(&format!("name=\"{}\"", v.name)), "{}", v.name);
        }
        assert_eq!(fnv1a_128(b"a"), 0xd228cb696f1a8caf78912b704e4a8964);
    }
}
