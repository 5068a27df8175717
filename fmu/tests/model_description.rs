//! Parses the generated modelDescription.xml back with fmi-schema (an
//! independent FMI 2 reader) and checks it against the variable table.

use std::str::FromStr;

use fmi_schema::fmi2::{
    Causality as SCausality, Fmi2ModelDescription, ScalarVariableElement,
    Variability as SVariability,
};
use traction_fmu::model_description::{guid, model_description_xml};
use traction_fmu::variables::{Causality, Kind, UNITS, VARIABLES, Variability};

fn parsed() -> Fmi2ModelDescription {
    let xml = model_description_xml().expect("XML generation");
    Fmi2ModelDescription::from_str(&xml)
        .unwrap_or_else(|e| panic!("fmi-schema cannot read the XML: {e}\n{xml}"))
}

#[test]
fn header_and_capabilities() {
    let md = parsed();
    assert_eq!(md.fmi_version, "2.0");
    assert_eq!(md.guid, guid());
    let cs = md.co_simulation.as_ref().expect("CoSimulation element");
    assert_eq!(cs.model_identifier, "TractionContact");
    assert_eq!(cs.can_handle_variable_communication_step_size, Some(true));
    assert_eq!(cs.can_get_and_set_fmu_state, Some(true));
    assert_eq!(cs.can_serialize_fmu_state, Some(true));
    assert_eq!(cs.provides_directional_derivative, Some(false));
    assert!(md.model_exchange.is_none());
    let units = md.unit_definitions.as_ref().expect("UnitDefinitions");
    assert_eq!(units.units.len(), UNITS.len());
    let degc = units.units.iter().find(|u| u.name == "degC").expect("degC");
    let base = degc.base_unit.as_ref().expect("BaseUnit");
    assert_eq!((base.k, base.offset), (Some(1), Some(273.15)));
}

#[test]
fn variables_match_the_table() {
    let md = parsed();
    let vars = &md.model_variables.variables;
    assert_eq!(vars.len(), VARIABLES.len());
    for (sv, v) in vars.iter().zip(VARIABLES) {
        assert_eq!(sv.name, v.name);
        assert_eq!(sv.value_reference, v.vr);
        let c = match v.causality {
            Causality::Parameter => SCausality::Parameter,
            Causality::Input => SCausality::Input,
            Causality::Output => SCausality::Output,
        };
        assert_eq!(sv.causality, c, "{}", v.name);
        let var = match v.variability {
            Variability::Fixed => SVariability::Fixed,
            Variability::Discrete => SVariability::Discrete,
            Variability::Continuous => SVariability::Continuous,
        };
        assert_eq!(sv.variability, Some(var), "{}", v.name);
        assert!(sv.description.as_deref().is_some_and(|d| !d.is_empty()));
        match (v.kind, &sv.elem) {
            (
                Kind::Real {
                    start, declared, ..
                },
                ScalarVariableElement::Real(r),
            ) => {
                assert_eq!(r.start, start, "{}", v.name);
                assert_eq!(r.declared_type.as_deref(), Some(declared));
            }
            (Kind::Boolean { start }, ScalarVariableElement::Boolean(b)) => {
                assert_eq!(b.start, start)
            }
            (Kind::Enumeration { .. }, ScalarVariableElement::Enumeration) => {}
            (k, e) => panic!("{}: table {k:?} vs XML {e:?}", v.name),
        }
    }
}

#[test]
fn model_structure_lists_every_output_with_input_dependencies() {
    let md = parsed();
    let outputs: Vec<usize> = VARIABLES
        .iter()
        .enumerate()
        .filter(|(_, v)| v.causality == Causality::Output)
        .map(|(i, _)| i + 1)
        .collect();
    let inputs: Vec<u32> = VARIABLES
        .iter()
        .enumerate()
        .filter(|(_, v)| v.causality == Causality::Input)
        .map(|(i, _)| i as u32 + 1)
        .collect();
    for list in [
        &md.model_structure.outputs.unknowns,
        &md.model_structure.initial_unknowns.unknowns,
    ] {
        let idx: Vec<usize> = list.iter().map(|u| u.index as usize).collect();
        assert_eq!(idx, outputs);
        for u in list.iter() {
            assert!(!u.dependencies.is_empty());
            assert!(u.dependencies.iter().all(|d| inputs.contains(d)), "{u:?}");
        }
    }
    // The contact size depends on the load only.
    let a = VARIABLES.iter().position(|v| v.name == "a").unwrap() + 1;
    let load = VARIABLES
        .iter()
        .position(|v| v.name == "normal_load")
        .unwrap() as u32
        + 1;
    let ua = md
        .model_structure
        .outputs
        .unknowns
        .iter()
        .find(|u| u.index as usize == a)
        .unwrap();
    assert_eq!(ua.dependencies, vec![load]);
}
