//! modelDescription.xml, generated from the variable table of
//! [`crate::variables`] with quick-xml (FMI 2.0 element order and attributes).
//!
//! The GUID is a hash (FNV-1a, 128 bit) of the XML written with an empty
//! GUID, so it changes whenever anything in the description changes, and the
//! binary checks it in `fmi2Instantiate`.

use std::io::Cursor;

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, Event};

use crate::variables::{
    Causality, Depends, ENUM_TYPES, Kind, REAL_TYPES, UNITS, VARIABLES, Variability,
};

/// The FMU's model identifier: the shared library is
/// `binaries/linux64/TractionContact.so`.
pub const MODEL_IDENTIFIER: &str = "TractionContact";

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
    (
        "logAll",
        "Every message, including a trace of the FMI calls",
    ),
];

/// FNV-1a, 128-bit (offset basis and prime of the FNV specification).
pub fn fnv1a_128(bytes: &[u8]) -> u128 {
    const OFFSET: u128 = 0x6c62272e07bb014262b821756295c58d;
    const PRIME: u128 = 0x0000000001000000000000000000013B;
    bytes
        .iter()
        .fold(OFFSET, |h, &b| (h ^ u128::from(b)).wrapping_mul(PRIME))
}

/// Formats a real value as xs:double that parses back to the same f64.
fn real(x: f64) -> String {
    if x.is_infinite() {
        if x > 0.0 { "INF".into() } else { "-INF".into() }
    } else {
        format!("{x:?}")
    }
}

