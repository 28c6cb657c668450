//! The hot path (kinematics, external forces, point kinematics, CRBA, RNEA, forward
//! dynamics, the sparse mass-matrix solve, energies, qdot) performs no heap allocation once
//! the workspace exists: counted by a global allocator wrapper, per thread.
#[path = "support/vehicle.rs"]
mod vehicle;

use multibody::{
    bias_forces, forward_dynamics, forward_dynamics_aba, inverse_dynamics, kinetic_energy,
    mass_matrix, potential_energy, solve_mass_matrix, spatial_momentum, update_kinematics,
    Workspace,
};
use nalgebra::{UnitQuaternion, Vector3};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use vehicle::{springs, truck, TRUCK_SPRINGS};

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

struct Counting;

// SAFETY: forwards to the system allocator; only adds a thread-local counter.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|c| c.set(c.get() + 1));
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

#[test]
fn right_hand_side_evaluation_does_not_allocate() {
    let model = truck(Vector3::new(0.0, 0.0, -9.81));
    let mut ws = Workspace::new(&model);
    let r = UnitQuaternion::from_euler_angles(0.5, -0.1, 0.3).into_inner();
    let q = [
        0.0, 0.0, 1.5, r.w, r.i, r.j, r.k, 0.05, -0.03, 0.02, 0.04, 0.3, -1.0, 2.0, 0.5,
    ];
    let v = [
        0.3, -0.2, 0.1, 5.0, 0.0, 1.0, 0.2, -0.4, 0.3, -0.5, 10.0, 10.0, 11.0, 9.0,
    ];
    let (mut tau, mut qdot, mut out) = ([0.0; 14], [0.0; 15], [0.0; 14]);
    let wheel = model.body_index("wheel_rl").unwrap();
    let before = allocations();
    for _ in 0..10 {
        update_kinematics(&model, &mut ws, &q, &v).unwrap();
        let contact = ws.point_position(wheel, &Vector3::new(0.0, 0.0, -0.8));
        let slip = ws.point_velocity(wheel, &Vector3::new(0.0, 0.0, -0.8));
        ws.apply_force_world(
            wheel,
            &(Vector3::new(0.0, 0.0, 5.0e4) - 10.0 * slip),
            &contact,
        );
        ws.apply_moment_world(0, &Vector3::new(100.0, 0.0, 0.0));
        springs(&model, &TRUCK_SPRINGS, &q, &mut tau);
        forward_dynamics(&model, &mut ws, &tau).unwrap();
        forward_dynamics_aba(&model, &mut ws, &tau).unwrap();
        mass_matrix(&model, &mut ws).unwrap();
        bias_forces(&model, &mut ws).unwrap();
        inverse_dynamics(&model, &mut ws, &tau, &mut out).unwrap();
        solve_mass_matrix(&model, &mut ws, &mut out).unwrap();
        kinetic_energy(&model, &ws).unwrap();
        potential_energy(&model, &ws).unwrap();
        spatial_momentum(&model, &ws).unwrap();
        model.velocity_to_qdot(&q, &v, &mut qdot);
    }
    assert_eq!(allocations() - before, 0);
    assert!(ws.accelerations().iter().all(|a| a.is_finite()));
}
