//! Random kinematic trees for the property tests: body 0 floating, then floating,
//! revolute, prismatic and fixed joints on random parents, with random placements, mass
//! properties, configuration and velocity. About one body in four is axis-aligned: its
//! placement is a pure translation and its inertia diagonal in body axes (the cases the
//! kinematics and CRBA take by shorter paths).
#![allow(dead_code)] // each test binary uses part of it

use multibody::{Body, Joint, Model, ModelBuilder};
use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;
use std::f64::consts::PI;

/// Random parameters of one body plus its joint state.
#[derive(Debug, Clone)]
pub struct RandomBody {
    parent_seed: usize,
    kind: u8,
    aligned: bool,
    axis: [f64; 3],
    offset: [f64; 3],
    tilt: [f64; 3],
    mass: f64,
    com: [f64; 3],
    moments: [f64; 3],
    q: [f64; 3],
    v: [f64; 6],
}

pub fn random_body() -> impl Strategy<Value = RandomBody> {
    let unit = || [-1.0..1.0_f64, -1.0..1.0, -1.0..1.0];
    let angles = || [-PI..PI, -PI..PI, -PI..PI];
    (
        (0..1000usize, 0..4u8, unit(), unit(), angles(), 0..4u8),
        (0.1..10.0_f64, unit(), [0.1..2.0_f64, 0.1..2.0, 0.1..2.0]),
        (
            angles(),
            [
                -2.0..2.0_f64,
                -2.0..2.0,
                -2.0..2.0,
                -2.0..2.0,
                -2.0..2.0,
                -2.0..2.0,
            ],
        ),
    )
        .prop_map(|(a, b, c)| RandomBody {
            parent_seed: a.0,
            kind: a.1,
            aligned: a.5 == 0,
            axis: a.2,
            offset: a.3,
            tilt: a.4,
            mass: b.0,
            com: b.1,
            moments: b.2,
            q: c.0,
            v: c.1,
        })
}

fn joint(r: &RandomBody, index: usize) -> Joint {
    let axis = Vector3::from(r.axis) + Vector3::new(0.0, 0.0, 1.5); // never zero
    match (index, r.kind) {
        (0, _) | (_, 0) => Joint::Floating,
        (_, 1) => Joint::Revolute { axis },
        (_, 2) => Joint::Prismatic { axis },
        _ => Joint::Fixed,
    }
}

/// Tree (body 0 floating, so nv > 0), configuration and velocity.
pub fn random_tree(bodies: &[RandomBody]) -> (Model, Vec<f64>, Vec<f64>) {
    let mut b = ModelBuilder::new(Vector3::new(0.3, -0.2, -9.81));
    for (i, r) in bodies.iter().enumerate() {
        let (rot, tilt) = if r.aligned {
            (Matrix3::identity(), UnitQuaternion::identity())
        } else {
            (
                Rotation3::from_euler_angles(r.tilt[2], r.tilt[0], r.tilt[1]).into_inner(),
                UnitQuaternion::from_euler_angles(r.tilt[0], r.tilt[1], r.tilt[2]),
            )
        };
        b.add_body(Body {
            name: format!("b{i}"),
            parent: (i > 0 && r.parent_seed % (i + 1) < i).then(|| r.parent_seed % (i + 1)),
            joint: joint(r, i),
            placement: Isometry3::from_parts(Translation3::from(Vector3::from(r.offset)), tilt),
            mass: r.mass,
            com: Vector3::from(r.com),
            inertia: rot * Matrix3::from_diagonal(&Vector3::from(r.moments)) * rot.transpose(),
        });
    }
    let model = b.build().expect("random tree is valid");
    let (mut q, mut v) = (Vec::new(), Vec::new());
    for (body, r) in model.bodies().iter().zip(bodies) {
        match body.joint {
            Joint::Floating => {
                let c = UnitQuaternion::from_euler_angles(r.q[0], r.q[1], r.q[2]).into_inner();
                q.extend_from_slice(&[r.offset[0], r.offset[1], r.offset[2], c.w, c.i, c.j, c.k]);
                v.extend_from_slice(&r.v);
            }
            Joint::Revolute { .. } | Joint::Prismatic { .. } => {
                q.push(r.q[0]);
                v.push(r.v[0]);
            }
            Joint::Fixed => {}
        }
    }
    (model, q, v)
}
