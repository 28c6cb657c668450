//! The vehicle's mechanical and hydraulic energy at a state: the physics check of the
//! model (conserved on rigid axles without losses, only lost through the passive elements).

use super::{Vehicle, MAX_DIM};
use crate::error::VehicleError;

impl Vehicle {
    /// Mechanical and hydraulic energy (J) at `y`: kinetic + gravitational + the AFS
    /// chambers' compression energy + the tires' elastic energy, and with the HPS the
    /// struts' stored energy ([`crate::suspension::AxleStruts::stored_energy`]). Conserved on rigid axles with
    /// the valve closed (steering-wheel angle inside the dead band), no leakage, no strut
    /// friction, no tire damping and no horizontal tire forces (`tests/physics.rs`); the
    /// HPS struts only lose it (`tests/rear_hps.rs`).
    pub fn energy(&self, y: &[f64]) -> Result<f64, VehicleError> {
        let mut struts = 0.0;
        for axle in self.axle_struts().into_iter().flatten() {
            struts += axle.stored_energy(y, self.offsets.v)?;
        }
        let mut ws = self.ws.borrow_mut();
        let mut tau = [0.0; MAX_DIM];
        let mut scratch = [0.0; MAX_DIM];
        let dynamics = |source| VehicleError::Dynamics { t: 0.0, source };
        let snap = self
            .apply_forces(
                0.0,
                y,
                &mut ws,
                &mut tau[..self.model.nv()],
                &mut scratch[..y.len()],
            )
            .map_err(dynamics)?;
        let kinetic = multibody::kinetic_energy(&self.model, &ws).map_err(dynamics)?;
        let gravity = multibody::potential_energy(&self.model, &ws).map_err(dynamics)?;
        let o = &self.offsets;
        let hydraulic = self.afs.strut_hydraulic_energy(
            snap.strut_disp_m[0],
            snap.strut_disp_m[1],
            &y[o.afs..o.afs + 3],
        );
        let table = self.tires.vertical().load_deflection();
        let tires: f64 = snap.tires[..self.mounts.len()]
            .iter()
            .map(|c| table.energy(c.deflection))
            .sum();
        Ok(kinetic + gravity + hydraulic + tires + struts)
    }
}
