//! The kinematic tree (Featherstone, "Rigid Body Dynamics Algorithms", 2008, chapter 4:
//! parent array `lambda(i) < i`, tree transforms `X_T`, joint models) and its validating
//! builder.

use crate::error::ModelError;
use crate::inertia::RigidInertia;
use crate::joint::Joint;
use crate::ltdl::DofTree;
use crate::spatial::{rigid_body_inertia, SpatialTransform};
use nalgebra::{DVector, Isometry3, Matrix3, Matrix6, SymmetricEigen, Vector3};

/// One body of the tree and the joint connecting it to its parent (plain data).
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Unique name, used in error messages and [`Model::body_index`].
    pub name: String,
    /// Index of the parent body, `None` for a body attached to the world. Must be
    /// smaller than this body's own index.
    pub parent: Option<usize>,
    /// The joint between the parent and this body.
    pub joint: Joint,
    /// Pose of the joint frame in the parent body frame (in the world for a root): the
    /// fixed tree transform `X_T` of Featherstone 2008, ch. 4.
    pub placement: Isometry3<f64>,
    /// Mass in kg; zero is allowed for an intermediate body with a massive descendant.
    pub mass: f64,
    /// Centre of mass in body coordinates, m.
    pub com: Vector3<f64>,
    /// Rotational inertia about the centre of mass in body axes, kg m².
    pub inertia: Matrix3<f64>,
}

/// Per-body data derived once by the builder.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Link {
    pub(crate) x_tree: SpatialTransform,
    /// Whether the placement `x_tree` is a pure translation (its rotation is exactly the
    /// identity), so the kinematics skip the rotation product.
    pub(crate) tree_translation_only: bool,
    pub(crate) inertia: Matrix6<f64>,
    /// The same inertia by its ten parameters (CRBA accumulates these).
    pub(crate) rigid_inertia: RigidInertia,
    /// Whether the rotational inertia about the centre of mass is diagonal in body axes
    /// (its off-diagonal entries exactly zero), which CRBA's transform exploits.
    pub(crate) inertia_diagonal: bool,
    pub(crate) subspace: Matrix6<f64>,
    pub(crate) nv: usize,
    pub(crate) q_offset: usize,
    pub(crate) v_offset: usize,
}

/// Validated kinematic tree with gravity; immutable apart from gravity.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    bodies: Vec<Body>,
    pub(crate) links: Vec<Link>,
    /// Expanded parent array and packed mass-matrix structure, computed once.
    pub(crate) dofs: DofTree,
    gravity: Vector3<f64>,
    nq: usize,
    nv: usize,
}

/// Collects bodies and validates them into a [`Model`].
#[derive(Debug, Clone, Default)]
pub struct ModelBuilder {
    bodies: Vec<Body>,
    gravity: Vector3<f64>,
}

impl ModelBuilder {
    /// Empty builder with gravity `gravity` (world frame, m/s², e.g. `[0, 0, -9.81]`).
    pub fn new(gravity: Vector3<f64>) -> Self {
        Self {
            bodies: Vec::new(),
            gravity,
        }
    }

    /// Appends a body and returns its index (validation happens in [`Self::build`]).
    pub fn add_body(&mut self, body: Body) -> usize {
        self.bodies.push(body);
        self.bodies.len() - 1
    }