fn write_xml(guid: &str) -> Result<String, quick_xml::Error> {
    let mut w = Writer::new_with_indent(Cursor::new(Vec::new()), b' ', 2);
    w.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))?;
    let mut root = BytesStart::new("fmiModelDescription");
    let n_vars = VARIABLES.len().to_string();
    let desc = concat!(
        "Lubricated rolling traction contact between two rotating bodies (J+T elastic/plastic model, ",
        "NASA report): forces, torques, spin moment and losses from load and angular speeds; ",
        "fluids Santotrac 50 and TDF-88 through the report's correlations or user m and mu."
    );
    root.extend_attributes([
        ("fmiVersion", "2.0"),
        ("modelName", MODEL_IDENTIFIER),
        ("guid", guid),
        ("description", desc),
        ("author", "traction developers"),
        ("version", env!("CARGO_PKG_VERSION")),
        (
            "generationTool",
            concat!("traction-fmu ", env!("CARGO_PKG_VERSION")),
        ),
        ("variableNamingConvention", "structured"),
        ("numberOfEventIndicators", "0"),
    ]);
    let _ = n_vars;
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
    for u in UNITS {
        w.write_event(Event::Start(
            BytesStart::new("Unit").with_attributes([("name", u.name)]),
        ))?;
        let names = ["kg", "m", "s", "A", "K", "mol", "cd", "rad"];
        let mut base = BytesStart::new("BaseUnit");
        let exps: Vec<(String, String)> = names
            .iter()
            .zip(u.exponents)
            .filter(|(_, e)| *e != 0)
            .map(|(n, e)| ((*n).to_owned(), e.to_string()))
            .collect();
        for (n, e) in &exps {
            base.push_attribute((n.as_str(), e.as_str()));
        }
        let offset = real(u.offset);
        if u.offset != 0.0 {
            base.push_attribute(("offset", offset.as_str()));
        }
        w.write_event(Event::Empty(base))?;
        w.write_event(Event::End(BytesEnd::new("Unit")))?;
    }
    w.write_event(Event::End(BytesEnd::new("UnitDefinitions")))?;

    w.write_event(Event::Start(BytesStart::new("TypeDefinitions")))?;
    for (name, quantity, unit) in REAL_TYPES {
        w.write_event(Event::Start(
            BytesStart::new("SimpleType").with_attributes([("name", *name)]),
        ))?;
        w.write_event(Event::Empty(
            BytesStart::new("Real").with_attributes([("quantity", *quantity), ("unit", *unit)]),
        ))?;
        w.write_event(Event::End(BytesEnd::new("SimpleType")))?;
    }
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
        let mut sv = BytesStart::new("ScalarVariable");
        sv.extend_attributes([
            ("name", v.name),
            ("valueReference", vr.as_str()),
            ("description", v.description),
            (
                "causality",
                match v.causality {
                    Causality::Parameter => "parameter",
                    Causality::Input => "input",
                    Causality::Output => "output",
                },
            ),
            (
                "variability",
                match v.variability {
                    Variability::Fixed => "fixed",
                    Variability::Discrete => "discrete",
                    Variability::Continuous => "continuous",
                },
            ),
        ]);
        if v.causality == Causality::Parameter {
            sv.push_attribute(("initial", "exact"));
        }
        w.write_event(Event::Start(sv))?;
        match v.kind {
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
                let mut e = BytesStart::new("Real");
                e.extend_attributes([("declaredType", declared), ("unit", unit)]);
                let (min, max, start) = (min.map(real), max.map(real), start.map(real));
                if let Some(m) = &min {
                    e.push_attribute(("min", m.as_str()));
                }
                if let Some(m) = &max {
                    e.push_attribute(("max", m.as_str()));
                }
                if let Some(s) = &start {
                    e.push_attribute(("start", s.as_str()));
                }
                w.write_event(Event::Empty(e))?;
            }
            Kind::Enumeration { declared, start } => {
                let mut e = BytesStart::new("Enumeration");
                e.push_attribute(("declaredType", declared));
                let s = start.map(|s| s.to_string());
                if let Some(s) = &s {
                    e.push_attribute(("start", s.as_str()));
                }
                w.write_event(Event::Empty(e))?;
            }
            Kind::Boolean { start } => {
                let mut e = BytesStart::new("Boolean");
                if let Some(s) = start {
                    e.push_attribute(("start", if s { "true" } else { "false" }));
                }
                w.write_event(Event::Empty(e))?;
            }
        }
        w.write_event(Event::End(BytesEnd::new("ScalarVariable")))?;
    }
    w.write_event(Event::End(BytesEnd::new("ModelVariables")))?;

    // ModelStructure: 1-based indices into ModelVariables.
    let index = |f: &dyn Fn(&crate::variables::Variable) -> bool| -> Vec<usize> {
        VARIABLES
            .iter()
            .enumerate()
            .filter(|(_, v)| f(v))
            .map(|(i, _)| i + 1)
            .collect()
    };
    let inputs = index(&|v| v.causality == Causality::Input);
    let load = index(&|v| v.name == "normal_load");
    let kinematic = index(&|v| {
        v.causality == Causality::Input && v.name != "inlet_temperature" && v.name != "normal_load"
    });
    let join = |xs: &[usize]| {
        xs.iter()
            .map(usize::to_string)
            .collect::<Vec<_>>()
            .join(" ")
    };
    w.write_event(Event::Start(BytesStart::new("ModelStructure")))?;
    for section in ["Outputs", "InitialUnknowns"] {
        w.write_event(Event::Start(BytesStart::new(section)))?;
        for (i, v) in VARIABLES.iter().enumerate() {
            if v.causality != Causality::Output {
                continue;
            }
            let deps = match v.depends {
                Depends::Load => join(&load),
                Depends::Kinematic => join(&kinematic),
                Depends::AllInputs | Depends::None => join(&inputs),
            };
            let idx = (i + 1).to_string();
            w.write_event(Event::Empty(BytesStart::new("Unknown").with_attributes([
                ("index", idx.as_str()),
                ("dependencies", deps.as_str()),
            ])))?;
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
    let h = fnv1a_128(body.as_bytes());
    let x = format!("{h:032x}");
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
    fn fnv_matches_the_published_test_vector() {
        // FNV-1a 128 of the empty string is the offset basis; of "a" per the
        // FNV reference tables: d228cb696f1a8caf78912b704e4a8964.
        assert_eq!(fnv1a_128(b""), 0x6c62272e07bb014262b821756295c58d);
        assert_eq!(fnv1a_128(b"a"), 0xd228cb696f1a8caf78912b704e4a8964);
    }

    #[test]
    fn guid_is_in_the_xml_and_depends_on_the_content() {
        let xml = model_description_xml().unwrap();
        let g = guid();
        assert!(xml.contains(&format!("guid=\"{g}\"")));
        assert_ne!(
            fnv1a_128(xml.as_bytes()),
            fnv1a_128(xml.replace("fx", "fX").as_bytes())
        );
        assert!(real(0.1).parse::<f64>().unwrap() == 0.1);
        assert_eq!(real(2.07e11).parse::<f64>().unwrap(), 2.07e11);
    }
}
