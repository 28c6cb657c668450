//! Names of the vehicle's states in messages (a divergence names the state that left).

use crate::vehicle::Vehicle;

const SPIN: [&str; 4] = ["front-left", "front-right", "rear-left", "rear-right"];

impl Vehicle {
    /// Name of state `i` in messages: the joint coordinate or velocity it is, a steering
    /// pressure, a tire lag, an HPS state (`left`/`right` front, `rear-left`/`rear-right`) or a
    /// controller state.
    pub fn state_name(&self, i: usize) -> String {
        let o = self.offsets();
        let j = self.joints();
        let carriers = [(j.carrier, "front"), (j.rear_carrier, "rear")];
        let joint = |k: usize| -> Option<String> {
            if k == j.articulation.0 {
                return Some("articulation".into());
            }
            if j.rear_roll.is_some_and(|r| r.0 == k) {
                return Some("rear-unit roll".into());
            }
            if let Some(w) = j.spin.iter().position(|s| s.0 == k) {
                return Some(format!("{} wheel spin", SPIN[w]));
            }
            carriers.iter().find_map(|(c, axle)| {
                let side = c.as_ref()?.iter().position(|c| c.0 == k)?;
                Some(format!("{axle}-{} carrier travel", ["left", "right"][side]))
            })
        };
        let q_of_v = |k: usize| {
            [Some(j.articulation), j.rear_roll]
                .into_iter()
                .flatten()
                .chain(j.spin)
                .chain(j.carrier.into_iter().flatten())
                .chain(j.rear_carrier.into_iter().flatten())
                .find(|p| p.1 == k)
                .map(|p| p.0)
        };
        if i < o.v {
            let k = i - o.q;
            joint(k).unwrap_or_else(|| format!("floating-base coordinate q[{k}]"))
        } else if i < o.afs {
            let k = i - o.v;
            match q_of_v(k).and_then(joint) {
                Some(n) => format!("{n} rate"),
                None => format!("floating-base velocity v[{k}]"),
            }
        } else if i < o.tires {
            [
                "steering pressure P_c",
                "steering pressure P_r",
                "valve housing angle theta_h",
                "valve spool x_v",
            ]
            .get(i - o.afs)
            .map_or_else(
                || format!("steering state {}", i - o.afs),
                |n| (*n).to_string(),
            )
        } else if i < o.hps {
            let k = i - o.tires;
            let tire = crate::model::TIRE_NAMES.get(k / 2).copied().unwrap_or("?");
            format!("{tire} tire {} lag", ["slip ratio", "slip angle"][k % 2])
        } else if i < o.pi {
            let [front, rear] = self.axle_struts();
            // the front struts keep their names from before the rear axle could be suspended
            [(front, ""), (rear, "rear-")]
                .into_iter()
                .find_map(|(axle, name)| {
                    let a = axle?;
                    let side = (0..2).find(|&s| a.states(s).contains(&i))?;
                    let state = a.strut.states()[i - a.states(side).start].name;
                    Some(format!(
                        "{name}{} HPS strut {state}",
                        ["left", "right"][side]
                    ))
                })
                .unwrap_or_else(|| format!("HPS state {i}"))
        } else if i == o.pi {
            "speed-error integral".into()
        } else if i == o.path {
            "path coordinate".into()
        } else if Some(i) == o.driver {
            "driver steering-wheel angle".into()
        } else {
            format!("state {i}")
        }
    }
}