    /// Validates every body and derives the per-body spatial data.
    ///
    /// Rules: finite numbers; parent index below the body's own index; mass >= 0; a
    /// massless body has zero inertia and, if its joint moves, a massive descendant;
    /// inertia symmetric positive semi-definite (stored symmetrised); revolute and
    /// prismatic axes non-zero (stored normalised); unique names.
    pub fn build(self) -> Result<Model, ModelError> {
        if self.bodies.is_empty() {
            return Err(ModelError::Empty);
        }
        if !self.gravity.iter().all(|g| g.is_finite()) {
            return Err(ModelError::NonFiniteGravity);
        }
        let mut bodies = self.bodies;
        for index in 0..bodies.len() {
            let (earlier, rest) = bodies.split_at_mut(index);
            let body = &mut rest[0];
            if earlier.iter().any(|b| b.name == body.name) {
                return Err(ModelError::DuplicateName {
                    body: body.name.clone(),
                });
            }
            validate_body(index, body)?;
        }
        check_massless_subtrees(&bodies)?;
        let (mut nq, mut nv) = (0, 0);
        let links = bodies
            .iter()
            .map(|b| {
                let x_tree = SpatialTransform::from_pose(&b.placement);
                let link = Link {
                    tree_translation_only: x_tree.rot == Matrix3::identity(),
                    x_tree,
                    inertia: rigid_body_inertia(b.mass, &b.com, &b.inertia),
                    rigid_inertia: RigidInertia::new(b.mass, &b.com, &b.inertia),
                    inertia_diagonal: b.inertia == Matrix3::from_diagonal(&b.inertia.diagonal()),
                    subspace: b.joint.motion_subspace(),
                    nv: b.joint.nv(),
                    q_offset: nq,
                    v_offset: nv,
                };
                nq += b.joint.nq();
                nv += b.joint.nv();
                link
            })
            .collect::<Vec<_>>();
        let dofs = DofTree::new(&bodies, &links);
        Ok(Model {
            bodies,
            links,
            dofs,
            gravity: self.gravity,
            nq,
            nv,
        })
    }
}

fn non_finite(body: &Body, field: &'static str) -> ModelError {
    ModelError::NonFinite {
        body: body.name.clone(),
        field,
    }
}

fn validate_body(index: usize, body: &mut Body) -> Result<(), ModelError> {
    if let Some(parent) = body.parent {
        if parent >= index {
            return Err(ModelError::InvalidParent {
                body: body.name.clone(),
                index,
                parent,
            });
        }
    }
    if !body.mass.is_finite() {
        return Err(non_finite(body, "mass"));
    }
    if !body.com.iter().all(|x| x.is_finite()) {
        return Err(non_finite(body, "com"));
    }
    if !body.inertia.iter().all(|x| x.is_finite()) {
        return Err(non_finite(body, "inertia"));
    }
    let p = &body.placement;
    if !(p.translation.vector.iter().all(|x| x.is_finite())
        && p.rotation.coords.iter().all(|x| x.is_finite()))
    {
        return Err(non_finite(body, "placement"));
    }
    validate_mass_properties(body)?;
    normalise_axis(body)
}

fn validate_mass_properties(body: &mut Body) -> Result<(), ModelError> {
    if body.mass < 0.0 {
        return Err(ModelError::NegativeMass {
            body: body.name.clone(),
            mass: body.mass,
        });
    }
    if body.mass == 0.0 && body.inertia.norm() != 0.0 {
        return Err(ModelError::MasslessWithInertia {
            body: body.name.clone(),
        });
    }
    let scale = body.inertia.norm().max(f64::MIN_POSITIVE);
    if (body.inertia - body.inertia.transpose()).norm() > 1e-9 * scale {
        return Err(ModelError::AsymmetricInertia {
            body: body.name.clone(),
        });
    }
    let sym = 0.5 * (body.inertia + body.inertia.transpose());
    let min_eigenvalue = SymmetricEigen::new(sym).eigenvalues.min();
    if min_eigenvalue < -1e-12 * scale {
        return Err(ModelError::IndefiniteInertia {
            body: body.name.clone(),
            min_eigenvalue,
        });
    }
    body.inertia = sym;
    Ok(())
}

fn normalise_axis(body: &mut Body) -> Result<(), ModelError> {
    let name = body.name.clone();
    let axis = match &mut body.joint {
        Joint::Revolute { axis } | Joint::Prismatic { axis } => axis,
        Joint::Floating | Joint::Fixed => return Ok(()),
    };
    if !axis.iter().all(|x| x.is_finite()) {
        return Err(ModelError::NonFinite {
            body: name,
            field: "axis",
        });
    }
    let norm = axis.norm();
    if norm < 1e-12 {
        return Err(ModelError::ZeroAxis { body: name });
    }
    *axis /= norm;
    Ok(())
}

