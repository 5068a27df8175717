//! modelDescription.xml, generated from the variable table of
//! [`crate::variables`] with quick-xml (FMI 2.0 element order and attributes).
//!
//! The GUID is a hash (FNV-1a, 128 bit) of the XML written with an empty
//! GUID, so it changes whenever anything in the description changes, and the
//! binary checks it in `fmi2Instantiate`.

use traction_fmi_support::xml::{
    Document, LOG_STATUS_ERROR, LOG_STATUS_FATAL, LOG_STATUS_WARNING, LogCategory, XmlResult,
    XmlWriter, boolean_element, enumeration_element, real_element, write_scalar_variable,
};

pub use traction_fmi_support::xml::fnv1a_128;

use crate::variables::{Causality, ENUM_TYPES, Kind, REAL_TYPES, UNITS, VARIABLES, Variable};

/// The FMU's model identifier: the shared libraries are
/// `binaries/linux64/TractionContact.so` and `binaries/win64/TractionContact.dll`.
pub const MODEL_IDENTIFIER: &str = "TractionContact";

/// Log categories declared in the XML and accepted by fmi2SetDebugLogging:
/// the three of the statuses (traction-fmi-support's, the categories
/// `Status::category` names), then `logAll`.
pub const LOG_CATEGORIES: &[LogCategory] = &[
    LOG_STATUS_WARNING,
    LOG_STATUS_ERROR,
    LOG_STATUS_FATAL,
    (
        "logAll",
        "Every message, including a trace of the FMI calls",
    ),
];

/// The description: the contact's identity around the variable table.
const DOCUMENT: Document = Document {
    model_identifier: MODEL_IDENTIFIER,
    description: concat!(
        "Lubricated rolling traction contact between two rotating bodies (J+T elastic/plastic model, ",
        "NASA report): forces, torques, spin moment and losses from load and angular speeds; ",
        "fluids Santotrac 50 and TDF-88 through the report's correlations or user m and mu."
    ),
    version: env!("CARGO_PKG_VERSION"),
    generation_tool: concat!("traction-fmu ", env!("CARGO_PKG_VERSION")),
    units: UNITS,
    real_types: REAL_TYPES,
    enum_types: ENUM_TYPES,
    log_categories: LOG_CATEGORIES,
    variables: write_model_variables,
    outputs,
};

/// `<ModelVariables>`: one ScalarVariable per row of [`VARIABLES`].
fn write_model_variables(w: &mut XmlWriter) -> XmlResult {
    for v in VARIABLES {
        let element = match v.kind {
            Kind::Real {
                declared,
                start,
                min,
                max,
            } => {
                let unit = REAL_TYPES
                    .iter()
                    .find(|t| t.0 == declared)
                    .map_or("1", |t| t.2);
                real_element(Some(declared), unit, min, max, start)
            }
            Kind::Enumeration { declared, start } => enumeration_element(declared, start),
            Kind::Boolean { start } => boolean_element(start),
        };
        write_scalar_variable(
            w,
            v.name,
            v.vr,
            v.description,
            v.causality,
            v.variability,
            element,
        )?;
    }
    Ok(())
}

/// The 1-based ModelVariables indices of the knowns an output depends on:
/// in `<Outputs>` the inputs, in `<InitialUnknowns>` the inputs and the
/// parameters (all `initial="exact"`, so known in Initialization Mode).
pub fn dependencies(output: &Variable, initialization: bool) -> Vec<usize> {
    VARIABLES
        .iter()
        .enumerate()
        .filter(|(_, k)| {
            (k.causality == Causality::Input
                || (initialization && k.causality == Causality::Parameter))
                && output.depends.includes(k)
        })
        .map(|(i, _)| i + 1)
        .collect()
}

/// Every output (1-based index) with its dependencies, for `<Outputs>`
/// (`initialization` false) and `<InitialUnknowns>` (true).
fn outputs(initialization: bool) -> Vec<(usize, String)> {
    VARIABLES
        .iter()
        .enumerate()
        .filter(|(_, v)| v.causality == Causality::Output)
        .map(|(i, v)| {
            let deps: Vec<String> = dependencies(v, initialization)
                .iter()
                .map(usize::to_string)
                .collect();
            (i + 1, deps.join(" "))
        })
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
    fn guid_is_in_the_xml_and_depends_on_the_content() {
        let xml = model_description_xml().unwrap();
        let g = guid();
        assert!(xml.contains(&format!("guid=\"{g}\"")));
        assert_ne!(
            fnv1a_128(xml.as_bytes()),
            fnv1a_128(xml.replace("fx", "fX").as_bytes())
        );
    }
}
