//! The parts of an FMI 2.0 co-simulation modelDescription.xml that do not
//! depend on a model's variables, written with quick-xml in the standard's
//! element order, and the GUID.
//!
//! An FMU describes itself as a [`Document`]: its identity, units, simple
//! types, log categories, and two functions of its own variable table, one
//! writing `<ModelVariables>` (with [`write_scalar_variable`] and the type
//! elements [`real_element`], [`enumeration_element`], [`boolean_element`])
//! and one listing each output's dependencies for `<ModelStructure>`.
//! [`Document::guid`] is the FNV-1a-128 hash of the XML written with an empty
//! GUID, so it changes whenever anything in the description changes, and
//! each FMU checks it in `fmi2Instantiate`.

use std::io::Cursor;

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, Event};

/// The in-memory XML writer (indent: two spaces).
pub type XmlWriter = Writer<Cursor<Vec<u8>>>;
/// Result of writing one part.
pub type XmlResult = Result<(), quick_xml::Error>;

/// The SI base units of `<BaseUnit>`, in the order of [`Unit::exponents`].
pub const BASE_UNITS: [&str; 8] = ["kg", "m", "s", "A", "K", "mol", "cd", "rad"];

/// A unit of UnitDefinitions: name, SI base-unit exponents
/// `[kg, m, s, A, K, mol, cd, rad]` and offset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    /// Unit name as used in `unit=`.
    pub name: &'static str,
    /// Exponents of kg, m, s, A, K, mol, cd, rad.
    pub exponents: [i32; 8],
    /// Offset to the SI base unit (degC: 273.15).
    pub offset: f64,
}

impl Unit {
    /// A unit from its name, exponents and offset.
    pub const fn new(name: &'static str, exponents: [i32; 8], offset: f64) -> Self {
        Self {
            name,
            exponents,
            offset,
        }
    }
}

/// A Real SimpleType: name, quantity, unit.
pub type RealType = (&'static str, &'static str, &'static str);
/// An enumeration item: name, value, description.
pub type EnumItem = (&'static str, i32, &'static str);
/// An enumeration SimpleType: name, description, items.
pub type EnumType = (&'static str, &'static str, &'static [EnumItem]);
/// A log category: name, description.
pub type LogCategory = (&'static str, &'static str);

/// The log category of warnings ([`crate::Status::category`] of
/// [`crate::Status::Warning`]).
pub const LOG_STATUS_WARNING: LogCategory = (
    "logStatusWarning",
    "Warnings: a model limitation that applies to the current inputs",
);
/// The log category of errors ([`crate::Status::category`] of
/// [`crate::Status::Error`] and [`crate::Status::Discard`]).
pub const LOG_STATUS_ERROR: LogCategory = (
    "logStatusError",
    "Errors: invalid calls, values or parameters",
);
/// The log category of fatal errors ([`crate::Status::category`] of
/// [`crate::Status::Fatal`]).
pub const LOG_STATUS_FATAL: LogCategory = (
    "logStatusFatal",
    "Fatal errors: internal failures; only fmi2FreeInstance may follow",
);

/// FMI 2 causality of a variable.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Causality {
    /// `parameter`.
    Parameter,
    /// `input`.
    Input,
    /// `output`.
    Output,
}

impl Causality {
    /// The attribute value.
    pub fn as_str(self) -> &'static str {
        match self {
            Causality::Parameter => "parameter",
            Causality::Input => "input",
            Causality::Output => "output",
        }
    }
}

/// FMI 2 variability of a variable.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variability {
    /// `fixed`: set before initialization ends, constant afterwards.
    Fixed,
    /// `discrete`: changes only at communication points (Integer, Enumeration).
    Discrete,
    /// `continuous` (Real only).
    Continuous,
}

impl Variability {
    /// The attribute value.
    pub fn as_str(self) -> &'static str {
        match self {
            Variability::Fixed => "fixed",
            Variability::Discrete => "discrete",
            Variability::Continuous => "continuous",
        }
    }
}

/// Formats a real value as xs:double that parses back to the same f64
/// (`INF`, `-INF` for the infinities).
pub fn real(x: f64) -> String {
    if x.is_infinite() {
        if x > 0.0 { "INF".into() } else { "-INF".into() }
    } else {
        format!("{x:?}")
    }
}

/// FNV-1a, 128-bit (offset basis and prime of the FNV specification).
pub fn fnv1a_128(bytes: &[u8]) -> u128 {
    const OFFSET: u128 = 0x6c62272e07bb014262b821756295c58d;
    const PRIME: u128 = 0x0000000001000000000000000000013B;
    bytes
        .iter()
        .fold(OFFSET, |h, &b| (h ^ u128::from(b)).wrapping_mul(PRIME))
}

