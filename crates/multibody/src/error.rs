//! Error types: model validation and per-call dimension checks.

/// Why [`crate::ModelBuilder::build`] rejected a body or the model.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// The builder holds no body.
    #[error("the model has no body")]
    Empty,
    /// The gravity vector has a NaN or infinite component.
    #[error("gravity is not finite")]
    NonFiniteGravity,
    /// Two bodies share a name.
    #[error("body name `{body}` is used twice")]
    DuplicateName {
        /// The repeated name.
        body: String,
    },
    /// A field holds a NaN or infinite number.
    #[error("body `{body}`: field `{field}` is not finite")]
    NonFinite {
        /// Body name.
        body: String,
        /// Offending field (`mass`, `com`, `inertia`, `placement`, `axis`).
        field: &'static str,
    },
    /// The parent index does not refer to an earlier body.
    #[error("body `{body}` (index {index}): parent {parent} is not an earlier body")]
    InvalidParent {
        /// Body name.
        body: String,
        /// The body's own index.
        index: usize,
        /// The rejected parent index.
        parent: usize,
    },
    /// Mass below zero.
    #[error("body `{body}`: field `mass` = {mass} is negative")]
    NegativeMass {
        /// Body name.
        body: String,
        /// The rejected mass.
        mass: f64,
    },
    /// A massless body must have zero rotational inertia.
    #[error("body `{body}`: field `inertia` must be zero for a massless body")]
    MasslessWithInertia {
        /// Body name.
        body: String,
    },
    /// A massless body with a moving joint has no massive descendant, so the mass
    /// matrix would be singular.
    #[error("body `{body}`: massless body with a moving joint and no massive descendant")]
    MasslessSubtree {
        /// Body name.
        body: String,
    },
    /// The inertia matrix is not symmetric.
    #[error("body `{body}`: field `inertia` is not symmetric")]
    AsymmetricInertia {
        /// Body name.
        body: String,
    },
    /// The inertia matrix has a negative eigenvalue.
    #[error("body `{body}`: field `inertia` is not positive semi-definite (eigenvalue {min_eigenvalue})")]
    IndefiniteInertia {
        /// Body name.
        body: String,
        /// Smallest eigenvalue found.
        min_eigenvalue: f64,
    },
    /// A revolute or prismatic axis of zero length.
    #[error("body `{body}`: field `axis` has zero length")]
    ZeroAxis {
        /// Body name.
        body: String,
    },
}

/// Why a kinematics or dynamics call was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DynamicsError {
    /// The workspace was built for a different model.
    #[error("workspace built for {workspace_bodies} bodies / {workspace_nv} DOF, model has {model_bodies} / {model_nv}")]
    WorkspaceMismatch {
        /// Bodies in the workspace.
        workspace_bodies: usize,
        /// DOF in the workspace.
        workspace_nv: usize,
        /// Bodies in the model.
        model_bodies: usize,
        /// DOF in the model.
        model_nv: usize,
    },
    /// A slice argument has the wrong length.
    #[error("argument `{argument}` has length {got}, expected {expected}")]
    DimensionMismatch {
        /// Argument name (`q`, `v`, `tau`, `vdot`).
        argument: &'static str,
        /// Required length.
        expected: usize,
        /// Given length.
        got: usize,
    },
    /// A dynamics call came before [`crate::update_kinematics`] for the current state.
    #[error("update_kinematics must be called before this function")]
    KinematicsNotUpdated,
    /// The Cholesky factorisation of the mass matrix failed.
    #[error("the joint-space mass matrix is not positive definite")]
    MassMatrixNotPositiveDefinite,
}
