//! The requested outputs: names, CSV columns and their values at a state. Only these are
//! computed.
//!
//! Book: §7.4, §7.6, §8.1 (momentum, angular momentum, energy).

use nalgebra::{DVector, Vector3};

use super::Scene;
use super::SceneError;
use super::build::Built;
use super::forces::centre;
use super::kin::{Kin, lift};
use super::loops::{Loop, LoopKind, orient};
use super::parts::Src;
use super::spec::SceneSpec;
use vectrix_dynamics::multibody::Joint;
use vectrix_tensor::Scalar;
use vectrix_units::Dimension;

/// One requested output.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Output {
    Q,
    V,
    Energy,
    Momentum,
    AngularMomentum,
    Position(usize),
    Velocity(usize),
    Omega(usize),
    OmegaBody(usize),
    /// The velocity of the body's centre of mass in the body's own axes, (u, v, w) of (11.5.1)
    /// for an aircraft: 𝓞 v_o + ω × c.
    VelocityBody(usize),
    Coordinates(usize),
    Speeds(usize),
    /// Airspeed V, angle of attack α and sideslip β of the body's centre of mass in still air
    /// (10.6.18), (10.6.27), link axes as aircraft axes.
    Air(usize),
    /// The 3-2-1 Euler angles (ψ, θ, φ) of the body relative to the ground (10.4.x): 𝓞_{B/G} =
    /// 𝓞₁(φ) 𝓞₂(θ) 𝓞₃(ψ).
    Euler321(usize),
    /// The force (and for a pin the couple) a loop joint exerts on its body `a`: the loop's
    /// index and its first row among the constraint rows.
    Reaction {
        index: usize,
        row: usize,
    },
}

const VALID: &str = "q, v, energy, momentum, angular_momentum, position:BODY, velocity:BODY, omega:BODY, \
omega_body:BODY, velocity_body:BODY, coordinates:BODY, speeds:BODY, air:BODY, euler321:BODY, reaction:LOOP";

/// Parses the `outputs` list.
pub(crate) fn parse(spec: &SceneSpec, b: &Built, src: &Src) -> Result<Vec<Output>, SceneError> {
    spec.outputs
        .iter()
        .enumerate()
        .map(|(k, o)| {
            let path = format!("outputs[{k}]");
            // a repeated output would repeat its columns and its figure (issue 33)
            if let Some(j) = spec.outputs[..k].iter().position(|p| p == o) {
                return Err(
                    src.invalid(&path, format!("output `{o}` repeats outputs[{j}]; valid: each output once"))
                );
            }
            let bad = || src.invalid(&path, format!("unknown output `{o}`; valid: {VALID}"));
            if let Some(name) = o.strip_prefix("reaction:") {
                let mut row = 0;
                for (index, l) in b.loops.iter().enumerate() {
                    if l.name == name {
                        return Ok(Output::Reaction { index, row });
                    }
                    row += l.rows();
                }
                let names: Vec<&str> = b.loops.iter().map(|l| l.name.as_str()).collect();
                return Err(src.invalid(
                    &path,
                    format!(
                        "unknown loop `{name}` in output `{o}`; valid: {}",
                        if names.is_empty() {
                            "none (the scene has no loops)".to_string()
                        } else {
                            names.join(", ")
                        }
                    ),
                ));
            }
            let (kind, body) = match o.split_once(':') {
                Some((kd, name)) => {
                    let i = b.bodies.iter().position(|x| x.name == name).ok_or_else(|| {
                        let names: Vec<&str> = b.bodies.iter().map(|x| x.name.as_str()).collect();
                        let hint = super::error::did_you_mean(name, names.iter().copied());
                        src.invalid(
                            &path,
                            format!(
                                "unknown body `{name}`{hint} in output `{o}`; valid: {}",
                                names.join(", ")
                            ),
                        )
                    })?;
                    (kd, Some(i))
                }
                None => (o.as_str(), None),
            };
            Ok(match (kind, body) {
                ("q", None) => Output::Q,
                ("v", None) => Output::V,
                ("energy", None) => Output::Energy,
                ("momentum", None) => Output::Momentum,
                ("angular_momentum", None) => Output::AngularMomentum,
                ("position", Some(i)) => Output::Position(i),
                ("velocity", Some(i)) => Output::Velocity(i),
                ("omega", Some(i)) => Output::Omega(i),
                ("omega_body", Some(i)) => Output::OmegaBody(i),
                ("velocity_body", Some(i)) => Output::VelocityBody(i),
                ("coordinates", Some(i)) => Output::Coordinates(i),
                ("speeds", Some(i)) => Output::Speeds(i),
                ("air", Some(i)) => Output::Air(i),
                ("euler321", Some(i)) => Output::Euler321(i),
                _ => return Err(bad()),
            })
        })
        .collect()
}

