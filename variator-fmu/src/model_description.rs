//! modelDescription.xml, generated from the variable table of
//! [`crate::variables`] with quick-xml (FMI 2.0 element order and attributes).
//!
//! The GUID is a hash (FNV-1a, 128 bit) of the XML written with an empty
//! GUID, so it changes whenever the description changes; `fmi2Instantiate`
//! checks it.

use std::io::Cursor;

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, Event};

use crate::variables::{Causality, ENUM_TYPES, Kind, UNITS, VARIABLES};

/// The FMU's model identifier: the library is `binaries/linux64/ToroidalVariator.so`.
pub const MODEL_IDENTIFIER: &str = "ToroidalVariator";

/// Log categories declared in the XML and accepted by fmi2SetDebugLogging.
pub const LOG_CATEGORIES: &[(&str, &str)] = &[
    (
        "logStatusWarning",
        "Warnings: a model limitation that applies to the current inputs",
    ),
    (
        "logStatusError",
        "Errors: invalid calls, values or parameters",
    ),
    (
        "logStatusFatal",
        "Fatal errors: internal failures; only fmi2FreeInstance may follow",
    ),
    ("logAll", "Every message"),
];

/// FNV-1a, 128-bit (offset basis and prime of the FNV specification).
pub fn fnv1a_128(bytes: &[u8]) -> u128 {
    const OFFSET: u128 = 0x6c62272e07bb014262b821756295c58d;
    const PRIME: u128 = 0x0000000001000000000000000000013B;
    bytes
        .iter()
        .fold(OFFSET, |h, &b| (h ^ u128::from(b)).wrapping_mul(PRIME))
}

/// A real as xs:double that parses back to the same f64.
fn real(x: f64) -> String {
    format!("{x:?}")
}