/// The GUID of a description: its FNV-1a-128 hash as `{8-4-4-4-12}` hex.
pub fn guid_of(body: &[u8]) -> String {
    let x = format!("{:032x}", fnv1a_128(body));
    format!(
        "{{{}-{}-{}-{}-{}}}",
        &x[0..8],
        &x[8..12],
        &x[12..16],
        &x[16..20],
        &x[20..32]
    )
}

/// One FMU's modelDescription.xml: everything but the variable table is
/// data; the table enters through two functions.
#[derive(Debug, Clone, Copy)]
pub struct Document {
    /// `modelName` and the `<CoSimulation>` `modelIdentifier` (the shared
    /// library's name).
    pub model_identifier: &'static str,
    /// The root's `description`.
    pub description: &'static str,
    /// The root's `version` (the FMU crate's version).
    pub version: &'static str,
    /// The root's `generationTool`.
    pub generation_tool: &'static str,
    /// `<UnitDefinitions>`.
    pub units: &'static [Unit],
    /// The Real SimpleTypes of `<TypeDefinitions>` (written first).
    pub real_types: &'static [RealType],
    /// The Enumeration SimpleTypes of `<TypeDefinitions>`.
    pub enum_types: &'static [EnumType],
    /// `<LogCategories>`.
    pub log_categories: &'static [LogCategory],
    /// Writes the `<ScalarVariable>` elements inside `<ModelVariables>`.
    pub variables: fn(&mut XmlWriter) -> XmlResult,
    /// Every output as (1-based ModelVariables index, its dependencies as
    /// space-separated indices), for `<Outputs>` (`false`) and
    /// `<InitialUnknowns>` (`true`).
    pub outputs: fn(initialization: bool) -> Vec<(usize, String)>,
}