/// Number of CSV columns the outputs produce.
pub(crate) fn count_columns(outputs: &[Output], b: &Built) -> usize {
    outputs
        .iter()
        .map(|o| match o {
            Output::Q => b.model.nq(),
            Output::V => b.model.nv(),
            Output::Energy => 1,
            Output::Coordinates(i) => b.bodies[*i].joint.nq(),
            Output::Speeds(i) => b.bodies[*i].joint.nv(),
            Output::Reaction { index, .. } if is_pin(b, *index) => 6,
            Output::Reaction { index, .. } if coupled(b, *index).is_some() => 1,
            _ => 3,
        })
        .sum()
}

/// Whether a loop's reaction has a couple (a pin, a weld).
fn is_pin(b: &Built, index: usize) -> bool {
    matches!(b.loops[index].kind, LoopKind::Pin { .. } | LoopKind::Weld { .. })
}

/// The follower body of a coupler (whose joint's generalized force is its reaction).
fn coupled(b: &Built, index: usize) -> Option<usize> {
    match b.loops[index].kind {
        LoopKind::Coupler { .. } => b.loops[index].a.0,
        _ => None,
    }
}

fn xyz(prefix: &str) -> Vec<String> {
    ["x", "y", "z"].iter().map(|c| format!("{prefix}.{c}")).collect()
}

impl Scene {
    /// Column names of trajectory.csv (after `t`), in the order of the outputs: what a run
    /// will write, known before it runs (the command line bounds its output size with it).
    pub fn columns(&self) -> Vec<String> {
        let b = &self.built;
        let name = |i: usize| b.bodies[i].name.clone();
        let mut cols = Vec::new();
        for o in &self.outputs {
            match o {
                Output::Q => cols.extend((0..b.model.nq()).map(|k| format!("q{k}"))),
                Output::V => cols.extend((0..b.model.nv()).map(|k| format!("v{k}"))),
                Output::Energy => cols.push("energy".into()),
                Output::Momentum => cols.extend(xyz("momentum")),
                Output::AngularMomentum => cols.extend(xyz("angular_momentum")),
                Output::Position(i) => cols.extend(xyz(&format!("position:{}", name(*i)))),
                Output::Velocity(i) => cols.extend(xyz(&format!("velocity:{}", name(*i)))),
                Output::Omega(i) => cols.extend(xyz(&format!("omega:{}", name(*i)))),
                Output::OmegaBody(i) => cols.extend(xyz(&format!("omega_body:{}", name(*i)))),
                Output::VelocityBody(i) => {
                    cols.extend(["u", "v", "w"].iter().map(|c| format!("velocity_body:{}.{c}", name(*i))))
                }
                Output::Coordinates(i) => {
                    cols.extend((0..b.bodies[*i].joint.nq()).map(|k| format!("coordinates:{}.{k}", name(*i))))
                }
                Output::Speeds(i) => {
                    cols.extend((0..b.bodies[*i].joint.nv()).map(|k| format!("speeds:{}.{k}", name(*i))))
                }
                Output::Air(i) => {
                    cols.extend(["airspeed", "alpha", "beta"].iter().map(|c| format!("air:{}.{c}", name(*i))))
                }
                Output::Euler321(i) => {
                    cols.extend(["psi", "theta", "phi"].iter().map(|c| format!("euler321:{}.{c}", name(*i))))
                }
                Output::Reaction { index, .. } => {
                    let p = format!("reaction:{}", b.loops[*index].name);
                    if coupled(b, *index).is_some() {
                        cols.push(p);
                        continue;
                    }
                    cols.extend(xyz(&p));
                    if is_pin(b, *index) {
                        cols.extend(["mx", "my", "mz"].iter().map(|c| format!("{p}.{c}")));
                    }
                }
            }
        }
        cols
    }