fn check_massless_subtrees(bodies: &[Body]) -> Result<(), ModelError> {
    let mut subtree_mass: Vec<f64> = bodies.iter().map(|b| b.mass).collect();
    for i in (0..bodies.len()).rev() {
        if let Some(p) = bodies[i].parent {
            subtree_mass[p] += subtree_mass[i];
        }
    }
    for (b, m) in bodies.iter().zip(&subtree_mass) {
        if *m <= 0.0 && b.joint.nv() > 0 {
            return Err(ModelError::MasslessSubtree {
                body: b.name.clone(),
            });
        }
    }
    Ok(())
}

impl Model {
    /// Number of configuration coordinates (a floating joint counts 7).
    pub fn nq(&self) -> usize {
        self.nq
    }

    /// Number of velocity coordinates = degrees of freedom (a floating joint counts 6).
    pub fn nv(&self) -> usize {
        self.nv
    }

    /// Number of bodies.
    pub fn num_bodies(&self) -> usize {
        self.bodies.len()
    }

    /// The validated bodies (axes normalised, inertia symmetrised).
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    /// Index of the body called `name`.
    pub fn body_index(&self, name: &str) -> Option<usize> {
        self.bodies.iter().position(|b| b.name == name)
    }

    /// First index of body `body`'s joint coordinates in `q`.
    pub fn q_offset(&self, body: usize) -> usize {
        self.links[body].q_offset
    }

    /// First index of body `body`'s joint velocities in `v` (and in `tau`, `vdot`).
    pub fn v_offset(&self, body: usize) -> usize {
        self.links[body].v_offset
    }

    /// Gravity in the world frame, m/s².
    pub fn gravity(&self) -> Vector3<f64> {
        self.gravity
    }

    /// Replaces the gravity vector (world frame, m/s²).
    pub fn set_gravity(&mut self, gravity: Vector3<f64>) {
        self.gravity = gravity;
    }

    /// Total mass, kg.
    pub fn total_mass(&self) -> f64 {
        self.bodies.iter().map(|b| b.mass).sum()
    }

    /// Zero configuration: joint coordinates 0, floating bases at the joint-frame origin
    /// with the identity quaternion `[1, 0, 0, 0]`.
    pub fn neutral_configuration(&self) -> DVector<f64> {
        let mut q = DVector::zeros(self.nq);
        for (b, l) in self.bodies.iter().zip(&self.links) {
            if b.joint == Joint::Floating {
                q[l.q_offset + 3] = 1.0;
            }
        }
        q
    }

    /// Configuration derivative `qdot` (length `nq`) from the velocity `v` (length `nv`)
    /// at configuration `q`, so an ODE integrator can integrate the state `[q, v]`
    /// (floating joints: `pdot = R v_O`, `Qdot = 1/2 Q (0, omega)`). Allocation free.
    ///
    /// # Panics
    /// If a slice length differs from `nq` / `nv`.
    pub fn velocity_to_qdot(&self, q: &[f64], v: &[f64], qdot: &mut [f64]) {
        assert_eq!(q.len(), self.nq, "q length");
        assert_eq!(qdot.len(), self.nq, "qdot length");
        assert_eq!(v.len(), self.nv, "v length");
        for (b, l) in self.bodies.iter().zip(&self.links) {
            let (qo, vo) = (l.q_offset, l.v_offset);
            let (nq, nv) = (b.joint.nq(), b.joint.nv());
            b.joint
                .velocity_to_qdot(&q[qo..qo + nq], &v[vo..vo + nv], &mut qdot[qo..qo + nq]);
        }
    }