fn write_xml(guid: &str) -> Result<String, quick_xml::Error> {
    let mut w = Writer::new_with_indent(Cursor::new(Vec::new()), b' ', 2);
    w.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))?;
    let mut root = BytesStart::new("fmiModelDescription");
    root.extend_attributes([
        ("fmiVersion", "2.0"),
        ("modelName", MODEL_IDENTIFIER),
        ("guid", guid),
        (
            "description",
            "Toroidal CVT variator: input disc, n power rollers, output disc; each roller's two lubricated \
             traction contacts by the J+T elastic/plastic model (NASA report), roller speed from its torque \
             balance: disc torques, losses, efficiency and the roller side force from the disc speeds, tilt, \
             end load and inlet temperature.",
        ),
        ("author", "traction developers"),
        ("version", env!("CARGO_PKG_VERSION")),
        (
            "generationTool",
            concat!("traction-variator-fmu ", env!("CARGO_PKG_VERSION")),
        ),
        ("variableNamingConvention", "structured"),
        ("numberOfEventIndicators", "0"),
    ]);
    w.write_event(Event::Start(root))?;
    let mut cs = BytesStart::new("CoSimulation");
    cs.extend_attributes([
        ("modelIdentifier", MODEL_IDENTIFIER),
        ("needsExecutionTool", "false"),
        ("canHandleVariableCommunicationStepSize", "true"),
        ("canInterpolateInputs", "false"),
        ("maxOutputDerivativeOrder", "0"),
        ("canRunAsynchronuously", "false"),
        ("canBeInstantiatedOnlyOncePerProcess", "false"),
        ("canNotUseMemoryManagementFunctions", "true"),
        ("canGetAndSetFMUstate", "true"),
        ("canSerializeFMUstate", "true"),
        ("providesDirectionalDerivative", "false"),
    ]);
    w.write_event(Event::Empty(cs))?;

    w.write_event(Event::Start(BytesStart::new("UnitDefinitions")))?;
    for (name, exps, offset) in UNITS {
        w.write_event(Event::Start(
            BytesStart::new("Unit").with_attributes([("name", *name)]),
        ))?;
        let names = ["kg", "m", "s", "A", "K", "mol", "cd", "rad"];
        let attrs: Vec<(String, String)> = names
            .iter()
            .zip(exps)
            .filter(|(_, e)| **e != 0)
            .map(|(n, e)| ((*n).to_owned(), e.to_string()))
            .chain((*offset != 0.0).then(|| ("offset".to_owned(), real(*offset))))
            .collect();
        let mut base = BytesStart::new("BaseUnit");
        for (n, e) in &attrs {
            base.push_attribute((n.as_str(), e.as_str()));
        }
        w.write_event(Event::Empty(base))?;
        w.write_event(Event::End(BytesEnd::new("Unit")))?;
    }
    w.write_event(Event::End(BytesEnd::new("UnitDefinitions")))?;

    w.write_event(Event::Start(BytesStart::new("TypeDefinitions")))?;
    for (name, description, items) in ENUM_TYPES {
        w.write_event(Event::Start(
            BytesStart::new("SimpleType")
                .with_attributes([("name", *name), ("description", *description)]),
        ))?;
        w.write_event(Event::Start(BytesStart::new("Enumeration")))?;
        for (item, value, d) in *items {
            let v = value.to_string();
            w.write_event(Event::Empty(BytesStart::new("Item").with_attributes([
                ("name", *item),
                ("value", v.as_str()),
                ("description", *d),
            ])))?;
        }
        w.write_event(Event::End(BytesEnd::new("Enumeration")))?;
        w.write_event(Event::End(BytesEnd::new("SimpleType")))?;
    }
    w.write_event(Event::End(BytesEnd::new("TypeDefinitions")))?;

    w.write_event(Event::Start(BytesStart::new("LogCategories")))?;
    for (name, d) in LOG_CATEGORIES {
        w.write_event(Event::Empty(
            BytesStart::new("Category").with_attributes([("name", *name), ("description", *d)]),
        ))?;
    }
    w.write_event(Event::End(BytesEnd::new("LogCategories")))?;
    w.write_event(Event::Empty(
        BytesStart::new("DefaultExperiment").with_attributes([
            ("startTime", "0.0"),
            ("stopTime", "1.0"),
            ("stepSize", "0.001"),
        ]),
    ))?;

    w.write_event(Event::Start(BytesStart::new("ModelVariables")))?;
    for v in VARIABLES {
        let vr = v.vr.to_string();
        let (causality, variability) = match (v.causality, v.kind) {
            (Causality::Parameter, _) => ("parameter", "fixed"),
            (Causality::Input, _) => ("input", "continuous"),
            (Causality::Output, Kind::Real { .. }) => ("output", "continuous"),
            (Causality::Output, _) => ("output", "discrete"),
        };
        let mut sv = BytesStart::new("ScalarVariable");
        sv.extend_attributes([
            ("name", v.name),
            ("valueReference", vr.as_str()),
            ("description", v.description),
            ("causality", causality),
            ("variability", variability),
        ]);
        if v.causality == Causality::Parameter {
            sv.push_attribute(("initial", "exact"));
        }
        w.write_event(Event::Start(sv))?;
        let e = match v.kind {
            Kind::Real { unit, start } => {
                let mut e = BytesStart::new("Real");
                e.push_attribute(("unit", unit));
                if let Some(s) = start {
                    e.push_attribute(("start", real(s).as_str()));
                }
                e
            }
            Kind::Integer { start, min, max } => {
                let mut e = BytesStart::new("Integer");
                e.push_attribute(("min", min.to_string().as_str()));
                e.push_attribute(("max", max.to_string().as_str()));
                e.push_attribute(("start", start.to_string().as_str()));
                e
            }
            Kind::Enumeration { declared, start } => {
                let mut e = BytesStart::new("Enumeration");
                e.push_attribute(("declaredType", declared));
                if let Some(s) = start {
                    e.push_attribute(("start", s.to_string().as_str()));
                }
                e
            }
            Kind::Boolean { start } => BytesStart::new("Boolean")
                .with_attributes([("start", if start { "true" } else { "false" })]),
        };
        w.write_event(Event::Empty(e))?;
        w.write_event(Event::End(BytesEnd::new("ScalarVariable")))?;
    }
    w.write_event(Event::End(BytesEnd::new("ModelVariables")))?;

    // ModelStructure: 1-based indices into ModelVariables.
    let index_of = |name: &str| VARIABLES.iter().position(|v| v.name == name).map(|i| i + 1);
    let inputs: Vec<String> = VARIABLES
        .iter()
        .enumerate()
        .filter(|(_, v)| v.causality == Causality::Input)
        .map(|(i, _)| (i + 1).to_string())
        .collect();
    let all = inputs.join(" ");
    let tilt = index_of("tilt_angle")
        .map(|i| i.to_string())
        .unwrap_or_default();
    w.write_event(Event::Start(BytesStart::new("ModelStructure")))?;
    for section in ["Outputs", "InitialUnknowns"] {
        w.write_event(Event::Start(BytesStart::new(section)))?;
        for (i, v) in VARIABLES.iter().enumerate() {
            if v.causality != Causality::Output {
                continue;
            }
            let idx = (i + 1).to_string();
            let deps = if v.tilt_only {
                tilt.as_str()
            } else {
                all.as_str()
            };
            w.write_event(Event::Empty(
                BytesStart::new("Unknown")
                    .with_attributes([("index", idx.as_str()), ("dependencies", deps)]),
            ))?;
        }
        w.write_event(Event::End(BytesEnd::new(section)))?;
    }
    w.write_event(Event::End(BytesEnd::new("ModelStructure")))?;
    w.write_event(Event::End(BytesEnd::new("fmiModelDescription")))?;
    let mut bytes = w.into_inner().into_inner();
    bytes.push(b'\n');
    String::from_utf8(bytes)
        .map_err(|e| quick_xml::Error::Io(std::sync::Arc::new(std::io::Error::other(e))))
}

/// The GUID: `{…}` formatted FNV-1a-128 hash of the XML with an empty GUID.
pub fn guid() -> String {
    let body = write_xml("").unwrap_or_default();
    let x = format!("{:032x}", fnv1a_128(body.as_bytes()));
    format!(
        "{{{}-{}-{}-{}-{}}}",
        &x[0..8],
        &x[8..12],
        &x[12..16],
        &x[16..20],
        &x[20..32]
    )
}

/// The complete modelDescription.xml.
///
/// # Errors
/// Only if the XML writer fails (it writes to memory, so never in practice).
pub fn model_description_xml() -> Result<String, quick_xml::Error> {
    write_xml(&guid())
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