    /// The dimension of every column of [`Scene::columns`], in the same order.
    pub(crate) fn column_dims(&self) -> Vec<Dimension> {
        let b = &self.built;
        let joint_dims = |i: usize, speed: bool| -> Vec<Dimension> {
            let (l, a) = if speed {
                (Dimension::VELOCITY, Dimension::ANGULAR_VELOCITY)
            } else {
                (Dimension::LENGTH, Dimension::ANGLE)
            };
            let one = Dimension::DIMENSIONLESS;
            match &b.bodies[i].joint {
                Joint::Pin { .. } => vec![a],
                Joint::Sleeve { .. } => vec![l],
                Joint::Collar { .. } | Joint::Slot { .. } => vec![l, a],
                Joint::Ball if speed => vec![a; 3],
                Joint::Ball => vec![one; 4],
                Joint::Free if speed => vec![l, l, l, a, a, a],
                Joint::Free => vec![l, l, l, one, one, one, one],
                Joint::Weld => vec![],
            }
        };
        let all = |speed: bool| -> Vec<Dimension> {
            (0..b.bodies.len()).flat_map(|i| joint_dims(i, speed)).collect()
        };
        let mut dims: Vec<Dimension> = Vec::new();
        for o in &self.outputs {
            match o {
                Output::Q => dims.extend(all(false)),
                Output::V => dims.extend(all(true)),
                Output::Energy => dims.push(Dimension::ENERGY),
                Output::Momentum => dims.extend([Dimension::MOMENTUM; 3]),
                Output::AngularMomentum => dims.extend([Dimension::ANGULAR_MOMENTUM; 3]),
                Output::Position(_) => dims.extend([Dimension::LENGTH; 3]),
                Output::Velocity(_) | Output::VelocityBody(_) => dims.extend([Dimension::VELOCITY; 3]),
                Output::Omega(_) | Output::OmegaBody(_) => dims.extend([Dimension::ANGULAR_VELOCITY; 3]),
                Output::Coordinates(i) => dims.extend(joint_dims(*i, false)),
                Output::Speeds(i) => dims.extend(joint_dims(*i, true)),
                Output::Air(_) => dims.extend([Dimension::VELOCITY, Dimension::ANGLE, Dimension::ANGLE]),
                Output::Euler321(_) => dims.extend([Dimension::ANGLE; 3]),
                Output::Reaction { index, .. } => {
                    if let Some(i) = coupled(b, *index) {
                        let pin = matches!(b.bodies[i].joint, Joint::Pin { .. });
                        dims.push(if pin { Dimension::MOMENT } else { Dimension::FORCE });
                        continue;
                    }
                    dims.extend([Dimension::FORCE; 3]);
                    if is_pin(b, *index) {
                        dims.extend([Dimension::MOMENT; 3]);
                    }
                }
            }
        }
        dims
    }

    /// The point about which `angular_momentum` is reported: that of the invariant, else the origin.
    pub(crate) fn h_point(&self) -> Vector3<f64> {
        self.invariants()
            .iter()
            .find_map(|i| match i {
                super::Invariant::AngularMomentum { about }
                | super::Invariant::AngularMomentumAlong { about, .. } => Some(Vector3::from(*about)),
                _ => None,
            })
            .unwrap_or_default()
    }

    /// Whether an output needs the constraint multipliers (a loop's reaction).
    pub(crate) fn needs_multipliers(&self) -> bool {
        self.outputs.iter().any(|o| matches!(o, Output::Reaction { .. }))
    }

