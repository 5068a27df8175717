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
    Causality, ENUM_TYPES, Kind, REAL_TYPES, UNITS, VARIABLES, Variability, Variable,
};

/// The FMU's model identifier: the shared libraries are
/// `binaries/linux64/TractionContact.so` and `binaries/win64/TractionContact.dll`.
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

type XmlWriter = Writer<Cursor<Vec<u8>>>;
type XmlResult = Result<(), quick_xml::Error>;

fn write_xml(guid: &str) -> Result<String, quick_xml::Error> {
    let mut w = Writer::new_with_indent(Cursor::new(Vec::new()), b' ', 2);
    w.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))?;
    w.write_event(Event::Start(root_element(guid)))?;
    write_capabilities(&mut w)?;
    write_unit_definitions(&mut w)?;
    write_type_definitions(&mut w)?;
    write_log_categories(&mut w)?;
    w.write_event(Event::Empty(
        BytesStart::new("DefaultExperiment").with_attributes([
            ("startTime", "0.0"),
            ("stopTime", "1.0"),
            ("stepSize", "0.001"),
        ]),
    ))?;
    write_model_variables(&mut w)?;
    write_model_structure(&mut w)?;
    w.write_event(Event::End(BytesEnd::new("fmiModelDescription")))?;
    let mut bytes = w.into_inner().into_inner();
    bytes.push(b'\n');
    String::from_utf8(bytes)
        .map_err(|e| quick_xml::Error::Io(std::sync::Arc::new(std::io::Error::other(e))))
}

/// `<fmiModelDescription ...>` with the model's identity.
fn root_element(guid: &str) -> BytesStart<'_> {
    let mut root = BytesStart::new("fmiModelDescription");
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
    root
}

/// `<CoSimulation>`: what the binary supports.
fn write_capabilities(w: &mut XmlWriter) -> XmlResult {
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
    Ok(())
}

/// `<UnitDefinitions>` from [`UNITS`].
fn write_unit_definitions(w: &mut XmlWriter) -> XmlResult {
    const BASE_UNITS: [&str; 8] = ["kg", "m", "s", "A", "K", "mol", "cd", "rad"];
    w.write_event(Event::Start(BytesStart::new("UnitDefinitions")))?;
    for u in UNITS {
        w.write_event(Event::Start(
            BytesStart::new("Unit").with_attributes([("name", u.name)]),
        ))?;
        let mut base = BytesStart::new("BaseUnit");
        for (n, e) in BASE_UNITS.iter().zip(u.exponents) {
            if e != 0 {
                base.push_attribute((*n, e.to_string().as_str()));
            }
        }
        if u.offset != 0.0 {
            base.push_attribute(("offset", real(u.offset).as_str()));
        }
        w.write_event(Event::Empty(base))?;
        w.write_event(Event::End(BytesEnd::new("Unit")))?;
    }
    w.write_event(Event::End(BytesEnd::new("UnitDefinitions")))?;
    Ok(())
}

/// `<TypeDefinitions>`: the Real and Enumeration SimpleTypes.
fn write_type_definitions(w: &mut XmlWriter) -> XmlResult {
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
    Ok(())
}

/// `<LogCategories>` from [`LOG_CATEGORIES`].
fn write_log_categories(w: &mut XmlWriter) -> XmlResult {
    w.write_event(Event::Start(BytesStart::new("LogCategories")))?;
    for (name, d) in LOG_CATEGORIES {
        w.write_event(Event::Empty(
            BytesStart::new("Category").with_attributes([("name", *name), ("description", *d)]),
        ))?;
    }
    w.write_event(Event::End(BytesEnd::new("LogCategories")))?;
    Ok(())
}

/// `<ModelVariables>`: one ScalarVariable per row of [`VARIABLES`].
fn write_model_variables(w: &mut XmlWriter) -> XmlResult {
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
        w.write_event(Event::Empty(type_element(v.kind)))?;
        w.write_event(Event::End(BytesEnd::new("ScalarVariable")))?;
    }
    w.write_event(Event::End(BytesEnd::new("ModelVariables")))?;
    Ok(())
}

/// The `<Real>`, `<Enumeration>` or `<Boolean>` element of a variable.
fn type_element(kind: Kind) -> BytesStart<'static> {
    match kind {
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
            for (attribute, value) in [("min", min), ("max", max), ("start", start)] {
                if let Some(x) = value {
                    e.push_attribute((attribute, real(x).as_str()));
                }
            }
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
        Kind::Boolean { start } => {
            let mut e = BytesStart::new("Boolean");
            if let Some(s) = start {
                e.push_attribute(("start", if s { "true" } else { "false" }));
            }
            e
        }
    }
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

/// `<ModelStructure>`: every output in `<Outputs>` and `<InitialUnknowns>`.
fn write_model_structure(w: &mut XmlWriter) -> XmlResult {
    w.write_event(Event::Start(BytesStart::new("ModelStructure")))?;
    for (section, initialization) in [("Outputs", false), ("InitialUnknowns", true)] {
        w.write_event(Event::Start(BytesStart::new(section)))?;
        for (i, v) in VARIABLES.iter().enumerate() {
            if v.causality != Causality::Output {
                continue;
            }
            let deps: Vec<String> = dependencies(v, initialization)
                .iter()
                .map(usize::to_string)
                .collect();
            let idx = (i + 1).to_string();
            w.write_event(Event::Empty(BytesStart::new("Unknown").with_attributes([
                ("index", idx.as_str()),
                ("dependencies", deps.join(" ").as_str()),
            ])))?;
        }
        w.write_event(Event::End(BytesEnd::new(section)))?;
    }
    w.write_event(Event::End(BytesEnd::new("ModelStructure")))?;
    Ok(())
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