impl Document {
    /// The complete XML with this GUID (ends with a newline).
    ///
    /// # Errors
    /// Only if the XML writer fails (it writes to memory, so never in practice).
    pub fn xml_with_guid(&self, guid: &str) -> Result<String, quick_xml::Error> {
        let mut w = Writer::new_with_indent(Cursor::new(Vec::new()), b' ', 2);
        w.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))?;
        w.write_event(Event::Start(self.root_element(guid)))?;
        w.write_event(Event::Empty(self.capabilities()))?;
        self.write_unit_definitions(&mut w)?;
        self.write_type_definitions(&mut w)?;
        self.write_log_categories(&mut w)?;
        w.write_event(Event::Empty(
            BytesStart::new("DefaultExperiment").with_attributes([
                ("startTime", "0.0"),
                ("stopTime", "1.0"),
                ("stepSize", "0.001"),
            ]),
        ))?;
        w.write_event(Event::Start(BytesStart::new("ModelVariables")))?;
        (self.variables)(&mut w)?;
        w.write_event(Event::End(BytesEnd::new("ModelVariables")))?;
        self.write_model_structure(&mut w)?;
        w.write_event(Event::End(BytesEnd::new("fmiModelDescription")))?;
        let mut bytes = w.into_inner().into_inner();
        bytes.push(b'\n');
        String::from_utf8(bytes)
            .map_err(|e| quick_xml::Error::Io(std::sync::Arc::new(std::io::Error::other(e))))
    }

    /// The GUID: [`guid_of`] the XML written with an empty GUID.
    pub fn guid(&self) -> String {
        guid_of(self.xml_with_guid("").unwrap_or_default().as_bytes())
    }

    /// The complete XML with its [`Document::guid`].
    ///
    /// # Errors
    /// Only if the XML writer fails (it writes to memory, so never in practice).
    pub fn xml(&self) -> Result<String, quick_xml::Error> {
        self.xml_with_guid(&self.guid())
    }

    /// `<fmiModelDescription ...>` with the model's identity.
    fn root_element<'a>(&'a self, guid: &'a str) -> BytesStart<'a> {
        let mut root = BytesStart::new("fmiModelDescription");
        root.extend_attributes([
            ("fmiVersion", "2.0"),
            ("modelName", self.model_identifier),
            ("guid", guid),
            ("description", self.description),
            ("author", "traction developers"),
            ("version", self.version),
            ("generationTool", self.generation_tool),
            ("variableNamingConvention", "structured"),
            ("numberOfEventIndicators", "0"),
        ]);
        root
    }

    /// `<CoSimulation>`: what the FMUs' binaries support (the same for both).
    fn capabilities(&self) -> BytesStart<'static> {
        let mut cs = BytesStart::new("CoSimulation");
        cs.extend_attributes([
            ("modelIdentifier", self.model_identifier),
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
        cs
    }

    /// `<UnitDefinitions>`.
    fn write_unit_definitions(&self, w: &mut XmlWriter) -> XmlResult {
        w.write_event(Event::Start(BytesStart::new("UnitDefinitions")))?;
        for u in self.units {
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

    /// `<TypeDefinitions>`: the Real, then the Enumeration SimpleTypes.
    fn write_type_definitions(&self, w: &mut XmlWriter) -> XmlResult {
        w.write_event(Event::Start(BytesStart::new("TypeDefinitions")))?;
        for (name, quantity, unit) in self.real_types {
            w.write_event(Event::Start(
                BytesStart::new("SimpleType").with_attributes([("name", *name)]),
            ))?;
            w.write_event(Event::Empty(
                BytesStart::new("Real").with_attributes([("quantity", *quantity), ("unit", *unit)]),
            ))?;
            w.write_event(Event::End(BytesEnd::new("SimpleType")))?;
        }
        for (name, description, items) in self.enum_types {
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

    /// `<LogCategories>`.
    fn write_log_categories(&self, w: &mut XmlWriter) -> XmlResult {
        w.write_event(Event::Start(BytesStart::new("LogCategories")))?;
        for (name, d) in self.log_categories {
            w.write_event(Event::Empty(
                BytesStart::new("Category").with_attributes([("name", *name), ("description", *d)]),
            ))?;
        }
        w.write_event(Event::End(BytesEnd::new("LogCategories")))?;
        Ok(())
    }

    /// `<ModelStructure>`: every output in `<Outputs>` and `<InitialUnknowns>`.
    fn write_model_structure(&self, w: &mut XmlWriter) -> XmlResult {
        w.write_event(Event::Start(BytesStart::new("ModelStructure")))?;
        for (section, initialization) in [("Outputs", false), ("InitialUnknowns", true)] {
            w.write_event(Event::Start(BytesStart::new(section)))?;
            for (index, deps) in (self.outputs)(initialization) {
                let idx = index.to_string();
                w.write_event(Event::Empty(BytesStart::new("Unknown").with_attributes([
                    ("index", idx.as_str()),
                    ("dependencies", deps.as_str()),
                ])))?;
            }
            w.write_event(Event::End(BytesEnd::new(section)))?;
        }
        w.write_event(Event::End(BytesEnd::new("ModelStructure")))?;
        Ok(())
    }
}

/// Writes one `<ScalarVariable>` (parameters get `initial="exact"`) around
/// its type element.
///
/// # Errors
/// The XML writer's.
pub fn write_scalar_variable(
    w: &mut XmlWriter,
    name: &str,
    value_reference: u32,
    description: &str,
    causality: Causality,
    variability: Variability,
    type_element: BytesStart<'_>,
) -> XmlResult {
    let vr = value_reference.to_string();
    let mut sv = BytesStart::new("ScalarVariable");
    sv.extend_attributes([
        ("name", name),
        ("valueReference", vr.as_str()),
        ("description", description),
        ("causality", causality.as_str()),
        ("variability", variability.as_str()),
    ]);
    if causality == Causality::Parameter {
        sv.push_attribute(("initial", "exact"));
    }
    w.write_event(Event::Start(sv))?;
    w.write_event(Event::Empty(type_element))?;
    w.write_event(Event::End(BytesEnd::new("ScalarVariable")))?;
    Ok(())
}

/// `<Real>`: `declaredType` (if any), `unit`, then `min`, `max`, `start`
/// where given.
pub fn real_element(
    declared: Option<&str>,
    unit: &str,
    min: Option<f64>,
    max: Option<f64>,
    start: Option<f64>,
) -> BytesStart<'static> {
    let mut e = BytesStart::new("Real");
    if let Some(d) = declared {
        e.push_attribute(("declaredType", d));
    }
    e.push_attribute(("unit", unit));
    for (attribute, value) in [("min", min), ("max", max), ("start", start)] {
        if let Some(x) = value {
            e.push_attribute((attribute, real(x).as_str()));
        }
    }
    e
}

/// `<Enumeration declaredType=... start=...>` (`start` where given).
pub fn enumeration_element(declared: &str, start: Option<i32>) -> BytesStart<'static> {
    let mut e = BytesStart::new("Enumeration");
    e.push_attribute(("declaredType", declared));
    if let Some(s) = start {
        e.push_attribute(("start", s.to_string().as_str()));
    }
    e
}

/// `<Boolean start=...>` (`start` where given).
pub fn boolean_element(start: Option<bool>) -> BytesStart<'static> {
    let mut e = BytesStart::new("Boolean");
    if let Some(s) = start {
        e.push_attribute(("start", if s { "true" } else { "false" }));
    }
    e
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
        assert_eq!(guid_of(b"a"), "{d228cb69-6f1a-8caf-7891-2b704e4a8964}");
    }

    #[test]
    fn reals_parse_back_and_infinities_are_xs_double() {
        for x in [0.1, 2.07e11, 273.15, -1e-300, 5e-7] {
            assert_eq!(real(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(
            (
                real(f64::INFINITY).as_str(),
                real(f64::NEG_INFINITY).as_str()
            ),
            ("INF", "-INF")
        );
    }

    fn variables(w: &mut XmlWriter) -> XmlResult {
        write_scalar_variable(
            w,
            "k",
            1,
            "stiffness, N/m",
            Causality::Parameter,
            Variability::Fixed,
            real_element(None, "N/m", Some(0.0), None, Some(2.5)),
        )?;
        write_scalar_variable(
            w,
            "mode",
            2,
            "a mode",
            Causality::Input,
            Variability::Discrete,
            enumeration_element("Mode", None),
        )?;
        write_scalar_variable(
            w,
            "on",
            3,
            "switch",
            Causality::Output,
            Variability::Discrete,
            boolean_element(Some(true)),
        )
    }

    fn outputs(initialization: bool) -> Vec<(usize, String)> {
        vec![(3, if initialization { "1 2" } else { "2" }.to_owned())]
    }

    const DOC: Document = Document {
        model_identifier: "Spring",
        description: "a spring & a <switch>",
        version: "1.0",
        generation_tool: "test",
        units: &[
            Unit::new("N/m", [1, 0, -2, 0, 0, 0, 0, 0], 0.0),
            Unit::new("degC", [0, 0, 0, 0, 1, 0, 0, 0], 273.15),
        ],
        real_types: &[],
        enum_types: &[("Mode", "modes", &[("a", 1, "first"), ("b", 2, "second")])],
        log_categories: &[("logAll", "everything")],
        variables,
        outputs,
    };

    /// The expected document, written out by hand from the FMI 2.0 standard's
    /// element order (fmi2ModelDescription.xsd).
    #[test]
    fn a_small_document_is_written_in_the_standards_order() {
        let xml = DOC.xml_with_guid("{g}").unwrap();
        let expected = r#"<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="Spring" guid="{g}" description="a spring &amp; a &lt;switch&gt;" author="traction developers" version="1.0" generationTool="test" variableNamingConvention="structured" numberOfEventIndicators="0">
  <CoSimulation modelIdentifier="Spring" needsExecutionTool="false" canHandleVariableCommunicationStepSize="true" canInterpolateInputs="false" maxOutputDerivativeOrder="0" canRunAsynchronuously="false" canBeInstantiatedOnlyOncePerProcess="false" canNotUseMemoryManagementFunctions="true" canGetAndSetFMUstate="true" canSerializeFMUstate="true" providesDirectionalDerivative="false"/>
  <UnitDefinitions>
    <Unit name="N/m">
      <BaseUnit kg="1" s="-2"/>
    </Unit>
    <Unit name="degC">
      <BaseUnit K="1" offset="273.15"/>
    </Unit>
  </UnitDefinitions>
  <TypeDefinitions>
    <SimpleType name="Mode" description="modes">
      <Enumeration>
        <Item name="a" value="1" description="first"/>
        <Item name="b" value="2" description="second"/>
      </Enumeration>
    </SimpleType>
  </TypeDefinitions>
  <LogCategories>
    <Category name="logAll" description="everything"/>
  </LogCategories>
  <DefaultExperiment startTime="0.0" stopTime="1.0" stepSize="0.001"/>
  <ModelVariables>
    <ScalarVariable name="k" valueReference="1" description="stiffness, N/m" causality="parameter" variability="fixed" initial="exact">
      <Real unit="N/m" min="0.0" start="2.5"/>
    </ScalarVariable>
    <ScalarVariable name="mode" valueReference="2" description="a mode" causality="input" variability="discrete">
      <Enumeration declaredType="Mode"/>
    </ScalarVariable>
    <ScalarVariable name="on" valueReference="3" description="switch" causality="output" variability="discrete">
      <Boolean start="true"/>
    </ScalarVariable>
  </ModelVariables>
  <ModelStructure>
    <Outputs>
      <Unknown index="3" dependencies="2"/>
    </Outputs>
    <InitialUnknowns>
      <Unknown index="3" dependencies="1 2"/>
    </InitialUnknowns>
  </ModelStructure>
</fmiModelDescription>
"#;
        assert_eq!(xml, expected);
    }

    #[test]
    fn the_guid_is_the_hash_of_the_document_without_it() {
        let g = DOC.guid();
        assert_eq!(g, guid_of(DOC.xml_with_guid("").unwrap().as_bytes()));
        assert!(DOC.xml().unwrap().contains(&format!("guid=\"{g}\"")));
        let other = Document {
            description: "another spring",
            ..DOC
        };
        assert_ne!(other.guid(), g);
    }
}