    /// Values of the requested outputs at (q, v); `lambda` holds the constraint multipliers
    /// when [`Scene::needs_multipliers`].
    pub(crate) fn row<T: Scalar>(
        &self,
        kin: &Kin<T>,
        q: &[T],
        v: &[T],
        lambda: Option<&DVector<T>>,
        out: &mut Vec<T>,
    ) {
        let b = &self.built;
        for o in &self.outputs {
            match o {
                Output::Q => out.extend_from_slice(q),
                Output::V => out.extend_from_slice(v),
                Output::Energy => out.push(self.energy(kin, q, v)),
                Output::Momentum => out.extend(self.momentum(kin).iter()),
                Output::AngularMomentum => out.extend(self.angular_momentum(kin, &self.h_point()).iter()),
                Output::Position(i) => out.extend(centre(kin, &b.bodies[*i], *i).iter()),
                Output::Velocity(i) => out.extend(kin.point(&(Some(*i), b.bodies[*i].com)).1.iter()),
                Output::Omega(i) => out.extend(kin.omega[*i].iter()),
                Output::OmegaBody(i) => out.extend((kin.poses[*i].0 * kin.omega[*i]).iter()),
                Output::VelocityBody(i) => {
                    out.extend(super::aero::air_velocity(kin, &b.bodies[*i], *i).0.iter())
                }
                Output::Coordinates(i) => {
                    let bd = &b.bodies[*i];
                    out.extend_from_slice(&q[bd.qi..bd.qi + bd.joint.nq()]);
                }
                Output::Speeds(i) => {
                    let bd = &b.bodies[*i];
                    out.extend_from_slice(&v[bd.vi..bd.vi + bd.joint.nv()]);
                }
                Output::Air(i) => {
                    let (vel, _) = super::aero::air_velocity(kin, &b.bodies[*i], *i);
                    let a = vectrix_flight::AeroAngles::from_body_velocity([vel[0], vel[1], vel[2]]);
                    out.extend([a.airspeed, a.alpha, a.beta]);
                }
                Output::Euler321(i) => {
                    // 𝓞_{B/G} = 𝓞₁(φ)𝓞₂(θ)𝓞₃(ψ): row 0 = (cθcψ, cθsψ, −sθ), column 2 = (−sθ, sφcθ, cφcθ)
                    let e = kin.poses[*i].0;
                    let theta = (-e[(0, 2)]).max(-T::one()).min(T::one()).asin();
                    out.extend([e[(0, 1)].atan2(e[(0, 0)]), theta, e[(1, 2)].atan2(e[(2, 2)])]);
                }
                Output::Reaction { index, row } => {
                    let lam = |k: usize| lambda.and_then(|l| l.get(row + k).copied()).unwrap_or_else(T::zero);
                    if coupled(b, *index).is_some() {
                        // −Gᵀλ on the follower's coordinate: −λ
                        out.push(-lam(0));
                        continue;
                    }
                    let (force, couple) = reaction(kin, &b.loops[*index], lam);
                    out.extend(force.iter());
                    if let Some(m) = couple {
                        out.extend(m.iter());
                    }
                }
            }
        }
    }
}

/// The force (ground components) and, for a pin, the couple that a loop joint exerts on its
/// body `a`, from the multipliers of its rows: the generalized constraint force is −Gᵀλ, so a
/// row λ·(v_a − v_b)·n gives −λn on `a`, and a pin's axis row λ·(ω_b − ω_a)·(k × e) gives the
/// couple λ(k × e) on `a` (§6.10: `b` receives the opposite).
fn reaction<T: Scalar>(kin: &Kin<T>, l: &Loop, lam: impl Fn(usize) -> T) -> (Vector3<T>, Option<Vector3<T>>) {
    let (ea, eb) = (orient(kin, l.a.0), orient(kin, l.b.0));
    let three = -Vector3::new(lam(0), lam(1), lam(2));
    match &l.kind {
        LoopKind::Ball => (three, None),
        LoopKind::Pin { e1_a, e2_a, axis_b } => {
            let k = eb.tr_mul(&lift::<T>(axis_b));
            let couple = k.cross(&ea.tr_mul(&lift::<T>(e1_a))) * lam(3)
                + k.cross(&ea.tr_mul(&lift::<T>(e2_a))) * lam(4);
            (three, Some(couple))
        }
        LoopKind::Line { n1_b, n2_b } => {
            (-(eb.tr_mul(&lift::<T>(n1_b)) * lam(0) + eb.tr_mul(&lift::<T>(n2_b)) * lam(1)), None)
        }
        LoopKind::Plane { n_b } => (-(eb.tr_mul(&lift::<T>(n_b)) * lam(0)), None),
        // a turning row λ·(ω_b − ω_a)·(u × w) gives the couple λ(u × w) on `a`
        LoopKind::Weld { pairs } => {
            let couple = pairs.iter().enumerate().fold(Vector3::zeros(), |m, (j, (u, w))| {
                m + eb.tr_mul(&lift::<T>(u)).cross(&ea.tr_mul(&lift::<T>(w))) * lam(3 + j)
            });
            (three, Some(couple))
        }
        // (reported by the caller as one generalized force)
        LoopKind::Coupler { .. } => (Vector3::zeros(), None),
    }
}
