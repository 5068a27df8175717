//! Parses the generated modelDescription.xml back with fmi-schema (an
//! independent FMI 2 reader) and checks it against the variable table.

use std::str::FromStr;

use fmi_schema::fmi2::{
    Causality as SCausality, Fmi2ModelDescription, ScalarVariableElement,
    Variability as SVariability,
};
use traction_fmu::model::{CoSimulation, NullLogger, TractionFmu};
use traction_fmu::model_description::{guid, model_description_xml};
use traction_fmu::variables::{Causality, ENUM_TYPES, Kind, UNITS, VARIABLES, Variability, vr};

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
fn model_structure_lists_every_output_with_its_knowns() {
    let md = parsed();
    let index = |name: &str| VARIABLES.iter().position(|v| v.name == name).unwrap() + 1;
    let outputs: Vec<usize> = VARIABLES
        .iter()
        .enumerate()
        .filter(|(_, v)| v.causality == Causality::Output)
        .map(|(i, _)| i + 1)
        .collect();
    for (list, initialization) in [
        (&md.model_structure.outputs.unknowns, false),
        (&md.model_structure.initial_unknowns.unknowns, true),
    ] {
        let idx: Vec<usize> = list.iter().map(|u| u.index as usize).collect();
        assert_eq!(idx, outputs);
        for u in list.iter() {
            assert!(!u.dependencies.is_empty());
            assert!(u.dependencies.is_sorted(), "{u:?}");
            for &d in &u.dependencies {
                let known = &VARIABLES[d as usize - 1];
                // Outputs: inputs only; InitialUnknowns: inputs and the
                // (initial = exact) parameters.
                assert!(
                    known.causality == Causality::Input
                        || (initialization && known.causality == Causality::Parameter),
                    "{u:?} lists {}",
                    known.name
                );
            }
        }
    }
    // The contact size depends on the load only among the inputs, and on
    // the load and the bodies' geometry and materials in Initialization Mode.
    let find = |list: &[fmi_schema::fmi2::Fmi2VariableDependency], i: usize| {
        list.iter()
            .find(|u| u.index as usize == i)
            .unwrap()
            .dependencies
            .iter()
            .map(|&d| d as usize)
            .collect::<Vec<_>>()
    };
    let a = index("a");
    assert_eq!(
        find(&md.model_structure.outputs.unknowns, a),
        vec![index("normal_load")]
    );
    let mut hertz: Vec<usize> = ["rx1", "ry1", "rx2", "ry2", "e1", "nu1", "e2", "nu2"]
        .iter()
        .map(|n| index(n))
        .collect();
    hertz.push(index("normal_load"));
    hertz.sort_unstable();
    assert_eq!(
        find(&md.model_structure.initial_unknowns.unknowns, a),
        hertz
    );
}