    /// Rescales every floating-joint quaternion in `q` to unit length (call after each
    /// integration step; the kinematics normalise on read anyway).
    pub fn normalize_quaternions(&self, q: &mut [f64]) {
        for (b, l) in self.bodies.iter().zip(&self.links) {
            if b.joint == Joint::Floating {
                let quat = &mut q[l.q_offset + 3..l.q_offset + 7];
                let norm = quat.iter().map(|x| x * x).sum::<f64>().sqrt();
                if norm > 0.0 {
                    quat.iter_mut().for_each(|x| *x /= norm);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn body(name: &str, parent: Option<usize>, joint: Joint, mass: f64) -> Body {
        Body {
            name: name.into(),
            parent,
            joint,
            placement: Isometry3::identity(),
            mass,
            com: Vector3::zeros(),
            inertia: Matrix3::identity() * mass,
        }
    }

    #[test]
    fn dimensions_and_offsets() {
        let mut b = ModelBuilder::new(Vector3::new(0.0, 0.0, -9.81));
        b.add_body(body("base", None, Joint::Floating, 10.0));
        let axis = Vector3::new(0.0, 0.0, 2.0);
        b.add_body(body("slider", Some(0), Joint::Prismatic { axis }, 1.0));
        b.add_body(body("mount", Some(1), Joint::Fixed, 1.0));
        let m = b.build().expect("valid model");
        assert_eq!((m.nq(), m.nv()), (8, 7));
        assert_eq!((m.q_offset(1), m.v_offset(1)), (7, 6));
        assert_eq!(m.bodies()[1].joint, Joint::Prismatic { axis: Vector3::z() });
        assert_eq!(m.neutral_configuration()[3], 1.0);
    }

    #[test]
    fn rejections_name_the_body_and_field() {
        let mut b = ModelBuilder::new(Vector3::zeros());
        b.add_body(body("base", None, Joint::Floating, -1.0));
        let e = b.build().unwrap_err();
        assert!(matches!(e, ModelError::NegativeMass { ref body, .. } if body == "base"));

        let mut b = ModelBuilder::new(Vector3::zeros());
        b.add_body(body("base", Some(0), Joint::Floating, 1.0));
        assert!(matches!(b.build(), Err(ModelError::InvalidParent { .. })));

        let mut b = ModelBuilder::new(Vector3::zeros());
        let axis = Vector3::zeros();
        b.add_body(body("arm", None, Joint::Revolute { axis }, 1.0));
        assert!(matches!(b.build(), Err(ModelError::ZeroAxis { .. })));

        let mut b = ModelBuilder::new(Vector3::zeros());
        let mut bad = body("arm", None, Joint::Fixed, 1.0);
        bad.inertia[(0, 0)] = -1.0;
        let e = b.add_body(bad);
        assert_eq!(e, 0);
        assert!(matches!(
            b.build(),
            Err(ModelError::IndefiniteInertia { .. })
        ));

        let mut b = ModelBuilder::new(Vector3::zeros());
        let mut bad = body("arm", None, Joint::Fixed, 1.0);
        bad.inertia[(0, 1)] = 0.5;
        b.add_body(bad);
        assert!(matches!(
            b.build(),
            Err(ModelError::AsymmetricInertia { .. })
        ));

        let mut b = ModelBuilder::new(Vector3::zeros());
        let mut bad = body("arm", None, Joint::Fixed, 1.0);
        bad.com.x = f64::NAN;
        b.add_body(bad);
        let e = b.build().unwrap_err();
        assert!(matches!(e, ModelError::NonFinite { field: "com", .. }));
    }

    #[test]
    fn massless_body_needs_a_massive_descendant() {
        let yaw = Joint::Revolute { axis: Vector3::z() };
        let roll = Joint::Revolute { axis: Vector3::x() };
        let mut b = ModelBuilder::new(Vector3::zeros());
        b.add_body(body("front", None, Joint::Floating, 10.0));
        b.add_body(body("intermediate", Some(0), yaw, 0.0));
        assert!(matches!(
            b.clone().build(),
            Err(ModelError::MasslessSubtree { .. })
        ));
        b.add_body(body("rear", Some(1), roll, 5.0));
        assert!(b.build().is_ok());

        let mut b = ModelBuilder::new(Vector3::zeros());
        let mut bad = body("ghost", None, Joint::Fixed, 0.0);
        bad.inertia = Matrix3::identity();
        b.add_body(bad);
        assert!(matches!(
            b.build(),
            Err(ModelError::MasslessWithInertia { .. })
        ));
    }
}