/// Every known (input or parameter) whose change moves an output in
/// Initialization Mode is listed among that output's InitialUnknowns
/// dependencies (and, for inputs, its Outputs dependencies): each known is
/// changed alone from two operating points (user fluid with input spin and
/// side slip; TDF-88 with tilt spin, skew angle, spin peak and the map) and
/// the outputs are compared bit for bit with the unchanged run.
#[test]
fn every_known_that_moves_an_output_is_listed() {
    let md = parsed();
    let listed = |output: usize, known: usize, initialization: bool| {
        let unknowns = if initialization {
            &md.model_structure.initial_unknowns.unknowns
        } else {
            &md.model_structure.outputs.unknowns
        };
        unknowns
            .iter()
            .find(|u| u.index as usize == output)
            .is_some_and(|u| u.dependencies.contains(&(known as u32)))
    };
    #[derive(Clone, Copy)]
    enum Value {
        Real(f64),
        Int(i32),
        Bool(bool),
    }
    let bases: [&[(u32, Value)]; 2] = [
        &[
            (vr::OMEGA1, Value::Real(600.0)),
            (vr::OMEGA2, Value::Real(270.0)),
            (vr::SIDE_SLIP_VELOCITY, Value::Real(0.05)),
            (vr::SKEW_ANGLE, Value::Real(0.01)),
            (vr::SPIN, Value::Real(20.0)),
            (vr::RHEOLOGY_MAP, Value::Bool(false)),
        ],
        &[
            (vr::OMEGA1, Value::Real(600.0)),
            (vr::OMEGA2, Value::Real(270.0)),
            (vr::SIDE_SLIP_VELOCITY, Value::Real(0.05)),
            (vr::SKEW_ANGLE, Value::Real(0.01)),
            (vr::SPIN, Value::Real(20.0)),
            (vr::FLUID, Value::Int(2)),
            (vr::SPIN_SOURCE, Value::Int(2)),
            (vr::SIDE_SLIP_SOURCE, Value::Int(2)),
            (vr::TILT_ANGLE, Value::Real(0.3)),
            (vr::SPIN_PEAK, Value::Bool(true)),
        ],
    ];
    let outputs: Vec<(usize, u32, bool)> = VARIABLES
        .iter()
        .enumerate()
        .filter(|(_, v)| v.causality == Causality::Output)
        .map(|(i, v)| (i + 1, v.vr, matches!(v.kind, Kind::Real { .. })))
        .collect();
    let evaluate = |settings: &[(u32, Value)]| -> Option<Vec<u64>> {
        let mut f = TractionFmu::instantiate("deps", &guid()).unwrap();
        for &(r, x) in settings {
            let ok = match x {
                Value::Real(x) => f.set_real(&[r], &[x]),
                Value::Int(x) => f.set_integer(&[r], &[x]),
                Value::Bool(x) => f.set_boolean(&[r], &[x]),
            };
            ok.ok()?;
        }
        f.enter_initialization_mode().unwrap();
        let mut out = Vec::new();
        for &(_, r, is_real) in &outputs {
            if is_real {
                let mut x = [0.0];
                f.get_real(&[r], &mut x, &mut NullLogger).ok()?;
                out.push(x[0].to_bits());
            } else {
                let mut x = [0];
                f.get_integer(&[r], &mut x, &mut NullLogger).ok()?;
                out.push(x[0] as u64);
            }
        }
        Some(out)
    };
    let mut moved = 0;
    for base in bases {
        let reference = evaluate(base).expect("base point evaluates");
        for (k, known) in VARIABLES.iter().enumerate() {
            let current = |r: u32| base.iter().find(|b| b.0 == r).map(|b| b.1);
            let changes: Vec<Value> = match known.kind {
                Kind::Real { start, .. } if known.causality != Causality::Output => {
                    let x = match current(known.vr) {
                        Some(Value::Real(x)) => x,
                        _ => start.unwrap(),
                    };
                    vec![Value::Real(if x == 0.0 { 0.01 } else { x * 1.1 })]
                }
                Kind::Enumeration { declared, .. } if known.causality == Causality::Parameter => {
                    let items = ENUM_TYPES.iter().find(|t| t.0 == declared).unwrap().2;
                    items.iter().map(|it| Value::Int(it.1)).collect()
                }
                Kind::Boolean { start } => {
                    let x = match current(known.vr) {
                        Some(Value::Bool(x)) => x,
                        _ => start.unwrap(),
                    };
                    vec![Value::Bool(!x)]
                }
                _ => continue,
            };
            for change in changes {
                let mut settings = base.to_vec();
                settings.push((known.vr, change));
                let Some(values) = evaluate(&settings) else {
                    continue; // an invalid combination: an error, not a value
                };
                for (&(output, _, _), (a, b)) in outputs.iter().zip(values.iter().zip(&reference)) {
                    if a != b {
                        moved += 1;
                        assert!(
                            listed(output, k + 1, true),
                            "{} moves with {} but InitialUnknowns do not list it",
                            VARIABLES[output - 1].name,
                            known.name
                        );
                        if known.causality == Causality::Input {
                            assert!(
                                listed(output, k + 1, false),
                                "{} moves with input {} but Outputs do not list it",
                                VARIABLES[output - 1].name,
                                known.name
                            );
                        }
                    }
                }
            }
        }
    }
    // Not vacuous: most pairs of a known and an output interact.
    assert!(moved > 300, "only {moved} changed outputs");
}
